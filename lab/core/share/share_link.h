// share_link.h — a scene or an exercise as a URL fragment: the links "Copy link" copies, the QR
// code on the projector shows and `lab share` prints, and the browser's saved state.
//
//   preset=05-full-phong     a bundled preset, unmodified
//   exercise=03-shininess    a bundled exercise (presets/exercises/), at its start
//   z=<base64url>            a preset: only what differs from the defaults (preset_fields.h
//                            presetPatch), minified JSON, zlib-deflated, base64url without padding
//   x=<base64url>            an exercise, likewise: its start as what differs from the defaults,
//                            its target as what differs from its start
//   p=<base64url>            a whole preset as minified JSON (links made before z=; still read)
//
// Decoding validates exactly like a file (the link is untrusted input; at most kMaxPresetBytes
// inflated) and reports problems as diagnostics naming the link. A fragment longer than
// kMaxLinkChars is refused before anything is decoded (the page refuses it before it reaches
// here). No GL, no browser: the web platform moves the strings in and out of location.hash and
// localStorage.
#pragma once

#include "core/exercise/exercise.h"
#include "core/scene/preset.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace lab {

// The longest link fragment (the characters after '#') the lab opens or makes. A real scene's
// link is a few hundred characters (a few thousand with long texts); a longer fragment is refused
// before it is decoded (megabytes held up the page's start). `lab share`, Copy link and the
// address bar never get a longer one: such a scene (a very long description) stays in the
// page's saved state, which is the page's own and may hold up to kMaxSavedLinkChars.
inline constexpr std::size_t kMaxLinkChars = 16384;
inline constexpr std::size_t kMaxSavedLinkChars = std::size_t{2} << 20; // a 1 MiB preset, deflated, base64url

// "longer than 16384 characters (it has N)": the refusal the page and parseLink give.
std::string linkTooLong(std::size_t length);

// The fragment for a preset: "preset=<bundledName>" when given, else "z=...".
std::string presetLink(const Preset& preset, const std::optional<std::string>& bundledName);
// The fragment for an exercise: "exercise=<bundledName>" when given, else "x=...", which carries
// linkedExercise(exercise).
std::string exerciseLink(const Exercise& exercise, const std::optional<std::string>& bundledName);

// What an "x=" link carries of an exercise: all of it but its scenes' names and descriptions, which
// its title and instructions stand for (the lab shows those), leaving room for the text that matters.
Exercise linkedExercise(Exercise exercise);

// The address a link opens: `base` (its own fragment dropped) + "#" + fragment.
std::string shareUrl(std::string_view base, std::string_view fragment);

// Empty when `url` can be a course page's address, else why not: an http:// or https:// URL with
// a host (no user name before it), in printable ASCII (0x21 to 0x7E) only, without the characters
// a URL never holds raw (" < > \ ^ ` { | }), at most 2000 characters. A byte refused is named with
// its offset; nothing is percent-encoded on the quiet, so the link printed is the one in the QR code.
std::string shareBaseProblem(const std::string& url);

struct LinkedPresetName {
    std::string name; // a bundled preset's file name without .json (letters, digits, '-', '_')
};
struct LinkedExerciseName {
    std::string name; // a bundled exercise's file name without .json
};
using Linked = std::variant<LinkedPresetName, Preset, LinkedExerciseName, Exercise>;

// Parses a fragment (with or without the leading '#'). `folder` is where glTF paths in a linked
// scene resolve (the bundled presets). Returns a name to open, a preset, an exercise, or nothing
// (with diagnostics) when the link is broken. `omitted`, when given, receives which of `camera` and
// `lights` a "p=" preset left out (a glTF model is then framed as a file's is, frameOmitted); a
// "z=" preset leaves nothing out (what it does not say is the default).
// `maxChars` is kMaxLinkChars for a link from outside, kMaxSavedLinkChars for the page's saved state.
std::optional<Linked> parseLink(std::string_view fragment, const std::filesystem::path& folder,
                                Diagnostics& diagnostics, OmittedKeys* omitted = nullptr,
                                std::size_t maxChars = kMaxLinkChars);

std::string base64UrlEncode(std::string_view bytes);
std::optional<std::string> base64UrlDecode(std::string_view text);

// zlib (RFC 1950) deflate and inflate; inflating stops (nullopt) past `maxBytes` or at broken data.
std::string deflateBytes(std::string_view bytes);
std::optional<std::string> inflateBytes(std::string_view bytes, std::size_t maxBytes);

} // namespace lab
