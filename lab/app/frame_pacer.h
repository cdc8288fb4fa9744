// frame_pacer.h — when the interactive lab draws a frame: never when nothing changes.
//
// Every platform loop (glfw_window.cpp, web_window.cpp) asks the pacer. A frame is due
//   * while input is queued (app/input.h hands it out a frame's share at a time);
//   * for a few frames after input, so Dear ImGui settles (hover states, a window that fits its
//     new contents, a request carried out at the end of a frame and shown by the next);
//   * when the app asked for one (FrameOutput::redrawIn: a toast that must go away, the full
//     resolution view after a drag).
// Otherwise the desktop sleeps in the window system until an event comes, and the browser's
// animation-frame callback returns at once: idle costs (close to) nothing.
// Pure: the loops pass the clock in.
#pragma once

namespace lab {

class FramePacer {
public:
    static constexpr int kSettleFrames = 3; // the frame with the input and two after it

    void input() { owed_ = owed_ > kSettleFrames ? owed_ : kSettleFrames; }
    // A frame is due now (queued input counts: pass InputQueue::empty()).
    bool due(double now, bool inputQueued) const { return inputQueued || owed_ > 0 || (wakeAt_ >= 0.0 && now >= wakeAt_); }
    // After a frame that asked to be drawn again in `redrawIn` seconds (0: at once; < 0: only on
    // input). While input is still queued the settling frames wait: they follow the frame that
    // took the last event (a tap is four events and four frames; a tab bar shown by the last one
    // needs its own frames to lay out).
    void drawn(double now, float redrawIn, bool inputQueued = false);
    // The frames still due after the one about to be drawn, whatever it asks (for tests that
    // wait for the lab to settle): owed ones, and one while input is queued.
    int dueAfterThis(bool inputQueued) const { return (owed_ > 1 ? owed_ - 1 : 0) + (inputQueued ? 1 : 0); }
    // How long the loop may sleep from `now` (0: not at all; < 0: until an event).
    double sleepFor(double now, bool inputQueued) const;

private:
    int owed_ = kSettleFrames; // the first frames
    double wakeAt_ = -1.0;     // < 0: none
};

} // namespace lab
