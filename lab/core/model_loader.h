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
std::optional<Mesh> loadModel(const Model& model, const std::filesystem::path& folder, Diagnostics& diagnostics,
                              std::vector<std::string>* notes = nullptr);

} // namespace lab
