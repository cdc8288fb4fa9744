// share_link.h — a preset as a URL fragment, for shareable links and the browser's saved state.
//
//   preset=05-full-phong     a bundled preset, unmodified
//   p=<base64url>            the whole preset: its minified JSON, base64url without padding
//
// Decoding validates exactly like a preset file (the link is untrusted input) and reports
// problems as diagnostics naming the link. No GL, no browser: the web platform moves the
// strings in and out of location.hash and localStorage.
#pragma once

#include "core/scene/preset.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace lab {

// The fragment for a preset: "preset=<bundledName>" when given, else "p=...".
std::string presetLink(const Preset& preset, const std::optional<std::string>& bundledName);

struct LinkedPresetName {
    std::string name; // a bundled preset's file name without .json (letters, digits, '-', '_')
};

// Parses a fragment (with or without the leading '#'). `folder` is where glTF paths in a "p="
// preset resolve (the bundled presets). Returns a name to open, a preset, or nothing (with
// diagnostics) when the link is broken. `omitted`, when given, receives which of `camera` and
// `lights` a "p=" preset left out (a glTF model is then framed as a file's is, frameOmitted).
std::optional<std::variant<LinkedPresetName, Preset>> parseLink(std::string_view fragment,
                                                                const std::filesystem::path& folder,
                                                                Diagnostics& diagnostics, OmittedKeys* omitted = nullptr);

std::string base64UrlEncode(std::string_view bytes);
std::optional<std::string> base64UrlDecode(std::string_view text);

} // namespace lab
