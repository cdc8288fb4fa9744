// web_main.cpp — the browser build's entry point: the lab with the bundled presets.
// (The native entry point, with the command line, is lab/cli/main.cpp.)
#include "platform/window.h"

#include "core/plots/theme.h"

#include <emscripten.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

// What the page knows (index.html), asked without eval: lab.js is minified with its names
// shortened (cmake/web.cmake), and a script run by eval could name none of them.
// clang-format off
EM_JS(char*, labJsSavedTheme, (), {
    const theme = labSavedTheme();
    return theme ? stringToNewUTF8(theme) : 0;
});
EM_JS(void, labJsThemeChosen, (const char* theme), { labThemeChosen(UTF8ToString(theme)); });
EM_JS(int, labJsReducedMotion, (), { return matchMedia("(prefers-reduced-motion: reduce)").matches ? 1 : 0; });
EM_JS(char*, labJsPageAddress, (), { return stringToNewUTF8(location.origin + location.pathname); });
// clang-format on

} // namespace

int main() {
    lab::AppOptions options;
    options.presetFolders = {"/presets"};   // bundled with the page (see CMakeLists.txt)
    options.screenshotFolder = "/screenshots";
    options.saveByDownload = true;
    // The visitor's own theme if they chose one (the panel, or the page's control), else the system's
    // light or dark setting, which the page follows until a choice is made (labFollowTheme, index.html).
    if (char* theme = labJsSavedTheme()) {
        options.theme = lab::themeFrom(theme);
        std::free(theme);
    }
    options.themeChosen = [](lab::Theme theme) { labJsThemeChosen(std::string(lab::toString(theme)).c_str()); };
    // The visitor asked the system for less motion: a moving light opens paused.
    options.reducedMotion = labJsReducedMotion() != 0;
    // The QR code (Q) opens the scene on this very page: its address without the fragment.
    if (char* here = labJsPageAddress()) {
        options.shareBase = here;
        std::free(here);
    }
    std::string error;
    if (lab::runLab(options, lab::WindowOptions{}, error) == lab::WindowResult::Failed) {
        std::fprintf(stderr, "lab: %s\n", error.c_str());
        return 1;
    }
    return 0;
}
