// share_link.cpp — links to scenes and exercises: what differs from the defaults, deflated,
// base64url; validated like a file.
#include "core/share/share_link.h"

#include "core/exercise/preset_fields.h"
#include "core/io/safe_text.h"

#include <nlohmann/json.hpp>
#include <stb_image.h> // stbi_zlib_decode_buffer

#include <cstdlib>
#include <cstdio>
#include <cctype>
#include <algorithm>

// stb_image_write's deflate, compiled into Debian's libstb (and the page's stb_impl.cpp) but not
// declared in its header.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int dataLength, int* outLength, int quality);

namespace lab {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

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

std::string deflateBytes(std::string_view bytes) {
    int length = 0;
    unsigned char* packed = stbi_zlib_compress(reinterpret_cast<unsigned char*>(const_cast<char*>(bytes.data())),
                                               static_cast<int>(bytes.size()), &length, 9);
    std::string out(reinterpret_cast<const char*>(packed), packed ? static_cast<std::size_t>(length) : 0);
    std::free(packed);
    return out;
}

std::optional<std::string> inflateBytes(std::string_view bytes, std::size_t maxBytes) {
    std::string out(maxBytes, '\0');
    int n = stbi_zlib_decode_buffer(out.data(), static_cast<int>(out.size()), bytes.data(), static_cast<int>(bytes.size()));
    if (n < 0) {
        return std::nullopt;
    }
    out.resize(static_cast<std::size_t>(n));
    return out;
}

std::string presetLink(const Preset& preset, const std::optional<std::string>& bundledName) {
    if (bundledName) {
        return "preset=" + *bundledName;
    }
    PresetJson patch = presetPatch(presetValue(Preset{}), presetValue(preset));
    return "z=" + base64UrlEncode(deflateBytes(patch.dump()));
}

std::string exerciseLink(const Exercise& exercise, const std::optional<std::string>& bundledName) {
    if (bundledName) {
        return "exercise=" + *bundledName;
    }
    PresetJson j = PresetJson::parse(std::string_view(exerciseToJson(linkedExercise(exercise))));
    j["start"] = presetPatch(presetValue(Preset{}), j["start"]);
    return "x=" + base64UrlEncode(deflateBytes(j.dump()));
}

Exercise linkedExercise(Exercise exercise) {
    for (Preset* p : {&exercise.start, &exercise.target}) {
        p->name = Preset{}.name;
        p->description.clear();
    }
    return exercise;
}

std::string shareUrl(std::string_view base, std::string_view fragment) {
    std::size_t hash = base.find('#');
    if (hash != std::string_view::npos) {
        base = base.substr(0, hash);
    }
    return std::string(base) + "#" + std::string(fragment);
}

namespace {

std::optional<std::string> bundledName(std::string_view name) {
    bool ok = !name.empty() && name.size() <= 128;
    for (char c : name) {
        ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.');
    }
    if (!ok || name.find("..") != std::string_view::npos) {
        return std::nullopt;
    }
    return std::string(name);
}

// The inflated JSON of a "z=" or "x=" link, or nullopt after a diagnostic.
std::optional<std::string> packedJson(std::string_view encoded, const std::string& file, const char* key,
                                      Diagnostics& diagnostics) {
    std::optional<std::string> packed = base64UrlDecode(encoded);
    if (!packed) {
        diagnostics.push_back({file, key, "not valid base64url"});
        return std::nullopt;
    }
    std::optional<std::string> json = inflateBytes(*packed, kMaxPresetBytes);
    if (!json) {
        diagnostics.push_back({file, key, "not deflated data, or more than " + std::to_string(kMaxPresetBytes) +
                                              " bytes inflated (the link is cut or broken)"});
    }
    return json;
}

} // namespace

std::string linkTooLong(std::size_t length) {
    return "longer than " + std::to_string(kMaxLinkChars) + " characters (it has " + std::to_string(length) +
           "): not a link the lab makes";
}

std::optional<Linked> parseLink(std::string_view fragment, const std::filesystem::path& folder,
                                Diagnostics& diagnostics, OmittedKeys* omitted, std::size_t maxChars) {
    if (!fragment.empty() && fragment.front() == '#') {
        fragment.remove_prefix(1);
    }
    const std::string file = "link";
    if (fragment.size() > maxChars) { // before anything is decoded
        diagnostics.push_back({file, "", maxChars == kMaxLinkChars ? linkTooLong(fragment.size())
                                                                   : "longer than " + std::to_string(maxChars) + " characters"});
        return std::nullopt;
    }
    if (fragment.starts_with("preset=") || fragment.starts_with("exercise=")) {
        bool exercise = fragment.starts_with("exercise=");
        std::string_view name = fragment.substr(exercise ? 9 : 7);
        std::optional<std::string> ok = bundledName(name);
        if (!ok) {
            diagnostics.push_back({file, exercise ? "exercise" : "preset",
                                   inQuotes(std::string(name)) + " is not the name of a bundled " +
                                       (exercise ? "exercise" : "preset")});
            return std::nullopt;
        }
        return exercise ? Linked(LinkedExerciseName{*ok}) : Linked(LinkedPresetName{*ok});
    }
    if (fragment.starts_with("z=")) {
        std::optional<std::string> json = packedJson(fragment.substr(2), file, "z", diagnostics);
        if (!json) {
            return std::nullopt;
        }
        PresetJson patch = PresetJson::parse(std::string_view(*json), nullptr, false);
        if (patch.is_discarded() || !patch.is_object()) {
            diagnostics.push_back({file, "z", "not a JSON object"});
            return std::nullopt;
        }
        PresetJson scene = mergePreset(presetValue(Preset{}), patch);
        std::optional<Preset> preset = parseInlinePreset(scene.dump(), file, "", folder, diagnostics);
        if (omitted) {
            *omitted = {};
        }
        return preset ? std::optional<Linked>(*preset) : std::nullopt;
    }
    if (fragment.starts_with("x=")) {
        std::optional<std::string> json = packedJson(fragment.substr(2), file, "x", diagnostics);
        if (!json) {
            return std::nullopt;
        }
        // The start is what differs from the defaults (exerciseLink): merged back over them, as a z=
        // scene is, before it is read. (Read as it was, a plane of 64 x 32 subdivisions, the
        // default sphere's, came back with a plane's own default of 16 x 16.)
        PresetJson exercise = PresetJson::parse(std::string_view(*json), nullptr, false);
        if (exercise.is_object() && exercise.contains("start") && exercise["start"].is_object()) {
            exercise["start"] = mergePreset(presetValue(Preset{}), exercise["start"]);
            json = exercise.dump();
        }
        std::optional<Exercise> e = parseExercise(*json, file, folder, diagnostics);
        return e ? std::optional<Linked>(*e) : std::nullopt;
    }
    if (fragment.starts_with("p=")) {
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
    diagnostics.push_back({file, "", "expected #preset=<name>, #exercise=<name>, #z=<scene>, #x=<exercise> or #p=<preset>"});
    return std::nullopt;
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

} // namespace lab
