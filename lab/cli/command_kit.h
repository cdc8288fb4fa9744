// command_kit.h — what the headless commands share (commands.cpp, check.cpp): the GL context and
// renderer they draw with, presets loaded with their messages on stderr, and the one way a
// preset's sweep grid is rendered (`lab render --sweep` and `lab check`).
#pragma once

#include "cli/commands.h"
#include "cli/run_files.h"
#include "core/io/diagnostics.h"
#include "core/scene/sweep.h"
#include "platform/headless_gl.h"
#include "render/offscreen.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lab {

struct Gpu {
    HeadlessGl gl;
    OffscreenRenderer renderer;

    // Makes the context and compiles the shaders; false after a message on stderr.
    bool start();
};

// Every diagnostic, one a line, on stderr.
void printDiagnostics(const Diagnostics& diagnostics);

// Loads every preset, printing all problems; nullopt entries for those that failed (and then
// `anyBad`, when given, is set).
std::vector<std::optional<LoadedPreset>> loadAll(const std::vector<std::filesystem::path>& files,
                                                 bool* anyBad = nullptr);

// A preset's file and the glTF model it names, as inputs of a run (cli/run_files.h); `what` names
// the file ("the preset", "the attempt").
void addPresetInputs(RunFiles& files, const LoadedPreset& preset, const std::string& what = "the preset");
// The glTF model `scene` names (none for a built-in), relative to `folder`, read for `owner`.
void addModelInput(RunFiles& files, const Preset& scene, const std::filesystem::path& folder,
                   const std::filesystem::path& owner);

// False, with "COMMAND: <the problem> (nothing was written)" on stderr, when the run's files may not
// be written as asked (RunFiles::problem()); true when they may.
bool filesUsable(const RunFiles& files, const char* command);

// A glTF preset without a camera or lights in its file framed, as `lab render` frames it for cells
// of any shape (core/gltf/model_loader.h frameOmitted); false when its model does not load.
bool frameForCells(LoadedPreset& preset, Diagnostics& diagnostics);

// `preset` (framed: frameForCells) swept along `axes` as one labelled grid of `cell`-sized
// renders (core/scene/sweep.h). Nullopt with a one-line `error`: `renderFailed` tells a render that
// failed (an internal failure) from a key or value the preset refuses (bad input). Each cell is
// drawn as `view` says (the lit model by default).
std::optional<Image> renderSweepGrid(Gpu& gpu, const LoadedPreset& preset, const std::vector<SweepAxis>& axes,
                                     Size cell, std::string& error, bool& renderFailed, const ViewportDraw& view = {});

} // namespace lab
