// main.cpp — `lab`: argument parsing and dispatch to the commands.
//
//   lab [--preset FILE]                   the interactive lab (a PNG preview where there is no GUI)
//   lab render PRESET... --out PATH [--size WxH]
//   lab plot PRESET --out FILE.csv [--incident-deg A]
//   lab check PRESET... --golden DIR [--update] [--report DIR] [--size WxH]
//
// Exit status: 0 success, 2 bad input (message on stderr), 1 internal failure or failed check.
#include "cli/commands.h"

#ifdef LAB_GUI
#include "platform/window.h"
#endif

#include <CLI/CLI.hpp>

#include <cstdio>
#include <unistd.h>

#ifndef LAB_VERSION
#define LAB_VERSION "0.0.0"
#endif

namespace {

// CLI11 validator for --size, so a bad size is reported like every other bad flag.
struct SizeValidator : CLI::Validator {
    SizeValidator() {
        name_ = "WxH";
        func_ = [](std::string& text) {
            std::string error;
            return lab::parseSize(text, error) ? std::string{} : error;
        };
    }
};

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lighting Lab: an interactive lab for local illumination (Phong, Blinn-Phong, Cook-Torrance)", "lab"};
    app.set_version_flag("--version", "lab " LAB_VERSION);
    app.require_subcommand(0, 1);
    std::string preset, screenshotDir = ".", layoutFile;
    bool presenter = false, fullscreen = false;
    app.add_option("--preset", preset, "Open the lab with this preset");
    app.add_flag("--presenter", presenter, "Start in presenter mode (large UI for a projector)");
    app.add_flag("--fullscreen", fullscreen, "Start fullscreen");
    app.add_option("--screenshot-dir", screenshotDir, "Folder for screenshots (F12)")->capture_default_str();
    // For GUI tests: the screen rectangles of the main widgets, rewritten when they change.
    app.add_option("--layout-file", layoutFile, "")->group("");

    std::vector<std::string> renderPresets;
    std::string renderOut, renderSize = "512x512";
    CLI::App* render = app.add_subcommand("render", "Render presets headless to PNG (no display or GPU needed)");
    render->add_option("presets", renderPresets, "Preset files")->required();
    render->add_option("--out", renderOut, "The PNG file; a folder when there are several presets")->required();
    render->add_option("--size", renderSize, "Image size")->check(SizeValidator())->capture_default_str();

    std::string plotPreset, plotOut;
    std::optional<float> incident;
    CLI::App* plot = app.add_subcommand("plot", "Write the polar-plot data (reflected intensity) as CSV");
    plot->add_option("preset", plotPreset, "Preset file")->required();
    plot->add_option("--out", plotOut, "CSV file to write")->required();
    plot->add_option("--incident-deg", incident, "Incident angle in degrees (default: the preset's plot.incident_deg)")
        ->check(CLI::Range(-90.0, 90.0));

    std::vector<std::string> checkPresets;
    std::string checkGolden, checkReport = "lab-check", checkSize = "512x512";
    bool update = false;
    lab::Tolerance tolerance;
    CLI::App* check = app.add_subcommand("check", "Render presets and compare them with golden images");
    check->add_option("presets", checkPresets, "Preset files")->required();
    check->add_option("--golden", checkGolden, "Folder of golden PNGs, <preset name>.png")->required();
    check->add_flag("--update", update, "Write goldens from the renders instead of comparing");
    check->add_option("--report", checkReport, "Folder for report.txt and the actual and diff images of failures")
        ->capture_default_str();
    check->add_option("--size", checkSize, "Render size")->check(SizeValidator())->capture_default_str();
    check->add_option("--pixel-tolerance", tolerance.pixelTolerance, "A pixel fails above this channel difference")
        ->check(CLI::Range(0, 255))->capture_default_str();
    check->add_option("--max-failing", tolerance.maxFailingShare, "Largest share of failing pixels (0.001 = 0.1%)")
        ->check(CLI::Range(0.0, 1.0))->capture_default_str();
    check->add_option("--max-mean", tolerance.maxMeanDifference, "Largest mean channel difference, in levels")
        ->check(CLI::Range(0.0, 255.0))->capture_default_str();

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int status = app.exit(e); // prints help/version to stdout, errors to stderr
        return status == 0 ? lab::kExitOk : lab::kExitBadInput;
    }

    auto toPaths = [](const std::vector<std::string>& v) { return std::vector<std::filesystem::path>(v.begin(), v.end()); };
    std::string error;
    if (*render) {
        return lab::runRender(toPaths(renderPresets), renderOut, *lab::parseSize(renderSize, error));
    }
    if (*plot) {
        return lab::runPlot(plotPreset, plotOut, incident);
    }
    if (*check) {
        lab::CheckOptions options{checkGolden, checkReport, update, *lab::parseSize(checkSize, error), tolerance};
        return lab::runCheck(toPaths(checkPresets), options);
    }
    std::optional<std::filesystem::path> presetPath;
    if (!preset.empty()) {
        presetPath = preset;
    }
#ifdef LAB_GUI
    lab::AppOptions options;
    options.preset = presetPath;
    options.presenter = presenter;
    options.screenshotFolder = screenshotDir;
    if (!layoutFile.empty()) {
        options.layoutFile = layoutFile;
    }
    // The preset list: the shipped presets beside the program, else those of the source tree.
    char exe[4096];
    ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        exe[n] = '\0';
        options.presetFolders.push_back(std::filesystem::path(exe).parent_path().parent_path() / "presets");
    }
    options.presetFolders.push_back(LAB_SOURCE_PRESETS);
    lab::App lab(std::move(options));
    lab::WindowOptions window;
    window.fullscreen = fullscreen;
    switch (lab::runWindow(lab, window, error)) {
    case lab::WindowResult::Closed: return lab::kExitOk;
    case lab::WindowResult::Failed:
        std::fprintf(stderr, "lab: %s\n", error.c_str());
        return lab::kExitFailure;
    case lab::WindowResult::NoDisplay:
        std::fprintf(stderr, "lab: no display (DISPLAY and WAYLAND_DISPLAY are unset); rendering a preview instead\n");
        break;
    }
#else
    (void)presenter;
    (void)fullscreen;
#endif
    return lab::runPreview(presetPath);
}
