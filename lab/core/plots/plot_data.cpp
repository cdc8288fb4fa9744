// plot_data.cpp — samples the lighting model in the plane of incidence.
#include "core/plots/plot_data.h"

#include "core/io/number_format.h"
#include "core/lighting/lighting.h"
#include "core/plots/plot_layout.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lab {

// Every lobe samples the same directions (the 3D lobe's rings too).
const std::array<glm::vec2, 181>& outgoingDirections() {
    static const std::array<glm::vec2, 181> table = [] {
        std::array<glm::vec2, 181> t{};
        for (int deg = -90; deg <= 90; ++deg) {
            float to = glm::radians(static_cast<float>(deg));
            t[static_cast<std::size_t>(deg + 90)] = {std::sin(to), std::cos(to)};
        }
        return t;
    }();
    return table;
}

LobeInputs lobeInputs(const Preset& preset, float incidentDeg) {
    LobeInputs in;
    static_cast<SurfaceUniforms&>(in) = packSurfaceUniforms(preset);
    in.incidentDeg = incidentDeg;
    return in;
}

bool operator==(const LobeInputs& x, const LobeInputs& y) {
    return static_cast<const SurfaceUniforms&>(x) == static_cast<const SurfaceUniforms&>(y) && x.incidentDeg == y.incidentDeg &&
           x.lightDiffuse == y.lightDiffuse && x.lightSpecular == y.lightSpecular;
}

glsl::Light unitLightFrom(const glm::vec3& L) {
    glsl::Light light{};
    light.type = glsl::LIGHT_DIRECTIONAL;
    light.direction = -L;
    light.diffuse = glm::vec3(1.0f);
    light.specular = glm::vec3(1.0f);
    light.attenuation = glm::vec3(1.0f, 0.0f, 0.0f);
    return light;
}

glsl::Light lobeLightFrom(const LobeInputs& inputs, const glm::vec3& L) {
    glsl::Light light = unitLightFrom(L);
    light.diffuse = inputs.lightDiffuse;
    light.specular = inputs.lightSpecular;
    return light;
}

LobeVectors lobeVectors(float incidentDeg) {
    const float ti = glm::radians(incidentDeg);
    LobeVectors v;
    v.N = glm::vec3(0.0f, 1.0f, 0.0f);
    v.L = glm::vec3(-std::sin(ti), std::cos(ti), 0.0f);
    v.R = glsl::reflectionVector(v.N, v.L);
    return v;
}

std::vector<PlotSample> reflectedIntensity(const LobeInputs& inputs, int stepDeg) {
    // The material, BRDF and term switches as the shaders get them, and a directional light from
    // L (unit white, or the inputs' colours): lightContribution() then gives each sample's diffuse
    // and specular parts, 0 where the preset switches the term off, exactly as the renderer sums them.
    const glsl::Material& material = inputs.material;
    const glsl::Brdf& brdf = inputs.brdf;
    const glsl::Terms& terms = inputs.terms;
    const LobeVectors v = lobeVectors(inputs.incidentDeg);
    const glm::vec3& N = v.N;
    const glsl::Light light = lobeLightFrom(inputs, v.L);
    const glm::vec3 p(0.0f);
    std::vector<PlotSample> samples;
    stepDeg = stepDeg > 0 && 90 % stepDeg == 0 ? stepDeg : 1;
    samples.reserve(static_cast<std::size_t>(180 / stepDeg + 1));
    const std::array<glm::vec2, 181>& directions = outgoingDirections();
    for (int deg = -90; deg <= 90; deg += stepDeg) {
        const glm::vec2& d = directions[static_cast<std::size_t>(deg + 90)];
        const glsl::LightTerms c = glsl::lightContribution(material, brdf, terms, light, p, N, glm::vec3(d.x, d.y, 0.0f));
        float diffuse = luminance(c.diffuse);
        float specular = luminance(c.specular);
        samples.push_back({static_cast<float>(deg), diffuse, specular, diffuse + specular});
    }
    return samples;
}

std::string plotCsv(const std::vector<PlotSample>& samples) {
    std::string out = "theta_out_deg,diffuse,specular,total\n";
    auto put = [&](float v, char end) {
        out += shortestFloat(v);
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

float componentOf(const PlotSample& s, PlotComponent c) {
    switch (c) {
    case PlotComponent::Diffuse: return s.diffuse;
    case PlotComponent::Specular: return s.specular;
    case PlotComponent::Total: return s.total;
    }
    return 0.0f;
}

float plotRadius(float intensity, float maxIntensity, RadialScale scale) {
    if (!(intensity > 0.0f) || !(maxIntensity > 0.0f)) {
        return 0.0f;
    }
    float ratio = intensity / maxIntensity;
    if (scale == RadialScale::Linear) {
        return std::min(ratio, 1.0f);
    }
    return std::clamp(1.0f + std::log10(ratio) / kLogDecades, 0.0f, 1.0f);
}

std::vector<glm::vec2> lobePoints(const std::vector<PlotSample>& samples, PlotComponent component,
                                  float maxIntensity, RadialScale scale) {
    std::vector<glm::vec2> points;
    points.reserve(samples.size());
    const std::array<glm::vec2, 181>& directions = outgoingDirections();
    for (const PlotSample& s : samples) {
        float r = plotRadius(componentOf(s, component), maxIntensity, scale);
        points.push_back(r * directions[static_cast<std::size_t>(std::lround(s.thetaOutDeg) + 90)]);
    }
    return points;
}

float maxTotal(const std::vector<std::vector<PlotSample>>& sets) {
    float m = 1e-6f;
    for (const auto& set : sets) {
        for (const PlotSample& s : set) {
            m = std::max(m, s.total);
        }
    }
    return m;
}

std::vector<RadialRing> radialRings(float outer, RadialScale scale) {
    std::vector<float> values = scale == RadialScale::Linear ? linearTicks(outer, 4) : decadeTicks(outer, kLogDecades);
    std::vector<RadialRing> out;
    for (float v : values) {
        float r = plotRadius(v, outer, scale);
        if (r > 0.02f) {
            out.push_back({v, r});
        }
    }
    std::sort(out.begin(), out.end(), [](const RadialRing& x, const RadialRing& y) { return x.radius < y.radius; });
    return out;
}

AttenuationSpan attenuationSpan(const LightDesc& light, const Model& model) {
    const float distance = glm::length(light.position - model.translate);
    if (light.type == LightType::Directional) {
        return {distance, 5.0f};
    }
    return {distance, std::max(5.0f, std::ceil(distance * 2.0f))};
}

std::vector<glm::vec2> attenuationCurve(const glm::vec3& coefficients, float maxDistance, int samples) {
    std::vector<glm::vec2> points;
    points.reserve(static_cast<std::size_t>(samples));
    for (int i = 0; i < samples; ++i) {
        float d = maxDistance * static_cast<float>(i) / static_cast<float>(samples - 1);
        points.emplace_back(d, glsl::attenuation(coefficients, d));
    }
    return points;
}

} // namespace lab
