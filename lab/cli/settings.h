// settings.h — the desktop lab's small settings file: $XDG_CONFIG_HOME/lighting-lab/settings.json
// (else ~/.config/lighting-lab/settings.json; with neither variable set there is none, and nothing
// is remembered). It holds what a course sets once: the course page's address for the QR codes
// (`lab --share-base URL`, remembered) and the theme (`--theme`, or the one last chosen in the
// panel); a setting never given is not written. Written atomically, through a symbolic link (a
// dotfiles folder's file stays where it is); a file that does not read is reported and ignored,
// never overwritten unasked.
#pragma once

#include "core/plots/theme.h"
#include "core/share/share_link.h" // shareBaseProblem, which the settings check

#include <filesystem>
#include <optional>
#include <string>

namespace lab {

struct Settings {
    std::string shareBase; // "https://course.example.org/lab/", empty when never given
    std::optional<Theme> theme; // "theme": "dark" or "light"; none when never chosen
};

// The settings file, or nullopt when neither XDG_CONFIG_HOME (absolute) nor HOME is set.
std::optional<std::filesystem::path> settingsFile();

// The settings, or the defaults (with `warning` saying why, when the file exists but does not read).
// An empty share_base, as earlier versions wrote for "never given", reads as never given.
Settings readSettings(const std::filesystem::path& file, std::string& warning);
bool writeSettings(const Settings& settings, const std::filesystem::path& file, std::string& error);


} // namespace lab
