// widgets.cpp — shared ImGui helpers.
#include "ui/widgets.h"

#include "core/scene/limits.h"

#include <glm/common.hpp>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

namespace lab::ui {

WidgetMap& widgets() {
    static WidgetMap map;
    return map;
}

void WidgetMap::mark(const std::string& name) {
    ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    rects_[name] = Rect{min.x, min.y, max.x - min.x, max.y - min.y};
    if (!focus_.empty() && name == focus_) {
        if (std::exchange(scroll_, false)) {
            ImGui::SetScrollHereY(0.5f);
        }
        const float pad = 3.0f;
        ImGui::GetForegroundDrawList()->AddRect(ImVec2(min.x - pad, min.y - pad), ImVec2(max.x + pad, max.y + pad),
                                                ImGui::GetColorU32(ImGuiCol_NavHighlight), 3.0f, 0, 3.0f);
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
    if (row.key != 0 && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        ImGui::SetTooltip("%s", keyName(row.key, row.modifiers).c_str());
    }
    if (clicked) {
        requests.push_back({command});
    }
    return clicked;
}

void disabledWrapped(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
}

void helpMarker(const char* text) {
    sameLineIfFits(ImGui::CalcTextSize("(?)").x);
    ImGui::TextDisabled("(?)");
    // Hovered with a mouse; tapped with a finger (which leaves no hovering cursor): a popup that
    // stays until the next tap.
    ImGui::PushID(text);
    if (ImGui::IsItemClicked()) {
        ImGui::OpenPopup("help");
    }
    bool popup = ImGui::BeginPopup("help");
    if (popup || ImGui::IsItemHovered()) {
        if (!popup) {
            ImGui::BeginTooltip();
        }
        ImGui::PushTextWrapPos(std::min(ImGui::GetFontSize() * 30.0f, ImGui::GetIO().DisplaySize.x * 0.8f));
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        if (popup) {
            ImGui::EndPopup();
        } else {
            ImGui::EndTooltip();
        }
    }
    ImGui::PopID();
}

void sameLineIfFits(float width) {
    float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
    if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) {
        ImGui::SameLine();
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
void pathField(const char* id, const char* hint, std::string& text, Command command, std::vector<Request>& requests) {
    const char* label = commandRow(command).label;
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize(label).x - ImGui::GetStyle().FramePadding.x * 2 -
                            ImGui::GetStyle().ItemSpacing.x);
    bool enter = ImGui::InputTextWithHint(id, hint, &text, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button(label) || enter) && !text.empty()) {
        requests.push_back({command, text});
    }
}

} // namespace lab::ui
