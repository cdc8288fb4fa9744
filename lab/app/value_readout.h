// value_readout.h — what the legend of a value view (core/scene/view_mode.h) says: the range A's
// render was drawn with (the automatic one is found as it is drawn: render/renderer.h), and the
// value under the pointer, read back from the GPU for that one pixel (Renderer::valueAt), so it is
// exactly what the view shows there. Asked again only when the pointer or the render changes.
#pragma once

#include "app/viewport_cache.h"
#include "ui/viewport/view_legend.h"

#include <optional>
#include <string>
#include <utility>

namespace lab {

class ValueReadout {
public:
    // After the frame's renders: A's render `a`, shown at `dest` (framebuffer pixels, GL's
    // convention) of a window `windowHeight` units high at `toPixels` pixels a unit; the pointer at
    // (x, y) window units. Off the model, on the wipe's lit side or outside the view: no value.
    void update(Renderer& renderer, const CachedViewport& a, const Viewport& dest, float toPixels, float windowHeight,
                float x, float y, const DisplaySettings& view);

    // The legend for `view` of `preset` (A) with B's range in compare mode; none for a view that
    // shows no value.
    std::optional<ui::LegendModel> legend(const DisplaySettings& view, const Preset& preset,
                                          const std::optional<ValueRange>& range) const;

    // True once after the value changed: the overlay showed the old one, a frame is owed.
    bool takeChanged() { return std::exchange(changed_, false); }

private:
    std::optional<float> value_;
    std::optional<std::pair<int, int>> pixel_; // where value_ was read
    std::optional<ViewportKey> key_;           // ... in this render
    bool changed_ = false;
};

// The legend in words, for the page ("D: microfacet distribution, light 1: 0 to 1.2, here 0.43"); "" for none.
std::string legendWords(const std::optional<ui::LegendModel>& legend);

} // namespace lab
