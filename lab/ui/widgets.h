// widgets.h — small ImGui helpers shared by the panels.
//
// ImGui only: no GL, no files. mark() (ui/widget_map.h) names the last item for the GUI tests.
#pragma once

#include "core/scene/limits.h"
#include "ui/actions.h"
#include "ui/tooltip.h"
#include "ui/widget_map.h"

#include <glm/vec3.hpp>
#include <imgui.h>

#include <string>
#include <string_view>
#include <vector>

namespace lab::ui {

// A colour triplet: colour square plus typed R, G, B, each clamped into `range` (a reflectance's
// [0, 1], a light's intensity, which may be brighter than 1). True if changed.
bool limitedColorEdit(const char* label, glm::vec3& value, const limits::Range& range);
// A vec3 dragged in `speed` steps, optionally clamped.
bool dragVec3(const char* label, glm::vec3& value, float speed, float min = 0.0f, float max = 0.0f,
              const char* format = "%.3f");
// After a SliderFloat that the keyboard is changing (Space on it, ui/keyboard.h): Page Up / Page Down
// move it a tenth of its length, Home / End to its ends (ImGui 1.86 has only the arrows). True if changed.
bool sliderPageKeys(float& value, float min, float max, bool logarithmic);
// A button for `command`, labelled from the command table (with its shortcut in the tooltip);
// a click appends the command to `requests`. Disabled (greyed) when `enabled` is false.
bool commandButton(Command command, std::vector<Request>& requests, bool enabled = true);
// A path field with a button after it (`command`'s label); Enter in the field or the button asks
// for `command` with the field's text. `fieldName`: the field's name in the widget map (mark()); the
// last item, for a mark() after it, is the button.
void pathField(const char* id, const char* hint, std::string& text, Command command, std::vector<Request>& requests,
               const char* fieldName = nullptr);
// SameLine() when an item `width` wide (a button labelled `label`) still fits on this line, so
// rows of buttons wrap in a narrow panel (a phone) instead of running off its edge.
// `spacing`: the gap after the last item (< 0: the style's ItemSpacing).
void sameLineIfFits(float width, float spacing = -1.0f);
void sameLineIfFits(const char* buttonLabel);
// ... for a radio button labelled `label`.
void sameLineIfFitsRadio(const char* label);
// The words of `text`, a space apart (a run of spaces is one gap), in order: where a text too wide
// for its room may break (the panel's equation, the plots' readouts).
std::vector<std::string_view> spaceSeparated(std::string_view text);
// Greyed text wrapped at the window's edge (a phone's panel is narrow).
void disabledWrapped(const char* text);
// A Selectable as wide as the window's room whose `text` (drawn as it is: no "##" in it) wraps
// onto more lines where it is wider than that room (a long file name in presenter mode), so none
// of it is cut. `id` is its ImGui label ("###preset3"). True when clicked.
bool wrappedSelectable(const char* id, const std::string& text, bool selected);
// A "(?)" marker with a tooltip (ui/tooltip.h), reachable by the keyboard; a tap, a click or Space
// opens it as a popup that stays.
void helpMarker(const char* text);

// Before Begin() of a tool window (shader editor, sweep): `columns` × `lines` text lines where
// that fits, else at most `share` of the screen's width and 90% of its height; centred, opaque (the
// panels behind must not show through). Its first appearance only: then the user's.
void nextToolWindow(float columns, float lines, float share);

} // namespace lab::ui
