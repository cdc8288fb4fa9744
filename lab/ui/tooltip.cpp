// tooltip.cpp — a tooltip that stays while hovered and closes with Esc.
#include "ui/tooltip.h"

#include <imgui.h>
#include <imgui_internal.h> // the keyboard's ring: NavId and NavDisableHighlight

#include <algorithm>

namespace lab::ui {

namespace {

struct Shown {
    ImGuiID item = 0;    // the item whose tooltip is shown, or was closed by Esc
    int frame = -1;      // ... last drawn in this frame (ImGui's frame count)
    ImRect rect;         // ... where
    bool closed = false; // closed by Esc: not shown again until the pointer and the ring have left
};

Shown& shown() {
    static Shown s; // the one ImGui context's
    return s;
}

} // namespace

void itemTooltip(const char* text) {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    Shown& s = shown();
    const ImGuiID item = g.LastItemData.ID != 0 ? g.LastItemData.ID : ImGui::GetID(text);
    const bool hovered = ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled);
    const bool focused =
        g.NavId == item && !g.NavDisableHighlight && (g.IO.ConfigFlags & ImGuiConfigFlags_NavEnableKeyboard);
    const bool overTip =
        s.item == item && (s.closed || s.frame >= ImGui::GetFrameCount() - 1) && s.rect.Contains(g.IO.MousePos);
    if (!hovered && !focused && !overTip) {
        if (s.item == item) {
            s = Shown{};
        }
        return;
    }
    if (s.item == item && s.closed) {
        return;
    }
    // Just below the item, touching it, so the pointer can move onto the tooltip; kept on screen
    // with the size it had in the last frame.
    const ImRect itemRect = g.LastItemData.Rect;
    const ImVec2 size = s.item == item ? s.rect.GetSize() : ImVec2(0, 0);
    const ImVec2 display = g.IO.DisplaySize;
    ImVec2 pos(std::clamp(itemRect.Min.x, 0.0f, std::max(0.0f, display.x - size.x)), itemRect.Max.y);
    if (pos.y + size.y > display.y && itemRect.Min.y - size.y >= 0.0f) {
        pos.y = itemRect.Min.y - size.y; // above, touching it, where below has no room
    }
    ImGui::SetNextWindowPos(pos);
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(std::min(ImGui::GetFontSize() * 30.0f, display.x * 0.8f));
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    s.rect = ImGui::GetCurrentWindow()->Rect();
    ImGui::EndTooltip();
    s.item = item;
    s.frame = ImGui::GetFrameCount();
}

bool closeTooltip() {
    Shown& s = shown();
    if (s.item == 0 || s.closed || s.frame != ImGui::GetFrameCount()) {
        return false;
    }
    s.closed = true;
    return true;
}

} // namespace lab::ui
