// gltf.cpp — glTF 2.0 through tinygltf, with the bounds checks tinygltf leaves out.
#include "core/gltf.h"

#include "core/file_io.h"
#include "core/paths.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace lab {

namespace fs = std::filesystem;

namespace {

//----------------------------------------------------------------------------------------
// File access: only regular files inside the model's folder
//----------------------------------------------------------------------------------------

struct FileGuard {
    fs::path folder; // canonical
    std::size_t maxBytes = 0;
    std::string refusal; // why the first refused file was refused, for the diagnostic

    // tinygltf tries the model's folder first, then the process's working folder; the first
    // answer is the one that explains the failure.
    bool refuse(const char* why) {
        if (refusal.empty()) {
            refusal = why;
        }
        return false;
    }
};

// tinygltf joins the base folder and the URI and asks whether that exists. Answer "no" for
// anything that leaves the folder or is not a regular file, and remember why.
bool guardedFileExists(const std::string& path, void* user) {
    auto* guard = static_cast<FileGuard*>(user);
    std::optional<fs::path> relative = relativeInside(guard->folder, fs::path(path));
    if (!relative) {
        return guard->refuse("leaves the model's folder");
    }
    std::error_code ec;
    fs::file_status status = fs::status(guard->folder / *relative, ec);
    if (!fs::exists(status)) {
        return guard->refuse("file not found");
    }
    if (!fs::is_regular_file(status)) {
        return guard->refuse("not a regular file");
    }
    return true;
}

// The default expands with wordexp(), which would run `$(...)` found in a URI. Never expand.
std::string noExpansion(const std::string& path, void*) { return path; }

bool guardedReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    auto* guard = static_cast<FileGuard*>(user);
    if (!guardedFileExists(path, user)) {
        if (err) {
            *err += guard->refusal;
        }
        return false;
    }
    std::string error;
    std::optional<std::string> bytes = readFile(path, guard->maxBytes, error);
    if (!bytes) {
        guard->refuse(error.c_str()); // copied before `error` goes
        if (err) {
            *err += error;
        }
        return false;
    }
    out->assign(bytes->begin(), bytes->end());
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) {
        *err += "the lab never writes glTF files";
    }
    return false;
}

// The lab ignores glTF images; count them so the user can be told.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void* user) {
    ++*static_cast<int*>(user);
    return true;
}

//----------------------------------------------------------------------------------------
// Bounds-checked accessor views
//----------------------------------------------------------------------------------------

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

struct View {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
};

class Loader {
public:
    Loader(const tinygltf::Model& model, const std::string& file, Diagnostics& out, const GltfLimits& limits)
        : model_(model), file_(file), out_(out), limits_(limits) {}

    bool error(const std::string& where, const std::string& message) {
        out_.push_back({file_, where, message});
        return false;
    }

    // Validates accessor `index` completely before anything reads through it.
    bool view(int index, const std::string& usedBy, bool (*typeOk)(int componentType, int type), const char* expected,
              View& v) {
        if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
            return error(usedBy, "accessor " + std::to_string(index) + " does not exist");
        }
        const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
        std::string where = "accessors[" + std::to_string(index) + "]";
        if (a.sparse.isSparse) {
            return error(where, "sparse accessors are not supported");
        }
        if (!typeOk(a.componentType, a.type)) {
            return error(where, std::string("bad component type or type for ") + usedBy + ": expected " + expected);
        }
        if (a.count == 0) {
            return error(where, "count is 0");
        }
        if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model_.bufferViews.size()) {
            return error(where, "bufferView " + std::to_string(a.bufferView) + " does not exist");
        }
        const tinygltf::BufferView& bv = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
        std::string bvWhere = "bufferViews[" + std::to_string(a.bufferView) + "]";
        if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model_.buffers.size()) {
            return error(bvWhere, "buffer " + std::to_string(bv.buffer) + " does not exist");
        }
        const std::vector<unsigned char>& buffer = model_.buffers[static_cast<std::size_t>(bv.buffer)].data;
        if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() - bv.byteOffset) {
            return error(bvWhere, "byte range [" + std::to_string(bv.byteOffset) + ", +" +
                                      std::to_string(bv.byteLength) + ") lies beyond its buffer of " +
                                      std::to_string(buffer.size()) + " bytes");
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
        v.data = buffer.data() + bv.byteOffset + a.byteOffset;
        v.stride = stride;
        v.count = a.count;
        v.componentType = a.componentType;
        return true;
    }

    static bool isFloatVec3(int componentType, int type) {
        return componentType == TINYGLTF_COMPONENT_TYPE_FLOAT && type == TINYGLTF_TYPE_VEC3;
    }
    static bool isIndex(int componentType, int type) {
        return type == TINYGLTF_TYPE_SCALAR && (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                                componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    }

    // Appends the accessor's vec3s to `out`, transformed by `m` unless it is the identity (and
    // then normalized when `normalize`; untransformed normals are used as given: glTF requires
    // unit length and the shaders renormalize). Non-finite input is refused. The loops are
    // written to vectorize: a model of a million triangles is mostly this copy.
    bool appendVec3s(const View& v, const std::string& where, const glm::mat3& m, const glm::vec3& offset,
                     bool identity, bool normalize, std::vector<glm::vec3>& out) {
        std::size_t first = out.size();
        out.resize(first + v.count);
        glm::vec3* dst = out.data() + first;
        if (v.stride == sizeof(glm::vec3)) {
            std::memcpy(static_cast<void*>(dst), v.data, v.count * sizeof(glm::vec3));
        } else {
            for (std::size_t i = 0; i < v.count; ++i) {
                std::memcpy(static_cast<void*>(dst + i), v.data + i * v.stride, sizeof(glm::vec3));
            }
        }
        // Infinity and NaN are the values whose exponent bits are all ones.
        const auto* bits = reinterpret_cast<const std::uint32_t*>(dst);
        std::uint32_t nonFinite = 0;
        for (std::size_t i = 0; i < 3 * v.count; ++i) {
            nonFinite |= static_cast<std::uint32_t>((bits[i] & 0x7F800000u) == 0x7F800000u);
        }
        if (nonFinite) {
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

    // The primitive's vertex order (its indices), checked against the vertex count.
    template <typename Index>
    bool readIndices(const View& v, std::size_t vertexCount, int accessor, const std::string& where,
                     std::vector<std::uint32_t>& sequence) {
        sequence.resize(v.count);
        std::uint32_t* dst = sequence.data();
        std::uint32_t largest = 0;
        if (v.stride == sizeof(Index)) {
            const auto* src = reinterpret_cast<const unsigned char*>(v.data);
            for (std::size_t i = 0; i < v.count; ++i) {
                Index x;
                std::memcpy(&x, src + i * sizeof(Index), sizeof x);
                dst[i] = x;
                largest = std::max<std::uint32_t>(largest, x);
            }
        } else {
            for (std::size_t i = 0; i < v.count; ++i) {
                Index x;
                std::memcpy(&x, v.data + i * v.stride, sizeof x);
                dst[i] = x;
                largest = std::max<std::uint32_t>(largest, x);
            }
        }
        if (largest >= vertexCount) {
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

    // Appends primitive `pi` of mesh `mi` under the world matrix to the output mesh. Each array
    // is read once and written once, straight into the output (large models are mostly copying).
    bool addPrimitive(std::size_t mi, std::size_t pi, const glm::mat4& world, Mesh& out, GltfResult& result) {
        const tinygltf::Primitive& prim = model_.meshes[mi].primitives[pi];
        std::string where = "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) + "]";
        int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            result.notes.push_back(where + ": skipped (points or lines, not triangles)");
            return true;
        }
        auto pos = prim.attributes.find("POSITION");
        if (pos == prim.attributes.end()) {
            return error(where, "has no POSITION attribute");
        }
        View positions;
        if (!view(pos->second, where + ".attributes.POSITION", isFloatVec3, "FLOAT VEC3", positions)) {
            return false;
        }
        if (positions.count > limits_.maxVertices - std::min(limits_.maxVertices, out.positions.size())) {
            return error(where, "more than " + std::to_string(limits_.maxVertices) + " vertices in the model");
        }
        View normals;
        auto nrm = prim.attributes.find("NORMAL");
        bool hasNormals = nrm != prim.attributes.end();
        if (hasNormals) {
            if (!view(nrm->second, where + ".attributes.NORMAL", isFloatVec3, "FLOAT VEC3", normals)) {
                return false;
            }
            if (normals.count != positions.count) {
                return error(where, "NORMAL has " + std::to_string(normals.count) + " elements but POSITION has " +
                                        std::to_string(positions.count));
            }
        }

        // The vertex order, then triangles (strips and fans unrolled).
        std::vector<std::uint32_t> sequence;
        if (prim.indices >= 0) {
            View indices;
            if (!view(prim.indices, where + ".indices", isIndex, "UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT SCALAR",
                      indices)) {
                return false;
            }
            if (indices.count > 3 * limits_.maxTriangles) {
                return error(where, "more than " + std::to_string(limits_.maxTriangles) + " triangles");
            }
            bool ok = indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
                          ? readIndices<std::uint8_t>(indices, positions.count, prim.indices, where, sequence)
                      : indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                          ? readIndices<std::uint16_t>(indices, positions.count, prim.indices, where, sequence)
                          : readIndices<std::uint32_t>(indices, positions.count, prim.indices, where, sequence);
            if (!ok) {
                return false;
            }
        } else {
            sequence.resize(positions.count);
            for (std::size_t i = 0; i < positions.count; ++i) {
                sequence[i] = static_cast<std::uint32_t>(i);
            }
        }
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            sequence.resize(sequence.size() - sequence.size() % 3);
        } else {
            std::vector<std::uint32_t> triangles;
            triangles.reserve(sequence.size() >= 2 ? 3 * (sequence.size() - 2) : 0);
            for (std::size_t i = 2; i < sequence.size(); ++i) {
                if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
                    triangles.insert(triangles.end(), {sequence[0], sequence[i - 1], sequence[i]});
                } else if (i % 2 == 0) {
                    triangles.insert(triangles.end(), {sequence[i - 2], sequence[i - 1], sequence[i]});
                } else {
                    triangles.insert(triangles.end(), {sequence[i - 1], sequence[i - 2], sequence[i]});
                }
            }
            sequence.swap(triangles);
        }
        if (sequence.empty()) {
            result.notes.push_back(where + ": skipped (no complete triangle)");
            return true;
        }
        if (sequence.size() / 3 > limits_.maxTriangles - std::min(limits_.maxTriangles, out.triangleCount())) {
            return error(where, "more than " + std::to_string(limits_.maxTriangles) + " triangles in the model");
        }

        // Vertices: straight into the output, transformed by the node's world matrix.
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        const bool identity = world == glm::mat4(1.0f);
        if (!appendVec3s(positions, "accessors[" + std::to_string(pos->second) + "]", glm::mat3(world),
                         glm::vec3(world[3]), identity, false, out.positions)) {
            return false;
        }
        if (hasNormals) {
            glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
            if (!appendVec3s(normals, "accessors[" + std::to_string(nrm->second) + "]", normalMatrix, glm::vec3(0.0f),
                             identity, true, out.normals)) {
                out.positions.resize(base);
                return false;
            }
        } else {
            // Computed after the node transform, so the area weights are those of the model as drawn.
            std::vector<glm::vec3> own(out.positions.begin() + base, out.positions.end());
            std::vector<glm::vec3> computed = computeVertexNormals(own, sequence);
            out.normals.insert(out.normals.end(), computed.begin(), computed.end());
            ++computedNormals_;
        }
        if (base == 0 && out.indices.empty()) {
            out.indices = std::move(sequence);
        } else {
            out.indices.reserve(out.indices.size() + sequence.size());
            for (std::uint32_t i : sequence) {
                out.indices.push_back(base + i);
            }
        }
        return true;
    }

    bool nodeMatrix(const tinygltf::Node& node, const std::string& where, glm::mat4& m) {
        auto finite = [](const std::vector<double>& v) {
            return std::all_of(v.begin(), v.end(), [](double d) { return std::isfinite(d); });
        };
        if (!finite(node.matrix) || !finite(node.translation) || !finite(node.rotation) || !finite(node.scale)) {
            return error(where, "transform has a non-finite number");
        }
        if (!node.matrix.empty()) {
            if (node.matrix.size() != 16) {
                return error(where, "matrix must have 16 numbers");
            }
            for (int c = 0; c < 4; ++c) {
                for (int r = 0; r < 4; ++r) {
                    m[c][r] = static_cast<float>(node.matrix[static_cast<std::size_t>(c * 4 + r)]);
                }
            }
            return true;
        }
        glm::mat4 t(1.0f), r(1.0f), s(1.0f);
        if (!node.translation.empty()) {
            if (node.translation.size() != 3) {
                return error(where, "translation must have 3 numbers");
            }
            t[3] = glm::vec4(glm::vec3(node.translation[0], node.translation[1], node.translation[2]), 1.0f);
        }
        if (!node.rotation.empty()) {
            if (node.rotation.size() != 4) {
                return error(where, "rotation must have 4 numbers");
            }
            glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                        static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
            r = glm::mat4_cast(glm::normalize(q));
        }
        if (!node.scale.empty()) {
            if (node.scale.size() != 3) {
                return error(where, "scale must have 3 numbers");
            }
            s = glm::scale(glm::mat4(1.0f), glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
        }
        m = t * r * s;
        return true;
    }

    bool visit(int index, const glm::mat4& parent, std::vector<char>& onPath, int depth, Mesh& out, GltfResult& result) {
        std::string where = "nodes[" + std::to_string(index) + "]";
        if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size()) {
            return error(where, "node does not exist");
        }
        if (depth > limits_.maxNodeDepth) {
            return error(where, "node hierarchy deeper than " + std::to_string(limits_.maxNodeDepth));
        }
        auto i = static_cast<std::size_t>(index);
        if (onPath[i]) {
            return error(where, "node cycle: the node is its own ancestor");
        }
        const tinygltf::Node& node = model_.nodes[i];
        glm::mat4 local(1.0f);
        if (!nodeMatrix(node, where, local)) {
            return false;
        }
        glm::mat4 world = parent * local;
        if (node.mesh >= 0) {
            if (static_cast<std::size_t>(node.mesh) >= model_.meshes.size()) {
                return error(where, "mesh " + std::to_string(node.mesh) + " does not exist");
            }
            if (std::abs(glm::determinant(glm::mat3(world))) < 1e-20f) {
                result.notes.push_back(where + ": skipped (its transform collapses the mesh)");
            } else {
                auto mi = static_cast<std::size_t>(node.mesh);
                for (std::size_t pi = 0; pi < model_.meshes[mi].primitives.size(); ++pi) {
                    if (!addPrimitive(mi, pi, world, out, result)) {
                        return false;
                    }
                }
            }
        }
        onPath[i] = 1;
        for (int child : node.children) {
            if (!visit(child, world, onPath, depth + 1, out, result)) {
                return false;
            }
        }
        onPath[i] = 0;
        return true;
    }

    int computedNormals() const { return computedNormals_; }

private:
    const tinygltf::Model& model_;
    const std::string& file_;
    Diagnostics& out_;
    const GltfLimits& limits_;
    int computedNormals_ = 0;
};

// tinygltf 2.7.0 trusts the GLB header's lengths; check them against the bytes we have.
bool checkGlbHeader(std::string_view bytes, std::string& error) {
    auto u32 = [&](std::size_t at) {
        std::uint32_t v;
        std::memcpy(&v, bytes.data() + at, 4);
        return v;
    };
    if (bytes.size() < 20 || std::memcmp(bytes.data(), "glTF", 4) != 0) {
        error = "not a GLB file (no \"glTF\" header)";
        return false;
    }
    if (u32(4) != 2) {
        error = "GLB version " + std::to_string(u32(4)) + " (expected 2)";
        return false;
    }
    if (u32(8) != bytes.size()) {
        error = "GLB header claims " + std::to_string(u32(8)) + " bytes but the file has " + std::to_string(bytes.size());
        return false;
    }
    std::uint64_t chunk = u32(12);
    if (20 + chunk > bytes.size() || u32(16) != 0x4E4F534Au /* "JSON" */) {
        error = "GLB JSON chunk is missing or runs past the end of the file";
        return false;
    }
    std::uint64_t at = 20 + ((chunk + 3) & ~std::uint64_t{3});
    if (at + 8 <= bytes.size()) {
        std::uint64_t binLength = u32(static_cast<std::size_t>(at));
        if (at + 8 + binLength > bytes.size()) {
            error = "GLB BIN chunk claims " + std::to_string(binLength) + " bytes, more than the file holds";
            return false;
        }
    }
    return true;
}

// Refuses, with the URI and its JSON path, every buffer or image URI that is absolute, has a
// scheme, or climbs out of the model's folder, before tinygltf tries to open anything. The
// file-system callbacks above stay as the second line of defence (symbolic links, for one).
bool checkUris(std::string_view json, const std::string& file, Diagnostics& out) {
    nlohmann::json doc = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !doc.is_object()) {
        return true; // tinygltf reports malformed JSON in its own words
    }
    bool ok = true;
    for (const char* list : {"buffers", "images"}) {
        auto items = doc.find(list);
        if (items == doc.end() || !items->is_array()) {
            continue;
        }
        for (std::size_t i = 0; i < items->size(); ++i) {
            const nlohmann::json& item = (*items)[i];
            if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) {
                continue;
            }
            std::string uri = item["uri"].get<std::string>();
            if (uri.rfind("data:", 0) == 0) {
                continue;
            }
            std::string where = std::string(list) + "[" + std::to_string(i) + "].uri";
            std::size_t colon = uri.find(':'), slash = uri.find('/');
            if (uri.empty() || uri[0] == '/' || uri[0] == '\\' || (colon != std::string::npos && colon < slash)) {
                out.push_back({file, where, "\"" + uri + "\" is absolute or has a scheme; only paths relative to the model's folder are read"});
                ok = false;
                continue;
            }
            int depth = 0;
            for (const fs::path& part : fs::path(uri).lexically_normal()) {
                depth += part == ".." ? -1 : (part == "." || part.empty()) ? 0 : 1;
                if (depth < 0) {
                    break;
                }
            }
            if (depth < 0) {
                out.push_back({file, where, "\"" + uri + "\" leaves the model's folder"});
                ok = false;
            }
        }
    }
    return ok;
}

} // namespace

std::optional<GltfResult> loadGltf(const fs::path& file, const std::string& displayName, Diagnostics& diagnostics,
                                   const GltfLimits& limits) {
    std::string error;
    std::optional<MappedFile> mapped = MappedFile::open(file, limits.maxFileBytes, error);
    if (!mapped) {
        diagnostics.push_back({displayName, "", error});
        return std::nullopt;
    }
    std::optional<std::string_view> bytes = mapped->bytes();
    FileGuard guard{canonicalFolder(file.parent_path()), limits.maxFileBytes, {}};
    tinygltf::TinyGLTF gltf;
    gltf.SetFsCallbacks({guardedFileExists, noExpansion, guardedReadWholeFile, refuseWrite, &guard});
    int skippedImages = 0;
    gltf.SetImageLoader(skipImage, &skippedImages);

    tinygltf::Model model;
    std::string err, warn;
    bool isGlb = bytes->size() >= 4 && std::memcmp(bytes->data(), "glTF", 4) == 0;
    bool ok;
    if (isGlb) {
        if (!checkGlbHeader(*bytes, error)) {
            diagnostics.push_back({displayName, "", error});
            return std::nullopt;
        }
        std::uint32_t jsonLength;
        std::memcpy(&jsonLength, bytes->data() + 12, 4);
        if (!checkUris(std::string_view(*bytes).substr(20, jsonLength), displayName, diagnostics)) {
            return std::nullopt;
        }
        ok = gltf.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes->data()),
                                       static_cast<unsigned>(bytes->size()), guard.folder.string());
    } else {
        if (!checkUris(*bytes, displayName, diagnostics)) {
            return std::nullopt;
        }
        ok = gltf.LoadASCIIFromString(&model, &err, &warn, bytes->data(), static_cast<unsigned>(bytes->size()),
                                      guard.folder.string());
    }
    bytes.reset();
    mapped.reset(); // tinygltf holds its own copy of the buffers now
    if (!ok) {
        std::string message = err.empty() ? "not a valid glTF file" : err;
        while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
            message.pop_back();
        }
        if (!guard.refusal.empty()) {
            message += " (" + guard.refusal + ")";
        }
        diagnostics.push_back({displayName, "", message});
        return std::nullopt;
    }

    Diagnostics out;
    Loader loader(model, displayName, out, limits);
    GltfResult result;
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (static_cast<std::size_t>(scene) >= model.scenes.size()) {
            diagnostics.push_back({displayName, "scene", "scene " + std::to_string(scene) + " does not exist"});
            return std::nullopt;
        }
        roots = model.scenes[static_cast<std::size_t>(scene)].nodes;
    } else {
        diagnostics.push_back({displayName, "scenes", "the file has no scene to show"});
        return std::nullopt;
    }
    std::vector<char> onPath(model.nodes.size(), 0);
    for (int root : roots) {
        if (!loader.visit(root, glm::mat4(1.0f), onPath, 0, result.mesh, result)) {
            diagnostics.insert(diagnostics.end(), out.begin(), out.end());
            return std::nullopt;
        }
    }
    if (result.mesh.indices.empty()) {
        diagnostics.push_back({displayName, "", "the default scene has no triangles"});
        return std::nullopt;
    }
    if (skippedImages > 0) {
        result.notes.push_back(std::to_string(skippedImages) +
                               " image(s) not loaded: the lab uses the preset's material, not glTF textures");
    }
    if (loader.computedNormals() > 0) {
        result.notes.push_back("normals computed for " + std::to_string(loader.computedNormals()) + " primitive(s)");
    }
    return result;
}

} // namespace lab
