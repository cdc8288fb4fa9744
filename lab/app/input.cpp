// input.cpp — one frame's share of the queued input.
#include "app/input.h"

#include <cmath>
#include <set>

namespace lab {

bool isPrintableKey(int code) { return code >= 32 && code <= 162; } // GLFW_KEY_SPACE .. GLFW_KEY_WORLD_2

std::vector<InputEvent> InputQueue::takeFrame() {
    std::vector<InputEvent> frame;
    std::set<int> buttons, keys; // changed in this frame
    bool moved = false, text = false, editingKey = false;
    while (!events_.empty()) {
        const InputEvent& e = events_.front();
        bool fits = true;
        switch (e.kind) {
        case InputEvent::Kind::Move:
        case InputEvent::Kind::Leave: fits = buttons.empty(); break;
        case InputEvent::Kind::Button: fits = !moved && !buttons.count(e.code); break;
        case InputEvent::Kind::Scroll: fits = true; break;
        case InputEvent::Kind::Key: fits = (e.repeat || !keys.count(e.code)) && !(text && !isPrintableKey(e.code)); break;
        case InputEvent::Kind::Char: fits = !editingKey; break;
        }
        if (!fits && !frame.empty()) {
            break;
        }
        switch (e.kind) {
        case InputEvent::Kind::Move:
        case InputEvent::Kind::Leave:
            if (moved && (frame.back().kind == InputEvent::Kind::Move || frame.back().kind == InputEvent::Kind::Leave)) {
                frame.pop_back(); // only where the cursor ended up counts
            }
            moved = true;
            break;
        case InputEvent::Kind::Button: buttons.insert(e.code); break;
        case InputEvent::Kind::Key:
            // A repeat keeps the key down: it is another press for the shortcuts, not a change.
            if (!e.repeat) {
                keys.insert(e.code);
            }
            editingKey = editingKey || !isPrintableKey(e.code);
            break;
        case InputEvent::Kind::Char: text = true; break;
        case InputEvent::Kind::Scroll: break;
        }
        frame.push_back(e);
        events_.pop_front();
    }
    return frame;
}

std::vector<std::string> InputQueue::takeDropped() {
    std::vector<std::string> dropped;
    dropped.swap(dropped_);
    return dropped;
}

std::vector<std::pair<float, float>> clicksOf(const std::vector<InputEvent>& events, std::optional<InputEvent>& pending) {
    std::vector<std::pair<float, float>> clicks;
    for (const InputEvent& e : events) {
        if (e.kind != InputEvent::Kind::Button || e.code != 0) {
            continue;
        }
        if (e.down) {
            pending = e;
        } else if (pending) {
            if (std::hypot(e.x - pending->x, e.y - pending->y) < 4.0f) {
                clicks.emplace_back(pending->x, pending->y);
            }
            pending.reset();
        }
    }
    return clicks;
}

} // namespace lab
