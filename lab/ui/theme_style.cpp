// theme_style.cpp — ImGui's colours from a theme's (theme_style.h). ImGui's own dark or light
// colours are the start, so that a colour the theme does not name (a resize grip, the modal
// dimming) still suits it; every colour text or a control stands on is the theme's.
#include "ui/theme_style.h"

#include <imgui.h>

namespace lab::ui {

namespace {

Theme current = Theme::Dark;

ImVec4 vec(FigureColor c, float alpha = 1.0f) { return ImVec4(float(c.r) / 255.0f, float(c.g) / 255.0f, float(c.b) / 255.0f, alpha); }

} // namespace

void applyTheme(Theme theme) {
    current = theme;
    ImGuiStyle& style = ImGui::GetStyle();
    if (theme == Theme::Light) {
        ImGui::StyleColorsLight(&style);
    } else {
        ImGui::StyleColorsDark(&style);
    }
    const ThemeColors& t = themeColors(theme);
    const UiColors& u = t.ui;
    ImVec4* c = style.Colors;
    c[ImGuiCol_Text] = vec(colorOf(t.plot, Ink::Text));
    c[ImGuiCol_TextDisabled] = vec(colorOf(t.plot, Ink::Muted));
    for (ImGuiCol i : {ImGuiCol_WindowBg, ImGuiCol_PopupBg, ImGuiCol_MenuBarBg, ImGuiCol_ScrollbarBg, ImGuiCol_TitleBg,
                       ImGuiCol_TitleBgCollapsed}) {
        c[i] = vec(u.window);
    }
    c[ImGuiCol_ChildBg] = vec(u.window, 0.0f); // a child shows its window's background
    for (ImGuiCol i : {ImGuiCol_FrameBg, ImGuiCol_Button, ImGuiCol_Header, ImGuiCol_Tab, ImGuiCol_TabUnfocused,
                       ImGuiCol_TableHeaderBg, ImGuiCol_TitleBgActive}) {
        c[i] = vec(u.control);
    }
    for (ImGuiCol i : {ImGuiCol_FrameBgHovered, ImGuiCol_ButtonHovered, ImGuiCol_HeaderHovered, ImGuiCol_TabHovered}) {
        c[i] = vec(u.controlHover);
    }
    for (ImGuiCol i : {ImGuiCol_FrameBgActive, ImGuiCol_ButtonActive, ImGuiCol_HeaderActive, ImGuiCol_TabActive,
                       ImGuiCol_TabUnfocusedActive}) {
        c[i] = vec(u.controlActive);
    }
    for (ImGuiCol i : {ImGuiCol_Border, ImGuiCol_Separator, ImGuiCol_TableBorderStrong, ImGuiCol_TableBorderLight,
                       ImGuiCol_ScrollbarGrab}) {
        c[i] = vec(u.controlBorder);
    }
    c[ImGuiCol_BorderShadow] = vec(u.window, 0.0f);
    for (ImGuiCol i : {ImGuiCol_CheckMark, ImGuiCol_SliderGrab, ImGuiCol_SliderGrabActive, ImGuiCol_ScrollbarGrabHovered,
                       ImGuiCol_ScrollbarGrabActive, ImGuiCol_SeparatorHovered, ImGuiCol_SeparatorActive,
                       ImGuiCol_PlotLines, ImGuiCol_PlotHistogram, ImGuiCol_ResizeGripHovered, ImGuiCol_ResizeGripActive}) {
        c[i] = vec(u.accent);
    }
    c[ImGuiCol_TextSelectedBg] = vec(u.accent, 0.35f);
    for (ImGuiCol i : {ImGuiCol_NavHighlight, ImGuiCol_NavWindowingHighlight, ImGuiCol_DragDropTarget}) {
        c[i] = vec(u.focusRing);
    }
    style.FrameBorderSize = 1.0f; // every field and button outlined in controlBorder
    style.WindowBorderSize = 1.0f;
    style.PopupBorderSize = 1.0f;
}

Theme currentTheme() { return current; }

} // namespace lab::ui
