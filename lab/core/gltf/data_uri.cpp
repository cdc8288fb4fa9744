// data_uri.cpp — the data: URI pass over a glTF's JSON text (see gltf_data_uri.h).
#include "core/gltf/data_uri.h"

#include <array>
#include <cstdint>

namespace lab::gltf_detail {

namespace {

// A string value found at buffers[index].uri: its contents' place in the text.
struct UriSpan {
    std::size_t index;
    std::size_t begin, end; // the characters between the quotes
};

// One container on the way down: an object (with the key last read) or an array (with the
// index of the element being read).
struct Frame {
    bool object;
    std::string_view key;
    std::size_t index = 0;
};

// The spans of every buffers[i].uri string, in text order; nullopt for text this scanner does not
// follow (it then changes nothing). Iterative: its depth costs a vector, not the stack.
std::optional<std::vector<UriSpan>> findBufferUris(std::string_view s, int maxDepth) {
    std::vector<UriSpan> spans;
    std::vector<Frame> stack;
    bool expectKey = false, sawBuffers = false;
    std::size_t i = 0;
    auto skipSpace = [&] {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) {
            ++i;
        }
    };
    // Returns the contents of the string starting at s[i] == '"', and moves past it.
    auto readString = [&](bool& escaped) -> std::optional<std::string_view> {
        std::size_t start = ++i;
        escaped = false;
        while (i < s.size() && s[i] != '"') {
            if (s[i] == '\\') {
                escaped = true;
                ++i;
            }
            ++i;
        }
        if (i >= s.size()) {
            return std::nullopt;
        }
        return s.substr(start, i++ - start);
    };
    while (true) {
        skipSpace();
        if (i >= s.size()) {
            return stack.empty() ? std::optional(spans) : std::nullopt;
        }
        char c = s[i];
        if (expectKey) {
            if (c == '}') { // an empty object
                expectKey = false;
                continue;
            }
            bool escaped = false;
            std::optional<std::string_view> key = c == '"' ? readString(escaped) : std::nullopt;
            skipSpace();
            if (!key || i >= s.size() || s[i] != ':') {
                return std::nullopt;
            }
            ++i;
            stack.back().key = *key;
            expectKey = false;
            if (stack.size() == 1 && *key == "buffers") {
                if (sawBuffers) {
                    return std::nullopt; // a second "buffers": which one counts is the parser's business
                }
                sawBuffers = true;
            }
            continue;
        }
        if (c == '{' || c == '[') {
            if (stack.size() >= static_cast<std::size_t>(maxDepth)) {
                return std::nullopt; // deeper than the loader reads at all
            }
            stack.push_back({c == '{', {}, 0});
            expectKey = c == '{';
            ++i;
            continue;
        }
        if (c == '}' || c == ']') {
            if (stack.empty() || stack.back().object != (c == '}')) {
                return std::nullopt;
            }
            stack.pop_back();
            ++i;
            continue;
        }
        if (c == ',') {
            if (stack.empty()) {
                return std::nullopt;
            }
            if (stack.back().object) {
                expectKey = true;
            } else {
                ++stack.back().index;
            }
            ++i;
            continue;
        }
        if (c == '"') {
            std::size_t begin = i + 1;
            bool escaped = false;
            std::optional<std::string_view> value = readString(escaped);
            if (!value) {
                return std::nullopt;
            }
            // root { "buffers": [ i: { "uri": <here> } ] }
            if (stack.size() == 3 && stack[0].object && stack[0].key == "buffers" && !stack[1].object && stack[2].object &&
                stack[2].key == "uri" && !escaped) {
                spans.push_back({stack[1].index, begin, begin + value->size()});
            }
            continue;
        }
        // A number, true, false or null: up to the next delimiter.
        std::size_t start = i;
        while (i < s.size() && s[i] != ',' && s[i] != '}' && s[i] != ']' && s[i] != ' ' && s[i] != '\n' && s[i] != '\r' &&
               s[i] != '\t') {
            ++i;
        }
        if (i == start) {
            return std::nullopt;
        }
    }
}

constexpr std::array<std::int8_t, 256> kBase64 = [] {
    std::array<std::int8_t, 256> t{};
    t.fill(-1);
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int k = 0; k < 64; ++k) {
        t[static_cast<unsigned char>(alphabet[k])] = static_cast<std::int8_t>(k);
    }
    return t;
}();

} // namespace

bool decodeBase64(std::string_view text, std::vector<unsigned char>& out, std::size_t& at) {
    std::size_t n = text.size();
    std::size_t padding = 0;
    while (padding < 2 && n > padding && text[n - 1 - padding] == '=') {
        ++padding;
    }
    std::size_t digits = n - padding;
    if (padding > 0 && n % 4 != 0) {
        at = n - padding;
        return false;
    }
    out.clear();
    out.reserve(digits / 4 * 3 + (digits % 4 ? digits % 4 - 1 : 0));
    std::uint32_t accumulator = 0;
    int bits = 0;
    for (std::size_t k = 0; k < digits; ++k) {
        std::int8_t v = kBase64[static_cast<unsigned char>(text[k])];
        if (v < 0) {
            at = k;
            return false;
        }
        accumulator = (accumulator << 6) | static_cast<std::uint32_t>(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<unsigned char>(accumulator >> bits));
        }
    }
    if (digits % 4 == 1) { // one digit alone holds no whole byte
        at = digits - 1;
        return false;
    }
    return true;
}

std::optional<DataUriBuffers> decodeDataUriBuffers(std::string_view json, int maxDepth, std::size_t maxBuffers,
                                                   const std::string& displayName, Diagnostics& diagnostics, bool& failed) {
    failed = false;
    std::optional<std::vector<UriSpan>> spans = findBufferUris(json, maxDepth);
    if (!spans) {
        return std::nullopt;
    }
    DataUriBuffers out;
    std::size_t copiedTo = 0;
    for (const UriSpan& span : *spans) {
        std::string_view uri = json.substr(span.begin, span.end - span.begin);
        std::size_t comma = uri.find(',');
        if (!uri.starts_with("data:") || comma == std::string_view::npos || !uri.substr(0, comma).ends_with(";base64")) {
            continue; // a file name, or a data: URI that is not base64: tinygltf's as before
        }
        if (span.index >= maxBuffers) {
            continue; // more buffers than the loader reads: refused by its count check
        }
        if (span.index >= out.bytes.size()) {
            out.bytes.resize(span.index + 1);
            out.decoded.resize(span.index + 1, false);
        }
        std::size_t at = 0;
        if (!decodeBase64(uri.substr(comma + 1), out.bytes[span.index], at)) {
            diagnostics.push_back({displayName, "buffers[" + std::to_string(span.index) + "].uri",
                                   "not valid base64 at character " + std::to_string(comma + 2 + at) + " of the URI"});
            failed = true;
            return std::nullopt;
        }
        out.decoded[span.index] = true;
        out.json.append(json.substr(copiedTo, span.begin - copiedTo));
        out.json.append(kDecodedPlaceholder);
        copiedTo = span.end;
    }
    if (copiedTo == 0) {
        return std::nullopt;
    }
    out.json.append(json.substr(copiedTo));
    return out;
}

} // namespace lab::gltf_detail
