// compression.h — compressed glTF geometry decoded into plain buffers before anything reads it.
//
// Internal to gltf*.cpp. Two extensions compress what accessors read:
//   * EXT_meshopt_compression: a bufferView's bytes are meshoptimizer's vertex or index codec
//     (with an optional filter) over bytes of another buffer; the view's own buffer is often a
//     "fallback" without data.
//   * KHR_draco_mesh_compression: a primitive's POSITION, NORMAL and indices are one Draco mesh
//     stored in a bufferView; their accessors carry no bufferView of their own.
// Both are undone here, on the parsed JSON and the buffers' bytes, before tinygltf sees the
// JSON: each decoded array becomes a new buffer the loader owns, with a bufferView (and for
// Draco, new accessors) pointing at it, so the rest of the loader reads plain, tightly packed
// data through the same bounds checks as any other accessor (gltf_accessors.h). Every input
// field is checked before a decoder is called (meshoptimizer asserts on bad strides and counts),
// and each decoder's output is checked before use: counts against the accessors and the
// loader's limits, every face index inside its points.
//
// The decoders are Debian's libmeshoptimizer and libdraco; a build without meshoptimizer
// (LAB_HAVE_MESHOPT) refuses a file that needs it, naming the extension. Draco is reached through
// draco_decoder.h: linked, or on the page a module fetched the first time a model needs it.
#pragma once

#include "core/gltf/accessors.h"
#include "core/io/diagnostics.h"

#include <nlohmann/json.hpp>

#include <deque>
#include <string>
#include <vector>

namespace lab::gltf_detail {

// Whether this build decodes each extension.
bool meshoptSupported();
bool dracoSupported();

// The buffers a model's accessors read: per buffer index, its bytes; `owned` keeps the ones the
// loader decoded or read itself alive.
struct ModelBuffers {
    std::vector<BufferBytes> bytes;
    std::deque<std::vector<unsigned char>> owned;
    std::size_t decoded = 0; // bytes the decoders made, all together (DecodeLimits::maxDecodedBytes)

    // Appends `data` as a new buffer, to `doc["buffers"]` too (a placeholder for tinygltf); returns its index.
    std::size_t add(nlohmann::json& doc, std::vector<unsigned char> data);
};

struct DecodeLimits {
    std::size_t maxVertices = 0;
    std::size_t maxTriangles = 0;
    // What the decoders may make for one file, all together: compressed data can ask for far more
    // than it holds, and many views or primitives may point at the same compressed bytes.
    std::size_t maxDecodedBytes = 0;
};

// Decodes every bufferView with EXT_meshopt_compression (when this build has the decoder; else
// leaves them, and a view still on a fallback buffer is refused when read), rewriting `doc`.
// False after a diagnostic naming the bufferView.
bool decodeMeshopt(nlohmann::json& doc, ModelBuffers& buffers, const DecodeLimits& limits,
                   const std::string& displayName, Diagnostics& diagnostics);

// Decodes every primitive with KHR_draco_mesh_compression (draco_decoder.h),
// pointing its POSITION, NORMAL and indices at new accessors of the decoded data. False after a
// diagnostic naming the primitive or accessor.
bool decodeDraco(nlohmann::json& doc, ModelBuffers& buffers, const DecodeLimits& limits,
                 const std::string& displayName, Diagnostics& diagnostics);

} // namespace lab::gltf_detail
