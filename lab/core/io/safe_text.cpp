// safe_text.cpp — escaping for messages (see safe_text.h).
#include "core/io/safe_text.h"

#include <cctype>
#include <cstdio>

namespace lab {

namespace {

// The length of the valid UTF-8 sequence at the start of `s` (1 to 4), or 0 when it is not one
// (overlong forms, surrogates and code points past U+10FFFF included).
std::size_t utf8Length(std::string_view s, unsigned& codePoint) {
    const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    unsigned c = b(0);
    if (c < 0x80) {
        codePoint = c;
        return 1;
    }
    std::size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c <= 0xDF ? 2 : 0;
    if (n == 0 || n > s.size() || (n == 3 && c >= 0xF0)) {
        return 0;
    }
    codePoint = c & (n == 2 ? 0x1Fu : n == 3 ? 0x0Fu : 0x07u);
    for (std::size_t i = 1; i < n; ++i) {
        if ((b(i) & 0xC0) != 0x80) {
            return 0;
        }
        codePoint = (codePoint << 6) | (b(i) & 0x3Fu);
    }
    bool overlong = (n == 3 && codePoint < 0x800) || (n == 4 && codePoint < 0x10000);
    bool surrogate = codePoint >= 0xD800 && codePoint <= 0xDFFF;
    return overlong || surrogate || codePoint > 0x10FFFF ? 0 : n;
}

void appendHex(std::string& out, const char* format, unsigned value) {
    char buf[16];
    std::snprintf(buf, sizeof buf, format, value);
    out += buf;
}

} // namespace

std::string printable(std::string_view text, bool oneLine) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        unsigned cp = 0;
        std::size_t n = utf8Length(text.substr(i), cp);
        if (n == 0) {
            appendHex(out, "\\x%02X", static_cast<unsigned char>(text[i]));
            ++i;
            continue;
        }
        if ((cp == '\n' || cp == '\t') && !oneLine) {
            out += static_cast<char>(cp);
        } else if (cp == '\n') {
            out += "\\n";
        } else if (cp == '\t') {
            out += "\\t";
        } else if (cp == '\r') {
            out += "\\r";
        } else if (cp == 0) {
            out += "\\0";
        } else if (cp < 0x20 || cp == 0x7F) {
            appendHex(out, "\\x%02X", cp);
        } else if (cp >= 0x80 && cp <= 0x9F) {
            appendHex(out, "\\u%04X", cp); // C1 controls (U+009B is a terminal's CSI)
        } else {
            out.append(text.substr(i, n));
        }
        i += n;
    }
    return out;
}

namespace {

// The longest prefix of at most `maxBytes` that does not split a UTF-8 character.
std::string_view cutAt(std::string_view text, std::size_t maxBytes) {
    std::size_t cut = maxBytes;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) {
        --cut;
    }
    return text.substr(0, cut);
}

} // namespace

std::string inQuotes(std::string_view value, std::size_t maxBytes) {
    if (value.size() <= maxBytes) {
        return "\"" + printable(value, true) + "\"";
    }
    return "\"" + printable(cutAt(value, maxBytes), true) + "\u2026\" (" + std::to_string(value.size()) + " bytes)";
}

std::string keyInPath(std::string_view key, std::size_t maxBytes) {
    bool plain = key.size() <= maxBytes;
    for (char c : key) {
        unsigned char u = static_cast<unsigned char>(c);
        plain = plain && (std::isalnum(u) || c == '_' || c == '-');
    }
    return plain ? std::string(key) : inQuotes(key, maxBytes);
}

std::string shortened(std::string_view text, std::size_t maxBytes) {
    if (text.size() <= maxBytes) {
        return std::string(text);
    }
    return std::string(cutAt(text, maxBytes)) + "\u2026 (" + std::to_string(text.size()) + " bytes)";
}

std::string xmlEscaped(std::string_view text, bool oneLine) {
    const std::string safe = printable(text, oneLine);
    std::string out;
    for (std::size_t i = 0; i < safe.size(); ++i) {
        const char c = safe[i];
        // U+FFFE and U+FFFF (EF BF BE, EF BF BF) are valid UTF-8 but no XML 1.0 character.
        if (c == '\xEF' && i + 2 < safe.size() && safe[i + 1] == '\xBF' && (safe[i + 2] == '\xBE' || safe[i + 2] == '\xBF')) {
            out += safe[i + 2] == '\xBE' ? "\\uFFFE" : "\\uFFFF";
            i += 2;
            continue;
        }
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        default: out += c;
        }
    }
    return out;
}

} // namespace lab
