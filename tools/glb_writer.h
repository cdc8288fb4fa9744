// glb_writer.h — writes a binary glTF (.glb) holding one triangle mesh, for the repository's
// generated models (tools/gen_models.cpp) and the load benchmark (tests/bench). Not part of the
// lab: the lab only reads glTF.
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
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

// `generator` names the program in the asset; `nodes` is the glTF "nodes" array; the scene's root is node 0, and a node with "mesh": 0
// places the mesh. The output is deterministic.
inline std::string writeGlb(const GlbMesh& mesh, const nlohmann::ordered_json& nodes, const std::string& generator) {
    using Json = nlohmann::ordered_json;
    auto append = [](std::string& out, const auto& v) {
        out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(v[0]));
    };
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    std::string bin;
    Json views = Json::array(), accessors = Json::array(), attributes = Json::object();
    auto view = [&](const auto& data, int target) {
        std::size_t offset = bin.size();
        append(bin, data);
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bin.size() - offset}, {"target", target}});
        return views.size() - 1;
    };
    accessors.push_back({{"bufferView", view(mesh.positions, 34962)}, {"componentType", 5126},
                         {"count", mesh.positions.size()}, {"type", "VEC3"},
                         {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}});
    attributes["POSITION"] = 0;
    if (!mesh.normals.empty()) {
        accessors.push_back({{"bufferView", view(mesh.normals, 34962)}, {"componentType", 5126},
                             {"count", mesh.normals.size()}, {"type", "VEC3"}});
        attributes["NORMAL"] = accessors.size() - 1;
    }
    accessors.push_back({{"bufferView", view(mesh.indices, 34963)}, {"componentType", 5125},
                         {"count", mesh.indices.size()}, {"type", "SCALAR"}});
    while (bin.size() % 4) {
        bin += '\0';
    }
    Json j = {
        {"asset", {{"version", "2.0"}, {"generator", generator}}},
        {"scene", 0},
        {"scenes", Json::array({{{"nodes", {0}}}})},
        {"nodes", nodes},
        {"meshes", Json::array({{{"name", mesh.name},
                                 {"primitives", Json::array({{{"attributes", attributes},
                                                              {"indices", accessors.size() - 1},
                                                              {"mode", 4}}})}}})},
        {"accessors", accessors},
        {"bufferViews", views},
        {"buffers", Json::array({{{"byteLength", bin.size()}}})},
    };
    return glbContainer(j.dump(), std::move(bin));
}

} // namespace lab::tools
