// frame_speed.cpp — the median of an interaction's frame costs.
#include "app/frame_speed.h"

#include <algorithm>
#include <cstddef>

namespace lab {

void FrameSpeed::interactionFrame(double now, float seconds) {
    if (now - last_ > kGapSeconds) {
        samples_.clear(); // a new interaction
    }
    if (samples_.size() == kMaxSamples) {
        samples_.erase(samples_.begin());
    }
    samples_.push_back(seconds);
    last_ = now;
}

std::optional<float> FrameSpeed::shownMs(double now) const {
    if (samples_.empty() || now - last_ > kLingerSeconds) {
        return std::nullopt;
    }
    std::vector<float> sorted = samples_;
    std::size_t mid = sorted.size() / 2;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(mid), sorted.end());
    float median = sorted[mid];
    if (sorted.size() % 2 == 0) { // the mean of the two middle ones
        median = 0.5f * (median + *std::max_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(mid)));
    }
    return median * 1000.0f;
}

float FrameSpeed::hidesIn(double now) const {
    return samples_.empty() || now - last_ > kLingerSeconds ? -1.0f : static_cast<float>(last_ + kLingerSeconds - now);
}

} // namespace lab
