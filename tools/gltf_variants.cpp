// gltf_variants.cpp — one torus, written plainly and in each way the loader must read or refuse.
#include "gltf_variants.h"

#include "glb_writer.h"

#include "core/io/file_io.h"
#include "core/scene/mesh.h"

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace lab::tools {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr int kFloat = 5126, kUint = 5125, kUshort = 5123, kShort = 5122, kUbyte = 5121, kByte = 5120;

void save(const fs::path& file, const std::string& bytes) {
    std::string error;
    if (!writeFileAtomic(file, bytes, error)) {
        throw std::runtime_error(error);
    }
}

// A glTF document and its one binary buffer (buffer 0), built up view by view.
struct Builder {
    Json doc;
    std::string bin;

    Builder() {
        doc = {{"asset", {{"version", "2.0"}, {"generator", "lab_gen_gltf_variants"}}},
               {"scene", 0},
               {"scenes", Json::array({{{"nodes", {0}}}})},
               {"nodes", Json::array()},
               {"meshes", Json::array()},
               {"accessors", Json::array()},
               {"bufferViews", Json::array()},
               {"buffers", Json::array({Json::object()})}}; // buffer 0, filled in by glb() or gltf()
    }

    // Appends `bytes` to buffer 0 (4-byte aligned) as a new bufferView; returns its index.
    std::size_t view(const void* bytes, std::size_t size, std::size_t stride = 0) {
        while (bin.size() % 4) {
            bin += '\0';
        }
        Json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
        if (stride) {
            v["byteStride"] = stride;
        }
        bin.append(static_cast<const char*>(bytes), size);
        doc["bufferViews"].push_back(v);
        return doc["bufferViews"].size() - 1;
    }
    template <typename T> std::size_t view(const std::vector<T>& v, std::size_t stride = 0) {
        return view(v.data(), v.size() * sizeof(T), stride);
    }

    std::size_t accessor(Json a) {
        doc["accessors"].push_back(std::move(a));
        return doc["accessors"].size() - 1;
    }

    void require(const std::string& extension) {
        doc["extensionsUsed"].push_back(extension);
        doc["extensionsRequired"].push_back(extension);
    }

    std::string glb() {
        while (bin.size() % 4) {
            bin += '\0';
        }
        doc["buffers"][0] = {{"byteLength", bin.size()}};
        return glbContainer(doc.dump(), bin);
    }

    // folder/name.gltf beside folder/name.bin, the .bin `extra` bytes longer than declared.
    fs::path gltf(const fs::path& folder, const std::string& name, std::size_t extra = 0) {
        doc["buffers"][0] = {{"uri", name + ".bin"}, {"byteLength", bin.size()}};
        save(folder / (name + ".bin"), bin + std::string(extra, '\x7f'));
        save(folder / (name + ".gltf"), doc.dump(1));
        return folder / (name + ".gltf");
    }
};

std::vector<float> flat(const std::vector<glm::vec3>& v) {
    std::vector<float> out;
    for (const glm::vec3& p : v) {
        out.insert(out.end(), {p.x, p.y, p.z});
    }
    return out;
}

Json minMax(const std::vector<glm::vec3>& positions) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return {{"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}};
}

// Mesh 0 of `b` stored plainly: float positions and normals (when there are any), 32-bit indices
// (when `indexed`).
void addPlainMesh(Builder& b, const Mesh& mesh, bool indexed = true) {
    Json attributes;
    Json position = {{"bufferView", b.view(flat(mesh.positions))}, {"componentType", kFloat},
                     {"count", mesh.positions.size()}, {"type", "VEC3"}};
    position.update(minMax(mesh.positions));
    attributes["POSITION"] = b.accessor(position);
    if (!mesh.normals.empty()) {
        attributes["NORMAL"] = b.accessor({{"bufferView", b.view(flat(mesh.normals))}, {"componentType", kFloat},
                                           {"count", mesh.normals.size()}, {"type", "VEC3"}});
    }
    Json primitive = {{"attributes", attributes}};
    if (indexed) {
        primitive["indices"] = b.accessor({{"bufferView", b.view(mesh.indices)}, {"componentType", kUint},
                                           {"count", mesh.indices.size()}, {"type", "SCALAR"}});
    }
    b.doc["meshes"].push_back({{"primitives", {primitive}}});
}

// A plain file of `mesh` under `nodes`.
fs::path writePlain(const Mesh& mesh, const Json& nodes, const fs::path& file, bool indexed = true) {
    Builder b;
    addPlainMesh(b, mesh, indexed);
    b.doc["nodes"] = nodes;
    save(file, b.glb());
    return file;
}

const Json kOneNode = Json::array({{{"mesh", 0}}});

// The torus with each triangle's corners as vertices of their own, in order (for non-indexed files).
Mesh unrolled(const Mesh& mesh) {
    Mesh out;
    for (std::uint32_t i : mesh.indices) {
        out.positions.push_back(mesh.positions[i]);
        out.normals.push_back(mesh.normals[i]);
        out.indices.push_back(static_cast<std::uint32_t>(out.indices.size()));
    }
    return out;
}

template <typename T> std::vector<T> quantized(const std::vector<glm::vec3>& v, float scale, std::size_t stride) {
    std::vector<T> out(v.size() * stride / sizeof(T), 0);
    const std::size_t per = stride / sizeof(T);
    for (std::size_t i = 0; i < v.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            out[i * per + k] = static_cast<T>(std::lround(v[i][k] * scale));
        }
    }
    return out;
}

std::vector<GltfVariant> sparse(const Mesh& torus, const fs::path& folder) {
    std::vector<GltfVariant> out;
    { // Over a bufferView: every third position and fourth normal stored wrong, put right by the sparse substitutions.
        Builder b;
        std::vector<glm::vec3> positions = torus.positions, normals = torus.normals, goodP, goodN;
        std::vector<std::uint16_t> whereP;
        std::vector<std::uint32_t> whereN;
        for (std::size_t i = 0; i < positions.size(); ++i) {
            if (i % 3 == 0) {
                whereP.push_back(static_cast<std::uint16_t>(i));
                goodP.push_back(positions[i]);
                positions[i] = glm::vec3(5.0f);
            }
            if (i % 4 == 1) {
                whereN.push_back(static_cast<std::uint32_t>(i));
                goodN.push_back(normals[i]);
                normals[i] = glm::vec3(0.0f, -1.0f, 0.0f);
            }
        }
        Json position = {{"bufferView", b.view(flat(positions))}, {"componentType", kFloat}, {"count", positions.size()}, {"type", "VEC3"}};
        position["sparse"] = {{"count", whereP.size()},
                              {"indices", {{"bufferView", b.view(whereP)}, {"componentType", kUshort}}},
                              {"values", {{"bufferView", b.view(flat(goodP))}}}};
        Json normal = {{"bufferView", b.view(flat(normals))}, {"componentType", kFloat}, {"count", normals.size()}, {"type", "VEC3"}};
        normal["sparse"] = {{"count", whereN.size()},
                            {"indices", {{"bufferView", b.view(whereN)}, {"componentType", kUint}, {"byteOffset", 0}}},
                            {"values", {{"bufferView", b.view(flat(goodN))}}}};
        Json attributes = {{"POSITION", b.accessor(position)}, {"NORMAL", b.accessor(normal)}};
        std::size_t indices = b.accessor({{"bufferView", b.view(torus.indices)}, {"componentType", kUint},
                                          {"count", torus.indices.size()}, {"type", "SCALAR"}});
        b.doc["meshes"].push_back({{"primitives", {{{"attributes", attributes}, {"indices", indices}}}}});
        b.doc["nodes"] = kOneNode;
        save(folder / "sparse-over-view.glb", b.glb());
        out.push_back({"sparse accessors over a bufferView, indexed", folder / "sparse-over-view.glb", folder / "plain.glb"});
    }
    { // Without a bufferView (zeros, then every element substituted), in a primitive without indices.
        Builder b;
        const Mesh soup = unrolled(torus);
        std::vector<std::uint32_t> all(soup.positions.size());
        for (std::size_t i = 0; i < all.size(); ++i) {
            all[i] = static_cast<std::uint32_t>(i);
        }
        Json position = {{"componentType", kFloat}, {"count", soup.positions.size()}, {"type", "VEC3"}};
        position.update(minMax(soup.positions));
        position["sparse"] = {{"count", all.size()},
                              {"indices", {{"bufferView", b.view(all)}, {"componentType", kUint}}},
                              {"values", {{"bufferView", b.view(flat(soup.positions))}}}};
        Json attributes = {{"POSITION", b.accessor(position)},
                           {"NORMAL", b.accessor({{"bufferView", b.view(flat(soup.normals))}, {"componentType", kFloat},
                                                  {"count", soup.normals.size()}, {"type", "VEC3"}})}};
        b.doc["meshes"].push_back({{"primitives", {{{"attributes", attributes}}}}});
        b.doc["nodes"] = kOneNode;
        save(folder / "sparse-no-view.glb", b.glb());
        writePlain(soup, kOneNode, folder / "plain-unrolled.glb", false);
        out.push_back({"sparse accessor without a bufferView, not indexed", folder / "sparse-no-view.glb", folder / "plain-unrolled.glb"});
    }
    return out;
}

std::vector<GltfVariant> quantization(const Mesh& torus, const fs::path& folder) {
    std::vector<GltfVariant> out;
    { // Normalized SHORT positions (the torus fits in [-1, 1]), normalized BYTE normals padded to 4 bytes, 16-bit indices.
        Builder b;
        b.require("KHR_mesh_quantization");
        std::vector<std::int16_t> p = quantized<std::int16_t>(torus.positions, 32767.0f, 8);
        std::vector<std::int8_t> n = quantized<std::int8_t>(torus.normals, 127.0f, 4);
        std::vector<std::uint16_t> indices(torus.indices.begin(), torus.indices.end());
        Json attributes = {
            {"POSITION", b.accessor({{"bufferView", b.view(p, 8)}, {"componentType", kShort}, {"normalized", true},
                                     {"count", torus.positions.size()}, {"type", "VEC3"}})},
            {"NORMAL", b.accessor({{"bufferView", b.view(n, 4)}, {"componentType", kByte}, {"normalized", true},
                                   {"count", torus.normals.size()}, {"type", "VEC3"}})}};
        std::size_t ix = b.accessor({{"bufferView", b.view(indices)}, {"componentType", kUshort}, {"count", indices.size()}, {"type", "SCALAR"}});
        b.doc["meshes"].push_back({{"primitives", {{{"attributes", attributes}, {"indices", ix}}}}});
        b.doc["nodes"] = kOneNode;
        save(folder / "quantized-short.glb", b.glb());
        // The twin: the same values as floats, dequantized as the specification says.
        Mesh twin = torus;
        for (std::size_t i = 0; i < twin.positions.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                twin.positions[i][k] = std::max(p[i * 4 + k] / 32767.0f, -1.0f);
                twin.normals[i][k] = std::max(n[i * 4 + k] / 127.0f, -1.0f);
            }
        }
        writePlain(twin, kOneNode, folder / "quantized-short-twin.glb");
        out.push_back({"KHR_mesh_quantization: normalized SHORT positions, BYTE normals", folder / "quantized-short.glb",
                       folder / "quantized-short-twin.glb"});
    }
    { // UNSIGNED_BYTE positions, not normalized, placed by the node; normalized SHORT normals.
        Builder b;
        b.require("KHR_mesh_quantization");
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& q : torus.positions) {
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
        const glm::vec3 step = (hi - lo) / 255.0f;
        std::vector<std::uint8_t> p(torus.positions.size() * 4, 0);
        Mesh twin = torus;
        for (std::size_t i = 0; i < torus.positions.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                p[i * 4 + k] = static_cast<std::uint8_t>(std::lround((torus.positions[i][k] - lo[k]) / step[k]));
                twin.positions[i][k] = p[i * 4 + k];
            }
        }
        std::vector<std::int16_t> n = quantized<std::int16_t>(torus.normals, 32767.0f, 8);
        for (std::size_t i = 0; i < twin.normals.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                twin.normals[i][k] = std::max(n[i * 4 + k] / 32767.0f, -1.0f);
            }
        }
        Json attributes = {
            {"POSITION", b.accessor({{"bufferView", b.view(p, 4)}, {"componentType", kUbyte}, {"count", torus.positions.size()}, {"type", "VEC3"}})},
            {"NORMAL", b.accessor({{"bufferView", b.view(n, 8)}, {"componentType", kShort}, {"normalized", true},
                                   {"count", torus.normals.size()}, {"type", "VEC3"}})}};
        std::size_t ix = b.accessor({{"bufferView", b.view(torus.indices)}, {"componentType", kUint}, {"count", torus.indices.size()}, {"type", "SCALAR"}});
        b.doc["meshes"].push_back({{"primitives", {{{"attributes", attributes}, {"indices", ix}}}}});
        const Json nodes = Json::array({{{"mesh", 0}, {"translation", {lo.x, lo.y, lo.z}}, {"scale", {step.x, step.y, step.z}}}});
        b.doc["nodes"] = nodes;
        save(folder / "quantized-byte.glb", b.glb());
        writePlain(twin, nodes, folder / "quantized-byte-twin.glb");
        out.push_back({"KHR_mesh_quantization: UNSIGNED_BYTE positions placed by the node, SHORT normals",
                       folder / "quantized-byte.glb", folder / "quantized-byte-twin.glb"});
    }
    return out;
}

GltfVariant draco(const Mesh& torus, const fs::path& folder) {
    draco::TriangleSoupMeshBuilder builder;
    const int faces = static_cast<int>(torus.triangleCount());
    builder.Start(faces);
    const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int nrm = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
    for (int f = 0; f < faces; ++f) {
        const std::uint32_t* t = &torus.indices[static_cast<std::size_t>(f) * 3];
        builder.SetAttributeValuesForFace(pos, draco::FaceIndex(f), &torus.positions[t[0]], &torus.positions[t[1]], &torus.positions[t[2]]);
        builder.SetAttributeValuesForFace(nrm, draco::FaceIndex(f), &torus.normals[t[0]], &torus.normals[t[1]], &torus.normals[t[2]]);
    }
    std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 16);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 14);
    draco::EncoderBuffer encoded;
    if (!mesh || !encoder.EncodeMeshToBuffer(*mesh, &encoded).ok()) {
        throw std::runtime_error("Draco could not encode the torus");
    }
    Builder b;
    b.require("KHR_draco_mesh_compression");
    const std::size_t view = b.view(encoded.data(), encoded.size());
    const auto points = mesh->num_points();
    Json position = {{"componentType", kFloat}, {"count", points}, {"type", "VEC3"}};
    position.update(minMax(torus.positions));
    Json attributes = {{"POSITION", b.accessor(position)},
                       {"NORMAL", b.accessor({{"componentType", kFloat}, {"count", points}, {"type", "VEC3"}})}};
    std::size_t ix = b.accessor({{"componentType", kUint}, {"count", torus.indices.size()}, {"type", "SCALAR"}});
    Json ext = {{"bufferView", view},
                {"attributes", {{"POSITION", mesh->GetNamedAttribute(draco::GeometryAttribute::POSITION)->unique_id()},
                                {"NORMAL", mesh->GetNamedAttribute(draco::GeometryAttribute::NORMAL)->unique_id()}}}};
    b.doc["meshes"].push_back(
        {{"primitives", {{{"attributes", attributes}, {"indices", ix}, {"extensions", {{"KHR_draco_mesh_compression", ext}}}}}}});
    b.doc["nodes"] = kOneNode;
    save(folder / "draco.glb", b.glb());
    return {"KHR_draco_mesh_compression (16-bit positions, 14-bit normals)", folder / "draco.glb", folder / "plain.glb", false};
}

GltfVariant meshopt(const Mesh& torus, const fs::path& folder) {
    Builder b;
    b.require("EXT_meshopt_compression");
    const std::size_t n = torus.positions.size();
    // The fallback buffer (buffer 1) has no data: every view on it is compressed into buffer 0.
    std::size_t fallbackSize = 0;
    auto compressed = [&](const std::vector<unsigned char>& encoded, std::size_t count, std::size_t stride,
                          const char* mode, const char* filter) {
        const std::size_t source = b.view(encoded.data(), encoded.size());
        Json ext = b.doc["bufferViews"][source];
        b.doc["bufferViews"].erase(source); // the compressed bytes are read through the extension only
        ext.erase("byteStride");
        ext.update({{"byteStride", stride}, {"count", count}, {"mode", mode}});
        if (std::strcmp(filter, "NONE") != 0) {
            ext["filter"] = filter;
        }
        Json view = {{"buffer", 1}, {"byteOffset", fallbackSize}, {"byteLength", count * stride},
                     {"extensions", {{"EXT_meshopt_compression", ext}}}};
        if (std::strcmp(mode, "ATTRIBUTES") == 0) {
            view["byteStride"] = stride;
        }
        fallbackSize += (count * stride + 3) / 4 * 4;
        b.doc["bufferViews"].push_back(view);
        return b.doc["bufferViews"].size() - 1;
    };
    std::vector<unsigned char> encoded(meshopt_encodeVertexBufferBound(n, 12));
    encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), torus.positions.data(), n, 12));
    const std::size_t positions = compressed(encoded, n, 12, "ATTRIBUTES", "NONE");
    // Normals: 16-bit octahedral (4 shorts a vertex), the filter meshoptimizer offers for unit vectors.
    std::vector<float> normals4;
    for (const glm::vec3& v : torus.normals) {
        normals4.insert(normals4.end(), {v.x, v.y, v.z, 1.0f});
    }
    std::vector<std::int16_t> oct(n * 4);
    meshopt_encodeFilterOct(oct.data(), n, 8, 16, normals4.data());
    encoded.assign(meshopt_encodeVertexBufferBound(n, 8), 0);
    encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), oct.data(), n, 8));
    const std::size_t normals = compressed(encoded, n, 8, "ATTRIBUTES", "OCTAHEDRAL");
    encoded.assign(meshopt_encodeIndexBufferBound(torus.indices.size(), n), 0);
    encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), torus.indices.data(), torus.indices.size()));
    const std::size_t indices = compressed(encoded, torus.indices.size(), 4, "TRIANGLES", "NONE");
    Json position = {{"bufferView", positions}, {"componentType", kFloat}, {"count", n}, {"type", "VEC3"}};
    position.update(minMax(torus.positions));
    Json attributes = {{"POSITION", b.accessor(position)},
                       {"NORMAL", b.accessor({{"bufferView", normals}, {"componentType", kShort}, {"normalized", true},
                                              {"count", n}, {"type", "VEC3"}})}};
    std::size_t ix = b.accessor({{"bufferView", indices}, {"componentType", kUint}, {"count", torus.indices.size()}, {"type", "SCALAR"}});
    b.doc["meshes"].push_back({{"primitives", {{{"attributes", attributes}, {"indices", ix}}}}});
    b.doc["nodes"] = kOneNode;
    b.doc["extensionsUsed"].push_back("KHR_mesh_quantization");
    b.doc["extensionsRequired"].push_back("KHR_mesh_quantization");
    b.doc["buffers"].push_back({{"byteLength", fallbackSize}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    save(folder / "meshopt.glb", b.glb());
    return {"EXT_meshopt_compression (positions, octahedral normals, triangles) with a fallback buffer",
            folder / "meshopt.glb", folder / "plain.glb", false};
}

GltfVariant instancing(const Mesh& torus, const fs::path& folder) {
    const std::vector<glm::vec3> translations = {{-1.1f, 0.0f, 0.0f}, {1.1f, 0.3f, 0.0f}, {0.0f, -0.2f, -1.2f}};
    const std::vector<float> rotations = {0, 0, 0, 1, 0.3826834f, 0, 0, 0.9238795f, 0, 0, 0.2588190f, 0.9659258f};
    const std::vector<glm::vec3> scales = {{0.5f, 0.5f, 0.5f}, {0.6f, 0.4f, 0.6f}, {0.45f, 0.45f, 0.45f}};
    Builder b;
    addPlainMesh(b, torus);
    Json instance = {{"TRANSLATION", b.accessor({{"bufferView", b.view(flat(translations))}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"}})},
                     {"ROTATION", b.accessor({{"bufferView", b.view(rotations)}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC4"}})},
                     {"SCALE", b.accessor({{"bufferView", b.view(flat(scales))}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"}})}};
    b.doc["nodes"] = Json::array({{{"mesh", 0}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", instance}}}}}}});
    b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    save(folder / "instanced.glb", b.glb());
    Json nodes = Json::array({{{"children", {1, 2, 3}}}});
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 t = translations[static_cast<std::size_t>(i)], s = scales[static_cast<std::size_t>(i)];
        nodes.push_back({{"mesh", 0},
                         {"translation", {t.x, t.y, t.z}},
                         {"rotation", {rotations[4 * i], rotations[4 * i + 1], rotations[4 * i + 2], rotations[4 * i + 3]}},
                         {"scale", {s.x, s.y, s.z}}});
    }
    writePlain(torus, nodes, folder / "instances-as-nodes.glb");
    return {"EXT_mesh_gpu_instancing: three instances", folder / "instanced.glb", folder / "instances-as-nodes.glb"};
}

} // namespace

std::vector<GltfVariant> writeGltfVariants(const fs::path& folder, int major, int minor) {
    fs::create_directories(folder);
    const Mesh torus = makeTorus(major, minor);
    std::vector<GltfVariant> out;
    writePlain(torus, kOneNode, folder / "plain.glb");

    { // The same buffer in a .bin file longer than its byteLength (the specification allows it).
        Builder b;
        addPlainMesh(b, torus);
        b.doc["nodes"] = kOneNode;
        out.push_back({"a .bin longer than its byteLength", b.gltf(folder, "longer-bin", 1001), folder / "plain.glb"});
    }
    for (GltfVariant& v : sparse(torus, folder)) {
        out.push_back(std::move(v));
    }
    for (GltfVariant& v : quantization(torus, folder)) {
        out.push_back(std::move(v));
    }
    out.push_back(draco(torus, folder));
    out.push_back(meshopt(torus, folder));
    out.push_back(instancing(torus, folder));

    { // A mirroring node (negative determinant): glTF winds its triangles clockwise; computed
      // normals must still point out. The twin is the mirrored torus stored counter-clockwise.
        Mesh noNormals = torus;
        noNormals.normals.clear();
        writePlain(noNormals, Json::array({{{"mesh", 0}, {"scale", {-1.0, 1.0, 1.0}}}}), folder / "mirrored.glb");
        Mesh twin = noNormals;
        for (glm::vec3& p : twin.positions) {
            p.x = -p.x;
        }
        for (std::size_t t = 0; t + 2 < twin.indices.size(); t += 3) {
            std::swap(twin.indices[t + 1], twin.indices[t + 2]);
        }
        writePlain(twin, kOneNode, folder / "mirrored-twin.glb");
        out.emplace_back("a node that mirrors the mesh, normals computed", folder / "mirrored.glb", folder / "mirrored-twin.glb");
    }
    { // Some normals NaN (as a Blender export of degenerate faces has): computed for those vertices only.
        Mesh nan = torus, twin = torus;
        const std::vector<glm::vec3> computed = computeVertexNormals(torus.positions, torus.indices);
        std::size_t count = 0;
        for (std::size_t i = 0; i < nan.normals.size(); i += 5, ++count) {
            nan.normals[i] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
            twin.normals[i] = computed[i];
        }
        nan.normals[1] = glm::vec3(0.0f); // and one zero normal
        twin.normals[1] = computed[1];
        writePlain(nan, kOneNode, folder / "nan-normals.glb");
        writePlain(twin, kOneNode, folder / "nan-normals-twin.glb");
        GltfVariant v{"normals NaN or zero at some vertices", folder / "nan-normals.glb", folder / "nan-normals-twin.glb"};
        v.note = "normals computed for " + std::to_string(count + 1) + " vertices";
        out.push_back(v);
    }
    { // A required extension that only adds material data: ignored, with a note.
        Builder b;
        b.require("KHR_materials_unlit");
        addPlainMesh(b, torus);
        b.doc["nodes"] = kOneNode;
        save(folder / "material-extension-required.glb", b.glb());
        GltfVariant v{"a required material extension", folder / "material-extension-required.glb", folder / "plain.glb"};
        v.note = "required extension(s) ignored";
        out.push_back(v);

        b.doc["extensionsRequired"] = {"EXT_lab_unknown_extension"};
        save(folder / "unknown-extension-required.glb", b.glb());
        GltfVariant u{"an unknown required extension", folder / "unknown-extension-required.glb", {}};
        u.refusal = "unknown-extension-required.glb: needs the glTF extension \"EXT_lab_unknown_extension\", which this lab does not support";
        out.push_back(u);
    }
    { // glTF 1.0: objects keyed by name, as JSON and as GLB version 1.
        const char* json = R"({"asset": {"version": "1.0"}, "scene": "defaultScene",
            "scenes": {"defaultScene": {"nodes": ["node_1"]}}, "nodes": {"node_1": {"meshes": ["mesh_1"]}},
            "meshes": {"mesh_1": {"primitives": [{"attributes": {"POSITION": "accessor_1"}, "mode": 4}]}}})";
        save(folder / "gltf1.gltf", json);
        out.push_back({"glTF 1.0", folder / "gltf1.gltf", {}, true, "gltf1.gltf: a glTF 1.0 file; the lab reads glTF 2.0"});
        std::string glb = "glTF";
        std::string content = json;
        while (content.size() % 4) {
            content += ' ';
        }
        auto u32 = [&glb](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
        u32(1);
        u32(static_cast<std::uint32_t>(20 + content.size()));
        u32(static_cast<std::uint32_t>(content.size()));
        u32(0);
        glb += content;
        save(folder / "gltf1.glb", glb);
        out.push_back({"binary glTF 1.0", folder / "gltf1.glb", {}, true, "gltf1.glb: a binary glTF 1.0 file (GLB version 1)"});
    }
    return out;
}

} // namespace lab::tools
