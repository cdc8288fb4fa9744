// plot.cpp — samples the lighting model in the plane of incidence.
#include "core/plot.h"

#include "core/lighting.h"

#include <charconv>

namespace lab {

std::vector<PlotSample> reflectedIntensity(const Preset& preset, float incidentDeg) {
    const glsl::Brdf brdf = packBrdf(preset);
    const float ti = glm::radians(incidentDeg);
    const glm::vec3 N(0.0f, 1.0f, 0.0f);
    const glm::vec3 L(-std::sin(ti), std::cos(ti), 0.0f);
    const float diffuse = luminance(preset.material.diffuse * std::max(glm::dot(N, L), 0.0f));
    std::vector<PlotSample> samples;
    samples.reserve(181);
    for (int deg = -90; deg <= 90; ++deg) {
        float to = glm::radians(static_cast<float>(deg));
        glm::vec3 V(std::sin(to), std::cos(to), 0.0f);
        float S = glsl::specularFactor(N, L, V, preset.material.shininess, brdf);
        float specular = luminance(preset.material.specular * S);
        samples.push_back({static_cast<float>(deg), diffuse, specular, diffuse + specular});
    }
    return samples;
}

std::string plotCsv(const std::vector<PlotSample>& samples) {
    std::string out = "theta_out_deg,diffuse,specular,total\n";
    auto put = [&](float v, char end) {
        char buf[32];
        auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v); // shortest round-trip form
        out.append(buf, p);
        out += end;
    };
    for (const PlotSample& s : samples) {
        put(s.thetaOutDeg, ',');
        put(s.diffuse, ',');
        put(s.specular, ',');
        put(s.total, '\n');
    }
    return out;
}

} // namespace lab
