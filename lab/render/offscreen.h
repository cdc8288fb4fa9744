// offscreen.h — presets to images without a window: what `lab render` and `lab check` run.
//
// Owns a Renderer and a mesh cache, so rendering many presets of the same model loads it once. Test renders are deterministic: fixed size, no MSAA, no dithering, no UI.
// Needs a current GL context (platform/headless_gl.h).
#pragma once

#include "core/gltf/mesh_cache.h"
#include "core/io/image.h"
#include "core/scene/preset.h"
#include "render/renderer.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lab {

inline constexpr int kMaxRenderSide = 8192;

// A render and, for a value view, the range its palette spans.
struct Rendered {
    Image image;
    std::optional<ValueRange> range;
};

class OffscreenRenderer {
public:
    bool init(Diagnostics& diagnostics);

    // The same as render(), drawn as `view` says (render/renderer.h drawView): a factor view, the
    // wipe, a fixed or automatic range. The caller checks that the view applies (notApplicable).
    std::optional<Rendered> renderView(const LoadedPreset& preset, int width, int height, const ViewportDraw& view,
                                       Diagnostics& diagnostics, std::vector<std::string>* notes = nullptr);
    // The automatic range `view` would find in such a render (nullopt: no value, or no model pixel).
    std::optional<ValueRange> autoRange(const LoadedPreset& preset, int width, int height, const ViewportDraw& view,
                                        Diagnostics& diagnostics);

    // Renders at width × height. Problems with the preset's model are reported with the
    // preset's file name; `notes` gets what the model loader skipped. A glTF model whose file
    // has no camera is framed first (MeshCache::get), the same way whatever the size.
    std::optional<Image> render(const LoadedPreset& preset, int width, int height, Diagnostics& diagnostics,
                                std::vector<std::string>* notes = nullptr);

private:
    std::shared_ptr<const Mesh> mesh(LoadedPreset& framed, const LoadedPreset& preset, Diagnostics& diagnostics,
                                     std::vector<std::string>* notes);

    Renderer renderer_;
    MeshCache meshes_{1};
};

} // namespace lab
