// screen.cpp — the fixed windows of the lab and everything drawn over them.
#include "ui/screen.h"

#include "ui/viewport/overlay.h"

#include "ui/dialogs.h"
#include "ui/keyboard.h"
#include "ui/theme_style.h"
#include "ui/widgets.h"

#include <imgui.h>
#include <imgui_internal.h> // the window's MoveId: a press on its background

#include <algorithm>
#include <cctype>
#include <string>

namespace lab::ui {

namespace {

// Keyboard navigation is on (ui/keyboard.h says when the keys are a window's rather than the model's).
constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;

void beginFixed(const char* title, const Rect& r, ImGuiWindowFlags extra = 0) {
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
    ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
    ImGui::Begin(title, nullptr, kFixed | extra);
}

// A drag that starts on the window's background scrolls it, as a finger expects (ImGui 1.86
// scrolls only by wheel and scrollbar); a drag that starts on a widget is the widget's.
void dragToScroll() {
    ImGuiIO& io = ImGui::GetIO();
    // A press on the window's own background makes its move handle the active item (ImGui 1.86 does
    // so even for a window that cannot move): that is the background being dragged, not a widget.
    bool background = !ImGui::IsAnyItemActive() || ImGui::GetActiveID() == ImGui::GetCurrentWindow()->MoveId;
    if (ImGui::IsWindowHovered() && background && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        ImGui::SetScrollY(ImGui::GetScrollY() - io.MouseDelta.y);
    }
}

PanelPart partOf(const Layout& layout) {
    if (!layout.compact) {
        return PanelPart::All;
    }
    switch (layout.tab) {
    case PanelTab::Model: return PanelPart::Model;
    case PanelTab::Material: return PanelPart::Material;
    case PanelTab::Lights: return PanelPart::Lights;
    case PanelTab::Plots: break;
    }
    return PanelPart::All;
}

// The compact layout's tab row: one wide button a tab, the chosen one highlighted ("tab.plots").
void tabRow(const Rect& r, PanelTab& tab) {
    const float unit = uiScale();
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4.0f * unit, 4.0f * unit));
    beginFixed("###tabs", r, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    const float gap = 4.0f * unit;
    ImVec2 avail = ImGui::GetContentRegionAvail();
    ImVec2 size((avail.x - gap * 3.0f) / 4.0f, std::max(avail.y, 1.0f));
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(gap, gap));
    for (PanelTab t : kPanelTabs) {
        if (t != kPanelTabs[0]) {
            ImGui::SameLine();
        }
        bool chosen = t == tab;
        ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(chosen ? ImGuiCol_ButtonActive : ImGuiCol_FrameBg));
        if (ImGui::Button(toString(t), size)) {
            tab = t;
        }
        ImGui::PopStyleColor();
        std::string name = std::string("tab.") + toString(t);
        for (char& c : name) {
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
        mark(name);
    }
    ImGui::PopStyleVar();
    ImGui::End();
    widgets().set("tabs", r);
}

// The control panel and the plots, each where the layout puts it (nowhere when hidden).
void panels(const Layout& layout, ScreenModel& m, ScreenEvents& events) {
    // The compact layout's windows have no title bar: the tab row says what they are.
    const ImGuiWindowFlags extra = layout.compact ? ImGuiWindowFlags_NoTitleBar : 0;
    if (layout.tabs.w > 0.0f) {
        tabRow(layout.tabs, m.panel->tab);
    }
    if (layout.panel.w > 0.0f) {
        beginFixed("Lighting Lab###panel", layout.panel, extra);
        // Fields to the width less a label's and a help marker's room where ImGui's default (65% of
        // the window) leaves the labels too little: a phone's panel, and presenter mode's large
        // font in a projector's narrow panel, which would cut them at the side.
        const float labelRoom = ImGui::GetFontSize() * 9.0f;
        const bool narrow = layout.compact || ImGui::GetContentRegionAvail().x * 0.35f < labelRoom;
        if (narrow) {
            ImGui::PushItemWidth(-labelRoom);
        }
        controlPanel(*m.edited, *m.view, m.panelInfo, *m.panel, events.requests, partOf(layout));
        if (narrow) {
            ImGui::PopItemWidth();
        }
        dragToScroll();
        ImGui::End();
        widgets().set("panel", layout.panel);
    }
    if (layout.plots.w > 0.0f) {
        beginFixed("Reflected intensity###plots", layout.plots, extra);
        m.plots->palette = m.view->palette; // the slice's colours are the value views'
        plotsPanel(*m.a, m.captions.exercise ? nullptr : m.b, *m.plots, m.probe && *m.probeOpen ? m.probe : nullptr, m.probeLobe);
        ImGui::End();
        widgets().set("plots", layout.plots);
    }
}

void dialogs(ScreenModel& m, ScreenEvents& events) {
    closeAnsweredDialogs(m.problem != nullptr, m.problem == nullptr && m.unsavedQuestion != nullptr);
    if (m.problem) {
        events.problemClosed = problemDialog(*m.problem);
    } else if (m.unsavedQuestion) {
        events.answer = unsavedChangesDialog(m.captions.documentName, *m.unsavedQuestion);
    }
}

} // namespace

float uiScale() { return ImGui::GetFontSize() / 13.0f; }

ScreenEvents drawScreen(const Layout& layout, ScreenModel& m) {
    ScreenEvents events;
    applyTheme(m.panel->theme); // before the first widget: the panel may have changed it last frame
    events.typing = ImGui::GetIO().WantTextInput;
    events.pointerX = ImGui::GetIO().MousePos.x;
    events.pointerY = ImGui::GetIO().MousePos.y;
    panels(layout, m, events);
    widgets().set("view", layout.viewport);
    widgets().set("view.area", layout.view);
    if (m.b) {
        widgets().set("view.a", layout.halves[0]);
        widgets().set("view.b", layout.halves[1]);
    }
    helpWindow(*m.showHelp);
    if (m.probe) {
        // The readout opens beside the model (over the plots or the panel), not over it; with both
        // hidden (Tab: the model only) it opens at the view's corner, over the model.
        const Rect& beside = layout.plots.w > 0.0f ? layout.plots : layout.panel.w > 0.0f ? layout.panel : layout.viewport;
        probeWindow(*m.probe, *m.a, *m.view, *m.probeOpen, beside.x + 10.0f, beside.y + ImGui::GetFontSize() * 2.0f);
    }
    if (m.showNotes) {
        notesWindow(m.notes, *m.showNotes, layout.viewport.x + 8.0f, layout.viewport.y + layout.viewport.h - 8.0f,
                    std::max(layout.viewport.w * 0.6f, 200.0f));
    }
    shaderEditorWindow(*m.shaderEditor, events.requests, m.lightingSource);
    if (m.shareCode) {
        shareCodeWindow(*m.shareCode, events.requests);
    }
    sweepWindow(*m.sweep, *m.a, events.requests);
    dialogs(m, events);
    const Rect& active = m.b ? layout.halves[0] : layout.viewport;
    const bool wipe = m.view->wipe && m.view->mode != ViewMode::Lit;
    events.viewport = viewportControls(*m.a, active, layout.viewport, *m.viewportControls, m.clicks, m.motion,
                                       m.captions.probePoint ? &*m.captions.probePoint : nullptr,
                                       wipe ? &m.view->wipeAt : nullptr);
    m.captions.wipeAt = wipe ? std::optional<float>(m.view->wipeAt) : std::nullopt;
    m.captions.wipeDragged = m.viewportControls->drag == ViewportControls::Drag::Wipe;
    const std::vector<Rect> markers =
        lightMarkers(m.motion ? orbitedScene(*m.a, *m.motion) : *m.a, active, m.viewportControls->light, m.lightShapes);
    captionStrips(m.captions, layout);
    if (m.equation && !m.captions.exercise && !*m.showHelp) { // (over the model, not over the help)
        const Rect& over = m.b ? layout.halves[0] : layout.viewport;
        std::vector<Rect> keepClear = markers; // the lights, and the notes' strip at the view's bottom left
        if (m.showNotes && *m.showNotes) {
            keepClear.push_back({layout.viewport.x, layout.viewport.y + 0.75f * layout.viewport.h, 0.6f * layout.viewport.w, 0.25f * layout.viewport.h});
        }
        equationOverlay(*m.a, over, keepClear);
    }
    if (m.pointer) {
        roomPointer(events.pointerX, events.pointerY, layout.viewport);
    }
    markKeyboardFocus();
    markClippedWindows();
    events.gesture = ImGui::IsAnyItemActive() || events.viewport.gesture;
    events.dragging = events.gesture && ImGui::IsAnyMouseDown();
    return events;
}

} // namespace lab::ui
