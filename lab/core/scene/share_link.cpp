// share_link.cpp — preset links: base64url of minified JSON, validated like a file.
#include "core/scene/share_link.h"

#include "core/io/safe_text.h"

#include <nlohmann/json.hpp>

namespace lab {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
constexpr std::size_t kMaxLinkBytes = 64 * 1024;

int decodeChar(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '-') return 62;
    if (c == '_') return 63;
    return -1;
}

} // namespace

std::string base64UrlEncode(std::string_view bytes) {
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 | (unsigned char)bytes[i + 2];
        out += kAlphabet[v >> 18];
        out += kAlphabet[(v >> 12) & 63];
        out += kAlphabet[(v >> 6) & 63];
        out += kAlphabet[v & 63];
    }
    if (i + 1 == bytes.size()) {
        unsigned v = (unsigned char)bytes[i] << 16;
        out += kAlphabet[v >> 18];
        out += kAlphabet[(v >> 12) & 63];
    } else if (i + 2 == bytes.size()) {
        unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8;
        out += kAlphabet[v >> 18];
        out += kAlphabet[(v >> 12) & 63];
        out += kAlphabet[(v >> 6) & 63];
    }
    return out;
}

std::optional<std::string> base64UrlDecode(std::string_view text) {
    while (!text.empty() && text.back() == '=') {
        text.remove_suffix(1);
    }
    if (text.size() % 4 == 1) {
        return std::nullopt;
    }
    std::string out;
    out.reserve(text.size() * 3 / 4);
    unsigned buffer = 0;
    int bits = 0;
    for (char c : text) {
        int v = decodeChar(c);
        if (v < 0) {
            return std::nullopt;
        }
        buffer = (buffer << 6) | unsigned(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += static_cast<char>((buffer >> bits) & 0xFF);
        }
    }
    return out;
}

std::string presetLink(const Preset& preset, const std::optional<std::string>& bundledName) {
    if (bundledName) {
        return "preset=" + *bundledName;
    }
    // The saved form, minified: every key, so the link does not depend on future defaults.
    // Parsed from a string_view, as preset_read.cpp parses: one parser in the page, not two.
    const std::string saved = presetToJson(preset);
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(std::string_view(saved));
    return "p=" + base64UrlEncode(j.dump());
}

std::optional<std::variant<LinkedPresetName, Preset>> parseLink(std::string_view fragment,
                                                                const std::filesystem::path& folder,
                                                                Diagnostics& diagnostics, OmittedKeys* omitted) {
    if (!fragment.empty() && fragment.front() == '#') {
        fragment.remove_prefix(1);
    }
    const std::string file = "link";
    if (fragment.size() > kMaxLinkBytes) {
        diagnostics.push_back({file, "", "longer than " + std::to_string(kMaxLinkBytes) + " characters"});
        return std::nullopt;
    }
    if (fragment.rfind("preset=", 0) == 0) {
        std::string name(fragment.substr(7));
        bool ok = !name.empty() && name.size() <= 128;
        for (char c : name) {
            ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.');
        }
        if (!ok || name.find("..") != std::string::npos) {
            diagnostics.push_back({file, "preset", inQuotes(name) + " is not the name of a bundled preset"});
            return std::nullopt;
        }
        return LinkedPresetName{name};
    }
    if (fragment.rfind("p=", 0) == 0) {
        std::optional<std::string> json = base64UrlDecode(fragment.substr(2));
        if (!json) {
            diagnostics.push_back({file, "p", "not valid base64url"});
            return std::nullopt;
        }
        std::optional<Preset> preset = parsePreset(*json, file, folder, diagnostics, omitted);
        if (!preset) {
            return std::nullopt;
        }
        return *preset;
    }
    diagnostics.push_back({file, "", "expected #preset=<name> or #p=<encoded preset>"});
    return std::nullopt;
}

} // namespace lab
