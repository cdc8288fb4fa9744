// keyboard.cpp — the keyboard between the model and ImGui's keyboard navigation.
#include "ui/keyboard.h"

#include "ui/tooltip.h"
#include "ui/widget_map.h"

#include <imgui.h>
#include <imgui_internal.h> // the navigation's state: its window, its item, its pending requests

#include <utility>

namespace lab::ui {

namespace {

// The lab's fixed windows (ui/screen.cpp names them "...###panel" and so on; "###" restarts the ID).
bool fixedWindow(const ImGuiWindow* w) {
    for (const char* name : {"###panel", "###plots", "###tabs"}) {
        if (w == ImGui::FindWindowByName(name)) {
            return true;
        }
    }
    return false;
}

// Where a Tab from the model goes: the tool window that has ImGui's focus, else the control panel,
// else the plots, else the compact layout's tab row; nullptr when nothing is shown.
ImGuiWindow* tabTarget() {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    ImGuiWindow* focused = g.NavWindow ? g.NavWindow->RootWindow : nullptr;
    if (focused && focused->WasActive && !fixedWindow(focused)) {
        return focused;
    }
    for (const char* name : {"###panel", "###plots", "###tabs"}) {
        ImGuiWindow* w = ImGui::FindWindowByName(name);
        if (w && w->WasActive) {
            return w;
        }
    }
    return nullptr;
}

} // namespace

KeyOwner KeyboardFocus::beforeNewFrame(std::vector<KeyPress>& presses, bool mousePressed) {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    const bool typing = g.WantTextInputNextFrame == 1; // a text field had the keyboard last frame
    // The keyboard goes back to the model: a mouse press, no window focused (a click on the model,
    // the window closed), or no widget left to focus (Esc with nothing else to end).
    const bool pending =
        g.NavMoveSubmitted || g.NavInitRequest || g.NavInitResultId != 0 || g.NavWindowingTarget != nullptr;
    if (window_ && (mousePressed || g.NavWindow == nullptr || (g.NavId == 0 && !pending && !typing))) {
        window_ = false;
    }
    entering_ = false;
    for (KeyPress& p : presses) {
        if (p.key == keys::Escape && p.modifiers == 0 && closeTooltip()) {
            p.used = true;
            continue;
        }
        if (window_ || (p.modifiers & kAlt)) {
            continue;
        }
        const bool tab = p.key == keys::Tab, enter = p.key == keys::Enter && p.modifiers == 0;
        if (tab && ((p.modifiers & kCtrl) || typing)) {
            window_ = true; // ImGui's window switcher, or its Tab on from a field typed in after a click
        } else if ((tab && tabEnters_) || (enter && !typing && g.OpenPopupStack.Size == 0)) {
            // The window's last widget, or its first (ImGui's own Tab would skip to its first text
            // field and start typing there), with the ring. The key itself goes no further.
            if (ImGuiWindow* target = tabTarget()) {
                ImGui::FocusWindow(target);
                window_ = entering_ = p.used = true;
            }
        }
    }
    ImGuiIO& io = ImGui::GetIO();
    if (window_) {
        io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
        if (!typing && g.NavId != 0) {
            g.NavDisableHighlight = false; // the ring shows wherever the keys go (ImGui hides it after a typed value)
        }
    } else {
        io.ConfigFlags &= ~ImGuiConfigFlags_NavEnableKeyboard;
    }
    return typing ? KeyOwner::Typing : window_ ? KeyOwner::Panel : KeyOwner::Canvas;
}

void KeyboardFocus::afterNewFrame() {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    if (std::exchange(entering_, false) && g.NavWindow) {
        ImGui::NavInitWindow(g.NavWindow, false); // a request of this frame's (NewFrame drops older ones)
        g.NavDisableHighlight = false;
    }
    if (g.NavMoveSubmitted && (g.NavMoveFlags & ImGuiNavMoveFlags_Tabbing) && g.NavTabbingDir == 0 && g.NavId != 0) {
        g.NavTabbingDir = +1;
    }
}

void markKeyboardFocus() {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    if (!(ImGui::GetIO().ConfigFlags & ImGuiConfigFlags_NavEnableKeyboard) || g.NavWindow == nullptr || g.NavId == 0 ||
        g.NavDisableHighlight) {
        return;
    }
    ImRect r = ImGui::WindowRectRelToAbs(g.NavWindow, g.NavWindow->NavRectRel[g.NavLayer]);
    widgets().set("focus", Rect{r.Min.x, r.Min.y, r.GetWidth(), r.GetHeight()});
}

} // namespace lab::ui
