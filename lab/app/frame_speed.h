// frame_speed.h — the view's honest frame time: what a frame costs while the model changes.
//
// The last frame drawn says little: after start-up it is the first frame (shader compiles, the
// mesh's upload), and a class reads "260 ms" as "this lab is slow". FrameSpeed keeps the costs
// of the frames of one interaction (frames that redrew the model while something changed it: a
// drag of a slider, a colour, the camera or a light, a moving light) and shows their median while
// the interaction goes on and for a few seconds after; before the first interaction, and once
// those seconds are over, it shows nothing. Pure: the app passes the clock and the costs in.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace lab {

class FrameSpeed {
public:
    static constexpr double kGapSeconds = 0.5;   // a pause this long ends an interaction
    static constexpr double kLingerSeconds = 3.0; // the readout stays this long after the last one
    static constexpr std::size_t kMaxSamples = 240; // the latest frames of a long interaction

    // One frame of an interaction drawn at `now` (seconds, any origin) that cost `seconds`.
    void interactionFrame(double now, float seconds);
    // The median cost (milliseconds) of the current or last interaction's frames while it is
    // shown, else nothing.
    std::optional<float> shownMs(double now) const;
    // Seconds until the readout goes (a redraw is owed then), or < 0 when nothing is shown.
    float hidesIn(double now) const;

private:
    std::vector<float> samples_; // seconds
    double last_ = -1.0e9;       // when the latest sample's frame was drawn
};

} // namespace lab
