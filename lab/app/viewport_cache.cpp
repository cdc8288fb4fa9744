// viewport_cache.cpp — the model's viewport kept offscreen, and its resolution while dragging.
#include "app/viewport_cache.h"

#include <algorithm>
#include <cmath>

namespace lab {

ViewDraw viewDraw(const ViewSettings& view) {
    ViewDraw d;
    d.options.view = view.mode;
    d.options.light = view.light;
    d.options.palette = view.palette;
    d.automatic = showsValue(view.mode) && !view.range;
    d.options.range = view.range.value_or(ValueRange{});
    d.wipe = view.wipe && view.mode != ViewMode::Lit;
    if (d.wipe) {
        d.options.fromX = std::clamp(view.wipeAt, 0.0f, 1.0f);
    }
    return d;
}

std::optional<ValueRange> drawView(Renderer& renderer, const Preset& preset, const std::shared_ptr<const Mesh>& mesh,
                                   const Viewport& viewport, const ViewDraw& draw) {
    DrawOptions options = draw.options;
    std::optional<ValueRange> range;
    if (showsValue(options.view) && notApplicable(options.view, preset, options.light).empty()) {
        range = draw.automatic ? renderer.autoValueRange(preset, mesh, viewport.width, viewport.height, options)
                               : std::optional<ValueRange>(options.range);
        options.range = range.value_or(ValueRange{});
    }
    if (draw.wipe) {
        DrawOptions lit;
        lit.toX = options.fromX;
        renderer.draw(preset, mesh, viewport, lit);
    }
    renderer.draw(preset, mesh, viewport, options);
    return range;
}

bool CachedViewport::update(Renderer& renderer, const ViewportKey& key, const Viewport& full, int samples) {
    if (key_ && *key_ == key && target_) {
        return false;
    }
    int w = std::max(full.width, key.width), h = std::max(full.height, key.height);
    if (!target_ || target_->width() != w || target_->height() != h || target_->samples() != samples) {
        target_.reset(); // its memory first
        target_ = std::make_unique<ViewportTarget>(w, h, samples);
        if (!target_->complete() && samples > 0) { // a driver that offers samples it cannot attach
            target_ = std::make_unique<ViewportTarget>(w, h, 0);
        }
    }
    target_->bind();
    range_.reset();
    if (key.mesh) {
        range_ = drawView(renderer, key.preset, key.mesh, Viewport{0, 0, key.width, key.height}, key.draw);
    } else {
        clearFramebuffer(key.preset.background, key.width, key.height);
    }
    target_->resolve(key.width, key.height);
    key_ = key;
    return true;
}

void CachedViewport::present(unsigned target, const Viewport& dest) const {
    if (target_ && key_) {
        target_->present(target, dest, key_->width, key_->height);
    }
}

void CachedViewport::reset() {
    key_.reset();
    range_.reset();
    target_.reset();
}

float ViewportResolution::update(bool dragging, float lastFrameSeconds, float budgetSeconds) {
    if (!dragging || budgetSeconds <= 0.0f) {
        scale_ = 1.0f;
    } else if (lastFrameSeconds > budgetSeconds) {
        // The shading cost goes with the pixels, the square of the scale; the UI's share does
        // not shrink, so aim a little lower and never more than halve the pixels at once.
        float factor = std::sqrt(budgetSeconds / lastFrameSeconds) * 0.9f;
        scale_ = std::max(kLowest, scale_ * std::max(factor, std::sqrt(0.5f)));
    } else if (lastFrameSeconds < 0.6f * budgetSeconds) {
        scale_ = std::min(1.0f, scale_ * 1.15f);
    }
    return scale_;
}

} // namespace lab
