// model_loader.cpp — builtin or glTF, through the same checks as preset loading.
#include "core/model_loader.h"

#include "core/gltf.h"

namespace lab {

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
