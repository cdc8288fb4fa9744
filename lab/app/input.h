// input.h — what the platform saw between frames, in order, and how it is handed out a frame at a
// time so that nothing is lost however slow a frame is.
//
// Dear ImGui 1.86 reads the mouse and the keys as a state once a frame: a press and its release
// that fall within one frame would never be seen as down, two clicks would merge into one, and a
// click would land where the cursor is at the end of the frame, not where it was pressed. So the
// platforms queue every event here (glfw_window.cpp, web_window.cpp through imgui_glfw.cpp; tests
// through HeadlessApp), and each frame takes the longest run of events that ImGui can still tell
// apart — the rule ImGui 1.87 later adopted as "input trickling": a run ends before a second
// change of the same button or key, before a button change that follows a move (and a move that
// follows a button change), and between text and the editing keys (Backspace after "ab" stays
// after it). What is left waits for the next frame, and the loop draws that frame at once.
// Pure: no ImGui, no GLFW (key codes are GLFW's, as KeyPress's always were).
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lab {

struct InputEvent {
    enum class Kind { Move, Button, Leave, Scroll, Key, Char };
    Kind kind = Kind::Move;
    float x = 0, y = 0;     // Move, Button: window units (ImGui's); Scroll: wheel offsets
    int code = 0;           // Button: 0 left, 1 right, 2 middle; Key: GLFW key code; Char: code point
    bool down = false;      // Button, Key: pressed (true) or released
    bool repeat = false;    // Key: the keyboard's own auto-repeat (down is true)
    unsigned modifiers = 0; // Key: kCtrl | kShift | kAlt (ui/actions.h)

    static InputEvent move(float x, float y) { return {Kind::Move, x, y}; }
    static InputEvent button(int b, bool down, float x, float y) { return {Kind::Button, x, y, b, down}; }
    static InputEvent leave() { return {Kind::Leave}; }
    static InputEvent scroll(float dx, float dy) { return {Kind::Scroll, dx, dy}; }
    static InputEvent key(int code, bool down, unsigned modifiers = 0, bool repeat = false) {
        return {Kind::Key, 0, 0, code, down, repeat, modifiers};
    }
    static InputEvent character(unsigned codePoint) { return {Kind::Char, 0, 0, static_cast<int>(codePoint)}; }
};

// Events in arrival order; takeFrame() hands out one frame's share.
class InputQueue {
public:
    void push(const InputEvent& e) { events_.push_back(e); }
    void drop(std::string path) { dropped_.push_back(std::move(path)); }
    bool empty() const { return events_.empty() && dropped_.empty(); }
    std::size_t size() const { return events_.size(); }

    // The longest run from the front that one ImGui frame can tell apart (see above); at least
    // one event when any is queued. Consecutive moves are merged into the last.
    std::vector<InputEvent> takeFrame();
    // Every dropped file (a drop is one event for the app, however many files).
    std::vector<std::string> takeDropped();

private:
    std::deque<InputEvent> events_;
    std::vector<std::string> dropped_;
};

// The left-button clicks among `events`: a press and its release less than 4 units apart, at the
// press's place. A press whose release has not come yet is carried over in `pending`.
std::vector<std::pair<float, float>> clicksOf(const std::vector<InputEvent>& events, std::optional<InputEvent>& pending);

// GLFW's printable keys (space to the last punctuation key): their text arrives as Char events,
// so only the other keys (Backspace, arrows, Enter, ...) must stay in order with text.
bool isPrintableKey(int code);

// The left-button clicks among `events`: a press and its release less than 4 units apart, at the
// press's place. A press whose release has not come yet is carried over in `pending`.
std::vector<std::pair<float, float>> clicksOf(const std::vector<InputEvent>& events, std::optional<InputEvent>& pending);

} // namespace lab
