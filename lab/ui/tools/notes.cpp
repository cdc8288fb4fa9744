// notes.cpp — the speaker's notes: the strip over the model and the window of their own.
#include "ui/tools/notes.h"

#include "core/io/safe_text.h"

#include "ui/widgets.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace lab::ui {

namespace {

constexpr const char* kNoNotes = "No notes for this slide (a deck's \"notes\", or the preset's).";

} // namespace

std::string wallClock() {
    std::time_t now = std::time(nullptr);
    char clock[16] = "";
    if (std::tm local{}; localtime_r(&now, &local)) {
        std::snprintf(clock, sizeof clock, "%02d:%02d", local.tm_hour, local.tm_min);
    }
    return clock;
}

void notesWindow(const NotesModel& m, bool& open, float x, float y, float width) {
    if (!open) {
        return;
    }
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Appearing, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width * 0.3f, 0.0f), ImVec2(width, ImGui::GetIO().DisplaySize.y * 0.6f));
    ImGui::SetNextWindowBgAlpha(0.9f);
    if (ImGui::Begin("Speaker notes (S)###notes", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                                                           ImGuiWindowFlags_NoFocusOnAppearing)) {
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width - 2.0f * ImGui::GetStyle().WindowPadding.x);
        ImGui::TextDisabled("%s   %s", printable(m.position, true).c_str(), m.clock.c_str());
        ImGui::Separator();
        if (m.notes.empty()) {
            ImGui::TextDisabled("%s", kNoNotes);
        } else {
            ImGui::TextUnformatted(printable(m.notes).c_str());
        }
        if (!m.next.empty()) {
            ImGui::Separator();
            ImGui::TextDisabled("Next: %s", printable(m.next, true).c_str());
        }
        ImGui::PopTextWrapPos();
    }
    mark("notes");
    ImGui::End();
}

namespace {

// The largest of the font's scales from 1 down to 0.6 at which `text`, wrapped at `width`, is no
// taller than `height` (0.6 when none is: the rest scrolls).
float fittingScale(const std::string& text, float width, float height) {
    for (float scale = 1.0f; scale > 0.6f; scale -= 0.05f) {
        ImGui::SetWindowFontScale(scale);
        if (ImGui::CalcTextSize(text.c_str(), nullptr, false, width).y <= height) {
            return scale;
        }
    }
    return 0.6f;
}

} // namespace

void notesScreen(const NotesModel& m) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(io.DisplaySize);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::Begin("notes-screen", nullptr, flags);
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::SetWindowFontScale(0.75f);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ImGui::TextDisabled("%s", printable(m.position, true).c_str());
    ImGui::PopTextWrapPos();
    ImGui::SameLine(std::max(0.0f, width - ImGui::CalcTextSize(m.clock.c_str()).x));
    ImGui::TextUnformatted(m.clock.c_str());
    ImGui::Separator();
    const std::string next = m.next.empty() ? std::string("Last slide") : "Next: " + printable(m.next, true);
    const float foot = ImGui::GetTextLineHeightWithSpacing() * 2.0f + ImGui::GetStyle().ItemSpacing.y;
    const float height = std::max(ImGui::GetContentRegionAvail().y - foot, ImGui::GetTextLineHeight());
    const std::string notes = m.notes.empty() ? std::string(kNoNotes) : printable(m.notes);
    ImGui::BeginChild("notes-text", ImVec2(width, height));
    const float scrollbar = ImGui::GetStyle().ScrollbarSize;
    ImGui::SetWindowFontScale(fittingScale(notes, width - scrollbar, height));
    ImGui::PushTextWrapPos(width - scrollbar);
    if (m.notes.empty()) {
        ImGui::TextDisabled("%s", notes.c_str());
    } else {
        ImGui::TextUnformatted(notes.c_str());
    }
    ImGui::PopTextWrapPos();
    ImGui::EndChild();
    ImGui::Separator();
    ImGui::SetWindowFontScale(0.75f);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ImGui::TextDisabled("%s", next.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

} // namespace lab::ui
