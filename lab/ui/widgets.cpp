// widgets.cpp — shared ImGui helpers.
#include "ui/widgets.h"

#include "core/scene/limits.h"

#include "ui/tooltip.h"

#include <glm/common.hpp>
#include <imgui_internal.h> // a help marker: an item over its text (ItemAdd, ButtonBehavior)
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lab::ui {

namespace {

// A window whose contents may be wider than it: what runs past its side is scrolled to, not cut.
bool scrollsSideways(const ImGuiWindow& w) {
    return (w.Flags & (ImGuiWindowFlags_HorizontalScrollbar | ImGuiWindowFlags_AlwaysHorizontalScrollbar)) != 0;
}

} // namespace

WidgetMap& widgets() {
    static WidgetMap map;
    return map;
}

void WidgetMap::mark(const std::string& name) {
    ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    rects_[name] = Rect{min.x, min.y, max.x - min.x, max.y - min.y};
    if (const ImGuiWindow* w = ImGui::GetCurrentWindowRead(); w && !scrollsSideways(*w) &&
                                                             (max.x > w->InnerClipRect.Max.x + 1.0f || min.x < w->InnerClipRect.Min.x - 1.0f)) {
        rects_["clipped:" + name] = rects_[name]; // cut at the window's side (markClippedWindows())
    }
    if (!focus_.empty() && name == focus_) {
        if (std::exchange(scroll_, false)) {
            ImGui::SetScrollHereY(0.5f);
        }
        const float pad = 3.0f;
        ImGui::GetForegroundDrawList()->AddRect(ImVec2(min.x - pad, min.y - pad), ImVec2(max.x + pad, max.y + pad),
                                                ImGui::GetColorU32(ImGuiCol_NavHighlight), 3.0f, 0, 3.0f);
    }
}

void markClippedWindows() {
    for (ImGuiWindow* w : GImGui->Windows) {
        if (!w->Active || w->Hidden || scrollsSideways(*w) || (w->Flags & ImGuiWindowFlags_Tooltip)) {
            continue;
        }
        // (plus a vertical scrollbar's width: a collapsing header's frame reaches under it, ImGui's own way;
        // a marked widget cut there is still found by mark())
        const float shown = w->InnerRect.GetWidth() - 2.0f * w->WindowPadding.x + w->ScrollbarSizes.x;
        // (an auto-resized window's ideal size is what it would take; another's, what it has)
        const float content = (w->Flags & ImGuiWindowFlags_AlwaysAutoResize) ? std::max(w->ContentSize.x, w->ContentSizeIdeal.x) : w->ContentSize.x;
        if (content > shown + 1.0f) {
            std::string name = w->Name;
            for (char& c : name) {
                c = c == ' ' ? '_' : c; // one word in the map's line
            }
            widgets().set("clipped:" + name, Rect{w->Pos.x, w->Pos.y, w->Size.x, w->Size.y});
        }
    }
}

std::string WidgetMap::text() const {
    std::string s;
    char line[256];
    for (const auto& [name, r] : rects_) {
        std::snprintf(line, sizeof line, "%s %.0f %.0f %.0f %.0f\n", name.c_str(), r.x, r.y, r.w, r.h);
        s += line;
    }
    return s;
}

bool limitedColorEdit(const char* label, glm::vec3& value, const limits::Range& r) {
    // A range above 1 (a light's intensity) lets the picker go past white.
    ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float | (r.max > 1.0f ? ImGuiColorEditFlags_HDR : ImGuiColorEditFlags_None);
    bool changed = ImGui::ColorEdit3(label, &value.x, flags);
    if (changed) {
        value = {limits::clamp(r, value.x), limits::clamp(r, value.y), limits::clamp(r, value.z)};
    }
    return changed;
}

bool dragVec3(const char* label, glm::vec3& value, float speed, float min, float max, const char* format) {
    bool changed = ImGui::DragFloat3(label, &value.x, speed, min, max, format);
    if (changed && min < max) {
        value = glm::clamp(value, glm::vec3(min), glm::vec3(max));
    }
    return changed;
}

bool commandButton(Command command, std::vector<Request>& requests, bool enabled) {
    const CommandRow& row = commandRow(command);
    ImGui::BeginDisabled(!enabled);
    bool clicked = ImGui::Button(row.label);
    ImGui::EndDisabled();
    if (row.key != 0) {
        itemTooltip(keyName(row.key, row.modifiers).c_str());
    }
    if (clicked) {
        requests.push_back({command});
    }
    return clicked;
}

bool sliderPageKeys(float& value, float min, float max, bool logarithmic) {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    const ImGuiID id = g.LastItemData.ID;
    if (g.ActiveId != id || id == 0 || g.ActiveIdSource != ImGuiInputSource_Nav || ImGui::TempInputIsActive(id) ||
        !(min < max)) {
        return false;
    }
    // The slider reads these keys while it is active, so ImGui's navigation does not page away from it.
    const ImGuiKey claimed[] = {ImGuiKey_PageUp, ImGuiKey_PageDown, ImGuiKey_Home, ImGuiKey_End};
    for (ImGuiKey k : claimed) {
        g.ActiveIdUsingKeyInputMask |= ImU64(1) << k;
    }
    auto pressed = [](ImGuiKey k) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(k)); };
    float to = value;
    if (pressed(ImGuiKey_Home)) {
        to = min;
    } else if (pressed(ImGuiKey_End)) {
        to = max;
    } else if (int step = int(pressed(ImGuiKey_PageUp)) - int(pressed(ImGuiKey_PageDown)); step != 0) {
        if (logarithmic && min > 0.0f) { // a tenth of the slider's length, as the grab moves
            double t = std::log(std::max(value, min) / min) / std::log(max / min) + 0.1 * step;
            to = static_cast<float>(min * std::pow(double(max) / min, std::clamp(t, 0.0, 1.0)));
        } else {
            to = std::clamp(value + 0.1f * static_cast<float>(step) * (max - min), min, max);
        }
    }
    if (to == value) {
        return false;
    }
    value = to;
    ImGui::MarkItemEdited(id);
    return true;
}

void disabledWrapped(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
}

bool wrappedSelectable(const char* id, const std::string& text, bool selected) {
    const float room = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize());
    const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, room);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const bool clicked = ImGui::Selectable(id, selected, 0, ImVec2(room, size.y));
    ImGui::GetWindowDrawList()->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, ImGui::GetColorU32(ImGuiCol_Text),
                                        text.c_str(), nullptr, room);
    return clicked;
}

void helpMarker(const char* text) {
    sameLineIfFits(ImGui::CalcTextSize("(?)").x);
    ImGui::TextDisabled("(?)");
    // The marker is a widget of its own over its text, so the keyboard reaches it (its tooltip shows
    // while it has the ring) as the pointer does. A tap (a finger leaves no hovering cursor), a click
    // or Space opens the text as a popup that stays until the next tap or Esc.
    ImGui::PushID(text);
    const ImRect bb(ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
    const ImGuiID id = ImGui::GetID("(?)");
    ImGui::ItemAdd(bb, id);
    bool hovered = false, held = false;
    if (ImGui::ButtonBehavior(bb, id, &hovered, &held)) {
        ImGui::OpenPopup("help");
    }
    ImGui::RenderNavHighlight(bb, id);
    if (ImGui::BeginPopup("help")) {
        ImGui::PushTextWrapPos(std::min(ImGui::GetFontSize() * 30.0f, ImGui::GetIO().DisplaySize.x * 0.8f));
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndPopup();
    } else {
        itemTooltip(text);
    }
    ImGui::PopID();
}

std::vector<std::string_view> spaceSeparated(std::string_view text) {
    std::vector<std::string_view> words;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t space = std::min(text.find(' ', at), text.size());
        if (space > at) {
            words.push_back(text.substr(at, space - at));
        }
        at = space + 1;
    }
    return words;
}

void sameLineIfFits(float width, float spacing) {
    const float gap = spacing < 0.0f ? ImGui::GetStyle().ItemSpacing.x : spacing;
    float right = ImGui::GetItemRectMax().x + gap + width;
    if (right <= ImGui::GetCurrentWindowRead()->WorkRect.Max.x) { // (less a vertical scrollbar)
        ImGui::SameLine(0.0f, spacing);
    }
}

void sameLineIfFits(const char* buttonLabel) {
    sameLineIfFits(ImGui::CalcTextSize(buttonLabel, nullptr, true).x + ImGui::GetStyle().FramePadding.x * 2.0f);
}

void sameLineIfFitsRadio(const char* label) {
    sameLineIfFits(ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x);
}

void nextToolWindow(float columns, float lines, float share) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float font = ImGui::GetFontSize();
    ImGui::SetNextWindowSize(ImVec2(std::min(font * columns, display.x * share), std::min(font * lines, display.y * 0.9f)),
                             ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(1.0f);
}

// A path field with a button after it; Enter in the field or the button sends `command`.
void pathField(const char* id, const char* hint, std::string& text, Command command, std::vector<Request>& requests,
               const char* fieldName) {
    const char* label = commandRow(command).label;
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize(label).x - ImGui::GetStyle().FramePadding.x * 2 -
                            ImGui::GetStyle().ItemSpacing.x);
    bool enter = ImGui::InputTextWithHint(id, hint, &text, ImGuiInputTextFlags_EnterReturnsTrue);
    if (fieldName) {
        mark(fieldName);
    }
    ImGui::SameLine();
    if ((ImGui::Button(label) || enter) && !text.empty()) {
        requests.push_back({command, text});
    }
}

} // namespace lab::ui
