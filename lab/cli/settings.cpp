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

std::string shareBaseProblem(const std::string& url) {
    // What the teacher reads is what the phone opens: printable ASCII only, nothing encoded on the
    // quiet (a raw ESC was printed escaped but put into the QR code as the byte itself).
    const std::string expected = "expected the course page's address, e.g. https://course.example.org/lab/";
    if (url.size() > 2000) {
        return expected + ", got " + std::to_string(url.size()) + " characters (at most 2000)";
    }
    for (std::size_t i = 0; i < url.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(url[i]);
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02X", c);
        if (c < 0x21 || c > 0x7E) {
            return "byte " + std::string(hex) + " at offset " + std::to_string(i) +
                   " is not allowed: an address is printable ASCII (0x21 to 0x7E); percent-encode it where it "
                   "belongs (%20 for a space)";
        }
        if (std::string_view("\"<>\\^`{|}").find(static_cast<char>(c)) != std::string_view::npos) {
            return "'" + std::string(1, static_cast<char>(c)) + "' (" + hex + ") at offset " + std::to_string(i) +
                   " is not allowed in an address; percent-encode it where it belongs";
        }
    }
    std::string lower = url.substr(0, 8);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const std::size_t schemeEnd = lower.starts_with("https://") ? 8 : lower.starts_with("http://") ? 7 : 0;
    if (schemeEnd == 0) {
        return expected + ", got " + inQuotes(url);
    }
    const std::string authority = url.substr(schemeEnd, url.find_first_of("/?#", schemeEnd) - schemeEnd);
    if (authority.find('@') != std::string::npos) {
        return "a user name in the address (before '@') is not allowed: it hides the host a student's phone opens";
    }
    std::size_t hostEnd = authority.starts_with("[") ? authority.find(']') + 1 : authority.find(':');
    if (hostEnd == 0) { // "[" without "]"
        return expected + ", got " + inQuotes(url) + ": '[' without ']'";
    }
    const std::string host = authority.substr(0, hostEnd), port = hostEnd < authority.size() ? authority.substr(hostEnd) : "";
    if (host.empty()) {
        return "no host after \"" + url.substr(0, schemeEnd) + "\": " + expected;
    }
    if (!port.empty() && (port.size() < 2 || port[0] != ':' ||
                          !std::all_of(port.begin() + 1, port.end(), [](unsigned char c) { return std::isdigit(c); }))) {
        return "the port " + inQuotes(port) + " is not a number: " + expected;
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
