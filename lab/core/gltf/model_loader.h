// model_loader.h — the mesh a preset's `model` names: a built-in shape or a glTF file.
#pragma once

#include "core/io/diagnostics.h"
#include "core/scene/camera.h"
#include "core/scene/mesh.h"
#include "core/scene/preset.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lab {

// `folder` is the preset's folder (glTF paths are relative to it and may not leave it).
// `notes` receives what was skipped or computed while loading, for the user.
// What identifies a loaded model for caching: the built-in and its subdivisions, or the glTF
// file's canonical path with its size and modification time (a file rewritten in place, say a
// model exported again, is a new model).
std::string modelCacheKey(const Model& model, const std::filesystem::path& folder);

std::optional<Mesh> loadModel(const Model& model, const std::filesystem::path& folder, Diagnostics& diagnostics,
                              std::vector<std::string>* notes = nullptr);

// `mesh`'s positions as `model` draws them (after its scale, rotation and translation), what
// framing fits in the view (core/scene/camera.h framedCamera); and their bounding sphere, centred
// on the box around them through the farthest of them. nullopt for a mesh without positions, or
// one whose drawn coordinates overflow float.
std::optional<std::vector<glm::vec3>> drawnPositions(const Mesh& mesh, const Model& model);
std::optional<Sphere> drawnBounds(const Mesh& mesh, const Model& model);

// Framing, for a preset met with its mesh (MeshCache::get does it for every consumer). A glTF
// model whose file had no `camera` gets framedCamera(default camera, drawnPositions,
// threeQuarterDirection()) (core/scene/camera.h): seen from above the front, spanning 85% of the
// view's narrower side in any shape of view. Without `lights` either, the default light
// stands where it stands for a unit sphere, scaled to the model: centre + (2, 2, 2) · radius of
// drawnBounds (inside the coordinate range). Built-in models and keys the file had are left as
// they are. Clears `preset.omitted`: the camera and lights are then the preset's own, and saved as
// such.
void frameOmitted(LoadedPreset& preset, const Mesh& mesh);

// The lights carried from a model bounded by `from` to one bounded by `to`, so that they light it
// as they lit the old one: each point and spot light's position scaled about the centre by
// k = to.radius / from.radius (position' = to.center + (position - from.center) · k, inside the
// coordinate range), and its attenuation with it (c1 / k, c2 / k², c0 as it was; limits.h's
// range). Directions (directional and spot lights) and orbit axes stay as they are. Radii below
// 0.001 count as 0.001.
void carryLights(std::vector<LightDesc>& lights, const Sphere& from, const Sphere& to);

} // namespace lab
