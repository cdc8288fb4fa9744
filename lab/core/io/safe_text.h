// safe_text.h — text from files, links and arguments made safe to show: on a terminal, in the
// GUI, in the page.
//
// Presets, models and file names come from the internet. Anything they contain may end up in a
// message: an unknown key, an enum value, a path, a preset's name. printable() is the one
// function every message passes through on its way out (lab/cli's output, the GUI's dialogs and
// toasts, the page): control characters (C0 but line feed and tab, DEL, C1) become visible
// escapes so they cannot retitle, clear or recolour a terminal; invalid UTF-8 is shown byte by
// byte as \xNN; a NUL is shown as \0 and never ends the message early. inQuotes() is how a value
// from a file is put into a message: escaped the same way (line feeds and tabs too), in quotes,
// and cut to a bounded length with its full size noted, so a 21 MiB data: URI is not echoed.
// Pure: no I/O.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace lab {

// `text` with every control character and invalid UTF-8 byte escaped; line feeds (and tabs) kept
// unless `oneLine`.
std::string printable(std::string_view text, bool oneLine = false);

// "value" (escaped as printable(value, true)), or "first bytes…" (N bytes) when longer than
// `maxBytes`.
std::string inQuotes(std::string_view value, std::size_t maxBytes = 120);

// `text` cut to `maxBytes` (at a character boundary) with "… (N bytes)" after it when longer: for
// messages that other libraries wrote and that may quote a whole input (tinygltf, nlohmann-json).
std::string shortened(std::string_view text, std::size_t maxBytes = 1000);

// A key from a file as it goes into a JSON path: itself when a plain name (letters, digits, '_'
// and '-', at most `maxBytes`), else inQuotes(key, maxBytes).
std::string keyInPath(std::string_view key, std::size_t maxBytes = 60);

// `text` for XML (and HTML) character data and attribute values: printable(text, oneLine) first —
// XML 1.0 allows no control character but tab and line feed, even escaped — then U+FFFE and
// U+FFFF (no XML characters either) as \uFFFE, \uFFFF, and & < > " ' as entities. The SVG figures and lab check's reports (JUnit XML, the HTML page) write it.
std::string xmlEscaped(std::string_view text, bool oneLine = true);

// True when `text` holds a NUL byte (paths and keys with one are refused as such).
inline bool hasNul(std::string_view text) { return text.find('\0') != std::string_view::npos; }

} // namespace lab
