// viewport_cache.h — the model's viewport drawn only when what it shows changes, and at a lower resolution
// while the user drags on a machine too slow to draw it at full size in time.
//
// Hovering, opening a menu, dragging V in the plot or typing in a field changes nothing the 3D
// view shows, so the window composites the view kept offscreen (render/renderer.h, ViewportTarget)
// instead of shading every pixel again; on Mesa's llvmpipe that is the difference between a
// frame of a few milliseconds and one of a few hundred. Screenshots, `lab render` and the
// goldens never go through here: they are always drawn at full resolution.
#pragma once

#include "core/scene/mesh.h"
#include "core/scene/preset.h"
#include "render/renderer.h"

#include <memory>
#include <optional>

namespace lab {

// Everything a drawn view depends on; the view is drawn again when any of it changes.
struct ViewportKey {
    Preset preset;                     // as shown (the renderer applies the view)
    std::shared_ptr<const Mesh> mesh;  // held, so a new mesh can never reuse a cached one's address
    int width = 0, height = 0;         // the pixels drawn (less than the view's while dragging)
    ViewportDraw draw;
    unsigned programs = 0;             // Renderer::generation()
    bool operator==(const ViewportKey&) const = default;
};

// One view's offscreen copy (A, or B in compare mode).
class CachedViewport {
public:
    // Draws the view into the offscreen target if `key` differs from the last one drawn; true
    // when it drew. `full`: the view's size in the window (key's size is at most that);
    // `samples`: multisampling of the target (0 for none).
    bool update(Renderer& renderer, const ViewportKey& key, const Viewport& full, int samples);
    // Copies the last drawn view into `dest` of framebuffer `target`, scaled to fit.
    void present(unsigned target, const Viewport& dest) const;
    void reset(); // forget it (the next update draws)
    // What was drawn last (none before the first update, or after reset).
    const std::optional<ViewportKey>& key() const { return key_; }
    // The range the value view was drawn with (its legend's); none for the other views.
    const std::optional<ValueRange>& range() const { return range_; }

private:
    std::optional<ViewportKey> key_;
    std::optional<ValueRange> range_;
    std::unique_ptr<ViewportTarget> target_;
};

// The fraction of the view's width and height that is drawn: 1 unless the view is moving (the user
// drags, or a light moves by itself) and the frames are over budget, then lowered (at most halving
// the pixels a frame, never below a quarter of the width) until a frame fits, raised again when
// there is room, and back to 1 on the first frame after the motion.
class ViewportResolution {
public:
    static constexpr float kLowest = 0.25f;
    float update(bool moving, float lastFrameSeconds, float budgetSeconds);
    float scale() const { return scale_; }

private:
    float scale_ = 1.0f;
};

} // namespace lab
