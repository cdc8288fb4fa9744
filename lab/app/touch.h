// touch.h — fingers on a touch screen turned into the mouse events the lab already understands,
// so every widget, the view's gestures and the plots work by touch with no code of their own.
//
//   one finger, tapped          a click where it touched (a widget, or the probe in the view)
//   one finger, dragged         a left drag: orbits in the view, moves a light marker or L/V in
//                               the plot, drags a slider, scrolls a panel from its background
//   two fingers                 a middle drag at their midpoint (pans the view) and, as their
//                               distance changes, the wheel (zooms: spreading them zooms in)
//
// A finger's press is held back until it either lifts (a tap) or moves past a small slop (a
// drag), so a second finger arriving turns the gesture into a two-finger one without a stray
// click or orbit first. After each gesture the pointer leaves the window: a finger leaves no
// hovering cursor behind. A third finger is ignored; after a two-finger gesture nothing happens
// until every finger has lifted. Pure: no browser, no ImGui; the browser platform feeds it.
#pragma once

#include "app/input.h"

#include <vector>

namespace lab {

class TouchGestures {
public:
    // A finger touched, moved, lifted, or was cancelled by the browser (window units). What the
    // mouse would have done is appended to `out`.
    void start(long id, float x, float y, std::vector<InputEvent>& out);
    void move(long id, float x, float y, std::vector<InputEvent>& out);
    void end(long id, float x, float y, std::vector<InputEvent>& out);
    // The browser took the finger away (a system gesture, palm rejection): like end(), but a
    // finger that had not moved yet presses nothing.
    void cancel(long id, std::vector<InputEvent>& out);

    static constexpr float kSlop = 8.0f;         // window units a finger may move and still tap
    static constexpr float kWheelPerDoubling = 6.58f; // wheel steps (0.9 each) for a distance doubling: ln 2 / -ln 0.9

private:
    struct Finger {
        long id = 0;
        float x = 0, y = 0;
    };
    enum class Mode { Idle, Pending, Drag, Pinch, Lifting };
    Finger* find(long id);
    void beginPinch(std::vector<InputEvent>& out);
    float midX() const { return (fingers_[0].x + fingers_[1].x) * 0.5f; }
    float midY() const { return (fingers_[0].y + fingers_[1].y) * 0.5f; }
    float spread() const;

    Mode mode_ = Mode::Idle;
    std::vector<Finger> fingers_; // down, in the order they touched (at most two are followed)
    float startX_ = 0, startY_ = 0; // where the first finger touched
    float spread_ = 0;             // the two fingers' distance when the wheel last turned
};

} // namespace lab
