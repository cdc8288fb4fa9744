// settings.cpp — the settings file, read and written.
#include "cli/settings.h"

#include "core/io/file_io.h"
#include "core/io/safe_text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace lab {

namespace fs = std::filesystem;

std::optional<fs::path> settingsFile() {
    const char* config = std::getenv("XDG_CONFIG_HOME");
    if (config && *config && fs::path(config).is_absolute()) {
        return fs::path(config) / "lighting-lab" / "settings.json";
    }
    const char* home = std::getenv("HOME");
    if (home && *home) {
        return fs::path(home) / ".config" / "lighting-lab" / "settings.json";
    }
    return std::nullopt; // (not the working folder: nobody looks for a settings file there)
}

Settings readSettings(const fs::path& file, std::string& warning) {
    Settings s;
    std::error_code ec;
    if (!fs::exists(file, ec)) {
        return s;
    }
    std::string error;
    std::optional<std::string> text = readFile(file, 64 * 1024, error);
    if (!text) {
        warning = file.string() + ": " + error + " (ignored)";
        return s;
    }
    nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        warning = file.string() + ": not a JSON object (ignored)";
        return s;
    }
    if (auto base = j.find("share_base"); base != j.end()) {
        if (base->is_string() && base->get<std::string>().empty()) {
            // never given (written so before issue 49)
        } else if (!base->is_string() || !shareBaseProblem(base->get<std::string>()).empty()) {
            warning = file.string() + ": share_base: " +
                      (base->is_string() ? shareBaseProblem(base->get<std::string>()) : std::string("expected a string")) +
                      " (ignored)";
        } else {
            s.shareBase = base->get<std::string>();
        }
    }
    if (auto theme = j.find("theme"); theme != j.end()) {
        if (std::optional<Theme> t = theme->is_string() ? themeFrom(theme->get<std::string>()) : std::nullopt) {
            s.theme = t;
        } else {
            warning += (warning.empty() ? "" : "; ") + file.string() + ": theme: expected one of " + themeNames() + " (ignored)";
        }
    }
    return s;
}

bool writeSettings(const Settings& settings, const fs::path& file, std::string& error) {
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    nlohmann::json j = nlohmann::json::object();
    if (!settings.shareBase.empty()) {
        j["share_base"] = settings.shareBase;
    }
    if (settings.theme) {
        j["theme"] = std::string(toString(*settings.theme));
    }
    return writeFileAtomic(file, j.dump(2) + "\n", error);
}

} // namespace lab
