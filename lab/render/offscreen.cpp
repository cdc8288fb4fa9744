// offscreen.cpp — load the model (cached), draw into a framebuffer, read it back.
#include "render/offscreen.h"


namespace lab {

bool OffscreenRenderer::init(Diagnostics& diagnostics) { return renderer_.init(diagnostics); }

std::optional<Image> OffscreenRenderer::render(const LoadedPreset& preset, int width, int height,
                                               Diagnostics& diagnostics, std::vector<std::string>* notes) {
    Diagnostics problems;
    LoadedPreset framed = preset; // a glTF model without a camera in its file is framed here (mesh_cache.h)
    std::shared_ptr<const Mesh> mesh = meshes_.get(framed, problems, notes);
    if (!mesh) {
        for (Diagnostic& d : problems) {
            d.file = d.file.empty() ? preset.file.string() : preset.file.string() + ": " + d.file;
        }
        diagnostics.insert(diagnostics.end(), problems.begin(), problems.end());
        return std::nullopt;
    }
    Framebuffer target(width, height);
    if (!target.complete()) {
        diagnostics.push_back({"", "", "cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                                           " framebuffer"});
        return std::nullopt;
    }
    target.bind();
    renderer_.draw(framed.preset, mesh, Viewport{0, 0, width, height});
    return target.readRgb();
}

} // namespace lab
