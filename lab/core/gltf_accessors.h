// gltf_accessors.h — reading glTF accessors, with every index and byte range proved first.
//
// Internal to gltf*.cpp. tinygltf 2.7.0 accepts accessors that read past their buffer,
// bufferViews larger than their buffer and out-of-range indices; nothing here reads a byte
// before view() has checked the accessor, its bufferView and its buffer (with overflow checks).
// Every refusal is a diagnostic naming the accessor or bufferView.
//
// This file owns the accessor/bufferView/buffer chain and the copies out of it. It does not
// know about nodes, scenes, primitive modes or files (gltf.cpp).
#pragma once

#include "core/diagnostics.h"

#include <tiny_gltf.h>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace lab::gltf_detail {

// Where a buffer's bytes are: tinygltf's copy (a .gltf's buffers, a GLB's buffers with a uri),
// or, for a GLB's buffers stored in its BIN chunk, the chunk itself in the mapped file.
struct BufferBytes {
    const unsigned char* data = nullptr;
    std::size_t size = 0;
};

// A validated accessor: `count` elements of `componentType`, `stride` bytes apart from `data`.
struct View {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
};

// What an accessor must hold to be used where it is.
enum class AccessorUse {
    FloatVec3, // POSITION, NORMAL
    Index,     // indices: UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT scalars
};

class Accessors {
public:
    // `buffers` holds the bytes of each of the model's buffers, in order.
    Accessors(const tinygltf::Model& model, std::vector<BufferBytes> buffers, const std::string& file, Diagnostics& out)
        : model_(model), buffers_(std::move(buffers)), file_(file), out_(out) {}

    // Adds a diagnostic; returns false so callers can `return error(...)`.
    bool error(const std::string& where, const std::string& message);

    // Validates accessor `index` completely (for `use`, by `usedBy`) before anything reads through it.
    bool view(int index, const std::string& usedBy, AccessorUse use, View& v);

    // Appends the accessor's vec3s to `out`, transformed by `m` and `offset` unless `identity`
    // (and then normalized when `normalize`; untransformed normals are used as given: glTF
    // requires unit length and the shaders renormalize). Non-finite values are refused, also
    // those a transform overflows to. `accessor` names it in diagnostics.
    bool appendVec3s(const View& v, int accessor, const glm::mat3& m, const glm::vec3& offset, bool identity,
                     bool normalize, std::vector<glm::vec3>& out);

    // The index accessor's values (any of the three index types) into `sequence`, each checked to
    // be below `vertexCount`; `where` names the primitive in diagnostics.
    bool readIndices(const View& v, std::size_t vertexCount, int accessor, const std::string& where,
                     std::vector<std::uint32_t>& sequence);

private:
    template <typename Index>
    bool readIndicesOf(const View& v, std::size_t vertexCount, int accessor, const std::string& where,
                       std::vector<std::uint32_t>& sequence);

    const tinygltf::Model& model_;
    std::vector<BufferBytes> buffers_;
    const std::string& file_;
    Diagnostics& out_;
};

} // namespace lab::gltf_detail
