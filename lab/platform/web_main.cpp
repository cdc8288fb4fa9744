// web_main.cpp — the browser build's entry point: the lab with the bundled presets.
// (The native entry point, with the command line, is lab/cli/main.cpp.)
#include "platform/window.h"

#include "core/plots/theme.h"

#include <emscripten.h>

#include <cstdio>
#include <cstdlib>
#include <string>

int main() {
    lab::AppOptions options;
    options.presetFolders = {"/presets"};   // bundled with the page (see CMakeLists.txt)
    options.screenshotFolder = "/screenshots";
    options.saveByDownload = true;
    // The visitor's own theme if they chose one (the panel, or the page's control), else the system's
    // light or dark setting, which the page follows until a choice is made (labFollowTheme, index.html).
    if (char* theme = emscripten_run_script_string("labSavedTheme()")) {
        options.theme = lab::themeFrom(theme);
    }
    options.themeChosen = [](lab::Theme theme) {
        std::string script = "labThemeChosen('" + std::string(lab::toString(theme)) + "')";
        emscripten_run_script(script.c_str());
    };
    // The visitor asked the system for less motion: a moving light opens paused.
    options.reducedMotion = emscripten_run_script_int("matchMedia('(prefers-reduced-motion: reduce)').matches ? 1 : 0") != 0;
    // The QR code (Q) opens the scene on this very page: its address without the fragment.
    if (char* here = emscripten_run_script_string("location.origin + location.pathname")) {
        options.shareBase = here;
    }
    std::string error;
    if (lab::runLab(options, lab::WindowOptions{}, error) == lab::WindowResult::Failed) {
        std::fprintf(stderr, "lab: %s\n", error.c_str());
        return 1;
    }
    return 0;
}
