// check_plan.h — what `lab check` will compare and write, known before it renders anything.
//
// Each preset's cases with their goldens, in the golden folder and named after the preset's file:
// <name>.png (its render), <name>.<view>.png (<name>.<view>.light<N>.png: a view its `check`
// block lists), <name>.sweep.png (the grid of its `sweep`, compared cell by cell) and
// <name>.plot.csv (its lobe CSV, with --plots or where that golden exists); and the files a
// failing case leaves in the report folder (<case>.golden.png, .actual.png, .diff.png; a sweep
// cell's as <name>.sweep.r<row>c<column>.*; a plot's <name>.plot.actual.csv, .golden.csv).
//
// From the plan, checkRunIsSafe() refuses a run before anything is written (check.cpp then exits
// with status 2): a golden folder or report folder that cannot be used; two presets whose goldens
// share a name (x.json's view d and a preset x.d.json both mean x.d.png), which --update would
// write twice; and an output (--junit, --html, the report's files, the goldens --update writes)
// that is one of the run's inputs — a preset, its model, a golden (cli/run_files.h).
#pragma once

#include "cli/check_report.h"
#include "cli/commands.h"
#include "core/scene/preset.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lab {

struct PlannedCase {
    CheckCase::Kind kind = CheckCase::Kind::Render;
    std::string name;             // "p", "p.d", "p.spot.light2", "p.sweep", "p.plot"
    std::filesystem::path golden; // in the golden folder
    int view = -1;                // the index in check.views of a view's render
};

struct PresetPlan {
    std::filesystem::path file;
    const LoadedPreset* loaded = nullptr; // nullptr when it does not load (an ERROR case)
    std::vector<PlannedCase> cases;
};

// The name a sweep cell's failure files start with: "<name>.sweep.r<row>c<column>".
std::string sweepCellFiles(const std::string& whole, int row, int column);

// The cases of each preset (`loaded[i]` is files[i] loaded, or nullopt).
std::vector<PresetPlan> planCheck(const std::vector<std::filesystem::path>& files,
                                  const std::vector<std::optional<LoadedPreset>>& loaded, const CheckOptions& options);

// False, with the message printed ("lab check: ..."), when the run cannot go ahead as planned
// (above). Writes nothing; the folders are made by makeCheckFolders() after.
bool checkRunIsSafe(const std::vector<PresetPlan>& plans, const CheckOptions& options);

// Makes the folder the run writes to (the report folder; the golden folder with --update);
// false, with the message printed, when it cannot be made or written in.
bool makeCheckFolders(const CheckOptions& options);

} // namespace lab
