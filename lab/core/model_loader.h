// model_loader.h — the mesh a preset's `model` names: a built-in shape or a glTF file.
#pragma once

#include "core/diagnostics.h"
#include "core/mesh.h"
#include "core/preset.h"

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

} // namespace lab
