// probe_lobe.cpp — a probed point's N, L and V in the plots' frame.
#include "core/scene/transforms.h"
#include "core/plots/probe_lobe.h"

#include "core/plots/lobe3d.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace lab {

namespace {

// A unit vector perpendicular to unit `n`.
glm::vec3 anyPerpendicular(const glm::vec3& n) {
    return glm::normalize(glm::cross(n, std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
}

// The plot's x axis at the point: in the plane of N and L, away from L. Where L lies along N
// every plane through N is a plane of incidence: the one through V is taken, so that V lies in it.
glm::vec3 tangentAxis(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V) {
    const glm::vec3 side = L - glm::dot(N, L) * N;
    if (glm::length(side) > 1e-5f) {
        return -glm::normalize(side);
    }
    const glm::vec3 towardsV = V - glm::dot(N, V) * N;
    return glm::length(towardsV) > 1e-5f ? glm::normalize(towardsV) : anyPerpendicular(N);
}

float degreesOf(float radians) { return glm::degrees(radians); }

} // namespace

std::optional<ProbeLobe> probeLobe(const ProbeResult& probe, const Preset& preset, int light) {
    const int packed = packedLightIndex(preset, light);
    if (packed < 0) {
        return std::nullopt;
    }
    // The light in eye space as the shaders get it, and the probe's point, normal and viewer.
    const glm::mat4 view = computeTransforms(preset, 1.0f).view;
    const glsl::Light l = packShading(preset, view).lights[packed];
    const glm::vec3 &p = probe.positionEye, &N = probe.N, &V = probe.V;
    glm::vec3 L = glsl::lightVector(l, p);
    if (glm::length(L) < 0.5f) {
        L = N; // the light at the point itself: lightVector() gives 0; any direction lights it as much
    }

    ProbeLobe at;
    at.light = light;
    at.incidentDeg = degreesOf(std::acos(glm::clamp(glm::dot(N, L), -1.0f, 1.0f)));
    at.distance = glsl::lightDistance(l, p);
    at.attenuation = glsl::distanceAttenuation(l, p);
    at.spot = glsl::spotTerm(l, L);
    at.incomingDiffuse = l.diffuse * at.attenuation * at.spot;
    at.incomingSpecular = l.specular * at.attenuation * at.spot;

    const glm::vec3 tangent = tangentAxis(N, L, V), across = glm::cross(tangent, N);
    at.viewer = glm::vec3(glm::dot(V, tangent), glm::dot(V, N), glm::dot(V, across));
    at.viewerDeg = degreesOf(std::atan2(at.viewer.x, at.viewer.y));
    at.outOfPlaneDeg = degreesOf(std::asin(std::min(std::abs(at.viewer.z), 1.0f)));

    // Eye space back to world space: the view matrix is a rotation and a translation.
    const glm::mat3 toWorld = glm::transpose(glm::mat3(view));
    at.world = {probe.positionWorld, glm::normalize(toWorld * N), glm::normalize(toWorld * tangent),
                glm::normalize(toWorld * across)};
    return at;
}

float plottedIncidentDeg(const ProbeLobe& at) { return std::min(at.incidentDeg, 90.0f); }

LobeInputs probeLobeInputs(const Preset& preset, const ProbeLobe& at) {
    LobeInputs in = lobeInputs(preset, plottedIncidentDeg(at));
    in.lightDiffuse = at.incomingDiffuse;
    in.lightSpecular = at.incomingSpecular;
    return in;
}

std::vector<std::vector<glm::vec3>> lobeWireframe(const LobeInputs& inputs, int planes) {
    std::vector<std::vector<glm::vec3>> curves;
    float largest = 0.0f;
    for (int k = 0; k < planes; ++k) {
        const float phi = 180.0f * static_cast<float>(k) / static_cast<float>(planes);
        std::vector<glm::vec3> curve;
        for (int deg = -90; deg <= 90; deg += 3) {
            // θo < 0 is the other half of the same plane: azimuth φ + 180°.
            const glm::vec3 V = outgoingDirection(std::fabs(static_cast<float>(deg)), deg >= 0 ? phi : phi + 180.0f);
            const float r = intensityAt(inputs, V, PlotComponent::Total);
            largest = std::max(largest, r);
            curve.push_back(r * V);
        }
        curves.push_back(std::move(curve));
    }
    const float scale = largest > kNothingLit ? 1.0f / largest : 0.0f;
    for (std::vector<glm::vec3>& curve : curves) {
        for (glm::vec3& point : curve) {
            point *= scale;
        }
    }
    return curves;
}

} // namespace lab
