// widgets.h — small ImGui helpers shared by the panels, and the widget map for GUI tests.
//
// ImGui only: no GL, no files. mark() records the screen rectangle of the last item under a
// stable name ("material.diffuse"); the app writes the map to a file when asked
// (`lab --layout-file`), so GUI tests can point real mouse events at real widgets.
#pragma once

#include <glm/vec3.hpp>
#include <imgui.h>

#include <map>
#include <string>

namespace lab::ui {

struct Rect {
    float x, y, w, h;
};

class WidgetMap {
public:
    void clear() { rects_.clear(); }
    void mark(const std::string& name); // the last ImGui item
    void set(const std::string& name, const Rect& r) { rects_[name] = r; }
    std::string text() const;           // "name x y w h" per line, sorted by name
private:
    std::map<std::string, Rect> rects_;
};

WidgetMap& widgets();
inline void mark(const std::string& name) { widgets().mark(name); }

// A material coefficient triplet: colour square plus typed R, G, B in [0, 1]. True if changed.
bool colorEdit(const char* label, glm::vec3& value);
// A light colour: as colorEdit, but any value ≥ 0 (lights may be brighter than 1).
bool lightColorEdit(const char* label, glm::vec3& value);
// A vec3 dragged in `speed` steps, optionally clamped.
bool dragVec3(const char* label, glm::vec3& value, float speed, float min = 0.0f, float max = 0.0f,
              const char* format = "%.3f");
// A "(?)" marker with a tooltip.
void helpMarker(const char* text);

// Keyboard keys as the GLFW backend of ImGui 1.86 indexes io.KeysDown (GLFW key codes, the same
// in the browser through Emscripten's GLFW). Letters and digits are their ASCII codes.
namespace keys {
constexpr int Space = 32, Escape = 256, Enter = 257, Tab = 258, Right = 262, Left = 263, Down = 264, Up = 265;
constexpr int F1 = 290, F11 = 300, F12 = 301, Equal = 61, Minus = 45, KeypadAdd = 334, KeypadSubtract = 333;
constexpr int KeypadEnter = 335;
} // namespace keys

} // namespace lab::ui
