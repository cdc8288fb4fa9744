// exercise_panel.h — the control panel's exercise parts (ui/panel/panel.cpp calls them).
//
// An exercise being solved shows only its open fields (core/exercise/preset_fields.h paths; the
// widgets are named by the same paths) and a section with its instructions, score, hints, start
// again and leave; while an exercise is being made, a checkbox before every field opens it.
#pragma once

#include "ui/actions.h"

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace lab::ui {

// An exercise being solved (core/exercise/exercise.h), as the panel shows it: only its open
// fields can be edited, and its own section says what to do and how close the attempt is.
struct ExercisePanelModel {
    std::string title, instructions;
    std::vector<std::string> hints; // those shown so far
    int hintsLeft = 0;
    std::vector<std::string> open; // JSON paths (core/exercise/preset_fields.h)
    std::string score;             // its line: "Score 42%: not solved yet" (core/exercise/score.h), empty before the first score
    std::string details;           // what is still too far: "0.5% of the image differs by more than 6 levels ..."
    double progress = 0.0;         // 0..1, the bar's fill: 1 only when solved
    bool solved = false;
};

// "Make exercise": the author's draft, edited in place (a checkbox beside every field opens it).
struct DraftPanelModel {
    std::vector<std::string>* open = nullptr;
    std::string* title = nullptr;
    std::string* instructions = nullptr;
    std::string* hints = nullptr;
    std::string problem; // why the draft is not an exercise yet (the first reason), empty when it is
};

// Which fields the panel draws: in an exercise being solved only its open fields (and the always
// free); while one is being made, every field with a checkbox before it that opens it to students;
// both null: every field, no checkbox.
struct FieldGate {
    const ExercisePanelModel* exercise = nullptr;
    DraftPanelModel* draft = nullptr;
    // Whether the field at JSON path `path` gets its widget (drawing the draft's checkbox first).
    bool field(const std::string& path) const;
    // Whether a section holding the fields under these paths shows at all.
    bool any(std::initializer_list<const char*> prefixes) const;
};

void exerciseSection(const ExercisePanelModel& exercise, std::vector<Request>& requests);
// The shipped exercises, a button each ("exercises.<file stem>"): opens it like a file.
void exerciseList(const std::vector<std::filesystem::path>& files, std::vector<Request>& requests);
void draftSection(DraftPanelModel& draft, bool browser, std::string& path, std::vector<Request>& requests);

} // namespace lab::ui
