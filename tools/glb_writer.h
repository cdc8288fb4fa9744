// glb_writer.h — writes a binary glTF (.glb) holding one triangle mesh, for the repository's
// generated models (tools/gen_models.cpp) and the load benchmark (tests/bench). Not part of the
// lab: the lab only reads glTF.
#pragma once

#include <glm/glm.hpp>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace lab::tools {

struct GlbMesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; // empty: the file has none
    std::vector<std::uint32_t> indices;
};

// A GLB version 2 holding `json` and a BIN chunk of `bin`, each padded to 4 bytes (the JSON with
// spaces, the BIN chunk with zeros), as the specification asks.
inline std::string glbContainer(std::string json, std::string bin) {
    while (json.size() % 4) {
        json += ' ';
    }
    while (bin.size() % 4) {
        bin += '\0';
    }
    auto u32 = [](std::string& out, std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    std::string glb = "glTF";
    u32(glb, 2);
    u32(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    u32(glb, static_cast<std::uint32_t>(json.size()));
    u32(glb, 0x4E4F534Au); // "JSON"
    glb += json;
    u32(glb, static_cast<std::uint32_t>(bin.size()));
    u32(glb, 0x004E4942u); // "BIN\0"
    glb += bin;
    return glb;
}

// How writeGlb stores the mesh's data: as it is, or with EXT_meshopt_compression's vertex and
// index codecs. Plain and the codecs alone are lossless but for one liberty of the index codec: it
// may start a triangle at another of its corners (the triangles, their order and winding are kept).
// MeshoptExponential also stores the positions through meshopt's EXPONENTIAL filter with a 16-bit
// mantissa (what gltfpack does for float data): each position moves by at most 2^-16 of its
// largest coordinate (5e-5 for the trefoil), and its bytes compress to about half — the codec and
// gzip find little to share in a float's last mantissa bits. The accessor's min and max are those
// of the positions as a reader decodes them.
enum class GlbStorage { Plain, Meshopt, MeshoptExponential };
inline constexpr int kExponentialMantissaBits = 16;

// `generator` names the program in the asset; `nodes` is the glTF "nodes" array; the scene's root is node 0, and a node with "mesh": 0
// places the mesh. The output is deterministic.
inline std::string writeGlb(const GlbMesh& mesh, const nlohmann::ordered_json& nodes, const std::string& generator,
                            GlbStorage storage = GlbStorage::Plain) {
    using Json = nlohmann::ordered_json;
    constexpr int kIndexTarget = 34963;
    auto append = [](std::string& out, const auto& v) {
        out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(v[0]));
    };
    // The positions as the EXPONENTIAL filter stores them, and as a reader decodes them.
    // (The filter's output is integers, kept as such: not every one of them is a float's bits.)
    struct Filtered {
        std::uint32_t xyz[3];
    };
    std::vector<Filtered> filtered;
    std::vector<glm::vec3> decoded;
    if (storage == GlbStorage::MeshoptExponential) {
        filtered.resize(mesh.positions.size());
        meshopt_encodeFilterExp(filtered.data(), filtered.size(), sizeof(Filtered), kExponentialMantissaBits,
                                &mesh.positions.data()->x);
        std::vector<Filtered> bits = filtered;
        meshopt_decodeFilterExp(bits.data(), bits.size(), sizeof(Filtered));
        decoded.resize(bits.size());
        std::memcpy(decoded.data(), bits.data(), bits.size() * sizeof(Filtered));
    }
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : decoded.empty() ? mesh.positions : decoded) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    std::string bin;
    std::size_t fallbackBytes = 0; // Meshopt: buffer 1, which holds no data (the views' plain size)
    Json views = Json::array(), accessors = Json::array(), attributes = Json::object();
    auto view = [&](const auto& data, int target, const char* filter = nullptr) {
        std::size_t offset = bin.size();
        if (storage == GlbStorage::Plain) {
            append(bin, data);
            views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bin.size() - offset}, {"target", target}});
            return views.size() - 1;
        }
        const std::size_t count = data.size(), stride = sizeof(data[0]);
        std::vector<unsigned char> encoded;
        if constexpr (std::is_same_v<std::decay_t<decltype(data[0])>, std::uint32_t>) {
            encoded.resize(meshopt_encodeIndexBufferBound(count, mesh.positions.size()));
            encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), data.data(), count));
        } else {
            encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
            encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), data.data(), count, stride));
        }
        append(bin, encoded);
        while (bin.size() % 4) {
            bin += '\0';
        }
        Json compressed = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", encoded.size()}, {"byteStride", stride},
                           {"count", count}, {"mode", target == kIndexTarget ? "TRIANGLES" : "ATTRIBUTES"}};
        if (filter) {
            compressed["filter"] = filter;
        }
        Json v = {{"buffer", 1}, {"byteOffset", fallbackBytes}, {"byteLength", count * stride}};
        if (target != kIndexTarget) {
            v["byteStride"] = stride;
        }
        v["target"] = target;
        v["extensions"] = {{"EXT_meshopt_compression", compressed}};
        views.push_back(v);
        fallbackBytes += (count * stride + 3) / 4 * 4;
        return views.size() - 1;
    };
    const std::size_t positionView =
        filtered.empty() ? view(mesh.positions, 34962) : view(filtered, 34962, "EXPONENTIAL");
    accessors.push_back({{"bufferView", positionView}, {"componentType", 5126},
                         {"count", mesh.positions.size()}, {"type", "VEC3"},
                         {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}});
    attributes["POSITION"] = 0;
    if (!mesh.normals.empty()) {
        accessors.push_back({{"bufferView", view(mesh.normals, 34962)}, {"componentType", 5126},
                             {"count", mesh.normals.size()}, {"type", "VEC3"}});
        attributes["NORMAL"] = accessors.size() - 1;
    }
    accessors.push_back({{"bufferView", view(mesh.indices, kIndexTarget)}, {"componentType", 5125},
                         {"count", mesh.indices.size()}, {"type", "SCALAR"}});
    while (bin.size() % 4) {
        bin += '\0';
    }
    Json j = {{"asset", {{"version", "2.0"}, {"generator", generator}}}};
    Json buffers = Json::array({{{"byteLength", bin.size()}}});
    if (storage != GlbStorage::Plain) {
        j["extensionsUsed"] = {"EXT_meshopt_compression"};
        j["extensionsRequired"] = {"EXT_meshopt_compression"};
        buffers.push_back({{"byteLength", fallbackBytes}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    }
    j.update(Json{
        {"scene", 0},
        {"scenes", Json::array({{{"nodes", {0}}}})},
        {"nodes", nodes},
        {"meshes", Json::array({{{"name", mesh.name},
                                 {"primitives", Json::array({{{"attributes", attributes},
                                                              {"indices", accessors.size() - 1},
                                                              {"mode", 4}}})}}})},
        {"accessors", accessors},
        {"bufferViews", views},
        {"buffers", buffers},
    });
    return glbContainer(j.dump(), std::move(bin));
}

} // namespace lab::tools
