// model_loader.cpp — builtin or glTF, through the same checks as preset loading.
#include "core/model_loader.h"

#include "core/gltf.h"

namespace lab {

std::string modelCacheKey(const Model& model, const std::filesystem::path& folder) {
    if (model.gltf.empty()) {
        return std::string(toString(model.builtin)) + ":" + std::to_string(model.subdivisions.x) + "x" +
               std::to_string(model.subdivisions.y);
    }
    std::error_code ec;
    std::filesystem::path file = std::filesystem::weakly_canonical(folder / model.gltf, ec);
    // The file-time count is 128 bits wide in the browser build's libc++: narrow it explicitly.
    auto size = static_cast<unsigned long long>(std::filesystem::file_size(file, ec));
    auto time = static_cast<long long>(std::filesystem::last_write_time(file, ec).time_since_epoch().count());
    return "gltf:" + file.string() + ":" + std::to_string(ec ? 0ull : size) + ":" + std::to_string(ec ? 0ll : time);
}

std::optional<Mesh> loadModel(const Model& model, const std::filesystem::path& folder, Diagnostics& diagnostics,
                              std::vector<std::string>* notes) {
    if (model.gltf.empty()) {
        return makeBuiltin(model.builtin, model.subdivisions);
    }
    std::string error;
    std::optional<std::filesystem::path> path = resolveModelPath(model.gltf, folder, error);
    if (!path) {
        diagnostics.push_back({"", "model.gltf", error});
        return std::nullopt;
    }
    std::optional<GltfResult> result = loadGltf(*path, model.gltf, diagnostics);
    if (!result) {
        return std::nullopt;
    }
    if (notes) {
        for (std::string& n : result->notes) {
            notes->push_back(model.gltf + ": " + n);
        }
    }
    return std::move(result->mesh);
}

} // namespace lab
