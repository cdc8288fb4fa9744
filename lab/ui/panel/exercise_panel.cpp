// exercise_panel.cpp — the panel's exercise parts: which fields show, the Exercise section, Make exercise.
#include "ui/panel/exercise_panel.h"

#include "core/exercise/preset_fields.h"
#include "ui/widget_map.h"
#include "ui/theme_style.h"
#include "ui/widgets.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace lab::ui {

// Whether the field at JSON path `path` (core/scene/field_path.h) gets its widget: in an
// exercise only the open ones (and the always free); while making one, every field, with a
// checkbox before it that opens it to students.
bool FieldGate::field(const std::string& path) const {
    if (exercise) {
        return alwaysFree(path) || std::any_of(exercise->open.begin(), exercise->open.end(),
                                               [&](const std::string& o) { return covers(o, path); });
    }
    if (draft && draft->open) {
        std::vector<std::string>& open = *draft->open;
        auto at = std::find(open.begin(), open.end(), path);
        bool on = at != open.end();
        ImGui::PushID(path.c_str());
        if (ImGui::Checkbox("##open", &on)) {
            if (on) {
                open.push_back(path);
            } else {
                open.erase(at);
            }
        }
        itemTooltip(("Students may change " + path).c_str());
        mark("open." + path);
        ImGui::PopID();
        ImGui::SameLine();
    }
    return true;
}

// Whether a section holding the fields under these paths shows at all (in an exercise: some open).
bool FieldGate::any(std::initializer_list<const char*> prefixes) const {
    if (!exercise) {
        return true;
    }
    for (const char* p : prefixes) {
        for (const std::string& o : exercise->open) {
            if (overlaps(o, p)) {
                return true;
            }
        }
    }
    return false;
}

// The exercise being solved: what to do, how close the attempt is, hints, start again, leave.
void exerciseSection(const ExercisePanelModel& e, std::vector<Request>& requests) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(e.title.c_str());
    mark("exercise.title");
    if (!e.instructions.empty()) {
        ImGui::TextDisabled("%s", e.instructions.c_str());
    }
    ImGui::PopTextWrapPos();
    if (e.solved) {
        ImGui::PushStyleColor(ImGuiCol_PlotHistogram, IM_COL32(40, 170, 70, 255));
    }
    // The bar says the score's line itself, as the page's live region and `lab exercise check` do.
    ImGui::ProgressBar(static_cast<float>(e.progress), ImVec2(-1, 0), e.score.empty() ? "..." : e.score.c_str());
    mark(e.solved ? "exercise.solved" : "exercise.score");
    if (e.solved) {
        ImGui::PopStyleColor();
    }
    ImGui::PushTextWrapPos(0.0f);
    if (e.solved) {
        const FigureColor ok = currentColors().ui.success;
        ImGui::TextColored(ImVec4(float(ok.r) / 255.0f, float(ok.g) / 255.0f, float(ok.b) / 255.0f, 1.0f),
                           "Your attempt matches the target.");
    } else if (!e.details.empty()) {
        ImGui::TextDisabled("%s", e.details.c_str());
    }
    ImGui::PopTextWrapPos();
    for (std::size_t i = 0; i < e.hints.size(); ++i) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::Text("Hint %zu: %s", i + 1, e.hints[i].c_str());
        ImGui::PopTextWrapPos();
    }
    commandButton(Command::ExerciseReset, requests);
    mark("exercise.reset");
    sameLineIfFits(commandRow(Command::ExerciseHint).label);
    commandButton(Command::ExerciseHint, requests, e.hintsLeft > 0);
    mark("exercise.hint");
    sameLineIfFits(commandRow(Command::Undo).label);
    commandButton(Command::Undo, requests);
    sameLineIfFits(commandRow(Command::ExerciseLeave).label);
    commandButton(Command::ExerciseLeave, requests);
    mark("exercise.leave");
    disabledWrapped("Only the fields the exercise opens are shown. The target is beside or below your attempt; "
                    "turn the camera freely (both follow).");
}

void exerciseList(const std::vector<std::filesystem::path>& files, std::vector<Request>& requests) {
    ImGui::TextDisabled("Exercises: match a target");
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::string name = files[i].stem().string();
        const float width = ImGui::CalcTextSize(name.c_str()).x + ImGui::GetStyle().FramePadding.x * 2.0f;
        if (i > 0) {
            sameLineIfFits(width);
        }
        // A name wider than the panel (presenter mode's font) wraps in a row of its own instead of being cut.
        const bool fits = width <= ImGui::GetContentRegionAvail().x;
        if (fits ? ImGui::SmallButton(name.c_str()) : wrappedSelectable(("###exercise" + std::to_string(i)).c_str(), name, false)) {
            requests.push_back({Command::OpenPath, files[i].string()});
        }
        mark("exercises." + name);
    }
}

// "Make exercise": title, instructions, hints, the open fields (ticked below), save.
void draftSection(DraftPanelModel& d, bool browser, std::string& path, std::vector<Request>& requests) {
    disabledWrapped("The scene when you pressed Make exercise is the target. Tick the fields students may change "
                    "(the boxes before them below), set those fields to where students start, then save.");
    ImGui::InputText("title", d.title);
    mark("draft.title");
    ImGui::TextDisabled("instructions");
    ImGui::InputTextMultiline("##instructions", d.instructions, ImVec2(-1, ImGui::GetTextLineHeight() * 3.5f));
    mark("draft.instructions");
    ImGui::TextDisabled("hints, one a line (students reveal them one at a time)");
    ImGui::InputTextMultiline("##hints", d.hints, ImVec2(-1, ImGui::GetTextLineHeight() * 2.5f));
    mark("draft.hints");
    std::string open;
    for (const std::string& o : *d.open) {
        open += (open.empty() ? "" : ", ") + o;
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("open: %s", open.empty() ? "(none ticked yet)" : open.c_str());
    if (!d.problem.empty()) {
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "%s", d.problem.c_str());
    }
    ImGui::PopTextWrapPos();
    if (browser) {
        commandButton(Command::SaveExercise, requests, d.problem.empty());
    } else {
        pathField("##exercise-path", "path/to/exercise.json", path, Command::SaveExercise, requests);
    }
    mark("draft.save");
    commandButton(Command::MakeExercise, requests); // again: stop making it
    ImGui::SameLine();
    ImGui::TextDisabled("(stop)");
}

} // namespace lab::ui
