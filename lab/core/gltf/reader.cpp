// reader.cpp — glTF 2.0 through tinygltf, with the checks tinygltf leaves out.
//
// Owns loadGltf: the scene's node hierarchy (transforms, cycles, depth) and each triangle
// primitive's assembly into the one output Mesh, with the vertex and triangle limits.
//
// It does not parse the file itself: parse.cpp does, behind the guards (folder, URIs, counts,
// buffers). Nor does it read accessor bytes: accessors.cpp proves each accessor in bounds and
// copies out of it; a GLB's BIN chunk stays in place (glb.cpp), so it reads from the mapped file.
#include "core/gltf/reader.h"

#include "core/gltf/accessors.h"
#include "core/gltf/parse.h"
#include "core/io/paths.h"
#include "core/io/safe_text.h"

#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <limits>

namespace lab {

namespace fs = std::filesystem;
using gltf_detail::Accessors;
using gltf_detail::AccessorUse;
using gltf_detail::BufferBytes;
using gltf_detail::AccessorData;
using gltf_detail::FileGuard;
using gltf_detail::ParsedModel;


namespace {

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
    AccessorData positions;
    AccessorData normals;
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
            AccessorData v;
            if (!index.IsInt() || !accessors_.data(index.GetNumberAsInt(), extWhere + "." + names[k],
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
        if (!accessors_.data(pos->second, where + ".attributes.POSITION", AccessorUse::Position, limits_.maxVertices,
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
        if (!accessors_.data(nrm->second, where + ".attributes.NORMAL", AccessorUse::Normal, limits_.maxVertices,
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
        AccessorData indices;
        if (!accessors_.data(prim.indices, where + ".indices", AccessorUse::Index, 3 * limits_.maxTriangles, indices)) {
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
        // counts.)
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
            // and copies every index again for each of 100,000 nodes (quadratic time).
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
    std::optional<ParsedModel> parsed = gltf_detail::parseModel(mapped->bytes(), guard, skippedImages, limits, displayName, diagnostics);
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