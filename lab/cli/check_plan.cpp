// check_plan.cpp — lab check's cases, goldens and report files, and the checks made of them
// before anything is written.
#include "cli/check_plan.h"

#include "cli/command_kit.h"
#include "cli/output.h"
#include "cli/run_files.h"
#include "core/scene/sweep.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>

namespace lab {

namespace fs = std::filesystem;

std::string sweepCellFiles(const std::string& whole, int row, int column) {
    return whole + ".r" + std::to_string(row) + "c" + std::to_string(column);
}

std::vector<PresetPlan> planCheck(const std::vector<fs::path>& files, const std::vector<std::optional<LoadedPreset>>& loaded,
                                  const CheckOptions& options) {
    std::vector<PresetPlan> plans;
    for (std::size_t i = 0; i < files.size(); ++i) {
        PresetPlan plan{files[i], loaded[i] ? &*loaded[i] : nullptr, {}};
        const std::string stem = files[i].stem().string();
        auto add = [&](CheckCase::Kind kind, std::string name, std::string golden, int view = -1) {
            plan.cases.push_back({kind, std::move(name), options.golden / golden, view});
        };
        add(CheckCase::Kind::Render, stem, stem + ".png");
        if (plan.loaded) {
            const CheckSettings& check = plan.loaded->preset.check;
            for (std::size_t v = 0; v < check.views.size(); ++v) {
                const CheckView& view = check.views[v];
                std::string name = stem + "." + view.view + (view.light == 1 ? "" : ".light" + std::to_string(view.light));
                add(CheckCase::Kind::Render, name, name + ".png", static_cast<int>(v));
            }
            if (!plan.loaded->preset.sweep.empty()) {
                add(CheckCase::Kind::SweepCell, stem + ".sweep", stem + ".sweep.png");
            }
            std::error_code ec;
            if (options.plots || fs::exists(options.golden / (stem + ".plot.csv"), ec)) {
                add(CheckCase::Kind::Plot, stem + ".plot", stem + ".plot.csv");
            }
        }
        plans.push_back(std::move(plan));
    }
    return plans;
}

namespace {

// The files a failing case may leave in the report folder (check.cpp's Checker writes these names).
std::vector<std::string> reportFiles(const PresetPlan& plan, const PlannedCase& c) {
    if (c.kind == CheckCase::Kind::Plot) {
        return {c.name + ".actual.csv", c.name + ".golden.csv"};
    }
    std::vector<std::string> stems{c.name};
    if (c.kind == CheckCase::Kind::SweepCell) {
        std::vector<std::size_t> counts;
        for (const std::string& text : plan.loaded->preset.sweep) {
            std::string error;
            std::optional<SweepAxis> axis = parseSweepAxis(text, error); // checked when the preset was read
            counts.push_back(axis ? axis->values.size() : 0);
        }
        for (std::size_t row = 0; row < (counts.size() > 1 ? counts[1] : 1); ++row) {
            for (std::size_t column = 0; column < (counts.empty() ? 0 : counts[0]); ++column) {
                stems.push_back(sweepCellFiles(c.name, static_cast<int>(row), static_cast<int>(column)));
            }
        }
    }
    std::vector<std::string> files;
    for (const std::string& s : stems) {
        for (const char* end : {".golden.png", ".actual.png", ".diff.png"}) {
            files.push_back(s + end);
        }
    }
    return files;
}

// Goldens are named after the preset's file: two presets of one name in a run would share theirs,
// a preset named like another's sweep or plot golden (x.sweep.json) would share that, and so would
// a view's (x.json's view d and a preset x.d.json: x.d.png).
bool goldensDistinct(const std::vector<PresetPlan>& plans) {
    std::map<std::string, const PresetPlan*> owner;
    for (const PresetPlan& plan : plans) {
        std::string stem = plan.file.stem().string();
        std::string last = fs::path(stem).extension().string();
        if (last == ".sweep" || last == ".plot") {
            print(stderr, "lab check: %s: a preset named *%s.json would share its golden with another preset's %s golden; rename it\n",
                  plan.file.string().c_str(), last.c_str(), last.c_str() + 1);
            return false;
        }
        for (const PlannedCase& c : plan.cases) {
            auto [it, fresh] = owner.emplace(c.golden.filename().string(), &plan);
            if (!fresh && it->second != &plan && !sameFile(it->second->file, plan.file)) {
                print(stderr, "lab check: %s and %s would both be checked against %s\n", it->second->file.string().c_str(),
                      plan.file.string().c_str(), c.golden.filename().string().c_str());
                return false;
            }
        }
    }
    return true;
}

// A folder the run writes in (made later, when missing): it must not be a file, and must be
// writable where it exists. `flag` names it.
bool folderUsable(const char* flag, const fs::path& folder) {
    std::error_code ec;
    if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
        print(stderr, "lab check: %s %s: cannot be used as a folder (it is a file)\n", flag, folder.string().c_str());
        return false;
    }
    if (fs::is_directory(folder, ec) && ::access(folder.c_str(), W_OK) != 0) {
        print(stderr, "lab check: %s %s: cannot write in it: %s\n", flag, folder.string().c_str(), std::strerror(errno));
        return false;
    }
    return true;
}

// Every file the run reads and writes (cli/run_files.h).
RunFiles runFiles(const std::vector<PresetPlan>& plans, const CheckOptions& options) {
    RunFiles files;
    const bool toReport = !options.update;
    if (toReport) {
        files.output(options.report / "report.txt", "--report", true);
        files.output(options.report / "index.html", "--report", true);
    }
    std::error_code ec;
    for (auto [flag, file] : {std::pair{"--junit", options.junit}, std::pair{"--html", options.html}}) {
        if (file) {
            fs::path parent = file->parent_path().empty() ? fs::path(".") : file->parent_path();
            bool inReport = toReport && !fs::exists(options.report, ec) && sameFile(parent, options.report);
            files.output(*file, flag, inReport); // (a report folder still to be made: checked as one)
        }
    }
    for (std::size_t i = 0; i < plans.size(); ++i) {
        const PresetPlan& plan = plans[i];
        bool again = false; // the same preset named twice is checked twice, into the same files
        for (std::size_t j = 0; j < i && !again; ++j) {
            again = sameFile(plans[j].file, plan.file);
        }
        if (again) {
            continue;
        }
        if (plan.loaded) {
            addPresetInputs(files, *plan.loaded);
        } else {
            files.input(plan.file, "the preset " + plan.file.string());
        }
        for (const PlannedCase& c : plan.cases) {
            files.input(c.golden, "the golden " + c.golden.string());
            if (options.update) {
                files.replacing(c.golden, "--update", true);
            } else if (plan.loaded) {
                for (const std::string& name : reportFiles(plan, c)) {
                    files.output(options.report / name, "--report", true);
                }
            }
        }
    }
    return files;
}

} // namespace

bool checkRunIsSafe(const std::vector<PresetPlan>& plans, const CheckOptions& options) {
    std::error_code ec;
    if (!options.update && !fs::is_directory(options.golden, ec)) {
        print(stderr, "lab check: --golden %s: no such folder\n", options.golden.string().c_str());
        return false;
    }
    if (!(options.update ? folderUsable("--golden", options.golden) : folderUsable("--report", options.report))) {
        return false;
    }
    if (!goldensDistinct(plans)) {
        return false;
    }
    if (std::string problem = runFiles(plans, options).problem(); !problem.empty()) {
        print(stderr, "lab check: " + problem + " (nothing was written)\n");
        return false;
    }
    return true;
}

bool makeCheckFolders(const CheckOptions& options) {
    const char* flag = options.update ? "--golden" : "--report";
    const fs::path& folder = options.update ? options.golden : options.report;
    std::error_code ec, isFolder; // (the throwing forms would end the program on a name too long)
    fs::create_directories(folder, ec);
    if (!fs::is_directory(folder, isFolder)) {
        print(stderr, "lab check: %s %s: cannot be used as a folder (%s)\n", flag, folder.string().c_str(),
              ec ? ec.message().c_str() : "it is a file");
        return false;
    }
    return folderUsable(flag, folder);
}

} // namespace lab
