// offscreen.cpp — load the model (cached), draw into a framebuffer, read it back.
#include "render/offscreen.h"


namespace lab {

bool OffscreenRenderer::init(Diagnostics& diagnostics) { return renderer_.init(diagnostics); }

// The preset's mesh (a glTF model without a camera in its file is framed into `framed`:
// mesh_cache.h); problems are reported with the preset's file name.
std::shared_ptr<const Mesh> OffscreenRenderer::mesh(LoadedPreset& framed, const LoadedPreset& preset,
                                                    Diagnostics& diagnostics, std::vector<std::string>* notes) {
    Diagnostics problems;
    framed = preset;
    std::shared_ptr<const Mesh> mesh = meshes_.get(framed, problems, notes);
    if (!mesh) {
        for (Diagnostic& d : problems) {
            d.file = d.file.empty() ? preset.file.string() : preset.file.string() + ": " + d.file;
        }
        diagnostics.insert(diagnostics.end(), problems.begin(), problems.end());
    }
    return mesh;
}

std::optional<Image> OffscreenRenderer::render(const LoadedPreset& preset, int width, int height,
                                               Diagnostics& diagnostics, std::vector<std::string>* notes) {
    std::optional<Rendered> r = renderView(preset, width, height, ViewportDraw{}, diagnostics, notes);
    return r ? std::optional<Image>(std::move(r->image)) : std::nullopt;
}

std::optional<Rendered> OffscreenRenderer::renderView(const LoadedPreset& preset, int width, int height,
                                                      const ViewportDraw& view, Diagnostics& diagnostics,
                                                      std::vector<std::string>* notes) {
    LoadedPreset framed;
    std::shared_ptr<const Mesh> m = mesh(framed, preset, diagnostics, notes);
    if (!m) {
        return std::nullopt;
    }
    Framebuffer target(width, height);
    if (!target.complete()) {
        diagnostics.push_back({"", "", "cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                                           " framebuffer"});
        return std::nullopt;
    }
    target.bind();
    std::optional<ValueRange> range = drawView(renderer_, framed.preset, m, Viewport{0, 0, width, height}, view);
    return Rendered{target.readRgb(), range};
}

std::optional<ValueRange> OffscreenRenderer::autoRange(const LoadedPreset& preset, int width, int height,
                                                       const ViewportDraw& view, Diagnostics& diagnostics) {
    LoadedPreset framed;
    std::shared_ptr<const Mesh> m = mesh(framed, preset, diagnostics, nullptr);
    return m ? renderer_.autoValueRange(framed.preset, m, width, height, view.options) : std::nullopt;
}

} // namespace lab
