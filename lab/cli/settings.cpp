// settings.cpp — the settings file, read and written.
#include "cli/settings.h"

#include "core/io/file_io.h"
#include "core/io/safe_text.h"

#include <nlohmann/json.hpp>

#include <cstdlib>

namespace lab {

namespace fs = std::filesystem;

fs::path settingsFile() {
    const char* config = std::getenv("XDG_CONFIG_HOME");
    if (config && *config && fs::path(config).is_absolute()) {
        return fs::path(config) / "lighting-lab" / "settings.json";
    }
    const char* home = std::getenv("HOME");
    if (home && *home) {
        return fs::path(home) / ".config" / "lighting-lab" / "settings.json";
    }
    return fs::path("lighting-lab-settings.json");
}

std::string shareBaseProblem(const std::string& url) {
    if (!(url.starts_with("https://") || url.starts_with("http://")) || url.size() > 2000 ||
        url.find_first_of(" \t\r\n\"<>") != std::string::npos) {
        return "expected the course page's address, e.g. https://course.example.org/lab/, got " + inQuotes(url);
    }
    return {};
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
        if (!base->is_string() || !shareBaseProblem(base->get<std::string>()).empty()) {
            warning = file.string() + ": share_base: " +
                      (base->is_string() ? shareBaseProblem(base->get<std::string>()) : std::string("expected a string")) +
                      " (ignored)";
        } else {
            s.shareBase = base->get<std::string>();
        }
    }
    return s;
}

bool writeSettings(const Settings& settings, const fs::path& file, std::string& error) {
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    nlohmann::json j = {{"share_base", settings.shareBase}};
    return writeFileAtomic(file, j.dump(2) + "\n", error);
}

} // namespace lab
