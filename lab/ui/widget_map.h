// widget_map.h — where each named widget was drawn this frame, for the GUI and browser tests.
//
// mark() records the screen rectangle of the last ImGui item under a stable name
// ("material.diffuse"); the app writes the map to a file when asked (`lab --layout-file`), the
// page hands it to its tests, so tests can point real mouse events at real widgets. This header
// needs no ImGui.
#pragma once

#include "ui/layout.h"

#include <map>
#include <string>
#include <utility>

namespace lab::ui {

class WidgetMap {
public:
    void clear() { rects_.clear(); }
    // The widget the page's focused control stands for (its name; "" none): mark() rings it and
    // scrolls it into view once. True when it changed.
    bool focus(const std::string& name) {
        scroll_ = scroll_ || name != focus_;
        return std::exchange(focus_, name) != name;
    }
    void mark(const std::string& name); // the last ImGui item
    void set(const std::string& name, const Rect& r) { rects_[name] = r; }
    std::string text() const;           // "name x y w h" per line, sorted by name
    const Rect* find(const std::string& name) const {
        auto it = rects_.find(name);
        return it == rects_.end() ? nullptr : &it->second;
    }
private:
    std::map<std::string, Rect> rects_;
    std::string focus_;
    bool scroll_ = false;
};

WidgetMap& widgets();
inline void mark(const std::string& name) { widgets().mark(name); }

// After every window of the frame: each one whose contents are wider than it shows and that cannot
// scroll sideways (some text or widget in it is cut) goes into the map as "clipped:<its name>" (its
// rectangle), for the GUI tests that find no cut text in presenter mode on a projector.
void markClippedWindows();

} // namespace lab::ui
