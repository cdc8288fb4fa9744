// gltf_accessors.cpp — accessor views proved in bounds, and the copies out of them.
#include "core/gltf_accessors.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <type_traits>

namespace lab::gltf_detail {

namespace {

std::size_t componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

std::size_t componentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

bool holds(const tinygltf::Accessor& a, AccessorUse use) {
    if (use == AccessorUse::FloatVec3) {
        return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT && a.type == TINYGLTF_TYPE_VEC3;
    }
    return a.type == TINYGLTF_TYPE_SCALAR && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                              a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                              a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
}

const char* expectedFor(AccessorUse use) {
    return use == AccessorUse::FloatVec3 ? "FLOAT VEC3" : "UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT SCALAR";
}

// The elements of a validated view as an iterator (each read with memcpy, at any alignment), so
// that a vector is filled by insert() in one pass: resize() would first zero-fill what is then
// overwritten, a second pass over a large model's arrays.
template <typename T> class Elements {
public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = const T*;
    using reference = T;

    Elements(const unsigned char* at, std::size_t stride) : at_(at), stride_(stride) {}
    T operator*() const {
        T x;
        std::memcpy(&x, at_, sizeof x);
        return x;
    }
    T operator[](difference_type n) const { return *(*this + n); }
    Elements& operator++() {
        at_ += stride_;
        return *this;
    }
    Elements operator++(int) {
        Elements old = *this;
        ++*this;
        return old;
    }
    Elements& operator--() {
        at_ -= stride_;
        return *this;
    }
    Elements& operator+=(difference_type n) {
        at_ += n * static_cast<difference_type>(stride_);
        return *this;
    }
    friend Elements operator+(Elements e, difference_type n) { return e += n; }
    friend difference_type operator-(const Elements& x, const Elements& y) {
        return (x.at_ - y.at_) / static_cast<difference_type>(x.stride_);
    }
    friend bool operator==(const Elements& x, const Elements& y) { return x.at_ == y.at_; }
    friend bool operator!=(const Elements& x, const Elements& y) { return x.at_ != y.at_; }
    friend bool operator<(const Elements& x, const Elements& y) { return x.at_ < y.at_; }

private:
    const unsigned char* at_;
    std::size_t stride_;
};

// Appends the view's `count` elements of T to `out`, converted to U, in one pass: one memmove
// where they are packed and aligned as U already (a well-formed GLB's arrays are).
template <typename T, typename U> void append(const View& v, std::vector<U>& out) {
    if constexpr (std::is_same_v<T, U>) {
        if (v.stride == sizeof(T) && reinterpret_cast<std::uintptr_t>(v.data) % alignof(T) == 0) {
            const auto* packed = reinterpret_cast<const T*>(v.data);
            out.insert(out.end(), packed, packed + v.count);
            return;
        }
    }
    const Elements<T> first(v.data, v.stride);
    out.insert(out.end(), first, first + static_cast<std::ptrdiff_t>(v.count));
}

// Checks over a large model's arrays at memory speed: 4 words at a time in the vector extension
// GCC and Clang share (plain loops of unknown length stay scalar at -O2), read with memcpy (any
// alignment), the last few words one by one.
using Words = std::uint32_t __attribute__((vector_size(16)));
constexpr std::size_t kWords = sizeof(Words) / sizeof(std::uint32_t);

Words wordsAt(const unsigned char* bytes, std::size_t i) {
    Words w;
    std::memcpy(&w, bytes + 4 * i, sizeof w);
    return w;
}

std::uint32_t wordAt(const unsigned char* bytes, std::size_t i) {
    std::uint32_t w;
    std::memcpy(&w, bytes + 4 * i, 4);
    return w;
}

// Whether any of n 32-bit words is `limit` or more. SSE2 has no unsigned comparison: with the
// top bit flipped on both sides, the signed one orders them the same way.
bool anyAtLeast(const void* words, std::size_t n, std::uint32_t limit) {
    using Signed = std::int32_t __attribute__((vector_size(16)));
    constexpr std::uint32_t kFlip = 0x80000000u;
    const auto* bytes = static_cast<const unsigned char*>(words);
    if (limit == 0) {
        return n > 0;
    }
    const auto largestAllowed = static_cast<std::int32_t>((limit - 1) ^ kFlip);
    Signed any = {};
    std::size_t i = 0;
    for (; i + kWords <= n; i += kWords) {
        any |= reinterpret_cast<Signed>(wordsAt(bytes, i) ^ kFlip) > largestAllowed;
    }
    std::int32_t result = 0;
    for (std::size_t k = 0; k < kWords; ++k) {
        result |= any[k];
    }
    for (; i < n; ++i) {
        result |= wordAt(bytes, i) >= limit;
    }
    return result != 0;
}

// Whether any of n floats (as their 32-bit patterns) is infinite or NaN: all exponent bits set.
bool anyNonFinite(const void* floats, std::size_t n) {
    constexpr std::uint32_t kExponent = 0x7F800000u;
    const auto* bytes = static_cast<const unsigned char*>(floats);
    Words any = {};
    std::size_t i = 0;
    for (; i + kWords <= n; i += kWords) {
        any |= (wordsAt(bytes, i) & kExponent) == kExponent;
    }
    std::uint32_t result = 0;
    for (std::size_t k = 0; k < kWords; ++k) {
        result |= any[k];
    }
    for (; i < n; ++i) {
        result |= (wordAt(bytes, i) & kExponent) == kExponent;
    }
    return result != 0;
}

} // namespace

bool Accessors::error(const std::string& where, const std::string& message) {
    out_.push_back({file_, where, message});
    return false;
}

bool Accessors::view(int index, const std::string& usedBy, AccessorUse use, View& v) {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
        return error(usedBy, "accessor " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    std::string where = "accessors[" + std::to_string(index) + "]";
    if (a.sparse.isSparse) {
        return error(where, "sparse accessors are not supported");
    }
    if (!holds(a, use)) {
        return error(where, std::string("bad component type or type for ") + usedBy + ": expected " + expectedFor(use));
    }
    if (a.count == 0) {
        return error(where, "count is 0");
    }
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model_.bufferViews.size()) {
        return error(where, "bufferView " + std::to_string(a.bufferView) + " does not exist");
    }
    const tinygltf::BufferView& bv = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    std::string bvWhere = "bufferViews[" + std::to_string(a.bufferView) + "]";
    if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= buffers_.size()) {
        return error(bvWhere, "buffer " + std::to_string(bv.buffer) + " does not exist");
    }
    const BufferBytes& buffer = buffers_[static_cast<std::size_t>(bv.buffer)];
    if (bv.byteOffset > buffer.size || bv.byteLength > buffer.size - bv.byteOffset) {
        return error(bvWhere, "byte range [" + std::to_string(bv.byteOffset) + ", +" +
                                  std::to_string(bv.byteLength) + ") lies beyond its buffer of " +
                                  std::to_string(buffer.size) + " bytes");
    }
    std::size_t element = componentSize(a.componentType) * componentCount(a.type);
    std::size_t stride = bv.byteStride ? bv.byteStride : element;
    if (bv.byteStride && (bv.byteStride < element || bv.byteStride > 252 || bv.byteStride % 4 != 0)) {
        return error(bvWhere, "byteStride " + std::to_string(bv.byteStride) + " is invalid for elements of " +
                                  std::to_string(element) + " bytes");
    }
    // The last element ends at byteOffset + stride * (count - 1) + element; compute it without overflow.
    std::size_t span = 0;
    if (__builtin_mul_overflow(stride, a.count - 1, &span) || __builtin_add_overflow(span, element, &span) ||
        __builtin_add_overflow(span, a.byteOffset, &span) || span > bv.byteLength) {
        return error(where, "reads beyond its bufferView (" + std::to_string(a.count) + " elements from byte " +
                                std::to_string(a.byteOffset) + " need more than the view's " +
                                std::to_string(bv.byteLength) + " bytes)");
    }
    v.data = buffer.data + bv.byteOffset + a.byteOffset;
    v.stride = stride;
    v.count = a.count;
    v.componentType = a.componentType;
    return true;
}


// The loops are written to vectorize: a model of a million triangles is mostly this copy.
bool Accessors::appendVec3s(const View& v, int accessor, const glm::mat3& m, const glm::vec3& offset, bool identity,
                            bool normalize, std::vector<glm::vec3>& out) {
    const std::string where = "accessors[" + std::to_string(accessor) + "]";
    std::size_t first = out.size();
    append<glm::vec3>(v, out);
    glm::vec3* dst = out.data() + first;
    // Infinity and NaN are the values whose exponent bits are all ones.
    if (anyNonFinite(dst, 3 * v.count)) {
        std::size_t bad = 0;
        while (std::isfinite(dst[bad].x) && std::isfinite(dst[bad].y) && std::isfinite(dst[bad].z)) {
            ++bad;
        }
        out.resize(first);
        return error(where, "element " + std::to_string(bad) + " is not a finite number");
    }
    if (!identity) {
        bool finite = true;
        for (std::size_t i = 0; i < v.count; ++i) {
            glm::vec3 p = m * dst[i] + offset;
            if (normalize) {
                float len = glm::length(p);
                p = len > 0.0f ? p / len : glm::vec3(0, 0, 1);
            }
            finite &= std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
            dst[i] = p;
        }
        // Finite input can overflow under a node's scale (found by fuzz_gltf).
        if (!finite) {
            out.resize(first);
            return error(where, "values overflow to infinity under the node's transform");
        }
    }
    return true;
}


template <typename Index>
bool Accessors::readIndicesOf(const View& v, std::size_t vertexCount, int accessor, const std::string& where,
                              std::vector<std::uint32_t>& sequence) {
    sequence.clear();
    append<Index>(v, sequence);
    const std::uint32_t* dst = sequence.data();
    if (vertexCount <= 0xFFFFFFFFu && anyAtLeast(dst, v.count, static_cast<std::uint32_t>(vertexCount))) {
        std::size_t i = 0;
        while (dst[i] < vertexCount) {
            ++i;
        }
        return error("accessors[" + std::to_string(accessor) + "]",
                     "index " + std::to_string(dst[i]) + " at element " + std::to_string(i) + " is beyond the " +
                         std::to_string(vertexCount) + " vertices of " + where);
    }
    return true;
}


bool Accessors::readIndices(const View& v, std::size_t vertexCount, int accessor, const std::string& where,
                            std::vector<std::uint32_t>& sequence) {
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return readIndicesOf<std::uint8_t>(v, vertexCount, accessor, where, sequence);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return readIndicesOf<std::uint16_t>(v, vertexCount, accessor, where, sequence);
    default: return readIndicesOf<std::uint32_t>(v, vertexCount, accessor, where, sequence);
    }
}

} // namespace lab::gltf_detail
