// sweep_image.cpp — the grid rendered when its inputs change, uploaded as a texture.
#include "app/sweep_image.h"

#include "core/scene/sweep.h"

namespace lab {

bool SweepImage::update(ui::SweepViewState& state, Renderer& renderer, const Preset& scene,
                        const std::filesystem::path& file, const std::shared_ptr<const Mesh>& mesh, bool dragging) {
    texture_.dropPrevious(); // the last frame drew with the current one
    if (!state.open) {
        if (key_) { // closed: its memory back (the texture the next frame: this one may draw it)
            key_.reset();
            image_.reset();
            texture_.retire();
            state.texture = 0;
        }
        return false;
    }
    Key key{ui::sweepArguments(state), state.cellSize, scene, mesh, renderer.generation()};
    // Not while a drag or the typing of a key or values goes on: the frame that ends it renders.
    if (dragging || state.editing || (key_ && *key_ == key)) {
        return false;
    }
    key_ = key;
    std::string error;
    std::vector<SweepAxis> axes;
    for (const std::string& argument : key.arguments) {
        std::optional<SweepAxis> axis = parseSweepAxis(argument, error);
        if (!axis) {
            break;
        }
        axes.push_back(std::move(*axis));
    }
    std::optional<Image> grid;
    if (error.empty() && !mesh) {
        error = "no model to render";
    } else if (error.empty()) {
        auto renderCell = [&](const LoadedPreset& cell, int width, int height, std::string& why) -> std::optional<Image> {
            Framebuffer target(width, height);
            if (!target.complete()) {
                why = "cannot create a " + std::to_string(width) + "x" + std::to_string(height) + " framebuffer";
                return std::nullopt;
            }
            target.bind();
            renderer.draw(cell.preset, mesh, Viewport{0, 0, width, height});
            return target.readRgb();
        };
        grid = renderSweep(LoadedPreset{scene, file, {}}, axes, state.cellSize, state.cellSize, renderCell, error);
    }
    state.error = error;
    if (!grid) {
        // The last good grid stays on screen under the message, but Save PNG is off.
        image_.reset();
        return true;
    }
    if (!texture_.upload(*grid)) {
        state.error = "the grid (" + std::to_string(grid->width) + "x" + std::to_string(grid->height) +
                      ") is larger than this GL's textures: choose smaller cells";
        image_.reset();
        state.texture = 0;
        return true;
    }
    image_ = std::move(grid);
    state.texture = texture_.id();
    state.textureWidth = texture_.width();
    state.textureHeight = texture_.height();
    return true;
}

} // namespace lab
