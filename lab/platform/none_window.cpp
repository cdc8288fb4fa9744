// none_window.cpp — the platform without an interactive lab (LAB_PLATFORM=none): builds with no
// window system, no ImGui, for the command line and the fuzzers. `lab` then renders a preview.
#include "platform/window.h"

namespace lab {

WindowResult runLab(const AppOptions&, const WindowOptions&, std::string&) { return WindowResult::NoDisplay; }

} // namespace lab
