// draco_mesh.cpp — libdraco behind decodeDracoMesh (draco_mesh.h). Linked into the desktop and
// the command line; compiled into the page's Draco module (lab/platform/web_draco_module.cpp).
#include "core/gltf/draco_mesh.h"

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>
#include <memory>

namespace lab::gltf_detail {

namespace {

DracoResult failure(std::string message, std::string where = "") {
    return DracoFailure{std::move(where), std::move(message)};
}

// The library reports malformed data as a status; the catch is for allocation failures a hostile
// header might provoke.
std::unique_ptr<draco::Mesh> decodeMesh(const unsigned char* data, std::size_t size, std::string& error) {
    try {
        draco::DecoderBuffer input;
        input.Init(reinterpret_cast<const char*>(data), size);
        draco::Decoder decoder;
        auto result = decoder.DecodeMeshFromBuffer(&input);
        if (result.ok()) {
            return std::move(result).value();
        }
        error = result.status().error_msg_string();
    } catch (const std::exception& e) {
        error = e.what();
    }
    return nullptr;
}

// Attribute `name` when the extension lists it: checked, and its values copied into `values`
// (points × 3 floats) when the primitive uses it. A failure, or nullopt.
std::optional<DracoFailure> readAttribute(const draco::Mesh& mesh, const DracoAttributeQuery& query, const char* name,
                                          std::vector<float>& values) {
    if (!query.listed) {
        return std::nullopt;
    }
    const std::string where = ".attributes." + std::string(name);
    const std::size_t points = mesh.num_points();
    const draco::PointAttribute* attribute =
        query.id >= 0 && query.id <= 0xFFFFFFFF ? mesh.GetAttributeByUniqueId(static_cast<std::uint32_t>(query.id)) : nullptr;
    if (!attribute) {
        return DracoFailure{where, "names no attribute of the Draco data"};
    }
    if (attribute->num_components() != 3) {
        return DracoFailure{where, "the Draco attribute has " + std::to_string(attribute->num_components()) +
                                       " components, not 3"};
    }
    if (!attribute->is_mapping_identity() && attribute->indices_map_size() < points) {
        return DracoFailure{where, "the Draco attribute maps fewer values than the mesh has points"};
    }
    if (!query.used) {
        return std::nullopt; // the primitive does not use it
    }
    values.resize(points * 3);
    for (std::size_t p = 0; p < points; ++p) {
        draco::AttributeValueIndex value = attribute->mapped_index(draco::PointIndex(static_cast<std::uint32_t>(p)));
        if (value.value() >= attribute->size() || !attribute->ConvertValue<float>(value, 3, values.data() + p * 3)) {
            return DracoFailure{where, "point " + std::to_string(p) + " has no value in the Draco data"};
        }
    }
    return std::nullopt;
}

} // namespace

DracoResult decodeDracoMesh(const unsigned char* data, std::size_t size, const DracoQuery& query) {
    try {
        std::string error;
        std::unique_ptr<draco::Mesh> decoded = decodeMesh(data, size, error);
        if (!decoded) {
            return failure("the Draco data does not decode: " + (error.empty() ? std::string("not a Draco mesh") : error));
        }
        const std::uint64_t points = decoded->num_points(), faces = decoded->num_faces();
        if (faces == 0 || points == 0) {
            return failure("the Draco data decodes to no triangles");
        }
        if (points > query.maxPoints || faces > query.maxFaces || 24 * points + 12 * faces > query.maxBytes) {
            return failure("the Draco data decodes to " + std::to_string(points) + " points and " + std::to_string(faces) +
                           " triangles, more than the lab reads");
        }
        DracoMesh mesh;
        mesh.points = static_cast<std::uint32_t>(points);
        mesh.faces = static_cast<std::uint32_t>(faces);
        if (auto f = readAttribute(*decoded, query.position, "POSITION", mesh.positions)) {
            return *f;
        }
        if (auto f = readAttribute(*decoded, query.normal, "NORMAL", mesh.normals)) {
            return *f;
        }
        mesh.indices.resize(faces * 3);
        for (std::uint32_t f = 0; f < faces; ++f) {
            const draco::Mesh::Face& face = decoded->face(draco::FaceIndex(f));
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = face[k].value();
                if (v >= points) {
                    return failure("triangle " + std::to_string(f) + " names point " + std::to_string(v) + " of " +
                                   std::to_string(points));
                }
                mesh.indices[f * 3 + k] = v;
            }
        }
        return mesh;
    } catch (const std::exception& e) { // an allocation the data asked for
        return failure(std::string("the Draco data does not decode: ") + e.what());
    }
}

} // namespace lab::gltf_detail
