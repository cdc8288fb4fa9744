// data_uri.h — a glTF's buffers given as base64 `data:` URIs, decoded once, straight from
// the file's bytes, before any JSON parser copies their text.
//
// A .gltf can carry its whole mesh as base64 text inside the JSON. Parsed as it is, that text
// would be held four times over (the file, our check's JSON tree, tinygltf's tree, tinygltf's
// decoding: about 6.6 times the file at the peak). Here one pass over the text, with
// no recursion, finds `buffers[i].uri` strings of the form `data:<type>;base64,<data>`, decodes
// each into bytes of its own, and hands back the JSON with a 1-byte placeholder in its place;
// the loader reads the decoded bytes in place (as it reads a GLB's BIN chunk) and tinygltf only
// ever sees the small JSON. What this pass cannot follow — malformed JSON, a URI with escapes,
// a second "buffers" — is left as it was, for the parsers to read or refuse as before.
#pragma once

#include "core/io/diagnostics.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab::gltf_detail {

struct DataUriBuffers {
    std::string json;                               // the JSON with the decoded URIs replaced
    std::vector<std::vector<unsigned char>> bytes;  // per buffer index: its decoded bytes
    std::vector<bool> decoded;                      // per buffer index: whether `bytes` holds it
};

// The placeholder a decoded URI becomes: one byte, as tinygltf then expects of byteLength 1.
inline constexpr const char* kDecodedPlaceholder = "data:application/octet-stream;base64,AA==";

// Nullopt when nothing was decoded (no such URI, or JSON this pass does not follow); the
// diagnostics name the buffer when a URI's base64 is broken (then `failed` is set).
// The pass follows JSON no deeper than `maxDepth` and buffers below `maxBuffers` (the loader's
// limits, GltfLimits): beyond them it changes nothing, and the parsers' own checks refuse the file.
std::optional<DataUriBuffers> decodeDataUriBuffers(std::string_view json, int maxDepth, std::size_t maxBuffers,
                                                   const std::string& displayName, Diagnostics& diagnostics, bool& failed);

// Standard base64 (RFC 4648, '=' padding only at the end) into `out`; false at the first byte
// that is not, with its offset (from 0) in `at`.
bool decodeBase64(std::string_view text, std::vector<unsigned char>& out, std::size_t& at);

} // namespace lab::gltf_detail
