// command_line.h — `lab`'s arguments, parsed (CLI11) but not acted on.
//
// main.cpp dispatches what this returns; the command-line fuzzer (tests/fuzz) calls it with
// arbitrary arguments. Parsing never touches files beyond what CLI11 itself checks.
#pragma once

#include "cli/commands.h"
#include "core/scene/sweep.h"

#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace lab {

struct CommandLine {
    enum class Command { Lab, Render, Plot, Check, ExerciseCheck, Share, Fit } command = Command::Lab;
    // lab (the interactive lab)
    std::optional<std::filesystem::path> preset;
    bool presenter = false, fullscreen = false;
    float frameBudgetMs = 50.0f; // --frame-budget (app/viewport_cache.h)
    std::optional<Size> windowSize; // --size: else fitted to the screen
    std::filesystem::path screenshotFolder = ".";
    std::optional<std::filesystem::path> layoutFile;
    std::string shareBase; // --share-base (remembered in the settings file, cli/settings.h)
    std::optional<Theme> theme; // --theme (remembered likewise)
    // render, plot, check
    std::vector<std::filesystem::path> presets;
    std::filesystem::path out;
    Size size;
    std::optional<float> incidentDeg;
    std::optional<std::filesystem::path> albedoOut; // plot --albedo
    FigureOutputs figure;                           // plot --figure, --svg, --png, --csv
    std::vector<SweepAxis> sweeps;                  // render --sweep (core/scene/sweep.h), columns then rows
    RenderView view;                                // render --view, --light, --palette, --range, --legend
    CheckOptions check;
    // exercise check EXERCISE ATTEMPT [--diff FILE.png]
    std::filesystem::path exercise, attempt;
    std::optional<std::filesystem::path> diffOut;
    // share FILE --base URL [--qr FILE.png]
    std::filesystem::path shared;
    std::string base; // share --base
    std::optional<std::filesystem::path> qrOut;
    // fit PRESET --brdf MODEL [--distribution D] --out FITTED.json (presets.front(), out)
    FitRequest fit;
};

// The parsed command line, or the exit status when parsing ends the program: 0 after --help or
// --version (printed), 2 after a bad argument (the message on stderr).
std::variant<CommandLine, int> parseCommandLine(int argc, const char* const* argv);

} // namespace lab
