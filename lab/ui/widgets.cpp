// widgets.cpp — shared ImGui helpers.
#include "ui/widgets.h"

#include <glm/common.hpp>

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

bool colorEdit(const char* label, glm::vec3& value) {
    bool changed = ImGui::ColorEdit3(label, &value.x, ImGuiColorEditFlags_Float);
    if (changed) {
        value = glm::clamp(value, glm::vec3(0.0f), glm::vec3(1.0f));
    }
    return changed;
}

bool lightColorEdit(const char* label, glm::vec3& value) {
    bool changed = ImGui::ColorEdit3(label, &value.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    if (changed) {
        value = glm::max(value, glm::vec3(0.0f));
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

void helpMarker(const char* text) {
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

} // namespace lab::ui
