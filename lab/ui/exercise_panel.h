// exercise_panel.h — the control panel's exercise parts (ui/panel.cpp calls them).
//
// An exercise being solved shows only its open fields (core/exercise/preset_fields.h paths; the
// widgets are named by the same paths) and a section with its instructions, score, hints, start
// again and leave; while an exercise is being made, a checkbox before every field opens it.
#pragma once

#include "ui/actions.h"
#include "ui/panel.h"

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace lab::ui {

// For the panel drawn next: the exercise being solved (only its open fields show), or the draft
// being made (a checkbox before every field); both null: every field, no checkbox.
void setFieldGate(const ExerciseView* exercise, ExerciseDraftView* draft);

// Whether the field at JSON path `path` gets its widget (drawing the draft's checkbox first).
bool field(const std::string& path);
// Whether a section holding the fields under these paths shows at all.
bool anyField(std::initializer_list<const char*> prefixes);

void exerciseSection(const ExerciseView& exercise, std::vector<Request>& requests);
// The shipped exercises, a button each ("exercises.<file stem>"): opens it like a file.
void exerciseList(const std::vector<std::filesystem::path>& files, std::vector<Request>& requests);
void draftSection(ExerciseDraftView& draft, bool browser, std::string& path, std::vector<Request>& requests);

} // namespace lab::ui
