// probe.cpp — ray cast and per-term evaluation.
#include "core/scene/transforms.h"
#include "core/lighting/probe.h"

#include <limits>

namespace lab {

namespace {

// Möller–Trumbore; returns t and the barycentrics (u, v) of the hit.
bool intersect(const glm::vec3& o, const glm::vec3& d, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
               float& t, float& u, float& v) {
    glm::vec3 e1 = b - a, e2 = c - a;
    glm::vec3 p = glm::cross(d, e2);
    float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) {
        return false;
    }
    float inv = 1.0f / det;
    glm::vec3 s = o - a;
    u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) {
        return false;
    }
    glm::vec3 q = glm::cross(s, e1);
    v = glm::dot(d, q) * inv;
    if (v < 0.0f || u + v > 1.0f) {
        return false;
    }
    t = glm::dot(e2, q) * inv;
    return t > 0.0f;
}

// Where the ray origin + t direction first meets the mesh, with the normal the preset's shading
// uses there: the centroid and face normal for flat shading, else the hit point and the
// interpolated vertex normal (model space, not normalized).
struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 normal;
};

std::optional<SurfacePoint> nearestHit(const Mesh& mesh, Shading shading, const glm::vec3& origin,
                                       const glm::vec3& direction) {
    float best = std::numeric_limits<float>::max();
    std::size_t hit = 0;
    float hu = 0, hv = 0;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        float tt, u, v;
        if (intersect(origin, direction, mesh.positions[mesh.indices[i]], mesh.positions[mesh.indices[i + 1]],
                      mesh.positions[mesh.indices[i + 2]], tt, u, v) &&
            tt < best) {
            best = tt;
            hit = i;
            hu = u;
            hv = v;
        }
    }
    if (best == std::numeric_limits<float>::max()) {
        return std::nullopt;
    }
    const glm::vec3& a = mesh.positions[mesh.indices[hit]];
    const glm::vec3& b = mesh.positions[mesh.indices[hit + 1]];
    const glm::vec3& c = mesh.positions[mesh.indices[hit + 2]];
    if (shading == Shading::Flat) {
        return SurfacePoint{(a + b + c) / 3.0f, glm::cross(b - a, c - a)};
    }
    return SurfacePoint{origin + best * direction, (1.0f - hu - hv) * mesh.normals[mesh.indices[hit]] +
                                                       hu * mesh.normals[mesh.indices[hit + 1]] +
                                                       hv * mesh.normals[mesh.indices[hit + 2]]};
}

// Light `l` (preset.lights[index]) at the probed point: its terms as the shaders compute them
// (glsl::lightContribution), and the vectors and factors they come from.
ProbeLight probeLight(const ShadingInputs& in, const glsl::Light& l, int index, const ProbeResult& r) {
    const glsl::LightTerms terms = glsl::lightContribution(in.material, in.brdf, in.terms, l, r.positionEye, r.N, r.V);
    ProbeLight pl;
    pl.index = index;
    pl.L = terms.L;
    pl.R = glsl::reflectionVector(r.N, pl.L);
    pl.H = glsl::halfVector(pl.L, r.V);
    pl.NoL = terms.NoL;
    pl.RoV = glm::dot(pl.R, r.V);
    pl.NoH = glm::dot(r.N, pl.H);
    pl.VoH = glm::dot(r.V, pl.H);
    pl.NoV = glm::dot(r.N, r.V);
    pl.distance = l.type == glsl::LIGHT_DIRECTIONAL ? 0.0f : glm::length(l.position - r.positionEye);
    pl.attenuation = terms.attenuation;
    if (in.brdf.model == glsl::BRDF_COOK_TORRANCE) {
        pl.D = glsl::distributionTerm(pl.NoH, in.brdf);
        pl.F = glsl::fresnelTerm(pl.VoH, in.brdf);
        pl.G = glsl::geometryTerm(pl.NoH, pl.NoV, pl.NoL, pl.VoH, in.brdf);
    }
    pl.specularFactor = terms.specularFactor;
    pl.ambient = terms.ambient;
    pl.diffuse = terms.diffuse;
    pl.specular = terms.specular;
    return pl;
}

} // namespace

std::optional<ProbeResult> probePixel(const Preset& preset, const Mesh& mesh, glm::vec2 ndc, float aspect) {
    Transforms t = computeTransforms(preset, aspect);
    glm::mat4 inverse = glm::inverse(t.projection * t.modelView);
    glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    glm::vec3 origin = glm::vec3(nearPoint) / nearPoint.w;
    glm::vec3 direction = glm::vec3(farPoint) / farPoint.w - origin;
    std::optional<SurfacePoint> hit = nearestHit(mesh, preset.shading, origin, direction);
    if (!hit) {
        return std::nullopt;
    }
    return probeSurface(preset, hit->position, hit->normal);
}

ProbeResult probeSurface(const Preset& preset, const glm::vec3& positionModel, const glm::vec3& normalModel) {
    Transforms t = computeTransforms(preset, 1.0f); // the eye-space terms do not depend on the view's shape
    ProbeResult r;
    r.positionModel = positionModel;
    r.normalModel = normalModel;
    r.positionWorld = glm::vec3(t.model * glm::vec4(positionModel, 1.0f));
    r.positionEye = glm::vec3(t.modelView * glm::vec4(positionModel, 1.0f));
    r.N = glm::normalize(t.normalMatrix * normalModel);
    r.V = glm::normalize(-r.positionEye);
    ShadingInputs in = packShading(preset, t.view);
    r.emissive = preset.terms.emissive ? in.material.emissive : glm::vec3(0.0f);
    r.globalAmbient = preset.terms.ambient ? in.ambientLight * in.material.ambient : glm::vec3(0.0f);
    int packed = 0;
    for (std::size_t i = 0; i < preset.lights.size() && packed < in.lightCount; ++i) {
        if (preset.lights[i].enabled) {
            r.lights.push_back(probeLight(in, in.lights[packed++], static_cast<int>(i), r));
        }
    }
    r.color = shade(in, r.positionEye, r.N);
    return r;
}

} // namespace lab
