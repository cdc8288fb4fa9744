// mesh_cache.h — the one cache of loaded models: the app, the renderer and `lab render` share it.
//
// Meshes are keyed by modelCacheKey (a built-in and its subdivisions, or a glTF file's canonical
// path with its size and time), so a file rewritten in place is loaded again. The cache hands out
// shared pointers: a mesh stays alive while anyone draws it, and the renderer keeps a GPU copy of
// a mesh exactly as long as someone else holds it (Renderer::draw). No GL here.
#pragma once

#include "core/io/diagnostics.h"
#include "core/scene/mesh.h"
#include "core/scene/preset.h"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace lab {

class MeshCache {
public:
    explicit MeshCache(std::size_t capacity = 6) : capacity_(capacity) {}

    // The mesh of `model`, whose glTF path is relative to `folder`: from the cache, or loaded
    // (then `notes` gets what the loader skipped). nullptr, with diagnostics, when it cannot load.
    std::shared_ptr<const Mesh> get(const Model& model, const std::filesystem::path& folder,
                                    Diagnostics& diagnostics, std::vector<std::string>* notes = nullptr);

    // The mesh of a loaded preset, which meets it here: a glTF model whose file left out
    // `camera` (and `lights`) is framed (frameOmitted, core/gltf/model_loader.h), so that from then
    // on the preset holds an ordinary camera. Every consumer of a preset file loads its mesh
    // through this: `lab render` and `lab check` (OffscreenRenderer), the GUI and the page
    // (Workspace::open). The framing fits a view of any shape.
    std::shared_ptr<const Mesh> get(LoadedPreset& preset, Diagnostics& diagnostics,
                                    std::vector<std::string>* notes = nullptr);

    std::size_t size() const { return entries_.size(); }

private:
    struct Entry {
        std::string key;
        std::shared_ptr<const Mesh> mesh;
    };
    std::size_t capacity_;
    std::vector<Entry> entries_; // least recently used first
};

} // namespace lab
