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

// The bounding sphere of `mesh` as `model` draws it (after its scale, rotation and translation):
// centred on the box around the transformed positions, through the farthest of them. nullopt
// for a mesh without positions, or one whose drawn coordinates overflow float.
std::optional<Sphere> drawnBounds(const Mesh& mesh, const Model& model);

// Framing, for a preset met with its mesh (MeshCache::get does it for every consumer). A glTF
// model whose file had no `camera` gets framedCamera(default camera, drawnBounds) at `aspect`
// (the view's width / height: 1 for `lab render`'s square default; the GUI passes its view's):
// it looks along -z, as the default camera does. Without `lights` either, the default light
// stands where it stands for a unit sphere, scaled to the model: centre + (2, 2, 2) · radius
// (inside the coordinate range). Built-in models and keys the file had are left as they are.
// Clears `preset.omitted`: the camera and lights are then the preset's own, and saved as such.
void frameOmitted(LoadedPreset& preset, const Mesh& mesh, float aspect = 1.0f);

} // namespace lab
