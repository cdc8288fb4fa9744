// offscreen.cpp — load the model (cached), draw into a framebuffer, read it back.
#include "render/offscreen.h"

#include "core/model_loader.h"

namespace lab {

bool OffscreenRenderer::init(Diagnostics& diagnostics) { return renderer_.init(diagnostics); }

std::optional<Image> OffscreenRenderer::render(const LoadedPreset& preset, int width, int height,
                                               Diagnostics& diagnostics, std::vector<std::string>* notes) {
    std::string key = modelCacheKey(preset.preset.model, preset.folder());
    if (key != meshKey_) {
        Diagnostics problems;
        std::optional<Mesh> mesh = loadModel(preset.preset.model, preset.folder(), problems, notes);
        if (!mesh) {
            for (Diagnostic& d : problems) {
                if (d.file.empty()) {
                    d.file = preset.file.string();
                } else {
                    d.file = preset.file.string() + ": " + d.file;
                }
            }
            diagnostics.insert(diagnostics.end(), problems.begin(), problems.end());
            return std::nullopt;
        }
        mesh_ = std::make_unique<GpuMesh>(std::move(*mesh));
        meshKey_ = key;
    }
    Framebuffer target(width, height);
    if (!target.complete()) {
        diagnostics.push_back({"", "", "cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                                           " framebuffer"});
        return std::nullopt;
    }
    target.bind();
    renderer_.draw(preset.preset, *mesh_, Viewport{0, 0, width, height});
    return target.readRgb();
}

} // namespace lab
