// glb.h — a binary glTF (.glb) read in place: its chunks found and checked here, its BIN
// chunk never copied.
//
// Internal to gltf*.cpp. tinygltf 2.7.0's LoadBinaryFromMemory copies every buffer stored in the
// BIN chunk into a std::vector (a second pass over a model's bytes, and its pages), and trusts
// the chunk lengths more than it should. Instead the loader reads the 12-byte header and the
// chunk headers itself, checks every length against the file, and hands tinygltf only the JSON
// chunk — rewritten so that the buffers stored in the BIN chunk (those without a uri) are 1-byte
// placeholders; the accessors then read those buffers straight from the mapped file. Images
// stored in the BIN chunk get a placeholder too: the lab skips images, and tinygltf would
// otherwise be handed a view into a placeholder buffer.
#pragma once

#include "core/io/diagnostics.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab::gltf_detail {

// A GLB's chunks, as views into the file's bytes.
struct GlbChunks {
    std::string_view json;
    std::optional<std::string_view> bin; // absent when the file has no BIN chunk
};

// The header and chunk headers, checked against the file's `bytes`: "glTF", version 2, a total
// length equal to the file's; a non-empty JSON chunk first; then, when anything follows, a BIN
// chunk (a multiple of 4 bytes, as tinygltf requires) that lies inside the file. Chunks after
// the BIN chunk are ignored, as the specification asks. Nullopt with `error` saying which
// length or field is wrong otherwise.
std::optional<GlbChunks> readGlbChunks(std::string_view bytes, std::string& error);

// The GLB's parsed JSON `doc` (a JSON object) rewritten in place for tinygltf as described
// above, with each buffer stored in the BIN chunk checked against it: it must exist and hold the
// buffer's byteLength. Returns, per buffer, its byteLength when it is stored in the BIN chunk.
// Buffers with a uri and everything else are left to the loader as they were. Nullopt after a
// diagnostic naming the buffer.
std::optional<std::vector<std::optional<std::size_t>>> glbBuffersInPlace(nlohmann::json& doc,
                                                                         const std::optional<std::string_view>& bin,
                                                                         const std::string& displayName,
                                                                         Diagnostics& diagnostics);

} // namespace lab::gltf_detail
