// widgets.h — small ImGui helpers shared by the panels, and the widget map for GUI tests.
//
// ImGui only: no GL, no files. mark() records the screen rectangle of the last item under a
// stable name ("material.diffuse"); the app writes the map to a file when asked
// (`lab --layout-file`), so GUI tests can point real mouse events at real widgets.
#pragma once

#include "core/commands.h"
#include "ui/layout.h"

#include <glm/vec3.hpp>
#include <imgui.h>

#include <map>
#include <string>
#include <vector>

namespace lab::ui {

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
// A button for `command`, labelled from the command table (with its shortcut in the tooltip);
// a click appends the command to `requests`. Disabled (greyed) when `enabled` is false.
bool commandButton(Command command, std::vector<Request>& requests, bool enabled = true);
// A "(?)" marker with a tooltip.
void helpMarker(const char* text);

} // namespace lab::ui
