// gltf_variants_test.cpp — every way a downloaded glTF may store a model, against the same model
// stored plainly (tools/gltf_variants.h): sparse accessors, KHR_mesh_quantization, a longer
// .bin, KHR_draco_mesh_compression and EXT_meshopt_compression (made with the libraries' own
// encoders, here), EXT_mesh_gpu_instancing, NaN normals; and the files the lab must refuse in
// one line (an unknown required extension, glTF 1.0). Each shown variant is rendered with EGL
// beside its plain twin and must give the same pixels within the screenshot tests' tolerance.
// Then the decoders' inputs, broken one field at a time, must be refused naming the place.
#include "core/gltf/draco_mesh.h"
#include "core/gltf/reader.h"
#include "core/io/image.h"
#include "core/scene/preset.h"
#include "glb_writer.h"
#include "gltf_variants.h"
#include "render/offscreen.h"

#include "gl_suite.h"
#include "test_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>
#include <functional>

namespace lab {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using tools::GltfVariant;

bool contains(const std::vector<std::string>& lines, const std::string& part) {
    for (const std::string& line : lines) {
        if (line.find(part) != std::string::npos) {
            return true;
        }
    }
    return false;
}

// The largest difference between two loaded meshes' positions and normals; infinity when their
// sizes or indices differ.
float meshDifference(const Mesh& a, const Mesh& b) {
    if (a.positions.size() != b.positions.size() || a.normals.size() != b.normals.size() || a.indices != b.indices) {
        return std::numeric_limits<float>::infinity();
    }
    float most = 0.0f;
    for (std::size_t i = 0; i < a.positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            most = std::max({most, std::abs(a.positions[i][k] - b.positions[i][k]), std::abs(a.normals[i][k] - b.normals[i][k])});
        }
    }
    return most;
}

// A GLB's JSON and BIN chunk, to change a field and write it back.
struct Glb {
    Json json;
    std::string bin;

    static Glb read(const fs::path& file) {
        const std::string bytes = readText(file);
        std::uint32_t jsonLength = 0, binLength = 0;
        std::memcpy(&jsonLength, bytes.data() + 12, 4);
        std::memcpy(&binLength, bytes.data() + 20 + jsonLength, 4);
        return {Json::parse(bytes.substr(20, jsonLength)), bytes.substr(28 + jsonLength, binLength)};
    }
    void write(const fs::path& file) const { writeText(file, tools::glbContainer(json.dump(), bin)); }
};

class GltfVariants : public GlSuite<testing::Test, OffscreenRenderer> {
protected:
    static void SetUpTestSuite() {
        folder_ = new TempFolder;
        variants_ = new std::vector<GltfVariant>(tools::writeGltfVariants(folder_->path() / "models"));
        GlSuite::SetUpTestSuite();
    }
    static void TearDownTestSuite() {
        GlSuite::TearDownTestSuite();
        delete variants_;
        delete folder_;
    }

    // The model rendered at 200×200 by a preset with an explicit camera looking down at it.
    static std::optional<Image> render(const fs::path& model, Diagnostics& d) {
        const fs::path preset = folder_->path() / "scene.json";
        writeText(preset, Json{{"format", "lighting-lab-preset"}, {"version", 1},
                               {"model", {{"gltf", "models/" + model.filename().string()}}},
                               {"camera", {{"eye", {0.0, 2.4, 3.2}}, {"target", {0, 0, 0}}}},
                               {"material", {{"diffuse", {0.8, 0.5, 0.3}}, {"specular", {0.6, 0.6, 0.6}}, {"shininess", 40}}},
                               {"lights", {{{"position", {2, 3, 2}}}}}}
                              .dump());
        std::optional<LoadedPreset> loaded = loadPreset(preset, d);
        if (!loaded) {
            return std::nullopt;
        }
        std::optional<Image> image = renderer_->render(*loaded, 200, 200, d);
        if (const char* shots = std::getenv("LAB_VARIANT_SHOTS"); image && shots) {
            std::string error;
            writePng(*image, fs::path(shots) / (model.stem().string() + ".png"), error);
        }
        return image;
    }

    static inline TempFolder* folder_ = nullptr;
    static inline std::vector<GltfVariant>* variants_ = nullptr;
};

TEST_F(GltfVariants, EachLoadsAsItsPlainTwinAndRendersTheSame) {
    ASSERT_NE(renderer_, nullptr);
    int shown = 0;
    for (const GltfVariant& v : *variants_) {
        if (v.twin.empty()) {
            continue;
        }
        SCOPED_TRACE(v.name + " (" + v.file.filename().string() + ")");
        Diagnostics d;
        std::optional<GltfResult> variant = loadGltf(v.file, v.file.filename().string(), d);
        ASSERT_TRUE(variant) << toString(d);
        std::optional<GltfResult> twin = loadGltf(v.twin, v.twin.filename().string(), d);
        ASSERT_TRUE(twin) << toString(d);
        if (!v.note.empty()) {
            EXPECT_TRUE(contains(variant->notes, v.note)) << "notes: " << testing::PrintToString(variant->notes);
        }
        if (v.exact) {
            EXPECT_LE(meshDifference(variant->mesh, twin->mesh), 1e-5f);
        } else {
            EXPECT_EQ(variant->mesh.triangleCount(), twin->mesh.triangleCount());
        }
        std::optional<Image> a = render(v.file, d), b = render(v.twin, d);
        ASSERT_TRUE(a && b) << toString(d);
        Comparison c = compareImages(*a, *b, Tolerance{});
        EXPECT_TRUE(c.passes(Tolerance{})) << "failing share " << c.failingShare << ", mean difference "
                                           << c.meanDifference << ", max " << c.maxDifference;
        // ...and the picture is of the model, not of an empty scene both agree on.
        const Image empty = [&] {
            Image e = *b;
            std::fill(e.rgb.begin(), e.rgb.end(), std::uint8_t{0});
            return e;
        }();
        EXPECT_GT(compareImages(*b, empty, Tolerance{}).failingShare, 0.1);
        ++shown;
    }
    EXPECT_GE(shown, 10);
}

TEST_F(GltfVariants, FilesThatCannotBeShownAreRefusedInOneLineSayingWhy) {
    int refused = 0;
    for (const GltfVariant& v : *variants_) {
        if (!v.twin.empty()) {
            continue;
        }
        SCOPED_TRACE(v.name);
        Diagnostics d;
        EXPECT_FALSE(loadGltf(v.file, v.file.filename().string(), d));
        ASSERT_EQ(d.size(), 1u) << toString(d);
        EXPECT_NE(d[0].str().find(v.refusal), std::string::npos) << d[0].str();
        EXPECT_EQ(d[0].str().find('\n'), std::string::npos);
        ++refused;
    }
    EXPECT_EQ(refused, 3);
}

// One field of a variant's JSON changed (or its BIN chunk cut), and the diagnostic expected.
struct Breakage {
    const char* name;
    const char* file;
    std::function<void(Glb&)> change;
    const char* where;
    const char* message;
};

TEST_F(GltfVariants, BrokenCompressedSparseAndInstancedDataIsRefusedWithItsPlace) {
    const Breakage cases[] = {
        {"Draco bytes cut short", "draco.glb",
         [](Glb& g) { g.json["bufferViews"][0]["byteLength"] = 24; }, "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression",
         "the Draco data does not decode"},
        {"Draco data that is not Draco", "draco.glb",
         [](Glb& g) { std::fill(g.bin.begin(), g.bin.begin() + 64, '\x5a'); },
         "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression", "the Draco data does not decode"},
        {"Draco attribute id that names nothing", "draco.glb",
         [](Glb& g) { g.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 77; },
         "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression.attributes.NORMAL", "names no attribute"},
        {"Draco bufferView missing", "draco.glb",
         [](Glb& g) { g.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"].erase("bufferView"); },
         "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression.bufferView", "missing"},
        {"meshopt stride not a multiple of 4", "meshopt.glb",
         [](Glb& g) { g.json["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteStride"] = 6; },
         "bufferViews[0].extensions.EXT_meshopt_compression.byteStride", "multiple of 4"},
        {"meshopt count larger than encoded", "meshopt.glb",
         [](Glb& g) { g.json["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["count"] = 100000; },
         "bufferViews[0].extensions.EXT_meshopt_compression", "does not decode"},
        {"meshopt source beyond its buffer", "meshopt.glb",
         [](Glb& g) { g.json["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["byteOffset"] = 1u << 30; },
         "bufferViews[1].extensions.EXT_meshopt_compression", "do not exist"},
        {"meshopt unknown mode", "meshopt.glb",
         [](Glb& g) { g.json["bufferViews"][2]["extensions"]["EXT_meshopt_compression"]["mode"] = "STRIPS"; },
         "bufferViews[2].extensions.EXT_meshopt_compression.mode", "is not ATTRIBUTES, TRIANGLES or INDICES"},
        {"meshopt triangles not a multiple of 3", "meshopt.glb",
         [](Glb& g) { g.json["bufferViews"][2]["extensions"]["EXT_meshopt_compression"]["count"] = 10; },
         "bufferViews[2].extensions.EXT_meshopt_compression.count", "not a multiple of 3"},
        {"meshopt filter on indices", "meshopt.glb",
         [](Glb& g) { g.json["bufferViews"][2]["extensions"]["EXT_meshopt_compression"]["filter"] = "OCTAHEDRAL"; },
         "bufferViews[2].extensions.EXT_meshopt_compression.filter", "does not fit"},
        {"a view left on the fallback buffer", "meshopt.glb",
         [](Glb& g) { g.json["bufferViews"][0].erase("extensions"); }, "bufferViews[0]", "lies beyond its buffer of 0 bytes"},
        {"sparse index beyond the accessor", "sparse-over-view.glb",
         [](Glb& g) { g.json["accessors"][0]["count"] = 200; }, "accessors[0].sparse.indices", "is beyond the accessor's 200 elements"},
        {"sparse values beyond their view", "sparse-over-view.glb",
         [](Glb& g) { g.json["accessors"][0]["sparse"]["values"]["byteOffset"] = 4000; }, "accessors[0].sparse.values",
         "reads beyond its bufferView"},
        {"sparse count above the accessor's", "sparse-no-view.glb",
         [](Glb& g) { g.json["accessors"][0]["count"] = 3; }, "accessors[0].sparse", "is not between 1 and the accessor's 3 elements"},
        {"an accessor without a view asking for too much", "sparse-no-view.glb",
         [](Glb& g) { g.json["accessors"][0]["count"] = 3'000'000'000u; }, "accessors[0]", "the lab reads at most 20000000 there"},
        {"a sparse accessor asking for more vertices than the lab reads", "sparse-over-view.glb",
         [](Glb& g) { g.json["accessors"][0].erase("bufferView"); g.json["accessors"][0]["count"] = 50'000'000; },
         "accessors[0]", "the lab reads at most 20000000 there"},
        {"meshopt stride above glTF's 252", "meshopt.glb",
         [](Glb& g) { g.json["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteStride"] = 256; },
         "bufferViews[0].extensions.EXT_meshopt_compression.byteStride", "up to 252"},
        {"meshopt views asking for more than the lab decodes", "meshopt.glb",
         [](Glb& g) { g.json["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["count"] = 100'000'000; },
         "bufferViews[0].extensions.EXT_meshopt_compression.count", "bytes the lab decodes for a file"},
        {"a fallback flag that is not a boolean", "meshopt.glb",
         [](Glb& g) { g.json["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"] = 1; }, "buffers[1].byteLength",
         "more than the GLB's BIN chunk"},
        {"quantized normals not normalized", "quantized-short.glb",
         [](Glb& g) { g.json["accessors"][1]["normalized"] = false; }, "accessors[1]", "expected VEC3 of FLOAT, or of normalized BYTE or SHORT"},
        {"instances with different counts", "instanced.glb",
         [](Glb& g) { g.json["accessors"][5]["count"] = 2; },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.SCALE", "2 instances, but another attribute has 3"},
        {"an instance attribute that is no accessor", "instanced.glb",
         [](Glb& g) { g.json["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["ROTATION"] = 99; },
         "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.ROTATION", "accessor 99 does not exist"},
        {"a newer glTF", "draco.glb", [](Glb& g) { g.json["asset"]["minVersion"] = "2.1"; }, "asset.minVersion", "needs glTF"},
    };
    for (const Breakage& c : cases) {
        SCOPED_TRACE(c.name);
        Glb g = Glb::read(folder_->path() / "models" / c.file);
        c.change(g);
        const fs::path broken = folder_->path() / "models" / "broken.glb";
        g.write(broken);
        Diagnostics d;
        EXPECT_FALSE(loadGltf(broken, "broken.glb", d));
        ASSERT_EQ(d.size(), 1u) << toString(d);
        EXPECT_EQ(d[0].where, c.where) << d[0].str();
        EXPECT_NE(d[0].message.find(c.message), std::string::npos) << d[0].str();
    }
}

TEST_F(GltfVariants, ADracoPrimitiveIsTrianglesWhateverModeItNames) {
    Glb g = Glb::read(folder_->path() / "models" / "draco.glb");
    g.json["meshes"][0]["primitives"][0]["mode"] = 5; // a strip: Draco decodes a list all the same
    g.write(folder_->path() / "models" / "draco-strip.glb");
    Diagnostics d;
    std::optional<GltfResult> strip = loadGltf(folder_->path() / "models" / "draco-strip.glb", "draco-strip.glb", d);
    std::optional<GltfResult> list = loadGltf(folder_->path() / "models" / "draco.glb", "draco.glb", d);
    ASSERT_TRUE(strip && list) << toString(d);
    EXPECT_EQ(strip->mesh.indices, list->mesh.indices);
}

TEST_F(GltfVariants, RequiredExtensionNotesAreOneLineEachNameOnce) {
    Glb g = Glb::read(folder_->path() / "models" / "material-extension-required.glb");
    g.json["extensionsRequired"] = {"KHR_materials_x\nlab: a line of its own", "KHR_materials_x\nlab: a line of its own",
                                    "KHR_texture_transform"};
    g.write(folder_->path() / "models" / "ext-newline.glb");
    Diagnostics d;
    std::optional<GltfResult> r = loadGltf(folder_->path() / "models" / "ext-newline.glb", "ext-newline.glb", d);
    ASSERT_TRUE(r) << toString(d);
    ASSERT_EQ(r->notes.size(), 1u) << testing::PrintToString(r->notes);
    EXPECT_EQ(r->notes[0].find('\n'), std::string::npos) << r->notes[0];
    EXPECT_NE(r->notes[0].find("KHR_texture_transform"), std::string::npos) << r->notes[0];
    const std::size_t first = r->notes[0].find("KHR_materials_x");
    ASSERT_NE(first, std::string::npos);
    EXPECT_EQ(r->notes[0].find("KHR_materials_x", first + 1), std::string::npos) << "named twice: " << r->notes[0];
}

TEST_F(GltfVariants, DracoAndMeshoptAreRequiredAndLoadedWithoutNotes) {
    for (const char* name : {"draco.glb", "meshopt.glb"}) {
        Diagnostics d;
        std::optional<GltfResult> r = loadGltf(folder_->path() / "models" / name, name, d);
        ASSERT_TRUE(r) << toString(d);
        EXPECT_TRUE(r->notes.empty()) << testing::PrintToString(r->notes);
        EXPECT_EQ(r->mesh.triangleCount(), 24u * 12u * 2u);
    }
}


// The page's Draco module answers through packDracoResult / unpackDracoResult (the decoder is a
// WebAssembly module of its own there, core/gltf/draco_decoder.h): what crosses is the mesh as
// decoded, bit for bit, or the failure with its place; an answer that does not add up is refused.
TEST_F(GltfVariants, TheDracoModulesAnswerCarriesTheMeshOrTheFailureWhole) {
    using namespace gltf_detail;
    Glb g = Glb::read(folder_->path() / "models" / "draco.glb");
    const Json& ext = g.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"];
    const Json& view = g.json["bufferViews"][ext["bufferView"].get<std::size_t>()];
    const auto* bytes = reinterpret_cast<const unsigned char*>(g.bin.data()) + view.value("byteOffset", std::size_t{0});
    const std::size_t size = view["byteLength"].get<std::size_t>();
    DracoQuery query;
    query.position = {true, ext["attributes"]["POSITION"].get<std::int64_t>(), true};
    query.normal = {true, ext["attributes"]["NORMAL"].get<std::int64_t>(), true};
    query.maxPoints = query.maxFaces = 1u << 20;
    query.maxBytes = 1u << 30;
    // The query crosses as doubles.
    const DracoQueryWords words = queryWords(query);
    const DracoQuery back = queryFromWords(words.words, static_cast<double>(query.maxBytes));
    EXPECT_EQ(back.position.id, query.position.id);
    EXPECT_EQ(back.normal.id, query.normal.id);
    EXPECT_TRUE(back.normal.used && back.position.listed);
    EXPECT_EQ(back.maxFaces, query.maxFaces);
    EXPECT_EQ(back.maxBytes, query.maxBytes);

    DracoResult decoded = decodeDracoMesh(bytes, size, back);
    ASSERT_TRUE(std::holds_alternative<DracoMesh>(decoded)) << std::get<DracoFailure>(decoded).message;
    const DracoMesh& mesh = std::get<DracoMesh>(decoded);
    EXPECT_EQ(mesh.faces, 24u * 12u * 2u);
    EXPECT_EQ(mesh.positions.size(), mesh.points * 3u);
    EXPECT_EQ(mesh.normals.size(), mesh.points * 3u);
    std::vector<unsigned char> packed = packDracoResult(decoded);
    std::optional<DracoResult> unpacked = unpackDracoResult(packed.data(), packed.size());
    ASSERT_TRUE(unpacked && std::holds_alternative<DracoMesh>(*unpacked));
    const DracoMesh& crossed = std::get<DracoMesh>(*unpacked);
    EXPECT_EQ(crossed.points, mesh.points);
    EXPECT_EQ(crossed.indices, mesh.indices);
    EXPECT_EQ(0, std::memcmp(crossed.positions.data(), mesh.positions.data(), mesh.positions.size() * 4));
    EXPECT_EQ(0, std::memcmp(crossed.normals.data(), mesh.normals.data(), mesh.normals.size() * 4));

    // Cut short, one byte too many, or a triangle naming a point past the last: refused.
    EXPECT_FALSE(unpackDracoResult(packed.data(), packed.size() - 1));
    packed.push_back(0);
    EXPECT_FALSE(unpackDracoResult(packed.data(), packed.size()));
    packed.pop_back();
    const std::uint32_t past = mesh.points;
    std::memcpy(packed.data() + packed.size() - 4, &past, 4);
    EXPECT_FALSE(unpackDracoResult(packed.data(), packed.size()));

    // A failure keeps its place and message; a primitive that does not use NORMAL gets no normals.
    query.normal.id = 77;
    DracoResult failed = decodeDracoMesh(bytes, size, query);
    ASSERT_TRUE(std::holds_alternative<DracoFailure>(failed));
    packed = packDracoResult(failed);
    unpacked = unpackDracoResult(packed.data(), packed.size());
    ASSERT_TRUE(unpacked && std::holds_alternative<DracoFailure>(*unpacked));
    EXPECT_EQ(std::get<DracoFailure>(*unpacked).where, ".attributes.NORMAL");
    EXPECT_EQ(std::get<DracoFailure>(*unpacked).message, "names no attribute of the Draco data");
    query.normal = {false, -1, false};
    DracoResult bare = decodeDracoMesh(bytes, size, query);
    ASSERT_TRUE(std::holds_alternative<DracoMesh>(bare));
    EXPECT_TRUE(std::get<DracoMesh>(bare).normals.empty());
    query.maxFaces = mesh.faces - 1;
    DracoResult tooMany = decodeDracoMesh(bytes, size, query);
    ASSERT_TRUE(std::holds_alternative<DracoFailure>(tooMany));
    EXPECT_NE(std::get<DracoFailure>(tooMany).message.find("more than the lab reads"), std::string::npos);
}

} // namespace
} // namespace lab
