// command_line.cpp — the CLI11 definition of `lab`'s arguments.
#include "cli/command_line.h"

#include "cli/output.h"
#include "core/limits.h"

#include <CLI/CLI.hpp>

#include <sstream>

#ifndef LAB_VERSION
#define LAB_VERSION "0.0.0"
#endif

namespace lab {

namespace {

// An empty path is no path: `--out ""` is refused naming the option, not later as "cannot replace :".
const CLI::Validator kNotEmpty(
    [](std::string& text) { return text.empty() ? std::string("must not be empty") : std::string(); }, "PATH");


// CLI11 validator for --size, so a bad size is reported like every other bad flag.
struct SizeValidator : CLI::Validator {
    SizeValidator() {
        name_ = "WxH";
        func_ = [](std::string& text) {
            std::string error;
            return parseSize(text, error) ? std::string{} : error;
        };
    }
};

std::vector<std::filesystem::path> toPaths(const std::vector<std::string>& v) { return {v.begin(), v.end()}; }

// `check`'s arguments as text, until they are parsed into the CommandLine.
struct CheckArguments {
    std::vector<std::string> presets;
    std::string golden, report = "lab-check", size = "512x512";
};

CLI::App* addCheckCommand(CLI::App& app, CommandLine& line, CheckArguments& a) {
    CLI::App* check = app.add_subcommand("check", "Render presets and compare them with golden images");
    check->add_option("presets", a.presets, "Preset files")->required();
    check->add_option("--golden", a.golden, "Folder of golden PNGs, <preset name>.png")->required()->check(kNotEmpty);
    check->add_flag("--update", line.check.update, "Write goldens from the renders instead of comparing");
    check->add_option("--report", a.report, "Folder for report.txt and the actual and diff images of failures")
        ->capture_default_str()
        ->check(kNotEmpty);
    check->add_option("--size", a.size, "Render size")->check(SizeValidator())->capture_default_str();
    check->add_option("--pixel-tolerance", line.check.tolerance.pixelTolerance, "A pixel fails above this channel difference")
        ->check(CLI::Range(0, 255))->capture_default_str();
    check->add_option("--max-failing", line.check.tolerance.maxFailingShare, "Largest share of failing pixels (0.001 = 0.1%)")
        ->check(CLI::Range(0.0, 1.0))->capture_default_str();
    check->add_option("--max-mean", line.check.tolerance.maxMeanDifference, "Largest mean channel difference, in levels")
        ->check(CLI::Range(0.0, 255.0))->capture_default_str();
    return check;
}

} // namespace

std::variant<CommandLine, int> parseCommandLine(int argc, const char* const* argv) {
    CLI::App app{"Lighting Lab: an interactive lab for local illumination (Phong, Blinn-Phong, Cook-Torrance)", "lab"};
    app.set_version_flag("--version", "lab " LAB_VERSION);
    app.require_subcommand(0, 1);
    CommandLine line;
    std::string preset, layoutFile, screenshotFolder = ".", windowSize;
    app.add_option("--preset", preset, "Open the lab with this preset");
    app.add_flag("--presenter", line.presenter, "Start in presenter mode (large UI for a projector)");
    app.add_flag("--fullscreen", line.fullscreen, "Start fullscreen");
    app.add_option("--size", windowSize, "Window size (default: 1600x900, or the screen's work area if smaller)")
        ->check(SizeValidator());
    app.add_option("--screenshot-dir", screenshotFolder, "Folder for screenshots (F12)")->capture_default_str();
    app.add_option("--frame-budget", line.frameBudgetMs,
                   "While dragging, draw the 3D view at a lower resolution when a frame takes longer than this "
                   "many milliseconds (0: always full resolution)")
        ->check(CLI::Range(0.0f, 1000.0f))
        ->capture_default_str();
    // For GUI tests: the screen rectangles of the main widgets, rewritten every frame.
    app.add_option("--layout-file", layoutFile, "")->group("");

    std::vector<std::string> renderPresets;
    std::string renderOut, renderSize = "512x512";
    CLI::App* render = app.add_subcommand("render", "Render presets headless to PNG (no display or GPU needed)");
    render->add_option("presets", renderPresets, "Preset files")->required();
    render->add_option("--out", renderOut, "The PNG file; a folder when there are several presets")->required()->check(kNotEmpty);
    render->add_option("--size", renderSize, "Image size")->check(SizeValidator())->capture_default_str();

    std::string plotPreset, plotOut;
    std::string albedoOut;
    CLI::App* plot = app.add_subcommand("plot", "Write the polar-plot data (reflected intensity) and the albedo as CSV");
    plot->add_option("preset", plotPreset, "Preset file")->required();
    plot->add_option("--out", plotOut, "CSV file to write the polar-plot data to")->check(kNotEmpty);
    plot->add_option("--albedo", albedoOut, "CSV file to write the albedo of each term against the incident angle to")
        ->check(kNotEmpty);
    plot->add_option("--incident-deg", line.incidentDeg, "Incident angle in degrees (default: the preset's plot.incident_deg)")
        ->check(CLI::Range(limits::kPlotIncidentDeg.min, limits::kPlotIncidentDeg.max));

    CheckArguments checkArguments;
    CLI::App* check = addCheckCommand(app, line, checkArguments);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // Help and version to stdout, errors to stderr; CLI11 echoes the arguments, so escaped.
        std::ostringstream out, err;
        int status = app.exit(e, out, err);
        print(stdout, out.str());
        print(stderr, err.str());
        return status == 0 ? kExitOk : kExitBadInput;
    }

    std::string error;
    if (!preset.empty()) {
        line.preset = preset;
    }
    if (!layoutFile.empty()) {
        line.layoutFile = layoutFile;
    }
    line.screenshotFolder = screenshotFolder;
    if (!windowSize.empty()) {
        line.windowSize = *parseSize(windowSize, error); // validated by SizeValidator
    }
    if (*render) {
        line.command = CommandLine::Command::Render;
        line.presets = toPaths(renderPresets);
        line.out = renderOut;
        line.size = *parseSize(renderSize, error); // validated by SizeValidator
    } else if (*plot) {
        line.command = CommandLine::Command::Plot;
        line.presets = {plotPreset};
        line.out = plotOut;
        if (!albedoOut.empty()) {
            line.albedoOut = albedoOut;
        }
        if (plotOut.empty() && albedoOut.empty()) {
            print(stderr, "lab plot: nothing to write: give --out FILE.csv (the polar plot), --albedo FILE.csv (the albedo) or both\n");
            return kExitBadInput;
        }
    } else if (*check) {
        line.command = CommandLine::Command::Check;
        line.presets = toPaths(checkArguments.presets);
        line.check.golden = checkArguments.golden;
        line.check.report = checkArguments.report;
        line.check.size = *parseSize(checkArguments.size, error);
    }
    return line;
}

} // namespace lab
