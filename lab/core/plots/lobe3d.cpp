// lobe3d.cpp — samples the lighting model over the hemisphere and finds the lobe's maximum.
#include "core/plots/lobe3d.h"

#include "core/lighting/lighting.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace lab {

namespace {

// (cos φ, sin φ), exact at multiples of 90° (std::cos of a float π is -1, but std::sin of it is
// not 0: the meridians of the plane of incidence would leave it by 1e-7).
glm::vec2 azimuth(float phiDeg) {
    float wrapped = std::fmod(phiDeg, 360.0f);
    wrapped = wrapped < 0.0f ? wrapped + 360.0f : wrapped;
    if (wrapped == 0.0f) {
        return {1.0f, 0.0f};
    }
    if (wrapped == 90.0f) {
        return {0.0f, 1.0f};
    }
    if (wrapped == 180.0f) {
        return {-1.0f, 0.0f};
    }
    if (wrapped == 270.0f) {
        return {0.0f, -1.0f};
    }
    float p = glm::radians(wrapped);
    return {std::cos(p), std::sin(p)};
}

// What the samples share: the inputs' light and the point at the origin.
struct Evaluator {
    const LobeInputs& in;
    LobeVectors v;
    glsl::Light light;

    explicit Evaluator(const LobeInputs& inputs)
        : in(inputs), v(lobeVectors(inputs.incidentDeg)), light(lobeLightFrom(inputs, v.L)) {}

    glsl::LightTerms at(const glm::vec3& V) const {
        return glsl::lightContribution(in.material, in.brdf, in.terms, light, glm::vec3(0.0f), v.N, V);
    }
};

} // namespace

glm::vec3 outgoingDirection(float thetaDeg, float phiDeg) {
    // Whole degrees from the plot's own table, so that the in-plane meridians are the plot's
    // directions exactly (the table's sines may be rounded otherwise than a sine computed here).
    glm::vec2 sc;
    if (thetaDeg == std::round(thetaDeg) && std::fabs(thetaDeg) <= 90.0f) {
        sc = outgoingDirections()[static_cast<std::size_t>(std::lround(thetaDeg) + 90)];
    } else {
        const float to = glm::radians(thetaDeg);
        sc = {std::sin(to), std::cos(to)};
    }
    const glm::vec2 a = azimuth(phiDeg);
    return {sc.x * a.x, sc.y, sc.x * a.y};
}

float HemisphereGrid::largest(PlotComponent c) const {
    const std::vector<float>& values = component(c);
    return values.empty() ? 0.0f : *std::max_element(values.begin(), values.end());
}

HemisphereGrid sampleHemisphere(const LobeInputs& inputs, GridSteps steps) {
    const Evaluator e(inputs);
    HemisphereGrid g;
    g.steps = steps;
    const int rings = g.rings(), meridians = g.meridians();
    const std::size_t n = static_cast<std::size_t>(rings * meridians);
    g.directions.reserve(n);
    g.diffuse.reserve(n);
    g.specular.reserve(n);
    g.total.reserve(n);
    // The azimuths once: each ring has the same.
    std::vector<glm::vec2> phis(static_cast<std::size_t>(meridians));
    for (int j = 0; j < meridians; ++j) {
        phis[static_cast<std::size_t>(j)] = azimuth(static_cast<float>(j * steps.phiDeg));
    }
    for (int i = 0; i < rings; ++i) {
        // θo in whole degrees: the rings are the plot's directions.
        const glm::vec2 sc = outgoingDirections()[static_cast<std::size_t>(90 + i * steps.thetaDeg)];
        const float s = sc.x, c = sc.y;
        for (const glm::vec2& phi : phis) {
            const glm::vec3 V(s * phi.x, c, s * phi.y);
            const glsl::LightTerms t = e.at(V);
            const float diffuse = luminance(t.diffuse), specular = luminance(t.specular);
            g.directions.push_back(V);
            g.diffuse.push_back(diffuse);
            g.specular.push_back(specular);
            g.total.push_back(diffuse + specular); // as the plot's total
        }
    }
    g.largestTotal = g.largest(PlotComponent::Total);
    return g;
}

float intensityAt(const LobeInputs& inputs, const glm::vec3& V, PlotComponent component) {
    const glsl::LightTerms t = Evaluator(inputs).at(V);
    return componentOf(luminance(t.diffuse), luminance(t.specular), component);
}

glm::vec3 lobeSurfacePoint(const HemisphereGrid& grid, std::size_t k, PlotComponent component, float outer, RadialScale scale) {
    return plotRadius(grid.component(component)[k], outer, scale) * grid.directions[k];
}

std::vector<glm::vec3> lobeSurface(const HemisphereGrid& grid, PlotComponent component, float outer, RadialScale scale) {
    std::vector<glm::vec3> points;
    points.reserve(grid.directions.size());
    for (std::size_t k = 0; k < grid.directions.size(); ++k) {
        points.push_back(lobeSurfacePoint(grid, k, component, outer, scale));
    }
    return points;
}

glm::vec2 mapPoint(const glm::vec3& V) {
    const float horizontal = std::sqrt(V.x * V.x + V.z * V.z);
    if (horizontal < 1e-12f) {
        return {0.0f, 0.0f};
    }
    const float theta = std::atan2(horizontal, V.y); // 0 … π/2 over the hemisphere
    const float r = theta / glm::half_pi<float>();
    return {r * V.x / horizontal, r * V.z / horizontal};
}

LobeMaximum lobeMaximum(const LobeInputs& inputs, const HemisphereGrid& grid, PlotComponent component) {
    const std::vector<float>& values = grid.component(component);
    LobeMaximum m;
    if (values.empty()) {
        return m;
    }
    m.gridIndex = static_cast<int>(std::max_element(values.begin(), values.end()) - values.begin());
    m.thetaDeg = static_cast<float>(m.gridIndex / grid.meridians() * grid.steps.thetaDeg);
    m.phiDeg = static_cast<float>(m.gridIndex % grid.meridians() * grid.steps.phiDeg);
    m.V = grid.directions[static_cast<std::size_t>(m.gridIndex)];
    m.value = values[static_cast<std::size_t>(m.gridIndex)];
    // A compass search from the grid's best: try a step either way in θo and in φ, move to a
    // better one, else halve the step. The lobes are smooth near their peak, and the grid's
    // best lies within a cell of it, so this finds the peak to the last step.
    const Evaluator e(inputs);
    auto value = [&](float theta, float phi) {
        const glsl::LightTerms t = e.at(outgoingDirection(theta, phi));
        return componentOf(luminance(t.diffuse), luminance(t.specular), component);
    };
    for (float step = static_cast<float>(grid.steps.phiDeg); step > 1e-4f;) {
        bool moved = false;
        const float tries[4][2] = {{step, 0.0f}, {-step, 0.0f}, {0.0f, step}, {0.0f, -step}};
        for (const auto& t : tries) {
            const float theta = std::clamp(m.thetaDeg + t[0], 0.0f, 90.0f), phi = m.phiDeg + t[1];
            const float v = value(theta, phi);
            if (v > m.value) {
                m.thetaDeg = theta;
                m.phiDeg = phi;
                m.value = v;
                moved = true;
                break;
            }
        }
        if (!moved) {
            step *= 0.5f;
        }
    }
    m.phiDeg = std::fmod(m.phiDeg + 360.0f, 360.0f);
    m.V = outgoingDirection(m.thetaDeg, m.phiDeg);
    return m;
}

} // namespace lab
