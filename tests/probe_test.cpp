// probe_test.cpp — the pixel probe hits the right surface point and reports the model's terms.
#include "core/scene/transforms.h"
#include "core/lighting/probe.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

TEST(Probe, CentreOfTheDefaultSphere) {
    Preset p; // eye (0, 0, 4), unit sphere at the origin
    Mesh m = makeSphere(64, 32);
    std::optional<ProbeResult> r = probePixel(p, m, glm::vec2(0.0f), 1.0f);
    ASSERT_TRUE(r);
    // The front pole of the sphere is 3 units in front of the eye, facing it.
    EXPECT_NEAR(r->positionEye.z, -3.0f, 2e-3f);
    EXPECT_NEAR(r->N.z, 1.0f, 1e-3f);
    EXPECT_NEAR(r->V.z, 1.0f, 1e-6f);
    ASSERT_EQ(r->lights.size(), 1u);
    // The colour is the model's, term by term.
    EXPECT_NEAR(glm::distance(r->color, shade(packShading(p, computeTransforms(p, 1.0f).view), r->positionEye, r->N)), 0.0f, 1e-6f);
    glm::vec3 sum = r->emissive + r->globalAmbient + r->lights[0].ambient + r->lights[0].diffuse + r->lights[0].specular;
    EXPECT_NEAR(glm::distance(glm::clamp(sum, 0.0f, 1.0f), r->color), 0.0f, 1e-5f);
    EXPECT_NEAR(r->lights[0].NoL, glm::dot(r->N, r->lights[0].L), 1e-6f);
}

TEST(Probe, MissesOutsideTheModel) {
    Preset p;
    EXPECT_FALSE(probePixel(p, makeSphere(16, 8), glm::vec2(0.95f, 0.95f), 1.0f));
}

TEST(Probe, FlatShadingUsesTheFaceNormalAtTheCentroid) {
    Preset p;
    p.shading = Shading::Flat;
    Mesh m = makeCube(1, 1);
    p.camera.eye = {0.3f, 0.2f, 4.0f};
    std::optional<ProbeResult> r = probePixel(p, m, glm::vec2(0.02f, 0.01f), 1.0f);
    ASSERT_TRUE(r);
    glm::vec3 faceNormalEye = glm::normalize(computeTransforms(p, 1.0f).normalMatrix * glm::vec3(0, 0, 1));
    EXPECT_NEAR(glm::distance(r->N, faceNormalEye), 0.0f, 1e-5f);
}

TEST(Probe, CookTorranceTermsAreReported) {
    Preset p;
    p.brdf = BrdfModel::CookTorrance;
    std::optional<ProbeResult> r = probePixel(p, makeSphere(64, 32), glm::vec2(0.2f, 0.2f), 1.0f);
    ASSERT_TRUE(r);
    const ProbeLight& l = r->lights[0];
    glsl::Brdf b = packSurfaceUniforms(p).brdf;
    EXPECT_FLOAT_EQ(l.D, glsl::distributionTerm(l.NoH, b));
    EXPECT_FLOAT_EQ(l.F, glsl::fresnelTerm(l.VoH, b));
    EXPECT_NEAR(l.specularFactor, l.D * l.F * l.G / (4.0f * std::max(l.NoV, 1e-4f)), 1e-6f);
}

} // namespace
} // namespace lab
