// touch.cpp — the finger-to-mouse state machine (see touch.h).
#include "app/touch.h"

#include <algorithm>
#include <cmath>

namespace lab {

namespace {

constexpr int kLeft = 0, kMiddle = 2;

} // namespace

TouchGestures::Finger* TouchGestures::find(long id) {
    auto it = std::find_if(fingers_.begin(), fingers_.end(), [id](const Finger& f) { return f.id == id; });
    return it == fingers_.end() ? nullptr : &*it;
}

float TouchGestures::spread() const {
    return std::max(std::hypot(fingers_[0].x - fingers_[1].x, fingers_[0].y - fingers_[1].y), 1.0f);
}

void TouchGestures::beginPinch(std::vector<InputEvent>& out) {
    mode_ = Mode::Pinch;
    spread_ = spread();
    out.push_back(InputEvent::move(midX(), midY()));
    out.push_back(InputEvent::button(kMiddle, true, midX(), midY()));
}

void TouchGestures::start(long id, float x, float y, std::vector<InputEvent>& out) {
    if (find(id) || fingers_.size() >= 2 || mode_ == Mode::Lifting) {
        return; // a third finger, or one touching while the others lift
    }
    fingers_.push_back({id, x, y});
    if (mode_ == Mode::Idle) {
        mode_ = Mode::Pending;
        startX_ = x;
        startY_ = y;
    } else if (mode_ == Mode::Pending) {
        beginPinch(out); // nothing was sent for the first finger yet
    } else if (mode_ == Mode::Drag) {
        const Finger& first = fingers_[0];
        out.push_back(InputEvent::button(kLeft, false, first.x, first.y)); // past the slop: not a click
        beginPinch(out);
    }
}

void TouchGestures::move(long id, float x, float y, std::vector<InputEvent>& out) {
    Finger* f = find(id);
    if (!f || (f->x == x && f->y == y)) {
        return;
    }
    f->x = x;
    f->y = y;
    switch (mode_) {
    case Mode::Pending:
        if (std::hypot(x - startX_, y - startY_) > kSlop) {
            mode_ = Mode::Drag;
            out.push_back(InputEvent::move(startX_, startY_));
            out.push_back(InputEvent::button(kLeft, true, startX_, startY_));
            out.push_back(InputEvent::move(x, y));
        }
        break;
    case Mode::Drag: out.push_back(InputEvent::move(x, y)); break;
    case Mode::Pinch: {
        out.push_back(InputEvent::move(midX(), midY()));
        float now = spread();
        float wheel = std::log(now / spread_) / -std::log(0.9f); // the view zooms by 0.9 a wheel step
        if (std::abs(wheel) > 0.01f) {
            out.push_back(InputEvent::scroll(0.0f, wheel));
            spread_ = now;
        }
        break;
    }
    case Mode::Idle:
    case Mode::Lifting: break;
    }
}

void TouchGestures::end(long id, float x, float y, std::vector<InputEvent>& out) {
    Finger* f = find(id);
    if (!f) {
        return;
    }
    switch (mode_) {
    case Mode::Pending: // a tap: a click where the finger touched
        out.push_back(InputEvent::move(startX_, startY_));
        out.push_back(InputEvent::button(kLeft, true, startX_, startY_));
        out.push_back(InputEvent::button(kLeft, false, startX_, startY_));
        out.push_back(InputEvent::leave());
        break;
    case Mode::Drag:
        out.push_back(InputEvent::move(x, y));
        out.push_back(InputEvent::button(kLeft, false, x, y));
        out.push_back(InputEvent::leave());
        break;
    case Mode::Pinch:
        out.push_back(InputEvent::button(kMiddle, false, midX(), midY()));
        out.push_back(InputEvent::leave());
        mode_ = Mode::Lifting;
        break;
    case Mode::Idle:
    case Mode::Lifting: break;
    }
    fingers_.erase(fingers_.begin() + (f - fingers_.data()));
    if (fingers_.empty()) {
        mode_ = Mode::Idle;
    }
}

void TouchGestures::cancel(long id, std::vector<InputEvent>& out) {
    Finger* f = find(id);
    if (!f) {
        return;
    }
    if (mode_ == Mode::Pending) {
        fingers_.clear(); // nothing was sent for it
        mode_ = Mode::Idle;
        return;
    }
    end(id, f->x, f->y, out);
}

} // namespace lab
