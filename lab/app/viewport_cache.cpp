// viewport_cache.cpp — the model's viewport kept offscreen, and its resolution while dragging.
#include "app/viewport_cache.h"

#include <algorithm>
#include <cmath>

namespace lab {

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

float ViewportResolution::update(bool moving, float lastFrameSeconds, float budgetSeconds) {
    if (!moving || budgetSeconds <= 0.0f) {
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
