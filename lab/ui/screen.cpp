// screen.cpp — the fixed windows of the lab and everything drawn over them.
#include "ui/screen.h"

#include "ui/dialogs.h"
#include "ui/widgets.h"

#include <imgui.h>

namespace lab::ui {

namespace {

// NoNavInputs: Tab is the lab's (it cycles the panels); without it ImGui 1.86 would take a Tab in a
// focused window to activate its next field, and the next Tab would go to that field.
constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                    ImGuiWindowFlags_NoNavInputs;

void beginFixed(const char* title, const Rect& r) {
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
    ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
    ImGui::Begin(title, nullptr, kFixed);
}

// The control panel and the plots, each where the layout puts it (nowhere when hidden).
void panels(const Layout& layout, ScreenModel& m, ScreenEvents& events) {
    if (layout.panel.w > 0.0f) {
        beginFixed("Lighting Lab###panel", layout.panel);
        controlPanel(*m.edited, *m.view, m.panelInfo, *m.panel, events.requests);
        ImGui::End();
        widgets().set("panel", layout.panel);
    }
    if (layout.plots.w > 0.0f) {
        beginFixed("Reflected intensity###plots", layout.plots);
        plotsPanel(*m.a, m.b, *m.plots, m.probe && *m.probeOpen ? m.probe : nullptr);
        ImGui::End();
        widgets().set("plots", layout.plots);
    }
}

void dialogs(ScreenModel& m, ScreenEvents& events) {
    if (m.problem) {
        events.problemClosed = problemDialog(*m.problem);
    } else if (m.unsavedQuestion) {
        events.answer = unsavedChangesDialog(m.overlay.documentName, *m.unsavedQuestion);
    }
}

} // namespace

float uiScale() { return ImGui::GetFontSize() / 13.0f; }

ScreenEvents drawScreen(const Layout& layout, ScreenModel& m) {
    ScreenEvents events;
    events.typing = ImGui::GetIO().WantTextInput;
    panels(layout, m, events);
    widgets().set("view", layout.view);
    helpWindow(*m.showHelp);
    if (m.probe) {
        probeWindow(*m.probe, *m.a, *m.probeOpen, layout.view.x + 10.0f, layout.view.y + ImGui::GetFontSize() * 2.5f);
    }
    shaderEditorWindow(*m.shaderEditor, events.requests, m.lightingSource);
    dialogs(m, events);
    const Rect& active = m.b ? layout.viewA : layout.view;
    events.view = viewControls(*m.a, active, layout.view, *m.viewControls, m.clicks);
    lightMarkers(*m.a, active, m.viewControls->light, m.lightShapes);
    viewOverlay(m.overlay, layout);
    events.gesture = ImGui::IsAnyItemActive() || events.view.gesture;
    events.dragging = events.gesture && ImGui::IsAnyMouseDown();
    return events;
}

} // namespace lab::ui
