// reader.cpp — glTF 2.0 through tinygltf, with the checks tinygltf leaves out.
//
// Owns loadGltf: the file-system guard tinygltf reads through (regular files in the model's
// folder only), the URI checks before tinygltf parses, the scene's node hierarchy (transforms,
// cycles, depth) and each triangle primitive's assembly into the one output Mesh, with the
// vertex and triangle limits.
//
// It does not read accessor bytes itself: gltf_accessors.cpp proves each accessor in bounds and
// copies out of it. Nor does it read a GLB's container: gltf_glb.cpp checks the chunks and keeps
// the BIN chunk in place, so the accessors read it from the mapped file.
#include "core/gltf/reader.h"

#include "core/io/file_io.h"
#include "core/gltf/accessors.h"
#include "core/gltf/compression.h"
#include "core/gltf/data_uri.h"
#include "core/gltf/extensions.h"
#include "core/gltf/glb.h"
#include "core/io/json_text.h"
#include "core/io/paths.h"
#include "core/io/safe_text.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <deque>
#include <unordered_map>
#include <limits>

namespace lab {

namespace fs = std::filesystem;
using gltf_detail::Accessors;
using gltf_detail::AccessorUse;
using gltf_detail::BufferBytes;
using gltf_detail::View;

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
// Primitives and the node hierarchy
//----------------------------------------------------------------------------------------

// A primitive's vertex order as triangles: strips and fans unrolled, a triangle list cut to
// whole triangles. glTF's strip order alternates so every triangle keeps its winding.
std::vector<std::uint32_t> triangleList(std::vector<std::uint32_t> sequence, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        sequence.resize(sequence.size() - sequence.size() % 3);
        return sequence;
    }
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
    return triangles;
}

// A primitive's vertex attributes, validated.
struct Attributes {
    int positionAccessor = -1;
    int normalAccessor = -1; // -1: none, normals are computed
    View positions;
    View normals;
};

class Loader {
public:
    Loader(const tinygltf::Model& model, std::vector<BufferBytes> buffers, const std::string& file, Diagnostics& out,
           const GltfLimits& limits)
        : model_(model), accessors_(model, std::move(buffers), file, out), limits_(limits) {}

    bool error(const std::string& where, const std::string& message) { return accessors_.error(where, message); }

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
        Attributes attributes;
        std::vector<std::uint32_t> sequence;
        if (!readAttributes(prim, where, out, attributes) ||
            !readVertexOrder(prim, where, attributes.positions.count, sequence)) {
            return false;
        }
        sequence = triangleList(std::move(sequence), mode);
        if (sequence.empty()) {
            result.notes.push_back(where + ": skipped (no complete triangle)");
            return true;
        }
        if (sequence.size() / 3 > limits_.maxTriangles - std::min(limits_.maxTriangles, out.triangleCount())) {
            return error(where, "more than " + std::to_string(limits_.maxTriangles) + " triangles in the model");
        }
        // glTF: a node whose world transform mirrors (negative determinant) has its triangles wound
        // clockwise. The lab's meshes are counter-clockwise in model space, which is what computed
        // normals and flat shading's face normals follow, so a mirrored primitive is turned round.
        if (glm::determinant(glm::mat3(world)) < 0.0f) {
            for (std::size_t t = 0; t + 2 < sequence.size(); t += 3) {
                std::swap(sequence[t + 1], sequence[t + 2]);
            }
        }
        return appendPrimitive(attributes, std::move(sequence), world, out);
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
            std::vector<glm::mat4> placements{world}; // the node's, or one per EXT_mesh_gpu_instancing instance
            if (!instances(node, where, world, placements)) {
                return false;
            }
            auto mi = static_cast<std::size_t>(node.mesh);
            for (const glm::mat4& placement : placements) {
                if (std::abs(glm::determinant(glm::mat3(placement))) < 1e-20f) {
                    result.notes.push_back(where + ": skipped" + (placements.size() > 1 ? " an instance" : "") +
                                           " (its transform collapses the mesh)");
                    continue;
                }
                for (std::size_t pi = 0; pi < model_.meshes[mi].primitives.size(); ++pi) {
                    if (!addPrimitive(mi, pi, placement, out, result)) {
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

    std::size_t computedNormals() const { return computedNormals_; }

private:
    // EXT_mesh_gpu_instancing: the node's mesh drawn once per instance, each placed by its
    // TRANSLATION, ROTATION and SCALE (T * R * S, as a node's own) under the node's world matrix.
    // `placements` is left as it is for a node without the extension. False after a diagnostic.
    bool instances(const tinygltf::Node& node, const std::string& where, const glm::mat4& world,
                   std::vector<glm::mat4>& placements) {
        auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
        if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("attributes") ||
            !ext->second.Get("attributes").IsObject()) {
            return true;
        }
        const tinygltf::Value& attributes = ext->second.Get("attributes");
        const std::string extWhere = where + ".extensions.EXT_mesh_gpu_instancing.attributes";
        std::size_t count = 0;
        std::vector<float> values[3]; // translation, rotation, scale
        const char* names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
        for (int k = 0; k < 3; ++k) {
            if (!attributes.Has(names[k])) {
                continue;
            }
            const tinygltf::Value& index = attributes.Get(names[k]);
            View v;
            if (!index.IsInt() || !accessors_.view(index.GetNumberAsInt(), extWhere + "." + names[k],
                                                   k == 1 ? AccessorUse::Rotation : AccessorUse::Position,
                                                   limits_.maxInstances, v)) {
                return index.IsInt() ? false : error(extWhere + "." + names[k], "not an accessor index");
            }
            if (count != 0 && v.count != count) {
                return error(extWhere + "." + names[k], std::to_string(v.count) + " instances, but another attribute has " +
                                                            std::to_string(count));
            }
            count = v.count;
            if (instanceCount_ + count > limits_.maxInstances) {
                return error(extWhere, "more than " + std::to_string(limits_.maxInstances) + " instances in the model");
            }
            values[k] = accessors_.floats(v);
        }
        if (count == 0) {
            return true;
        }
        instanceCount_ += count;
        placements.clear();
        placements.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
            glm::mat4 t(1.0f), r(1.0f), s(1.0f);
            if (!values[0].empty()) {
                t[3] = glm::vec4(values[0][3 * i], values[0][3 * i + 1], values[0][3 * i + 2], 1.0f);
            }
            if (!values[1].empty()) {
                glm::quat q(values[1][4 * i + 3], values[1][4 * i], values[1][4 * i + 1], values[1][4 * i + 2]);
                const float len = glm::length(q);
                r = len > 0.0f && std::isfinite(len) ? glm::mat4_cast(q / len) : glm::mat4(1.0f);
            }
            if (!values[2].empty()) {
                s = glm::scale(glm::mat4(1.0f), glm::vec3(values[2][3 * i], values[2][3 * i + 1], values[2][3 * i + 2]));
            }
            const glm::mat4 m = world * t * r * s;
            for (int c = 0; c < 4; ++c) {
                for (int k = 0; k < 4; ++k) {
                    if (!std::isfinite(m[c][k])) {
                        return error(extWhere, "instance " + std::to_string(i) + " has a transform that is not finite");
                    }
                }
            }
            placements.push_back(m);
        }
        return true;
    }

    // POSITION and NORMAL (when present) of the primitive, validated and within the vertex limit.
    bool readAttributes(const tinygltf::Primitive& prim, const std::string& where, const Mesh& out,
                        Attributes& attributes) {
        auto pos = prim.attributes.find("POSITION");
        if (pos == prim.attributes.end()) {
            return error(where, "has no POSITION attribute");
        }
        attributes.positionAccessor = pos->second;
        if (!accessors_.view(pos->second, where + ".attributes.POSITION", AccessorUse::Position, limits_.maxVertices,
                             attributes.positions)) {
            return false;
        }
        if (attributes.positions.count > limits_.maxVertices - std::min(limits_.maxVertices, out.positions.size())) {
            return error(where, "more than " + std::to_string(limits_.maxVertices) + " vertices in the model");
        }
        auto nrm = prim.attributes.find("NORMAL");
        if (nrm == prim.attributes.end()) {
            return true;
        }
        attributes.normalAccessor = nrm->second;
        if (!accessors_.view(nrm->second, where + ".attributes.NORMAL", AccessorUse::Normal, limits_.maxVertices,
                             attributes.normals)) {
            return false;
        }
        if (attributes.normals.count != attributes.positions.count) {
            return error(where, "NORMAL has " + std::to_string(attributes.normals.count) +
                                    " elements but POSITION has " + std::to_string(attributes.positions.count));
        }
        return true;
    }

    // The primitive's vertex order: its indices (checked against the vertex count), or 0, 1, 2, ...
    bool readVertexOrder(const tinygltf::Primitive& prim, const std::string& where, std::size_t vertexCount,
                         std::vector<std::uint32_t>& sequence) {
        if (prim.indices < 0) {
            sequence.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i) {
                sequence[i] = static_cast<std::uint32_t>(i);
            }
            return true;
        }
        View indices;
        if (!accessors_.view(prim.indices, where + ".indices", AccessorUse::Index, 3 * limits_.maxTriangles, indices)) {
            return false;
        }
        if (indices.count > 3 * limits_.maxTriangles) {
            return error(where, "more than " + std::to_string(limits_.maxTriangles) + " triangles");
        }
        return accessors_.readIndices(indices, vertexCount, prim.indices, where, sequence);
    }

    // Vertices straight into the output, transformed by the node's world matrix; normals
    // transformed by its normal matrix, or computed when the primitive has none; then the
    // triangles, offset to the vertices' place in the output.
    bool appendPrimitive(const Attributes& attributes, std::vector<std::uint32_t> triangles, const glm::mat4& world,
                         Mesh& out) {
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        const bool identity = world == glm::mat4(1.0f);
        if (!accessors_.appendPositions(attributes.positions, attributes.positionAccessor, glm::mat3(world),
                                        glm::vec3(world[3]), identity, out.positions)) {
            return false;
        }
        // Normals that are missing, zero or not finite (some exporters write NaN for a degenerate
        // face's vertices) are computed, after the node transform, so the area weights are those of
        // the model as drawn. (A view of its own vertices, not a copy: a large model's peak memory
        // counts, issue 14.)
        const std::span<const glm::vec3> positions = std::span<const glm::vec3>(out.positions).subspan(base);
        if (attributes.normalAccessor < 0) {
            std::vector<glm::vec3> computed = computeVertexNormals(positions, triangles);
            if (out.normals.empty()) {
                out.normals = std::move(computed);
            } else {
                out.normals.insert(out.normals.end(), computed.begin(), computed.end());
            }
            computedNormals_ += positions.size();
        } else {
            glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
            const std::size_t missing = accessors_.appendNormals(attributes.normals, normalMatrix, identity, out.normals);
            if (missing > 0) {
                std::vector<glm::vec3> computed = computeVertexNormals(positions, triangles);
                glm::vec3* normals = out.normals.data() + base;
                for (std::size_t i = 0; i < computed.size(); ++i) {
                    if (normals[i] == glm::vec3(0.0f)) {
                        normals[i] = computed[i];
                    }
                }
                computedNormals_ += missing;
            }
        }
        if (base == 0 && out.indices.empty()) {
            out.indices = std::move(triangles);
        } else {
            // No reserve(size + n) here: an exact reserve per primitive defeats the vector's doubling
            // and copied every index again for each of 100,000 nodes (issue 14's quadratic time).
            for (std::uint32_t i : triangles) {
                out.indices.push_back(base + i);
            }
        }
        return true;
    }

    const tinygltf::Model& model_;
    Accessors accessors_;
    const GltfLimits& limits_;
    std::size_t computedNormals_ = 0; // vertices whose normal the loader computed
    std::size_t instanceCount_ = 0;   // EXT_mesh_gpu_instancing instances, all nodes together
};

// Refuses, with the URI and its JSON path, every buffer or image URI that is absolute, has a
// scheme, or climbs out of the model's folder, before tinygltf tries to open anything. The
// file-system callbacks above stay as the second line of defence (symbolic links, for one).
bool checkUris(const nlohmann::json& doc, const std::string& file, Diagnostics& out) {
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
            if (hasNul(uri)) { // "a\u0000.gltf" would open "a"
                out.push_back({file, where, inQuotes(uri) + " holds a NUL byte"});
                ok = false;
                continue;
            }
            std::size_t colon = uri.find(':'), slash = uri.find('/');
            if (uri.empty() || uri[0] == '/' || uri[0] == '\\' || (colon != std::string::npos && colon < slash)) {
                out.push_back({file, where, inQuotes(uri) + " is absolute or has a scheme; only paths relative to the model's folder are read"});
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
                out.push_back({file, where, inQuotes(uri) + " leaves the model's folder"});
                ok = false;
            }
        }
    }
    return ok;
}

// How many objects the file declares, against `limits`: each top-level array, and the meshes'
// primitives together. False after a diagnostic naming the array and the limit.
bool checkCounts(const nlohmann::json& doc, const GltfLimits& limits, const std::string& displayName,
                 Diagnostics& diagnostics) {
    std::size_t primitives = 0;
    for (const auto& [key, value] : doc.items()) {
        if (!value.is_array()) {
            continue;
        }
        std::size_t limit = key == "nodes" ? limits.maxNodes : key == "meshes" ? limits.maxMeshes
                          : key == "accessors" ? limits.maxAccessors : limits.maxOtherObjects;
        if (value.size() > limit) {
            diagnostics.push_back({displayName, keyInPath(key, 40),
                                   std::to_string(value.size()) + " objects; the lab reads at most " + std::to_string(limit)});
            return false;
        }
        if (key != "meshes") {
            continue;
        }
        for (const nlohmann::json& mesh : value) {
            auto list = mesh.is_object() ? mesh.find("primitives") : mesh.end();
            primitives += list != mesh.end() && list->is_array() ? list->size() : 0;
        }
        if (primitives > limits.maxPrimitives) {
            diagnostics.push_back({displayName, "meshes", std::to_string(primitives) + " primitives in all; the lab reads at most " +
                                                              std::to_string(limits.maxPrimitives)});
            return false;
        }
    }
    return true;
}

// The JSON of a .gltf, or of a .glb's JSON chunk, checked before any parser recurses into it:
// nested no deeper than `maxDepth`, and every buffer or image URI inside the model's folder.
// `doc` gets the parsed JSON when it is an object (malformed JSON is left for tinygltf to
// report in its own words: `doc` is then not an object).
bool checkJson(std::string_view json, const GltfLimits& limits, const std::string& displayName, Diagnostics& diagnostics,
               nlohmann::json& doc) {
    if (!jsonNestingWithin(json, limits.maxJsonDepth)) {
        diagnostics.push_back({displayName, "", "JSON nested deeper than " + std::to_string(limits.maxJsonDepth) + " levels"});
        return false;
    }
    doc = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
    return !doc.is_object() || (checkCounts(doc, limits, displayName, diagnostics) && checkUris(doc, displayName, diagnostics));
}

// What tinygltf parsed, and where each buffer's bytes are.
struct ParsedModel {
    tinygltf::Model model;
    std::optional<std::string_view> bin;            // the GLB's BIN chunk, in the mapped file
    gltf_detail::DataUriBuffers dataUris;           // buffers decoded from base64 data: URIs (gltf_data_uri.h)
    std::deque<MappedFile> external;                // .bin files the loader read itself
    gltf_detail::ModelBuffers buffers;              // per buffer index: its bytes (then decoded ones appended)
    std::vector<char> tinygltfReads;                // per buffer index: left to tinygltf (a data: URI our pass did not follow)
    std::vector<std::string> notes;
};

// The buffers decoded from data: URIs: each must hold its byteLength (a longer one is read up
// to it, as a .bin file is); its JSON then says 1 byte, as the placeholder holds. False after a
// diagnostic.
bool useDecodedBuffers(nlohmann::json& doc, ParsedModel& parsed, const std::string& displayName, Diagnostics& diagnostics) {
    auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) {
        return true;
    }
    for (std::size_t i = 0; i < buffers->size() && i < parsed.dataUris.decoded.size(); ++i) {
        nlohmann::json& buffer = (*buffers)[i];
        // The parser must see the placeholder where the pass put it (a duplicate "uri" key, or
        // one written with escapes, would make them disagree): else the buffer is tinygltf's.
        if (!parsed.dataUris.decoded[i] || !buffer.is_object() || !buffer.contains("uri") ||
            buffer["uri"] != gltf_detail::kDecodedPlaceholder) {
            continue;
        }
        auto length = buffer.find("byteLength");
        if (length == buffer.end() || !length->is_number_unsigned()) {
            continue; // tinygltf refuses it in its own words
        }
        const auto byteLength = length->get<std::uint64_t>();
        const std::size_t held = parsed.dataUris.bytes[i].size();
        if (byteLength > held) {
            diagnostics.push_back({displayName, "buffers[" + std::to_string(i) + "].byteLength",
                                   std::to_string(byteLength) + " bytes, more than its data: URI holds (" + std::to_string(held) + ")"});
            return false;
        }
        parsed.buffers.bytes[i] = {parsed.dataUris.bytes[i].data(), static_cast<std::size_t>(byteLength)};
        buffer["byteLength"] = 1;
    }
    return true;
}

// A URI's %XX escapes decoded (glTF URIs are URI-encoded: Blender writes a space as %20).
// Nullopt for a broken escape or one that decodes to NUL.
std::optional<std::string> percentDecoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            out += uri[i];
            continue;
        }
        auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) ? std::stoi(std::string(1, c), nullptr, 16) : -1; };
        int hi = i + 2 < uri.size() ? hex(uri[i + 1]) : -1, lo = i + 2 < uri.size() ? hex(uri[i + 2]) : -1;
        if (hi < 0 || lo < 0 || (hi == 0 && lo == 0)) {
            return std::nullopt;
        }
        out += static_cast<char>(hi * 16 + lo);
        i += 2;
    }
    return out;
}

// Buffers in files beside the model, read (mapped) by the loader through `guard`, not by
// tinygltf: a file longer than its buffer's byteLength is allowed (the specification allows
// it; tinygltf refuses it), a shorter one refused. Buffers without a uri that are
// EXT_meshopt_compression fallbacks hold nothing: the compressed views are decoded instead.
// Each becomes a placeholder for tinygltf. False after a diagnostic.
bool readOtherBuffers(nlohmann::json& doc, bool isGlb, FileGuard& guard, std::size_t maxBytes, ParsedModel& parsed,
                      const std::string& displayName, Diagnostics& diagnostics) {
    auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) {
        return true;
    }
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        nlohmann::json& buffer = (*buffers)[i];
        const std::string where = "buffers[" + std::to_string(i) + "]";
        auto length = buffer.is_object() ? buffer.find("byteLength") : buffer.end();
        if (!buffer.is_object() || length == buffer.end() || !length->is_number_unsigned() || parsed.buffers.bytes[i].data) {
            continue; // resolved already, or refused by tinygltf in its own words
        }
        const auto byteLength = length->get<std::uint64_t>();
        auto uri = buffer.find("uri");
        if (uri == buffer.end()) {
            auto ext = buffer.find("extensions");
            // (Every level's type checked: nlohmann throws on a wrong one, e.g. "fallback": 1.)
            const nlohmann::json* meshopt = ext != buffer.end() && ext->is_object() && ext->contains("EXT_meshopt_compression")
                                                ? &(*ext)["EXT_meshopt_compression"] : nullptr;
            const nlohmann::json* flag = meshopt && meshopt->is_object() && meshopt->contains("fallback") ? &(*meshopt)["fallback"] : nullptr;
            const bool fallback = flag && flag->is_boolean() && flag->get<bool>();
            if (fallback) {
                static const unsigned char kNothing = 0;
                parsed.buffers.bytes[i] = {&kNothing, 0};
                buffer["uri"] = gltf_detail::kDecodedPlaceholder;
                buffer["byteLength"] = 1;
            } else if (!isGlb) {
                diagnostics.push_back({displayName, where, "has no uri: a .gltf's buffers are files or data: URIs"});
                return false;
            }
            continue;
        }
        if (!uri->is_string() || uri->get<std::string>().rfind("data:", 0) == 0) {
            if (uri->is_string()) {
                parsed.tinygltfReads[i] = 1; // a data: URI the decoding pass did not follow
            }
            continue;
        }
        std::optional<std::string> name = percentDecoded(uri->get<std::string>());
        if (!name) {
            diagnostics.push_back({displayName, where + ".uri", inQuotes(uri->get<std::string>()) + " has a broken %-escape"});
            return false;
        }
        const std::string path = (guard.folder / *name).string();
        std::string error;
        if (!guardedFileExists(path, &guard)) {
            diagnostics.push_back({displayName, where + ".uri", inQuotes(uri->get<std::string>()) + ": " + guard.refusal});
            return false;
        }
        std::optional<MappedFile> file = MappedFile::open(path, maxBytes, error);
        if (!file) {
            diagnostics.push_back({displayName, where + ".uri", inQuotes(uri->get<std::string>()) + ": " + error});
            return false;
        }
        if (file->bytes().size() < byteLength) {
            diagnostics.push_back({displayName, where + ".byteLength",
                                   std::to_string(byteLength) + " bytes, more than " + inQuotes(*name) + " holds (" +
                                       std::to_string(file->bytes().size()) + ")"});
            return false;
        }
        parsed.external.push_back(std::move(*file));
        parsed.buffers.bytes[i] = {reinterpret_cast<const unsigned char*>(parsed.external.back().bytes().data()),
                                   static_cast<std::size_t>(byteLength)};
        buffer["uri"] = gltf_detail::kDecodedPlaceholder;
        buffer["byteLength"] = 1;
    }
    return true;
}

// The file parsed by tinygltf behind the guards: the GLB's chunks and the JSON checked first,
// the glTF version and required extensions, then every buffer resolved by the loader (a GLB's
// BIN chunk in place, data: URIs decoded, files beside the model mapped) and compressed
// geometry decoded (gltf_compression.h); tinygltf then parses only the JSON, with placeholders
// for the buffers. Images are skipped and counted in `skippedImages`. Nullopt after a diagnostic.
std::optional<ParsedModel> parseModel(std::string_view bytes, FileGuard& guard, int& skippedImages,
                                      const GltfLimits& limits, const std::string& displayName,
                                      Diagnostics& diagnostics) {
    tinygltf::TinyGLTF gltf;
    gltf.SetFsCallbacks({guardedFileExists, noExpansion, guardedReadWholeFile, refuseWrite, &guard});
    gltf.SetImageLoader(skipImage, &skippedImages);

    ParsedModel parsed;
    std::string err, warn, error;
    std::string_view json = bytes;
    std::string rewritten;
    nlohmann::json doc;
    const bool isGlb = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (isGlb) {
        std::optional<gltf_detail::GlbChunks> chunks = gltf_detail::readGlbChunks(bytes, error);
        if (!chunks) {
            diagnostics.push_back({displayName, "", error});
            return std::nullopt;
        }
        json = chunks->json;
        parsed.bin = chunks->bin;
    }
    // Buffers as base64 data: URIs, decoded straight from the file's bytes before any parser
    // copies them (gltf_data_uri.h).
    bool badDataUri = false;
    std::optional<gltf_detail::DataUriBuffers> dataUris =
        gltf_detail::decodeDataUriBuffers(json, limits.maxJsonDepth, limits.maxOtherObjects, displayName, diagnostics, badDataUri);
    if (badDataUri) {
        return std::nullopt;
    }
    if (dataUris) {
        parsed.dataUris = std::move(*dataUris);
        json = parsed.dataUris.json;
    }
    if (!checkJson(json, limits, displayName, diagnostics, doc)) {
        return std::nullopt;
    }
    if (doc.is_object()) { // (malformed JSON goes to tinygltf as it is, to be refused in its words)
        if (!gltf_detail::checkVersionAndExtensions(doc, displayName, diagnostics, parsed.notes)) {
            return std::nullopt;
        }
        const std::size_t bufferCount = doc.contains("buffers") && doc["buffers"].is_array() ? doc["buffers"].size() : 0;
        parsed.buffers.bytes.resize(bufferCount);
        parsed.tinygltfReads.resize(bufferCount);
        if (dataUris && !useDecodedBuffers(doc, parsed, displayName, diagnostics)) {
            return std::nullopt;
        }
        if (!readOtherBuffers(doc, isGlb, guard, limits.maxFileBytes, parsed, displayName, diagnostics)) {
            return std::nullopt;
        }
        if (isGlb) {
            std::optional<std::vector<std::optional<std::size_t>>> inBin =
                gltf_detail::glbBuffersInPlace(doc, parsed.bin, displayName, diagnostics);
            if (!inBin) {
                return std::nullopt;
            }
            for (std::size_t i = 0; i < inBin->size() && i < bufferCount; ++i) {
                if ((*inBin)[i]) {
                    parsed.buffers.bytes[i] = {reinterpret_cast<const unsigned char*>(parsed.bin->data()), *(*inBin)[i]};
                }
            }
        }
        const gltf_detail::DecodeLimits decodeLimits{limits.maxVertices, limits.maxTriangles, limits.maxFileBytes};
        if (!gltf_detail::decodeMeshopt(doc, parsed.buffers, decodeLimits, displayName, diagnostics) ||
            !gltf_detail::decodeDraco(doc, parsed.buffers, decodeLimits, displayName, diagnostics)) {
            return std::nullopt;
        }
        rewritten = doc.dump();
        json = rewritten;
        doc = nullptr; // its memory back before tinygltf builds its own
    }
    bool ok = gltf.LoadASCIIFromString(&parsed.model, &err, &warn, json.data(), static_cast<unsigned>(json.size()),
                                       guard.folder.string());
    if (!ok) {
        std::string message = err.empty() ? "not a valid glTF file" : shortened(err); // it may quote a whole data: URI
        while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
            message.pop_back();
        }
        if (!guard.refusal.empty()) {
            message += " (" + guard.refusal + ")";
        }
        diagnostics.push_back({displayName, "", message});
        return std::nullopt;
    }
    // The buffers tinygltf decoded itself, and any the JSON pass above did not see (malformed JSON never gets here).
    for (std::size_t i = 0; i < parsed.model.buffers.size() && i < parsed.buffers.bytes.size(); ++i) {
        if (i < parsed.tinygltfReads.size() && (parsed.tinygltfReads[i] || !parsed.buffers.bytes[i].data)) {
            const std::vector<unsigned char>& data = parsed.model.buffers[i].data;
            parsed.buffers.bytes[i] = {data.data(), data.size()};
        }
    }
    return parsed;
}

// The notes as the user reads them: a note repeated (the same primitive under many nodes or
// instances) once with its count, and at most `most` lines (a file can have 200,000 primitives).
std::vector<std::string> collapsed(const std::vector<std::string>& notes, std::size_t most = 12) {
    std::vector<std::pair<std::string, std::size_t>> counted;
    std::unordered_map<std::string, std::size_t> at;
    for (const std::string& note : notes) {
        auto [it, fresh] = at.try_emplace(note, counted.size());
        if (fresh) {
            counted.emplace_back(note, 0);
        }
        ++counted[it->second].second;
    }
    std::vector<std::string> out;
    for (std::size_t i = 0; i < counted.size() && i < most; ++i) {
        out.push_back(counted[i].first + (counted[i].second > 1 ? " (" + std::to_string(counted[i].second) + " times)" : ""));
    }
    if (counted.size() > most) {
        out.push_back("... and " + std::to_string(counted.size() - most) + " more notes");
    }
    return out;
}

// The root nodes of the default scene (scene 0 when the file names none); nullopt after a
// diagnostic.
std::optional<std::vector<int>> sceneRoots(const tinygltf::Model& model, const std::string& displayName,
                                           Diagnostics& diagnostics) {
    if (model.scenes.empty()) {
        diagnostics.push_back({displayName, "scenes", "the file has no scene to show"});
        return std::nullopt;
    }
    int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<std::size_t>(scene) >= model.scenes.size()) {
        diagnostics.push_back({displayName, "scene", "scene " + std::to_string(scene) + " does not exist"});
        return std::nullopt;
    }
    return model.scenes[static_cast<std::size_t>(scene)].nodes;
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
    FileGuard guard{canonicalFolder(file.parent_path()), limits.maxFileBytes, {}};
    int skippedImages = 0;
    // The mapping stays open until the mesh is built when a GLB's buffers are read from it in place.
    std::optional<ParsedModel> parsed = parseModel(mapped->bytes(), guard, skippedImages, limits, displayName, diagnostics);
    if (!parsed) {
        return std::nullopt;
    }
    if (!parsed->bin) {
        mapped.reset(); // the text is parsed and any data: URI decoded: only a GLB's BIN chunk is read from the file later
    }
    const tinygltf::Model& model = parsed->model;
    std::optional<std::vector<int>> roots = sceneRoots(model, displayName, diagnostics);
    if (!roots) {
        return std::nullopt;
    }

    Diagnostics out;
    Loader loader(model, std::move(parsed->buffers.bytes), displayName, out, limits);
    GltfResult result;
    result.notes = std::move(parsed->notes);
    std::vector<char> onPath(model.nodes.size(), 0);
    for (int root : *roots) {
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
        result.notes.push_back("normals computed for " + std::to_string(loader.computedNormals()) +
                               " vertices (missing, zero or not finite in the file)");
    }
    result.notes = collapsed(result.notes);
    return result;
}

} // namespace lab
