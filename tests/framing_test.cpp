// framing_test.cpp — a glTF model in a preset without a camera is framed, whatever its size.
//
// Real files written at test time: a box as .gltf + .bin, 0.01, 1 and 1000 units across, in a
// preset with no `camera` (and no `lights`) key, loaded with loadPreset and rendered with the
// OffscreenRenderer that `lab render` and `lab check` use. The model must cover a similar share
// of each image and touch no border; a long box and the trefoil knot fill 80–90% of the narrower
// side from a three-quarter view in square, wide and tall images; an explicit camera, a `lights`
// key and built-in models are left as they are. The unit tests of framedCamera itself are in camera_test.cpp.
#include "core/gltf/mesh_cache.h"
#include "core/gltf/model_loader.h"
#include "core/scene/camera.h"
#include "core/scene/preset.h"
#include "gl_suite.h"
#include "platform/headless_gl.h"
#include "render/offscreen.h"
#include "box_gltf.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace lab {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 96;

// An axis-aligned box `size` · `proportions` across (by default `size` units long (x), 0.6 · size
// high and 0.4 · size deep), centred on size · (3, -2, 1), as `name`.gltf (box_gltf.h).
void writeBox(const fs::path& folder, const std::string& name, float size,
              glm::vec3 proportions = {1.0f, 0.6f, 0.4f}) {
    const glm::vec3 center = size * glm::vec3(3.0f, -2.0f, 1.0f);
    const glm::vec3 half = size * proportions * 0.5f;
    writeBoxGltf(folder, name, center - half, center + half);
}

// A preset naming `gltf`, turned and moved in proportion to `size` (so that every size is the
// same scene at another scale), with `extra` keys ("" for none).
fs::path writePreset(const fs::path& folder, const std::string& name, const std::string& gltf, float size,
                     const std::string& extra = "", float scale = 1.0f) {
    fs::path file = folder / (name + ".json");
    std::string t = std::to_string(size);
    std::string s = std::to_string(scale);
    writeText(file, R"({"format": "lighting-lab-preset", "version": 1,
  "model": {"gltf": ")" + gltf + R"(", "rotate_deg": [20, 30, 0], "translate": [)" + t + ", " + t +
                        R"(, 0], "scale": [)" + s + ", " + s + ", " + s + "]}" + extra + "}");
    return file;
}

LoadedPreset load(const fs::path& file) {
    Diagnostics d;
    std::optional<LoadedPreset> p = loadPreset(file, d);
    EXPECT_TRUE(p) << toString(d);
    return p ? *p : LoadedPreset{};
}

// The preset as its consumers see it once it met its mesh.
Preset framed(const fs::path& file) {
    LoadedPreset p = load(file);
    MeshCache cache;
    Diagnostics d;
    EXPECT_TRUE(cache.get(p, d)) << toString(d);
    EXPECT_EQ(p.omitted, OmittedKeys{}) << "framing is done once: the preset then holds its camera";
    return p.preset;
}

// What an image of a preset shows: the share of pixels that are not the background, whether any
// of them lies on the border, and the box around them (in pixels, inclusive).
struct Coverage {
    double share = 0.0;
    bool onBorder = false;
    glm::ivec2 min{INT32_MAX}, max{-1};
    // The larger dimension of the model's pixels over the image's narrower side.
    double fill(const Image& image) const {
        return static_cast<double>(std::max(max.x - min.x + 1, max.y - min.y + 1)) / std::min(image.width, image.height);
    }
};

Coverage coverage(const Image& image, glm::vec3 background) {
    Coverage c;
    const glm::ivec3 bg = glm::ivec3(glm::round(background * 255.0f));
    int model = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.rgb[3 * static_cast<std::size_t>(y * image.width + x)];
            glm::ivec3 d = glm::abs(glm::ivec3(p[0], p[1], p[2]) - bg);
            if (std::max({d.x, d.y, d.z}) > 2) {
                ++model;
                c.min = glm::min(c.min, glm::ivec2(x, y));
                c.max = glm::max(c.max, glm::ivec2(x, y));
                c.onBorder = c.onBorder || x == 0 || y == 0 || x == image.width - 1 || y == image.height - 1;
            }
        }
    }
    c.share = static_cast<double>(model) / (image.width * image.height);
    return c;
}

class Framing : public GlSuite<testing::Test, OffscreenRenderer> {
protected:
    static Image render(const fs::path& preset) {
        Diagnostics d;
        std::optional<Image> image = renderer_->render(load(preset), kSize, kSize, d);
        EXPECT_TRUE(image) << toString(d);
        return image ? *image : Image{};
    }
    TempFolder dir;
};

TEST_F(Framing, AModelOfAnySizeFillsASimilarShareAndTouchesNoBorder) {
    ASSERT_NE(renderer_, nullptr);
    std::vector<Image> images;
    std::vector<double> shares;
    for (float size : {0.01f, 1.0f, 1000.0f}) {
        std::string name = "box-" + std::to_string(size);
        writeBox(dir.path(), name, size);
        Image image = render(writePreset(dir.path(), name, name + ".gltf", size));
        Coverage c = coverage(image, Preset{}.background);
        EXPECT_GT(c.share, 0.08) << "size " << size << ": the model should fill a fair share of the view";
        EXPECT_FALSE(c.onBorder) << "size " << size << ": the model touches the image's border";
        shares.push_back(c.share);
        images.push_back(std::move(image));
    }
    double lo = *std::min_element(shares.begin(), shares.end()), hi = *std::max_element(shares.begin(), shares.end());
    EXPECT_LT(hi / lo, 1.5) << "shares " << shares[0] << ", " << shares[1] << ", " << shares[2];
    // Camera and light scale with the model, so each size is the same picture.
    for (std::size_t i : {0u, 2u}) {
        Comparison cmp = compareImages(images[i], images[1], Tolerance{});
        EXPECT_TRUE(cmp.passes(Tolerance{})) << "size " << (i == 0 ? 0.01 : 1000.0) << " vs 1: max "
                                             << cmp.maxDifference << ", over tolerance " << cmp.failingShare;
    }
}

TEST_F(Framing, TheModelIsFramedAsDrawnAfterItsScale) {
    ASSERT_NE(renderer_, nullptr);
    writeBox(dir.path(), "unit", 1.0f);
    writeBox(dir.path(), "large", 1000.0f);
    // The unit box scaled by 1000 in the preset is the 1000-unit box.
    Image scaled = render(writePreset(dir.path(), "scaled", "unit.gltf", 1000.0f, "", 1000.0f));
    Image large = render(writePreset(dir.path(), "large", "large.gltf", 1000.0f));
    Comparison cmp = compareImages(scaled, large, Tolerance{});
    EXPECT_TRUE(cmp.passes(Tolerance{})) << "max " << cmp.maxDifference << ", over tolerance " << cmp.failingShare;
    EXPECT_FALSE(coverage(scaled, Preset{}.background).onBorder);
}

TEST_F(Framing, TheDefaultCameraDoesNotShowALargeModel) {
    // The test above can fail: the same 1000-unit model with the default camera written out.
    ASSERT_NE(renderer_, nullptr);
    writeBox(dir.path(), "large", 1000.0f);
    Image image = render(writePreset(dir.path(), "large", "large.gltf", 1000.0f, R"(, "camera": {})"));
    Coverage c = coverage(image, Preset{}.background);
    EXPECT_TRUE(c.share < 0.08 || c.onBorder) << c.share;
}

// fovy_deg spans the image's narrower side: a shipped preset's sphere, framed for a square, stays
// whole in an image twice as tall as wide (cut at both sides when fovy was always vertical) and in
// one twice as wide as tall.
TEST_F(Framing, AShippedPresetsModelIsWholeInTallAndWideImages) {
    ASSERT_NE(renderer_, nullptr);
    for (const char* name : {"05-full-phong", "13-cook-torrance-beckmann-schlick"}) {
        LoadedPreset preset = load(fs::path(LAB_SOURCE_DIR) / "presets" / (std::string(name) + ".json"));
        for (auto [w, h] : {std::pair{300, 600}, std::pair{600, 300}}) {
            SCOPED_TRACE(std::string(name) + " at " + std::to_string(w) + "x" + std::to_string(h));
            Diagnostics d;
            std::optional<Image> image = renderer_->render(preset, w, h, d);
            ASSERT_TRUE(image) << toString(d);
            Coverage c = coverage(*image, preset.preset.background);
            EXPECT_FALSE(c.onBorder) << "the model is cut at the image's border";
            EXPECT_GT(c.share, 0.1) << "the sphere should span most of the narrower side";
        }
    }
}

// Issue 25: framed as model viewers do. A model without a camera is seen from above its front,
// turned towards +x (core/scene/camera.h threeQuarterDirection), and its pixels span 80–90% of the
// image's narrower side in their larger dimension (the projected box spans 85%; a model fills its
// box's projection less or more), whole and centred in every shape of image: a long box (10 × 1 ×
// 1, unturned, so that its box is itself) and the shipped trefoil knot.
TEST_F(Framing, AModelWithoutACameraFillsTheNarrowerSideFromAThreeQuarterView) {
    ASSERT_NE(renderer_, nullptr);
    writeBox(dir.path(), "long", 10.0f, {1.0f, 0.1f, 0.1f});
    fs::copy_file(fs::path(LAB_SOURCE_DIR) / "presets" / "models" / "trefoil.glb", dir.path() / "trefoil.glb");
    for (const char* model : {"long.gltf", "trefoil.glb"}) {
        fs::path file = dir.path() / (std::string(model) + ".json");
        writeText(file, R"({"format": "lighting-lab-preset", "version": 1, "model": {"gltf": ")" + std::string(model) + R"("}})");
        Camera camera = framed(file).camera;
        glm::vec3 d = glm::normalize(camera.eye - camera.target);
        float elevation = glm::degrees(std::asin(d.y)), azimuth = glm::degrees(std::atan2(d.x, d.z));
        EXPECT_TRUE(elevation >= 20.0f && elevation <= 30.0f) << model << ": " << elevation << "° above the horizontal";
        EXPECT_TRUE(azimuth >= 30.0f && azimuth <= 40.0f) << model << ": " << azimuth << "° from +z towards +x";
        for (auto [w, h] : {std::pair{160, 160}, std::pair{256, 144}, std::pair{144, 256}, std::pair{256, 128}}) {
            SCOPED_TRACE(std::string(model) + " at " + std::to_string(w) + "x" + std::to_string(h));
            Diagnostics diagnostics;
            std::optional<Image> image = renderer_->render(load(file), w, h, diagnostics);
            ASSERT_TRUE(image) << toString(diagnostics);
            Coverage c = coverage(*image, Preset{}.background);
            EXPECT_FALSE(c.onBorder);
            EXPECT_GE(c.fill(*image), 0.80);
            EXPECT_LE(c.fill(*image), 0.90);
            // Centred: the margins either side differ by a few pixels at most.
            EXPECT_NEAR(c.min.x, w - 1 - c.max.x, 0.03 * std::min(w, h)) << "left and right margins";
            EXPECT_NEAR(c.min.y, h - 1 - c.max.y, 0.03 * std::min(w, h)) << "top and bottom margins";
            std::printf("[ fill     ] %s at %dx%d: %.3f\n", model, w, h, c.fill(*image));
        }
    }
}

//----------------------------------------------------------------------------------------
// What the preset holds after framing (no GL)
//----------------------------------------------------------------------------------------

TEST(FramingPreset, TheFileSaysWhichKeysItLeftOut) {
    TempFolder dir;
    writeBox(dir.path(), "box", 1.0f);
    EXPECT_EQ(load(writePreset(dir.path(), "bare", "box.gltf", 1.0f)).omitted, (OmittedKeys{true, true}));
    EXPECT_EQ(load(writePreset(dir.path(), "cam", "box.gltf", 1.0f, R"(, "camera": {})")).omitted,
              (OmittedKeys{false, true}));
    EXPECT_EQ(load(writePreset(dir.path(), "lit", "box.gltf", 1.0f, R"(, "lights": [])")).omitted,
              (OmittedKeys{true, false}));
}

TEST(FramingPreset, AnExplicitCameraIsUsedAsItIs) {
    TempFolder dir;
    writeBox(dir.path(), "box", 1000.0f);
    Preset p = framed(writePreset(dir.path(), "cam", "box.gltf", 1000.0f,
                                  R"(, "camera": {"eye": [1, 2, 30], "fovy_deg": 30})"));
    Camera expected;
    expected.eye = {1, 2, 30};
    expected.fovyDeg = 30;
    EXPECT_EQ(p.camera, expected);
    EXPECT_EQ(p.lights, Preset{}.lights) << "a camera given: the default light stays where it is";
}

TEST(FramingPreset, WithoutLightsTheDefaultLightStandsRelativeToTheBounds) {
    TempFolder dir;
    writeBox(dir.path(), "box", 1000.0f);
    fs::path file = writePreset(dir.path(), "bare", "box.gltf", 1000.0f);
    Preset p = framed(file);

    MeshCache cache;
    Diagnostics d;
    std::shared_ptr<const Mesh> mesh = cache.get(p.model, dir.path(), d);
    ASSERT_TRUE(mesh) << toString(d);
    std::optional<Sphere> bounds = drawnBounds(*mesh, p.model);
    ASSERT_TRUE(bounds);
    // The box's half diagonal is 1000 · |(0.5, 0.3, 0.2)|, wherever it was turned.
    EXPECT_NEAR(bounds->radius, 1000.0f * glm::length(glm::vec3(0.5f, 0.3f, 0.2f)), 0.5f);
    ASSERT_EQ(p.lights.size(), 1u);
    glm::vec3 expected = bounds->center + glm::vec3(2.0f) * bounds->radius;
    EXPECT_LT(glm::distance(p.lights[0].position, expected), 1e-3f * bounds->radius);
    LightDesc rest = p.lights[0];
    rest.position = LightDesc{}.position;
    EXPECT_EQ(rest, LightDesc{}) << "only the position moves";
    std::optional<std::vector<glm::vec3>> drawn = drawnPositions(*mesh, p.model);
    ASSERT_TRUE(drawn);
    EXPECT_EQ(p.camera, framedCamera(Camera{}, *drawn, threeQuarterDirection())) << "the default camera, from three-quarters";
    // The target lies across the image plane from the box's centre (centring its projection), at its depth.
    glm::vec3 forward = glm::normalize(p.camera.target - p.camera.eye);
    EXPECT_LT(std::abs(glm::dot(p.camera.target - bounds->center, forward)), 1e-3f * bounds->radius);
    EXPECT_LT(glm::distance(p.camera.target, bounds->center), bounds->radius);

    // A `lights` key is kept as it is.
    Preset lit = framed(writePreset(dir.path(), "lit", "box.gltf", 1000.0f,
                                    R"(, "lights": [{"type": "directional", "direction": [0, 0, -1]}])"));
    ASSERT_EQ(lit.lights.size(), 1u);
    EXPECT_EQ(lit.lights[0].type, LightType::Directional);
    EXPECT_EQ(lit.lights[0].position, LightDesc{}.position);
    EXPECT_EQ(lit.camera, p.camera) << "framed all the same";
}

TEST(FramingPreset, DrawnPositionsAndBoundsAreTheTransformedPositionsAndTheirSphere) {
    Mesh m;
    EXPECT_FALSE(drawnBounds(m, Model{})) << "nothing to frame";
    EXPECT_FALSE(drawnPositions(m, Model{}));
    m.positions = {{1.0f, 2.0f, 3.0f}, {3.0f, 2.0f, 1.0f}, {2.0f, 2.0f, 2.0f}};
    Model model;
    model.scale = glm::vec3(2.0f);
    model.translate = {0.0f, 0.0f, -10.0f};
    std::optional<Sphere> s = drawnBounds(m, model);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->center, glm::vec3(4.0f, 4.0f, -6.0f));
    EXPECT_FLOAT_EQ(s->radius, 2.0f * std::sqrt(2.0f));
    std::optional<std::vector<glm::vec3>> drawn = drawnPositions(m, model);
    ASSERT_TRUE(drawn);
    EXPECT_EQ(*drawn, (std::vector<glm::vec3>{{2.0f, 4.0f, -4.0f}, {6.0f, 4.0f, -8.0f}, {4.0f, 4.0f, -6.0f}}));
    m.positions = {{3e38f, 0.0f, 0.0f}, {-3e38f, 0.0f, 0.0f}}; // beyond float once scaled
    EXPECT_FALSE(drawnBounds(m, model));
    EXPECT_FALSE(drawnPositions(m, model));
}

TEST(FramingPreset, BuiltInModelsAreNeverFramed) {
    TempFolder dir;
    fs::path file = dir.path() / "cube.json";
    writeText(file, R"({"format": "lighting-lab-preset", "version": 1, "model": {"builtin": "cube", "scale": [50, 50, 50]}})");
    Preset p = framed(file);
    EXPECT_EQ(p.camera, Camera{});
    EXPECT_EQ(p.lights, Preset{}.lights);
}

TEST(FramingPreset, SavedAfterFramingTheCameraIsWrittenOut) {
    TempFolder dir;
    writeBox(dir.path(), "box", 0.01f);
    Preset p = framed(writePreset(dir.path(), "bare", "box.gltf", 0.01f));
    Diagnostics d;
    ASSERT_TRUE(savePreset(p, dir.path() / "saved.json", d)) << toString(d);
    LoadedPreset back = load(dir.path() / "saved.json");
    EXPECT_EQ(back.omitted, OmittedKeys{}) << "a saved preset has every key";
    EXPECT_EQ(back.preset, p);
}

} // namespace
} // namespace lab
