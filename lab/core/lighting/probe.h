// probe.h — what the lighting model computes at one pixel: the GUI's pixel probe.
//
// Casts the pixel's ray against the mesh (in model space), finds the nearest triangle and the
// shading normal the preset's shading mode uses there (the face normal for flat shading, the
// interpolated vertex normal otherwise), and evaluates every term with lab::glsl — the same
// functions the shaders run. Gouraud shading shows the per-pixel evaluation at the hit point;
// the pixel itself holds the interpolated vertex colours.
#pragma once

#include "core/lighting/lighting.h"
#include "core/scene/mesh.h"

#include <optional>
#include <vector>

namespace lab {

struct ProbeLight {
    int index;          // in preset.lights
    glm::vec3 L, R, H;  // eye space, unit
    float NoL, RoV, NoH, VoH, NoV;
    float distance;     // 0 for directional lights
    float attenuation;  // Att_i, the spot factor included
    float D = 0, F = 0, G = 0; // Cook-Torrance terms (when that BRDF is chosen)
    float specularFactor;      // S_i
    glm::vec3 ambient, diffuse, specular; // this light's three contributions, before clamping
};

struct ProbeResult {
    glm::vec3 positionModel, normalModel; // the point on the mesh and its shading normal (model space, not normalized)
    glm::vec3 positionWorld; // the shading point, where the GUI marks it
    glm::vec3 positionEye;
    glm::vec3 N, V;
    glm::vec3 emissive, globalAmbient; // contributions that belong to no light
    std::vector<ProbeLight> lights;
    glm::vec3 color; // clamped sum, as the shader computes it
};

// `ndc` is the pixel centre in normalized device coordinates ([-1, 1], y up).
std::optional<ProbeResult> probePixel(const Preset& preset, const Mesh& mesh, glm::vec2 ndc, float aspect);

// The same evaluation at a point already found (ProbeResult::positionModel, normalModel): how the
// GUI follows a probed point while the camera or a light moves, without casting a ray again (the
// point stays where it is on the mesh even where something now hides it).
ProbeResult probeSurface(const Preset& preset, const glm::vec3& positionModel, const glm::vec3& normalModel);

} // namespace lab
