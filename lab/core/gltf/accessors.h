// accessors.h — reading glTF accessors, with every index and byte range proved first.
//
// Internal to gltf*.cpp. tinygltf 2.7.0 accepts accessors that read past their buffer,
// bufferViews larger than their buffer and out-of-range indices; nothing here reads a byte
// before view() has checked the accessor, its bufferView and its buffer (with overflow checks).
// Every refusal is a diagnostic naming the accessor or bufferView.
//
// This file owns the accessor/bufferView/buffer chain and the copies out of it. It does not
// know about nodes, scenes, primitive modes or files (gltf.cpp).
#pragma once

#include "core/io/diagnostics.h"

#include <tiny_gltf.h>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <deque>
#include <unordered_map>
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

// A validated accessor: `count` elements of `components` values of `componentType`, `stride`
// bytes apart from `data`. A sparse accessor, or one without a bufferView (zeros), is read into
// storage of its own first, with its substitutions applied; then it is like any other.
struct AccessorData {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};

// What an accessor must hold to be used where it is. Integer types are KHR_mesh_quantization's
// (and EXT_mesh_gpu_instancing's), read as the specification says: normalized ones map to
// [0, 1] or [-1, 1], others are the integers themselves.
enum class AccessorUse {
    Position,  // VEC3: FLOAT, or BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT (normalized or not)
    Normal,    // VEC3: FLOAT, or normalized BYTE or SHORT
    Index,     // indices: UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT scalars
    Rotation,  // VEC4 (an instance's quaternion): FLOAT, or normalized BYTE or SHORT
};

class Accessors {
public:
    // `buffers` holds the bytes of each of the model's buffers, in order.
    Accessors(const tinygltf::Model& model, std::vector<BufferBytes> buffers, const std::string& file, Diagnostics& out)
        : model_(model), buffers_(std::move(buffers)), file_(file), out_(out) {}

    // Adds a diagnostic; returns false so callers can `return error(...)`.
    bool error(const std::string& where, const std::string& message);

    // Validates accessor `index` completely (for `use`, by `usedBy`) before anything reads through
    // it. A sparse accessor, or one without a bufferView, of more than `maxCount` elements is
    // refused before it is made (a few bytes of JSON could ask for gigabytes); it is made once,
    // then reused. Every other accessor is bounded by its bufferView.
    bool data(int index, const std::string& usedBy, AccessorUse use, std::size_t maxCount, AccessorData& v);

    // Appends the accessor's vec3s (of any type view() accepts) to `out`, transformed by `m`
    // and `offset` unless `identity`. Non-finite values are refused, also those a transform
    // overflows to. `accessor` names it in diagnostics.
    bool appendPositions(const AccessorData& v, int accessor, const glm::mat3& m, const glm::vec3& offset, bool identity,
                         std::vector<glm::vec3>& out);

    // Appends the accessor's normals, transformed by `m` (and normalized) unless `identity`
    // (untransformed normals are used as given: the shaders renormalize). A normal that is not
    // finite, zero, or becomes so under `m`, is appended as (0, 0, 0): the caller computes it.
    // Returns how many there were.
    std::size_t appendNormals(const AccessorData& v, const glm::mat3& m, bool identity, std::vector<glm::vec3>& out);

    // The view's elements as floats, `components` each (what view() accepted, converted).
    std::vector<float> floats(const AccessorData& v);

    // The index accessor's values (any of the three index types) into `sequence`, each checked to
    // be below `vertexCount`; `where` names the primitive in diagnostics.
    bool readIndices(const AccessorData& v, std::size_t vertexCount, int accessor, const std::string& where,
                     std::vector<std::uint32_t>& sequence);

private:
    template <typename Index>
    bool readIndicesOf(const AccessorData& v, std::size_t vertexCount, int accessor, const std::string& where,
                       std::vector<std::uint32_t>& sequence);

    // Where `count` elements of `element` bytes, `stride` apart (0: packed), start at `byteOffset`
    // in bufferView `viewIndex`, proved inside it and its buffer; nullptr after a diagnostic.
    const unsigned char* range(int viewIndex, std::size_t byteOffset, std::size_t count, std::size_t element,
                               std::size_t& stride, const std::string& where);
    // A sparse accessor, or one without a bufferView, made in storage of its own.
    bool materialize(const tinygltf::Accessor& a, const std::string& where, std::size_t element, AccessorData& v);

    const tinygltf::Model& model_;
    std::vector<BufferBytes> buffers_;
    const std::string& file_;
    Diagnostics& out_;
    std::deque<std::vector<unsigned char>> made_; // materialized accessors
    std::unordered_map<int, AccessorData> madeData_;      // ...by accessor index
};

} // namespace lab::gltf_detail
