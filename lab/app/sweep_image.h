// sweep_image.h — the sweep view's grid (ui/tools/sweep_view.h), rendered by the app's renderer.
//
// While the sweep window is open, the grid is rendered again when what it shows changes: the
// keys and values, the cell size, the scene (set A as the panel edits it) or the shader programs;
// never while a drag is in progress (the frame that ends it renders), and nothing at all while
// the window is closed (its texture and image are released), so the lab's ordinary frames cost
// the same with or without it. The cells go through core/scene/sweep.h renderSweep with each cell
// drawn into a Framebuffer by Renderer::draw, as `lab render` draws a preset; the image is the
// one Save PNG writes.
#pragma once

#include "core/plots/sweep_grid.h"
#include "core/scene/mesh.h"
#include "core/scene/preset.h"
#include "render/image_texture.h"
#include "render/renderer.h"
#include "ui/tools/sweep_view.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lab {

class SweepImage {
public:
    // `scene` (from `file`, which glTF paths are relative to) is what the grid varies; `mesh` its
    // model. Sets state.texture and state.error; true when it rendered (the window needs another
    // frame to show it).
    bool update(ui::SweepViewState& state, Renderer& renderer, const Preset& scene, const std::filesystem::path& file,
                const std::shared_ptr<const Mesh>& mesh, bool dragging);
    // The last grid (none while refused or closed).
    const std::optional<Image>& image() const { return image_; }

private:
    struct Key {
        std::vector<std::string> arguments;
        int cellSize = 0;
        Preset preset;
        std::shared_ptr<const Mesh> mesh;
        unsigned programs = 0;
        bool operator==(const Key&) const = default;
    };
    std::optional<Key> key_;
    std::optional<Image> image_;
    ImageTexture texture_;
};

} // namespace lab
