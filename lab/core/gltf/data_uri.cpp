// data_uri.cpp — the data: URI pass over a glTF's JSON text (see data_uri.h).
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
class UriScanner {
public:
    UriScanner(std::string_view text, int maxDepth) : s_(text), maxDepth_(static_cast<std::size_t>(maxDepth)) {}

    std::optional<std::vector<UriSpan>> scan() {
        while (true) {
            skipSpace();
            if (i_ >= s_.size()) {
                return stack_.empty() ? std::optional(spans_) : std::nullopt;
            }
            if (!(expectKey_ ? key() : token(s_[i_]))) {
                return std::nullopt;
            }
        }
    }

private:
    void skipSpace() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) {
            ++i_;
        }
    }

    // The contents of the string starting at s_[i_] == '"'; moves past it.
    std::optional<std::string_view> readString(bool& escaped) {
        std::size_t start = ++i_;
        escaped = false;
        while (i_ < s_.size() && s_[i_] != '"') {
            if (s_[i_] == '\\') {
                escaped = true;
                ++i_;
            }
            ++i_;
        }
        if (i_ >= s_.size()) {
            return std::nullopt;
        }
        return s_.substr(start, i_++ - start);
    }

    // An object's key and its ':' (or the '}' of an empty object). False for text not followed.
    bool key() {
        if (s_[i_] == '}') { // an empty object
            expectKey_ = false;
            return true;
        }
        bool escaped = false;
        std::optional<std::string_view> key = s_[i_] == '"' ? readString(escaped) : std::nullopt;
        skipSpace();
        if (!key || i_ >= s_.size() || s_[i_] != ':') {
            return false;
        }
        ++i_;
        stack_.back().key = *key;
        expectKey_ = false;
        if (stack_.size() == 1 && *key == "buffers") {
            if (sawBuffers_) {
                return false; // a second "buffers": which one counts is the parser's business
            }
            sawBuffers_ = true;
        }
        return true;
    }

    // A bracket, a comma, a string value or a scalar. False for text not followed.
    bool token(char c) {
        if (c == '{' || c == '[') {
            if (stack_.size() >= maxDepth_) {
                return false; // deeper than the loader reads at all
            }
            stack_.push_back({c == '{', {}, 0});
            expectKey_ = c == '{';
            ++i_;
            return true;
        }
        if (c == '}' || c == ']') {
            if (stack_.empty() || stack_.back().object != (c == '}')) {
                return false;
            }
            stack_.pop_back();
            ++i_;
            return true;
        }
        if (c == ',') {
            if (stack_.empty()) {
                return false;
            }
            if (stack_.back().object) {
                expectKey_ = true;
            } else {
                ++stack_.back().index;
            }
            ++i_;
            return true;
        }
        if (c == '"') {
            return stringValue();
        }
        // A number, true, false or null: up to the next delimiter.
        std::size_t start = i_;
        while (i_ < s_.size() && s_[i_] != ',' && s_[i_] != '}' && s_[i_] != ']' && s_[i_] != ' ' && s_[i_] != '\n' &&
               s_[i_] != '\r' && s_[i_] != '\t') {
            ++i_;
        }
        return i_ != start;
    }

    // A string value, kept when it is root { "buffers": [ i: { "uri": <here> } ] }.
    bool stringValue() {
        std::size_t begin = i_ + 1;
        bool escaped = false;
        std::optional<std::string_view> value = readString(escaped);
        if (!value) {
            return false;
        }
        if (stack_.size() == 3 && stack_[0].object && stack_[0].key == "buffers" && !stack_[1].object &&
            stack_[2].object && stack_[2].key == "uri" && !escaped) {
            spans_.push_back({stack_[1].index, begin, begin + value->size()});
        }
        return true;
    }

    std::string_view s_;
    std::size_t maxDepth_;
    std::size_t i_ = 0;
    std::vector<UriSpan> spans_;
    std::vector<Frame> stack_;
    bool expectKey_ = false, sawBuffers_ = false;
};

std::optional<std::vector<UriSpan>> findBufferUris(std::string_view s, int maxDepth) { return UriScanner(s, maxDepth).scan(); }

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
