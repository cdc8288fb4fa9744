// main.cpp — `lab`: parse the arguments (command_line.h), then run the command.
//
//   lab [--preset FILE] [--presenter] [--fullscreen] [--size WxH] [--frame-budget MS] [--theme dark|light]
//                                                      the interactive lab (a PNG preview where there is no display)
//   lab render PRESET... --out PATH [--size WxH]
//   lab render PRESET --sweep KEY=V1,V2,... [--sweep KEY2=...] --out FILE.png [--size WxH (a cell)]
//   lab plot PRESET [--out FILE.csv] [--incident-deg A] [--albedo FILE.csv]
//                   [--figure lobe|overlay|attenuation|albedo --svg FILE --png FILE --scale S --csv FILE
//                    --theme light|dark]
//   lab check PRESET... --golden DIR [--update] [--report DIR] [--size WxH]
//   lab exercise check EXERCISE ATTEMPT [--diff FILE.png]
//   lab share PRESET_OR_EXERCISE --base URL [--qr FILE.png]
//
// Exit status: 0 success, 2 bad input (message on stderr), 1 internal failure or failed check.
#include "cli/command_line.h"
#include "cli/output.h"
#include "cli/settings.h"
#include "platform/window.h"

#include <cstdio>
#include <unistd.h>

namespace {

// The shipped presets, one rule: those installed relative to the program (LAB_INSTALLED_PRESETS,
// cmake/package.cmake: bin/lab -> share/lighting-lab/presets) where that folder exists, else the
// source tree's presets/ this program was built from (a build tree).
std::filesystem::path shippedPresets() {
    std::filesystem::path shipped = LAB_SOURCE_PRESETS;
    char exe[4096];
    ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        exe[n] = '\0';
        std::filesystem::path installed = (std::filesystem::path(exe).parent_path() / LAB_INSTALLED_PRESETS).lexically_normal();
        std::error_code ec;
        if (std::filesystem::is_directory(installed, ec)) {
            shipped = installed;
        }
    }
    return shipped;
}

// The settings as the file holds them now (the defaults where there is none; `warning` says why one
// does not read).
lab::Settings remembered(std::string& warning) {
    const std::optional<std::filesystem::path> file = lab::settingsFile();
    return file ? lab::readSettings(*file, warning) : lab::Settings{};
}

// Writes `settings` to the settings file, or says on stderr why `what` is not remembered.
void remember(const lab::Settings& settings, const std::string& what) {
    std::string error;
    const std::optional<std::filesystem::path> file = lab::settingsFile();
    if (!file) {
        lab::print(stderr, "lab: cannot remember " + what +
                               ": neither XDG_CONFIG_HOME nor HOME is set (it applies to this run only)\n");
    } else if (!lab::writeSettings(settings, *file, error)) {
        lab::print(stderr, "lab: cannot remember " + what + ": " + error + "\n");
    }
}

// The interactive lab on this build's platform (platform/window.h), or a preview without one.
int runInteractive(const lab::CommandLine& line) {
    lab::AppOptions options;
    options.preset = line.preset;
    options.presenter = line.presenter;
    options.screenshotFolder = line.screenshotFolder;
    options.layoutFile = line.layoutFile;
    options.frameBudgetSeconds = line.frameBudgetMs / 1000.0f;
    options.presetFolders.push_back(shippedPresets());
    // The course page's address: --share-base, remembered; else what was remembered.
    std::string warning;
    lab::Settings settings = remembered(warning);
    if (!warning.empty()) {
        lab::print(stderr, "lab: " + warning + "\n");
    }
    if (!line.shareBase.empty() && line.shareBase != settings.shareBase) {
        settings.shareBase = line.shareBase;
        remember(settings, "--share-base");
    }
    options.shareBase = settings.shareBase;
    // The theme: --theme, remembered; else the one remembered; a choice in the panel is remembered too.
    if (line.theme && line.theme != settings.theme) {
        settings.theme = line.theme;
        remember(settings, "--theme");
    }
    options.theme = settings.theme;
    options.shareBaseChosen = [](const std::string& base) {
        std::string ignored;
        lab::Settings kept = remembered(ignored); // as it is now, the theme kept
        kept.shareBase = base;
        remember(kept, "the course page's address");
    };
    options.themeChosen = [](lab::Theme theme) {
        std::string ignored;
        lab::Settings kept = remembered(ignored); // as it is now, share_base kept
        kept.theme = theme;
        remember(kept, "the theme");
    };
    lab::WindowOptions window;
    window.fullscreen = line.fullscreen;
    if (line.windowSize) {
        window.width = line.windowSize->width;
        window.height = line.windowSize->height;
        window.sizeGiven = true;
    }
    std::string error;
    switch (lab::runLab(options, window, error)) {
    case lab::WindowResult::Closed: return lab::kExitOk;
    case lab::WindowResult::Failed:
        lab::print(stderr, "lab: " + error + "\n");
        return lab::kExitFailure;
    case lab::WindowResult::NoDisplay:
        lab::print(stderr, "lab: no window here (no display, or a build without a window platform); rendering a preview instead\n");
        break;
    }
    return lab::runPreview(line.preset);
}

} // namespace

int main(int argc, char** argv) {
    std::variant<lab::CommandLine, int> parsed = lab::parseCommandLine(argc, argv);
    if (const int* status = std::get_if<int>(&parsed)) {
        return *status;
    }
    const lab::CommandLine& line = std::get<lab::CommandLine>(parsed);
    switch (line.command) {
    case lab::CommandLine::Command::Render:
        return line.sweeps.empty() ? lab::runRender(line.presets, line.out, line.size, line.view)
                                   : lab::runSweep(line.presets, line.sweeps, line.out, line.size, line.view);
    case lab::CommandLine::Command::Plot:
        return lab::runPlot(line.presets.front(), line.out, line.incidentDeg, line.albedoOut, line.figure);
    case lab::CommandLine::Command::Check: return lab::runCheck(line.presets, line.check);
    case lab::CommandLine::Command::ExerciseCheck: return lab::runExerciseCheck(line.exercise, line.attempt, line.diffOut);
    case lab::CommandLine::Command::Share: return lab::runShare(line.shared, line.base, line.qrOut, shippedPresets());
    case lab::CommandLine::Command::Fit: return lab::runFit(line.presets.front(), line.fit, line.out);
    case lab::CommandLine::Command::Lab: break;
    }
    return runInteractive(line);
}
