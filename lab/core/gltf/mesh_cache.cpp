// mesh_cache.cpp — least-recently-used cache over loadModel.
#include "core/gltf/mesh_cache.h"

#include "core/gltf/model_loader.h"

namespace lab {

std::shared_ptr<const Mesh> MeshCache::get(const Model& model, const std::filesystem::path& folder,
                                           Diagnostics& diagnostics, std::vector<std::string>* notes) {
    std::string key = modelCacheKey(model, folder);
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
        if (it->key == key) {
            Entry hit = std::move(*it);
            entries_.erase(it);
            entries_.push_back(std::move(hit));
            return entries_.back().mesh;
        }
    }
    std::optional<Mesh> mesh = loadModel(model, folder, diagnostics, notes);
    if (!mesh) {
        return nullptr;
    }
    if (capacity_ > 0 && entries_.size() >= capacity_) {
        entries_.erase(entries_.begin());
    }
    entries_.push_back({std::move(key), std::make_shared<const Mesh>(std::move(*mesh))});
    return entries_.back().mesh;
}

std::shared_ptr<const Mesh> MeshCache::get(LoadedPreset& preset, Diagnostics& diagnostics,
                                           std::vector<std::string>* notes) {
    std::shared_ptr<const Mesh> mesh = get(preset.preset.model, preset.folder(), diagnostics, notes);
    if (mesh) {
        frameOmitted(preset, *mesh);
    }
    return mesh;
}

} // namespace lab
