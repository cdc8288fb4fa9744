// dialogs.cpp — modal popups, centred in the window.
#include "ui/dialogs.h"

#include "core/io/safe_text.h"
#include "ui/theme_style.h"
#include "ui/widgets.h"

#include <imgui.h>
#include <imgui_internal.h> // the open popups, to close one answered elsewhere

namespace lab::ui {

namespace {

// Opens the popup `name` if it is not open yet, centred; then BeginPopupModal.
bool beginModal(const char* name) {
    if (!ImGui::IsPopupOpen(name)) {
        ImGui::OpenPopup(name);
    }
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.4f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(io.DisplaySize.x * 0.8f, io.DisplaySize.y * 0.8f));
    return ImGui::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

bool answered(const char* label, const char* widget) {
    bool clicked = ImGui::Button(label);
    mark(widget);
    return clicked;
}

} // namespace

std::string unsavedQuestionText(const std::string& documentName, const std::string& what) {
    return printable(documentName, true) + " has unsaved changes. Discard them to " + printable(what, true) + "?";
}

void closeAnsweredDialogs(bool problemShown, bool questionShown) {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    for (auto [name, shown] : {std::pair{"Error", problemShown}, std::pair{"Unsaved changes", questionShown}}) {
        const ImGuiID id = ImGui::GetID(name);
        for (int i = 0; i < g.OpenPopupStack.Size && !shown; ++i) {
            if (g.OpenPopupStack[i].PopupId == id) {
                ImGui::ClosePopupToLevel(i, true);
                break;
            }
        }
    }
}

bool problemDialog(const Problem& problem) {
    if (!beginModal("Error")) {
        return false;
    }
    // Messages quote what files contain: shown through printable() (core/io/safe_text.h), whole.
    // Wrapped at the dialog's widest (80% of the screen): a long title or reason is never cut off,
    // even on a 1024-wide projector or a phone.
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + ImGui::GetIO().DisplaySize.x * 0.8f - 2.0f * ImGui::GetStyle().WindowPadding.x);
    ImGui::TextUnformatted(printable(problem.title).c_str());
    ImGui::Separator();
    const FigureColor error = currentColors().ui.error;
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(error.r, error.g, error.b, 255));
    for (const Diagnostic& d : problem.diagnostics) {
        ImGui::TextUnformatted(printable(d.str()).c_str());
    }
    ImGui::PopStyleColor();
    ImGui::PopTextWrapPos();
    widgets().set("error", {ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowSize().x, ImGui::GetWindowSize().y});
    bool close = ImGui::Button("OK", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
                 ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
    mark("error.ok");
    if (close) {
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return close;
}

std::optional<UnsavedAnswer> unsavedChangesDialog(const std::string& documentName, const std::string& what) {
    if (!beginModal("Unsaved changes")) {
        return std::nullopt;
    }
    std::optional<UnsavedAnswer> answer;
    // Wrapped at the dialog's widest, as the problem's: a long file name is never cut off.
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + ImGui::GetIO().DisplaySize.x * 0.8f - 2.0f * ImGui::GetStyle().WindowPadding.x);
    ImGui::TextUnformatted(unsavedQuestionText(documentName, what).c_str());
    ImGui::PopTextWrapPos();
    // Enter is the default (keep the work: save first), Esc cancels; no mouse needed.
    const bool enter = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
                       ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter), false);
    if (answered("Save first (Enter)", "confirm.save") || enter) {
        answer = UnsavedAnswer::SaveFirst;
    }
    ImGui::SameLine();
    if (answered("Discard", "confirm.discard")) {
        answer = UnsavedAnswer::Discard;
    }
    ImGui::SameLine();
    if (answered("Cancel (Esc)", "confirm.cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
        answer = UnsavedAnswer::Cancel;
    }
    if (answer) {
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return answer;
}

} // namespace lab::ui
