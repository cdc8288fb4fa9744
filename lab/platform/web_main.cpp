// web_main.cpp — the browser build's entry point: the lab with the bundled presets.
// (The native entry point, with the command line, is lab/cli/main.cpp.)
#include "platform/window.h"

#include <emscripten.h>

#include <cstdio>
#include <cstdlib>

int main() {
    lab::AppOptions options;
    options.presetFolders = {"/presets"};   // bundled with the page (see CMakeLists.txt)
    options.screenshotFolder = "/screenshots";
    options.saveByDownload = true;
    options.describePage = true; // the page's parallel DOM (web/access.js)
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
