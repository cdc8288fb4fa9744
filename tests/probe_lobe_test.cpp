// probe_lobe_test.cpp — "plots at the probe": a probed point's θi, incoming light and V, in the plots' frame.
#include "core/scene/transforms.h"
#include "core/plots/probe_lobe.h"

#include "core/plots/lobe3d.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lab {
namespace {

// A spot light at (3, 0, 4), seen from the front pole (0, 0, 1) of the unit sphere: L = (1, 0, 1)/√2,
// d = 3√2, aimed close to the pole so that its spot factor is neither 0 nor 1.
LightDesc knownSpot() {
    LightDesc l;
    l.type = LightType::Spot;
    l.position = {3.0f, 0.0f, 4.0f};
    l.direction = {-1.0f, 0.2f, -1.0f};
    l.diffuse = {0.8f, 0.6f, 0.4f};
    l.specular = {1.0f, 1.0f, 0.5f};
    l.attenuation = {1.0f, 0.1f, 0.02f};
    l.cutoffDeg = 30.0f;
    l.exponent = 8.0f;
    return l;
}

TEST(ProbeLobe, TheSpheresCentrePixelGivesThetaIIncomingLightAndV) {
    Preset p; // eye (0, 0, 4), unit sphere at the origin: the centre pixel is the front pole, N = V = +z
    p.lights = {knownSpot()};
    std::optional<ProbeResult> r = probePixel(p, makeSphere(64, 32), glm::vec2(0.0f), 1.0f);
    ASSERT_TRUE(r);
    std::optional<ProbeLobe> at = probeLobe(*r, p, 0);
    ASSERT_TRUE(at);
    EXPECT_NEAR(at->incidentDeg, 45.0f, 0.1f);
    // The formulas by hand: Att = 1/(c0 + c1 d + c2 d²), spot = (cos γ)^8 with cos γ = (−L)·S.
    const float d = 3.0f * std::sqrt(2.0f);
    const float att = 1.0f / (1.0f + 0.1f * d + 0.02f * d * d);
    const float cosGamma = glm::dot(-glm::normalize(glm::vec3(1, 0, 1)), glm::normalize(glm::vec3(-1.0f, 0.2f, -1.0f)));
    const float spot = std::pow(cosGamma, 8.0f);
    EXPECT_NEAR(at->distance, d, 2e-3f);
    EXPECT_NEAR(at->attenuation, att, 1e-3f);
    EXPECT_NEAR(at->spot, spot, 1e-3f);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(at->incomingDiffuse[c], knownSpot().diffuse[c] * att * spot, 1e-3f) << c;
        EXPECT_NEAR(at->incomingSpecular[c], knownSpot().specular[c] * att * spot, 1e-3f) << c;
    }
    // The probe's own Att_i is the same product (lightContribution computes it the same way).
    EXPECT_NEAR(at->attenuation * at->spot, r->lights[0].attenuation, 1e-6f);
    // V along N lies in the plane of incidence, straight up in the plot.
    EXPECT_NEAR(at->viewerDeg, 0.0f, 0.1f);
    EXPECT_NEAR(at->outOfPlaneDeg, 0.0f, 0.1f);
    EXPECT_NEAR(at->viewer.y, 1.0f, 1e-3f);
    // Where the frame lies on the model: the pole, N = +z, the x axis away from the light (−x).
    EXPECT_NEAR(glm::distance(at->world.origin, glm::vec3(0, 0, 1)), 0.0f, 2e-3f);
    EXPECT_NEAR(glm::distance(at->world.N, glm::vec3(0, 0, 1)), 0.0f, 2e-3f);
    EXPECT_NEAR(glm::distance(at->world.tangent, glm::vec3(-1, 0, 0)), 0.0f, 2e-3f);
    // The plots' inputs: that θi and that light.
    const LobeInputs in = probeLobeInputs(p, *at);
    EXPECT_FLOAT_EQ(in.incidentDeg, at->incidentDeg);
    EXPECT_EQ(in.lightDiffuse, at->incomingDiffuse);
    EXPECT_EQ(in.lightSpecular, at->incomingSpecular);
}

TEST(ProbeLobe, VOutOfThePlaneOfIncidenceHasItsAngle) {
    Preset p;
    LightDesc sun;
    sun.type = LightType::Directional;
    sun.direction = -glm::vec3(0.0f, 0.5f, std::sqrt(3.0f) / 2.0f); // L = (0, sin 30°, cos 30°): the y-z plane
    sun.diffuse = {0.5f, 0.25f, 1.0f};
    p.lights = {sun};
    std::optional<ProbeResult> r = probePixel(p, makeCube(1, 1), glm::vec2(0.2f, 0.0f), 1.0f); // front face: z = 1, N = +z
    ASSERT_TRUE(r);
    ASSERT_NEAR(r->positionWorld.z, 1.0f, 1e-5f);
    std::optional<ProbeLobe> at = probeLobe(*r, p, 0);
    ASSERT_TRUE(at);
    EXPECT_NEAR(at->incidentDeg, 30.0f, 1e-3f);
    // V = normalize(eye − p) lies in the x-z plane: its angle from the y-z plane is atan(x / (4 − z)).
    const glm::vec3 q = r->positionWorld;
    EXPECT_GT(q.x, 0.1f);
    EXPECT_NEAR(at->outOfPlaneDeg, glm::degrees(std::atan2(q.x, 4.0f - q.z)), 1e-3f);
    EXPECT_NEAR(at->viewerDeg, 0.0f, 1e-3f); // its projection on the plane is N
    // A directional light arrives whole.
    EXPECT_FLOAT_EQ(at->attenuation, 1.0f);
    EXPECT_FLOAT_EQ(at->spot, 1.0f);
    EXPECT_EQ(at->incomingDiffuse, sun.diffuse);
}

// The lobe made from the point's inputs reads, at the point's V, exactly what the model reflects
// there: the probe's own diffuse and specular terms, for every BRDF, also where V leaves the plane.
TEST(ProbeLobe, TheLobeAtVIsWhatTheModelReflectsThere) {
    for (BrdfModel brdf : {BrdfModel::Phong, BrdfModel::BlinnPhong, BrdfModel::CookTorrance}) {
        Preset p;
        p.brdf = brdf;
        p.material.shininess = 12.0f;
        p.lights = {knownSpot()};
        p.lights[0].cutoffDeg = 60.0f;
        for (glm::vec2 ndc : {glm::vec2(0.1f, 0.15f), glm::vec2(-0.2f, 0.05f), glm::vec2(0.25f, -0.2f)}) {
            std::optional<ProbeResult> r = probePixel(p, makeSphere(64, 32), ndc, 1.0f);
            ASSERT_TRUE(r);
            std::optional<ProbeLobe> at = probeLobe(*r, p, 0);
            ASSERT_TRUE(at);
            ASSERT_LT(at->incidentDeg, 90.0f);
            EXPECT_NEAR(glm::length(at->viewer), 1.0f, 1e-5f);
            const LobeInputs in = probeLobeInputs(p, *at);
            const float diffuse = luminance(r->lights[0].diffuse), specular = luminance(r->lights[0].specular);
            EXPECT_GT(diffuse, 0.0f);
            EXPECT_NEAR(intensityAt(in, at->viewer, PlotComponent::Diffuse), diffuse, 1e-4f * std::max(diffuse, 1.0f));
            EXPECT_NEAR(intensityAt(in, at->viewer, PlotComponent::Specular), specular, 1e-4f * std::max(specular, 1.0f))
                << toString(brdf) << " at " << ndc.x << ", " << ndc.y;
        }
    }
}

TEST(ProbeLobe, ALightThatIsOffOrMissingHasNoLobe) {
    Preset p;
    std::optional<ProbeResult> r = probePixel(p, makeSphere(32, 16), glm::vec2(0.0f), 1.0f);
    ASSERT_TRUE(r);
    EXPECT_TRUE(probeLobe(*r, p, 0));
    EXPECT_FALSE(probeLobe(*r, p, 1));
    EXPECT_FALSE(probeLobe(*r, p, -1));
    p.lights[0].enabled = false;
    EXPECT_FALSE(probeLobe(*r, p, 0));
}

TEST(ProbeLobe, ALightBehindTheSurfaceIsPlottedAlongItAndLightsNothing) {
    Preset p;
    p.lights[0].position = {0.0f, 0.0f, -5.0f}; // behind the sphere
    std::optional<ProbeResult> r = probePixel(p, makeSphere(64, 32), glm::vec2(0.0f), 1.0f);
    ASSERT_TRUE(r);
    std::optional<ProbeLobe> at = probeLobe(*r, p, 0);
    ASSERT_TRUE(at);
    EXPECT_GT(at->incidentDeg, 170.0f);
    EXPECT_FLOAT_EQ(plottedIncidentDeg(*at), 90.0f);
    for (const PlotSample& s : reflectedIntensity(probeLobeInputs(p, *at))) {
        EXPECT_LT(s.total, 1e-6f);
    }
}

TEST(ProbeLobe, ProbeSurfaceFollowsThePointAsTheCameraMoves) {
    Preset p;
    Mesh sphere = makeSphere(64, 32);
    std::optional<ProbeResult> r = probePixel(p, sphere, glm::vec2(0.1f, 0.2f), 1.0f);
    ASSERT_TRUE(r);
    ProbeResult again = probeSurface(p, r->positionModel, r->normalModel);
    EXPECT_EQ(again.positionEye, r->positionEye);
    EXPECT_EQ(again.N, r->N);
    EXPECT_EQ(again.color, r->color);
    p.camera.eye = {2.0f, 1.0f, 3.0f}; // orbited: the same point of the model, seen from elsewhere
    ProbeResult moved = probeSurface(p, r->positionModel, r->normalModel);
    EXPECT_NEAR(glm::distance(moved.positionWorld, r->positionWorld), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(moved.V, glm::normalize(glm::vec3(computeTransforms(p, 1.0f).view *
                                                                 glm::vec4(p.camera.eye - moved.positionWorld, 0.0f)))),
                0.0f, 1e-5f);
}

TEST(ProbeLobe, TheWireframeStartsInThePlaneOfIncidenceAndReachesOne) {
    Preset p;
    LobeInputs in = lobeInputs(p, 30.0f);
    std::vector<std::vector<glm::vec3>> curves = lobeWireframe(in, 4);
    ASSERT_EQ(curves.size(), 4u);
    float largest = 0.0f;
    for (const auto& curve : curves) {
        ASSERT_EQ(curve.size(), 61u);
        for (const glm::vec3& q : curve) {
            largest = std::max(largest, glm::length(q));
            EXPECT_GE(q.y, -1e-6f);
        }
    }
    EXPECT_NEAR(largest, 1.0f, 1e-6f);
    for (const glm::vec3& q : curves[0]) {
        EXPECT_EQ(q.z, 0.0f) << "the first curve is the plane of incidence";
    }
    in.terms.diffuse = in.terms.specular = false;
    for (const auto& curve : lobeWireframe(in, 2)) {
        for (const glm::vec3& q : curve) {
            EXPECT_EQ(glm::length(q), 0.0f);
        }
    }
}

} // namespace
} // namespace lab
