// wireframe_test.cpp — the shading-rate views over the shaded model (render/wireframe.h): the
// wireframe along the edges of the faces seen and not along the hidden ones, the vertex normals
// sticking out of the silhouette, and nothing at all with both switched off.
//
// Renders with headless EGL (llvmpipe) at a small size; where a line is is computed in C++ from
// the same transforms (computeTransforms), so the tests need no golden image.
#include "core/scene/transforms.h"
#include "core/lighting/lighting.h"
#include "gl_suite.h"
#include "render/wireframe.h"
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <vector>

namespace lab {
namespace {

//----------------------------------------------------------------------------------------
// The CPU parts
//----------------------------------------------------------------------------------------

TEST(EdgeIndices, EveryEdgeOnceWhicheverWayRound) {
    const std::vector<std::uint32_t> quad{0, 1, 2, 0, 2, 3}; // the diagonal 0-2 is in both triangles
    EXPECT_EQ(edgeIndices(quad), (std::vector<std::uint32_t>{0, 1, 0, 2, 0, 3, 1, 2, 2, 3}));
    const std::vector<std::uint32_t> tetrahedron{0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
    EXPECT_EQ(edgeIndices(tetrahedron).size(), 6u * 2u);
    const std::vector<std::uint32_t> degenerate{4, 4, 7};
    EXPECT_EQ(edgeIndices(degenerate), (std::vector<std::uint32_t>{4, 7}));
    EXPECT_TRUE(edgeIndices({}).empty());
}

TEST(EdgeIndices, AGridHasEulersCount) {
    // A triangulated disc: vertices - edges + triangles = 1, whichever way its quads are split.
    Mesh plane = makePlane(7, 5);
    EXPECT_EQ(edgeIndices(plane.indices).size() / 2, plane.positions.size() + plane.triangleCount() - 1);
}

TEST(NormalLineStep, EveryVertexUpToTheCapThenEveryKth) {
    EXPECT_EQ(normalLineStep(0), 1u);
    EXPECT_EQ(normalLineStep(10), 1u);
    EXPECT_EQ(normalLineStep(kMaxNormalLines), 1u);
    EXPECT_EQ(normalLineStep(kMaxNormalLines + 1), 2u);
    for (std::size_t n : {std::size_t{120'000}, std::size_t{500'500}, std::size_t{3'000'000}}) {
        std::size_t k = normalLineStep(n);
        EXPECT_LE((n + k - 1) / k, kMaxNormalLines) << n;
        EXPECT_GT((n + k - 2) / (k - 1), kMaxNormalLines) << n << ": a smaller step would do";
    }
}

TEST(WireframeColor, ContrastsWithTheBackground) {
    EXPECT_EQ(wireframeColor({0.05f, 0.05f, 0.08f}), kWireLight); // the presets' default
    EXPECT_EQ(wireframeColor({0.0f, 0.0f, 0.0f}), kWireLight);    // the value views'
    EXPECT_EQ(wireframeColor({1.0f, 1.0f, 1.0f}), kWireDark);
    EXPECT_EQ(wireframeColor({0.9f, 0.9f, 0.6f}), kWireDark);
}

//----------------------------------------------------------------------------------------
// Renders
//----------------------------------------------------------------------------------------

constexpr int kWidth = 200, kHeight = 150;

class Overlay : public GlSuite<> {
protected:
    // The model with `options` drawn over it, top row first.
    Image render(const Preset& preset, const std::shared_ptr<const Mesh>& mesh, const WireframeOptions& options) {
        Framebuffer target(kWidth, kHeight);
        EXPECT_TRUE(target.complete());
        target.bind();
        renderer_->draw(preset, mesh, Viewport{0, 0, kWidth, kHeight});
        renderer_->drawOverlay(preset, mesh, Viewport{0, 0, kWidth, kHeight}, options);
        return target.readRgb();
    }
};

// A cube seen from above a corner: three faces in view (+x, +y, +z), three hidden.
Preset cubePreset(Shading shading) {
    Preset p;
    p.model.builtin = Builtin::Cube;
    p.model.subdivisions = {1, 1};
    p.camera.eye = {3.2f, 2.6f, 4.0f};
    p.shading = shading;
    p.material.diffuse = {0.2f, 0.35f, 0.7f}; // blue, no highlight: no pixel of the model is grey like a line
    p.material.specular = glm::vec3(0.0f);
    return p;
}

// Where a model-space point lands in the image (pixels, top row first, pixel centres at .5).
glm::vec2 project(const Preset& preset, const glm::vec3& p) {
    Transforms t = computeTransforms(preset, float(kWidth) / float(kHeight));
    glm::vec4 clip = t.projection * t.modelView * glm::vec4(p, 1.0f);
    glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * kWidth, (0.5f - ndc.y * 0.5f) * kHeight};
}

struct Segment {
    glm::vec2 a, b;
};

float distanceTo(const Segment& s, glm::vec2 p) {
    glm::vec2 d = s.b - s.a;
    float t = std::clamp(glm::dot(p - s.a, d) / std::max(glm::dot(d, d), 1e-12f), 0.0f, 1.0f);
    return glm::length(p - (s.a + t * d));
}

// The projected edges of the triangles facing the camera (counter-clockwise on screen) and of
// those facing away.
void splitEdges(const Preset& preset, const Mesh& mesh, std::vector<Segment>& front, std::vector<Segment>& back) {
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        glm::vec2 q[3];
        for (int k = 0; k < 3; ++k) {
            q[k] = project(preset, mesh.positions[mesh.indices[t + std::size_t(k)]]);
        }
        glm::vec2 u = q[1] - q[0], v = q[2] - q[0];
        bool facing = u.x * v.y - u.y * v.x < 0.0f; // counter-clockwise with y pointing down
        for (int k = 0; k < 3; ++k) {
            (facing ? front : back).push_back({q[k], q[(k + 1) % 3]});
        }
    }
}

const std::uint8_t* pixel(const Image& image, int x, int y) {
    return &image.rgb[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3];
}

bool isColor(const std::uint8_t* px, const glm::vec3& c) {
    for (int k = 0; k < 3; ++k) {
        if (std::abs(int(px[k]) - int(std::lround(c[k] * 255.0f))) > 1) {
            return false;
        }
    }
    return true;
}

// Whether a pixel of `color` is within one pixel of `at`.
bool colorNear(const Image& image, glm::vec2 at, const glm::vec3& color) {
    int cx = int(std::floor(at.x)), cy = int(std::floor(at.y));
    for (int y = std::max(0, cy - 1); y <= std::min(image.height - 1, cy + 1); ++y) {
        for (int x = std::max(0, cx - 1); x <= std::min(image.width - 1, cx + 1); ++x) {
            if (isColor(pixel(image, x, y), color)) {
                return true;
            }
        }
    }
    return false;
}

class OverlayWireframe : public Overlay, public testing::WithParamInterface<Shading> {};

TEST_P(OverlayWireframe, LinesOnTheEdgesSeenAndNoneOnTheHiddenOnes) {
    const Preset preset = cubePreset(GetParam());
    auto mesh = std::make_shared<const Mesh>(makeBuiltin(preset.model.builtin, preset.model.subdivisions));
    const Image plain = render(preset, mesh, {});
    const Image wired = render(preset, mesh, {.wireframe = true, .background = preset.background});
    std::vector<Segment> front, back;
    splitEdges(preset, *mesh, front, back);
    ASSERT_EQ(front.size(), 18u) << "three faces in view, two triangles each";

    // (a) Along every edge in view, away from its ends, the line's colour.
    int samples = 0, hits = 0;
    for (const Segment& s : front) {
        for (float t = 0.1f; t < 0.91f; t += 0.05f) {
            ++samples;
            hits += colorNear(wired, s.a + t * (s.b - s.a), kWireLight);
        }
    }
    EXPECT_EQ(hits, samples) << "every sample of an edge in view has the line's colour within a pixel";

    // (b) Along the hidden edges, wherever no edge in view passes within 3 pixels, the plain model.
    int hidden = 0, unchanged = 0;
    for (const Segment& s : back) {
        for (float t = 0.0f; t < 1.01f; t += 0.05f) {
            glm::vec2 at = s.a + t * (s.b - s.a);
            auto near = [&](const Segment& f) { return distanceTo(f, at) < 3.0f; };
            if (std::any_of(front.begin(), front.end(), near)) {
                continue;
            }
            ++hidden;
            int x = int(at.x), y = int(at.y);
            bool same = true;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    same = same && std::equal(pixel(wired, x + dx, y + dy), pixel(wired, x + dx, y + dy) + 3,
                                              pixel(plain, x + dx, y + dy));
                }
            }
            unchanged += same;
        }
    }
    EXPECT_GE(hidden, 40) << "enough of the hidden edges lie clear of the ones in view to test";
    EXPECT_EQ(unchanged, hidden) << "the edges on the far side stay hidden behind the model";
}

std::string shadingName(const testing::TestParamInfo<Shading>& info) { return std::string(toString(info.param)); }

INSTANTIATE_TEST_SUITE_P(FlatAndPhong, OverlayWireframe, testing::Values(Shading::Flat, Shading::Phong), shadingName);

TEST_F(Overlay, BothOffChangesNoByte) {
    Preset preset = cubePreset(Shading::Gouraud);
    preset.model.builtin = Builtin::Sphere;
    preset.model.subdivisions = {16, 8};
    auto mesh = std::make_shared<const Mesh>(makeBuiltin(preset.model.builtin, preset.model.subdivisions));
    const Image plain = render(preset, mesh, {});
    WireframeOptions off;
    off.background = preset.background;
    EXPECT_EQ(render(preset, mesh, off).rgb, plain.rgb);
    EXPECT_NE(render(preset, mesh, {.wireframe = true}).rgb, plain.rgb) << "the comparison can fail";
}

// drawView (the one place the GUI and the page draw a viewport) draws what the view settings ask for.
TEST_F(Overlay, DrawViewFollowsTheViewSettings) {
    const Preset preset = cubePreset(Shading::Phong);
    auto mesh = std::make_shared<const Mesh>(makeBuiltin(preset.model.builtin, preset.model.subdivisions));
    auto viaView = [&](const DisplaySettings& settings) {
        Framebuffer target(kWidth, kHeight);
        target.bind();
        drawView(*renderer_, preset, mesh, Viewport{0, 0, kWidth, kHeight}, viewDraw(settings));
        return target.readRgb().rgb;
    };
    DisplaySettings settings;
    EXPECT_EQ(viaView(settings), render(preset, mesh, {}).rgb);
    settings.wireframe = true;
    EXPECT_EQ(viaView(settings), render(preset, mesh, {.wireframe = true, .background = preset.background}).rgb);
    settings.vertexNormals = true;
    EXPECT_EQ(viaView(settings), render(preset, mesh, {true, true, preset.background}).rgb);
    EXPECT_NE(viewDraw(settings), viewDraw(DisplaySettings{})) << "a cached view is drawn again when they change";
}

// On a wipe the lit side keeps the preset's background and a value view's side is black: on a
// light background each side's wireframe takes the colour that shows on its own background.
TEST_F(Overlay, OnAWipeEachSideOfTheWireframeContrastsWithItsBackground) {
    Preset preset = cubePreset(Shading::Phong);
    preset.background = glm::vec3(1.0f);
    auto mesh = std::make_shared<const Mesh>(makeBuiltin(preset.model.builtin, preset.model.subdivisions));
    DisplaySettings settings;
    settings.mode = ViewMode::NdotL;
    settings.wipe = true;
    settings.wireframe = true;
    Framebuffer target(kWidth, kHeight);
    target.bind();
    drawView(*renderer_, preset, mesh, Viewport{0, 0, kWidth, kHeight}, viewDraw(settings));
    const Image image = target.readRgb();
    std::vector<Segment> front, back;
    splitEdges(preset, *mesh, front, back);
    int left = 0, right = 0, wrong = 0;
    for (const Segment& s : front) {
        for (float t = 0.1f; t < 0.91f; t += 0.05f) {
            glm::vec2 at = s.a + t * (s.b - s.a);
            if (std::abs(at.x - 0.5f * kWidth) < 3.0f) {
                continue;
            }
            bool lit = at.x < 0.5f * kWidth;
            (lit ? left : right) += colorNear(image, at, lit ? kWireDark : kWireLight);
            wrong += colorNear(image, at, lit ? kWireLight : kWireDark);
        }
    }
    EXPECT_GE(left, 40);
    EXPECT_GE(right, 40);
    EXPECT_EQ(wrong, 0);
}

TEST_F(Overlay, NormalsStickOutOfTheSilhouetteBySixPercentOfTheDiagonal) {
    Preset preset;
    preset.model.subdivisions = {24, 12};
    auto mesh = std::make_shared<const Mesh>(makeBuiltin(preset.model.builtin, preset.model.subdivisions));
    const Image plain = render(preset, mesh, {});
    const Image normals = render(preset, mesh, {.vertexNormals = true});
    // The unit sphere's silhouette is a circle about its projected centre; its radius in pixels
    // from the projected point where a ray from the eye grazes it.
    const glm::vec2 centre = project(preset, glm::vec3(0.0f));
    const float d = glm::length(preset.camera.eye);
    const glm::vec3 grazing(0.0f, std::sqrt(d * d - 1.0f) / d, 1.0f / d); // tangent point seen from +z
    const float radius = glm::length(project(preset, grazing) - centre);
    // A tip is at most 1 + 0.06 * 2 * sqrt(3) from the centre (perspective widens it a little).
    const float reach = 1.0f + kNormalLineShare * 2.0f * std::sqrt(3.0f);
    int outside = 0, tooFar = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (!isColor(pixel(normals, x, y), kNormalLineColor)) {
                continue;
            }
            float r = glm::length(glm::vec2(x + 0.5f, y + 0.5f) - centre);
            outside += r > radius + 1.5f && isColor(pixel(plain, x, y), preset.background);
            tooFar += r > radius * reach * 1.05f + 1.5f;
        }
    }
    EXPECT_GE(outside, 30) << "normals stick out of the silhouette";
    EXPECT_EQ(tooFar, 0) << "no line reaches further than " << kNormalLineShare << " of the diagonal";
}

} // namespace
} // namespace lab
