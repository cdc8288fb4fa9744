// slice.cpp — the (θh, θd) slice of the lighting model (slice.h).
#include "core/plots/slice.h"

#include "core/io/number_format.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace lab {

namespace {

// sin and cos of an angle in degrees, in double, exact at 0° and 90° (std::sin of a rounded π/2's
// cosine is 6e-17, not 0: the 90° edge must read N·L = 0 exactly).
glm::dvec2 sinCos(double deg) {
    if (deg == 0.0) {
        return {0.0, 1.0};
    }
    if (deg == 90.0) {
        return {1.0, 0.0};
    }
    const double r = glm::radians(deg);
    return {std::sin(r), std::cos(r)};
}

} // namespace

SliceVectors sliceVectors(float thetaHDeg, float thetaDDeg, float phiDDeg) {
    const glm::dvec2 h = sinCos(thetaHDeg), d = sinCos(thetaDDeg), p = sinCos(phiDDeg);
    // D(θd, φd) in H's frame (x = (cos θh, 0, −sin θh), y = (0, 1, 0), z = H), and its opposite
    // azimuth for V: (−Dx, −Dy, Dz).
    const glm::dvec3 D(d.x * p.y, d.x * p.x, d.y);
    const glm::dvec3 x(h.y, 0.0, -h.x), y(0.0, 1.0, 0.0), z(h.x, 0.0, h.y);
    SliceVectors v;
    v.N = glm::vec3(0.0f, 0.0f, 1.0f);
    v.H = glm::vec3(z);
    v.L = glm::vec3(D.x * x + D.y * y + D.z * z);
    v.V = glm::vec3(-D.x * x - D.y * y + D.z * z);
    return v;
}

SliceValue sliceValue(const SurfaceUniforms& surface, float thetaHDeg, float thetaDDeg) {
    const SliceVectors v = sliceVectors(thetaHDeg, thetaDDeg);
    if (!(glm::dot(v.N, v.L) > 0.0f) || !(glm::dot(v.N, v.V) > 0.0f)) {
        return {};
    }
    const glsl::LightTerms t = glsl::lightContribution(surface.material, surface.brdf, surface.terms, unitLightFrom(v.L),
                                                       glm::vec3(0.0f), v.N, v.V);
    return {luminance(t.diffuse), luminance(t.specular)};
}

float SliceImage::largest(PlotComponent c) const {
    const std::vector<float>& values = component(c);
    return values.empty() ? 0.0f : *std::max_element(values.begin(), values.end());
}

SliceImage sampleSlice(const SurfaceUniforms& surface, int stepDeg) {
    SliceImage image;
    image.stepDeg = stepDeg > 0 && 90 % stepDeg == 0 ? stepDeg : 1;
    const int n = image.side();
    const std::size_t count = static_cast<std::size_t>(n * n);
    image.diffuse.reserve(count);
    image.specular.reserve(count);
    image.total.reserve(count);
    for (int row = 0; row < n; ++row) {
        for (int column = 0; column < n; ++column) {
            const SliceValue s = sliceValue(surface, static_cast<float>(column * image.stepDeg),
                                            static_cast<float>(row * image.stepDeg));
            image.diffuse.push_back(s.diffuse);
            image.specular.push_back(s.specular);
            image.total.push_back(s.total()); // as the plots' total
        }
    }
    return image;
}

SliceImage sliceDifference(const SliceImage& a, const SliceImage& b) {
    SliceImage d;
    d.stepDeg = a.stepDeg;
    if (a.stepDeg != b.stepDeg || a.total.size() != b.total.size()) {
        return d;
    }
    auto minus = [](const std::vector<float>& x, const std::vector<float>& y, std::vector<float>& out) {
        out.resize(x.size());
        std::transform(x.begin(), x.end(), y.begin(), out.begin(), [](float p, float q) { return p - q; });
    };
    minus(a.diffuse, b.diffuse, d.diffuse);
    minus(a.specular, b.specular, d.specular);
    minus(a.total, b.total, d.total);
    return d;
}

SliceMarker planeToSlice(float incidentDeg, float outgoingDeg) {
    SliceMarker m;
    m.thetaHDeg = std::fabs(outgoingDeg - incidentDeg) * 0.5f;
    m.thetaDDeg = std::fabs(incidentDeg + outgoingDeg) * 0.5f;
    // θh = 0 (V the mirror direction) or θd = 0 (V = L): L and V do not depend on φd there.
    m.onSlice = m.thetaHDeg == 0.0f || m.thetaDDeg == 0.0f;
    return m;
}

glm::vec3 divergingColor(float t) {
    // PuOr's 5-class stops, from B's side (purple) to A's (orange).
    static constexpr glm::vec3 stops[5] = {{94.0f, 60.0f, 153.0f}, {178.0f, 171.0f, 210.0f}, {247.0f, 247.0f, 247.0f},
                                           {253.0f, 184.0f, 99.0f}, {230.0f, 97.0f, 1.0f}};
    const float u = (std::clamp(std::isfinite(t) ? t : 0.0f, -1.0f, 1.0f) + 1.0f) * 2.0f; // 0 … 4
    const int i = std::min(static_cast<int>(u), 3);
    return glm::mix(stops[i], stops[i + 1], u - static_cast<float>(i)) / 255.0f;
}

float differencePosition(float v, float largestAbs, RadialScale scale) {
    if (!(largestAbs > kNothingLit) || !std::isfinite(v)) {
        return 0.0f;
    }
    const float t = plotRadius(std::fabs(v), largestAbs, scale);
    return v < 0.0f ? -t : t;
}

std::string sliceCsv(const SliceImage& image) {
    std::string out = "theta_h_deg,theta_d_deg,diffuse,specular,total\n";
    const int n = image.side();
    if (image.total.size() != static_cast<std::size_t>(n * n)) {
        return out;
    }
    for (int row = 0; row < n; ++row) {
        for (int column = 0; column < n; ++column) {
            const std::size_t k = static_cast<std::size_t>(image.index(column, row));
            for (float v : {static_cast<float>(column * image.stepDeg), static_cast<float>(row * image.stepDeg),
                            image.diffuse[k], image.specular[k]}) {
                out += shortestFloat(v);
                out += ',';
            }
            out += shortestFloat(image.total[k]);
            out += '\n';
        }
    }
    return out;
}

} // namespace lab
