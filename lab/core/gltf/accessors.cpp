// accessors.cpp — accessor views proved in bounds, and the copies out of them.
#include "core/gltf/accessors.h"

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

bool isInteger8or16(int t) {
    return t == TINYGLTF_COMPONENT_TYPE_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           t == TINYGLTF_COMPONENT_TYPE_SHORT || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

bool holds(const tinygltf::Accessor& a, AccessorUse use) {
    const int t = a.componentType;
    const bool isFloat = t == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool signedNormalized = a.normalized && (t == TINYGLTF_COMPONENT_TYPE_BYTE || t == TINYGLTF_COMPONENT_TYPE_SHORT);
    switch (use) {
    case AccessorUse::Position: return a.type == TINYGLTF_TYPE_VEC3 && (isFloat || isInteger8or16(t));
    case AccessorUse::Normal: return a.type == TINYGLTF_TYPE_VEC3 && (isFloat || signedNormalized);
    case AccessorUse::Rotation: return a.type == TINYGLTF_TYPE_VEC4 && (isFloat || signedNormalized);
    case AccessorUse::Index:
        return a.type == TINYGLTF_TYPE_SCALAR && !a.normalized &&
               (t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    }
    return false;
}

const char* expectedFor(AccessorUse use) {
    switch (use) {
    case AccessorUse::Position: return "VEC3 of FLOAT, or of BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT (KHR_mesh_quantization)";
    case AccessorUse::Normal: return "VEC3 of FLOAT, or of normalized BYTE or SHORT (KHR_mesh_quantization)";
    case AccessorUse::Rotation: return "VEC4 of FLOAT, or of normalized BYTE or SHORT";
    case AccessorUse::Index: return "UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT SCALAR";
    }
    return "";
}

// One component as a float, as glTF defines it: normalized integers map to [0, 1] (unsigned)
// or [-1, 1] (signed, the lowest value clamped), others are their value.
float component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        std::int8_t c;
        std::memcpy(&c, p, 1);
        return normalized ? std::max(c / 127.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0f : *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t c;
        std::memcpy(&c, p, 2);
        return normalized ? std::max(c / 32767.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t c;
        std::memcpy(&c, p, 2);
        return normalized ? c / 65535.0f : c;
    }
    default: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    }
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
template <typename T, typename U> void append(const AccessorData& v, std::vector<U>& out) {
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

const unsigned char* Accessors::range(int viewIndex, std::size_t byteOffset, std::size_t count, std::size_t element,
                                      std::size_t& stride, const std::string& where) {
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model_.bufferViews.size()) {
        error(where, "bufferView " + std::to_string(viewIndex) + " does not exist");
        return nullptr;
    }
    const tinygltf::BufferView& bv = model_.bufferViews[static_cast<std::size_t>(viewIndex)];
    std::string bvWhere = "bufferViews[" + std::to_string(viewIndex) + "]";
    if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= buffers_.size()) {
        error(bvWhere, "buffer " + std::to_string(bv.buffer) + " does not exist");
        return nullptr;
    }
    const BufferBytes& buffer = buffers_[static_cast<std::size_t>(bv.buffer)];
    if (bv.byteOffset > buffer.size || bv.byteLength > buffer.size - bv.byteOffset) {
        error(bvWhere, "byte range [" + std::to_string(bv.byteOffset) + ", +" + std::to_string(bv.byteLength) +
                           ") lies beyond its buffer of " + std::to_string(buffer.size) + " bytes");
        return nullptr;
    }
    if (stride != 0 && bv.byteStride) {
        stride = bv.byteStride;
        if (bv.byteStride < element || bv.byteStride > 252 || bv.byteStride % 4 != 0) {
            error(bvWhere, "byteStride " + std::to_string(bv.byteStride) + " is invalid for elements of " +
                               std::to_string(element) + " bytes");
            return nullptr;
        }
    } else {
        stride = element;
    }
    // The last element ends at byteOffset + stride * (count - 1) + element; compute it without overflow.
    std::size_t span = 0;
    if (count == 0 || __builtin_mul_overflow(stride, count - 1, &span) || __builtin_add_overflow(span, element, &span) ||
        __builtin_add_overflow(span, byteOffset, &span) || span > bv.byteLength) {
        error(where, "reads beyond its bufferView (" + std::to_string(count) + " elements from byte " +
                         std::to_string(byteOffset) + " need more than the view's " + std::to_string(bv.byteLength) +
                         " bytes)");
        return nullptr;
    }
    return buffer.data + bv.byteOffset + byteOffset;
}

bool Accessors::materialize(const tinygltf::Accessor& a, const std::string& where, std::size_t element, AccessorData& v) {
    std::vector<unsigned char> bytes(a.count * element); // zeros, when there is no bufferView
    if (a.bufferView >= 0) {
        std::size_t stride = 1; // the view's own
        const unsigned char* base = range(a.bufferView, a.byteOffset, a.count, element, stride, where);
        if (!base) {
            return false;
        }
        for (std::size_t i = 0; i < a.count; ++i) {
            std::memcpy(bytes.data() + i * element, base + i * stride, element);
        }
    }
    if (a.sparse.isSparse) {
        const std::string sparseWhere = where + ".sparse";
        const auto& s = a.sparse;
        const int it = s.indices.componentType;
        const std::size_t indexSize = it == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                                      : it == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                                      : it == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4 : 0;
        if (indexSize == 0) {
            return error(sparseWhere + ".indices", "componentType " + std::to_string(it) +
                                                       " is not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
        }
        if (s.count < 1 || static_cast<std::size_t>(s.count) > a.count) {
            return error(sparseWhere, "count " + std::to_string(s.count) + " is not between 1 and the accessor's " +
                                          std::to_string(a.count) + " elements");
        }
        const auto n = static_cast<std::size_t>(s.count);
        if (s.indices.byteOffset < 0 || s.values.byteOffset < 0) {
            return error(sparseWhere + (s.indices.byteOffset < 0 ? ".indices" : ".values"), "byteOffset is negative");
        }
        std::size_t packed = 0; // sparse arrays are tightly packed
        const unsigned char* indices =
            range(s.indices.bufferView, static_cast<std::size_t>(s.indices.byteOffset), n, indexSize, packed, sparseWhere + ".indices");
        packed = 0;
        const unsigned char* values = indices ? range(s.values.bufferView, static_cast<std::size_t>(s.values.byteOffset), n,
                                                      element, packed, sparseWhere + ".values")
                                              : nullptr;
        if (!indices || !values) {
            return false;
        }
        for (std::size_t i = 0; i < n; ++i) {
            std::uint32_t target = 0;
            std::memcpy(&target, indices + i * indexSize, indexSize); // little-endian, as glTF
            if (target >= a.count) {
                return error(sparseWhere + ".indices", "index " + std::to_string(target) + " at element " + std::to_string(i) +
                                                           " is beyond the accessor's " + std::to_string(a.count) + " elements");
            }
            std::memcpy(bytes.data() + target * element, values + i * element, element);
        }
    }
    made_.push_back(std::move(bytes));
    v.data = made_.back().data();
    v.stride = element;
    return true;
}

bool Accessors::data(int index, const std::string& usedBy, AccessorUse use, std::size_t maxCount, AccessorData& v) {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
        return error(usedBy, "accessor " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    std::string where = "accessors[" + std::to_string(index) + "]";
    if (!holds(a, use)) {
        return error(where, std::string("bad component type or type for ") + usedBy + ": expected " + expectedFor(use));
    }
    if (a.count == 0) {
        return error(where, "count is 0");
    }
    const std::size_t element = componentSize(a.componentType) * componentCount(a.type);
    v.count = a.count;
    v.componentType = a.componentType;
    v.components = static_cast<int>(componentCount(a.type));
    v.normalized = a.normalized;
    if (a.sparse.isSparse || a.bufferView < 0) {
        if (auto made = madeData_.find(index); made != madeData_.end()) {
            v = made->second;
            return true;
        }
        // Made before it is read: bounded first (a bufferView bounds every other accessor).
        if (a.count > maxCount) {
            return error(where, std::to_string(a.count) + " elements for " + usedBy + ": the lab reads at most " +
                                    std::to_string(maxCount) + " there");
        }
        if (!materialize(a, where, element, v)) {
            return false;
        }
        madeData_[index] = v;
        return true;
    }
    std::size_t stride = 1; // the view's own
    v.data = range(a.bufferView, a.byteOffset, a.count, element, stride, where);
    v.stride = stride;
    return v.data != nullptr;
}

// The loops are written to vectorize: a model of a million triangles is mostly this copy.
std::vector<float> Accessors::floats(const AccessorData& v) {
    const auto n = static_cast<std::size_t>(v.components);
    const std::size_t size = componentSize(v.componentType);
    std::vector<float> out(v.count * n);
    for (std::size_t i = 0; i < v.count; ++i) {
        for (std::size_t k = 0; k < n; ++k) {
            out[i * n + k] = component(v.data + i * v.stride + k * size, v.componentType, v.normalized);
        }
    }
    return out;
}

bool Accessors::appendPositions(const AccessorData& v, int accessor, const glm::mat3& m, const glm::vec3& offset,
                                bool identity, std::vector<glm::vec3>& out) {
    const std::string where = "accessors[" + std::to_string(accessor) + "]";
    std::size_t first = out.size();
    if (v.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        append<glm::vec3>(v, out);
    } else { // quantized (KHR_mesh_quantization): every integer is a finite float
        out.reserve(first + v.count);
        const std::size_t size = componentSize(v.componentType);
        for (std::size_t i = 0; i < v.count; ++i) {
            const unsigned char* p = v.data + i * v.stride;
            out.emplace_back(component(p, v.componentType, v.normalized), component(p + size, v.componentType, v.normalized),
                             component(p + 2 * size, v.componentType, v.normalized));
        }
    }
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

std::size_t Accessors::appendNormals(const AccessorData& v, const glm::mat3& m, bool identity, std::vector<glm::vec3>& out) {
    std::size_t first = out.size();
    if (v.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        append<glm::vec3>(v, out);
    } else {
        out.reserve(first + v.count);
        const std::size_t size = componentSize(v.componentType);
        for (std::size_t i = 0; i < v.count; ++i) {
            const unsigned char* p = v.data + i * v.stride;
            out.emplace_back(component(p, v.componentType, true), component(p + size, v.componentType, true),
                             component(p + 2 * size, v.componentType, true));
        }
    }
    glm::vec3* dst = out.data() + first;
    const bool anyBad = anyNonFinite(dst, 3 * v.count);
    if (identity && !anyBad && v.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        // The common case, at memory speed: only zero normals are left to find.
        std::size_t zero = 0;
        for (std::size_t i = 0; i < v.count; ++i) {
            zero += dst[i] == glm::vec3(0.0f);
        }
        return zero;
    }
    std::size_t bad = 0;
    for (std::size_t i = 0; i < v.count; ++i) {
        glm::vec3 n = identity ? dst[i] : m * dst[i];
        float len = glm::length(n);
        if (!std::isfinite(len) || !(len > 0.0f)) {
            dst[i] = glm::vec3(0.0f);
            ++bad;
        } else {
            dst[i] = identity ? n : n / len;
        }
    }
    return bad;
}


template <typename Index>
bool Accessors::readIndicesOf(const AccessorData& v, std::size_t vertexCount, int accessor, const std::string& where,
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


bool Accessors::readIndices(const AccessorData& v, std::size_t vertexCount, int accessor, const std::string& where,
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
