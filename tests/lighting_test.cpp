// lighting_test.cpp — every equation of the lighting model against values worked out by hand.
//
// The expected numbers come from the formulas in the README, evaluated independently in double
// precision (a few lines of Python, noted beside each), not from this code.
#include "core/scene/transforms.h"
#include "core/lighting/lighting.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace lab {
namespace {

using glsl::Brdf;

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

glm::vec3 inPlane(float deg, float sign) {
    float r = glm::radians(deg);
    return glm::vec3(sign * std::sin(r), std::cos(r), 0.0f);
}

Brdf brdf(int model, int distribution = glsl::DISTRIBUTION_BECKMANN, int fresnel = glsl::FRESNEL_SCHLICK,
          float roughness = 0.3f, float ior = 1.5f, bool geometry = true) {
    Brdf b;
    b.model = model;
    b.distribution = distribution;
    b.fresnel = fresnel;
    b.geometry = geometry;
    b.roughness = roughness;
    b.ior = ior;
    return b;
}

void expectVec(const glm::vec3& a, const glm::vec3& b, float eps = 1e-6f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

//----------------------------------------------------------------------------------------
// Phong and Blinn-Phong
//----------------------------------------------------------------------------------------

TEST(Lighting, ReflectionVectorMirrorsLAboutN) {
    glm::vec3 L = glm::normalize(glm::vec3(1, 1, 0));
    // R = 2(N.L)N - L = 2(1/sqrt2)(0,1,0) - (1,1,0)/sqrt2 = (-1, 1, 0)/sqrt2
    expectVec(glsl::reflectionVector(kUp, L), glm::vec3(-1, 1, 0) / std::sqrt(2.0f));
    // Grazing and normal incidence.
    expectVec(glsl::reflectionVector(kUp, kUp), kUp);
    expectVec(glsl::reflectionVector(kUp, glm::vec3(1, 0, 0)), glm::vec3(-1, 0, 0));
}

TEST(Lighting, PhongLobePeaksOnTheMirrorDirection) {
    glm::vec3 L = inPlane(30, -1);
    glm::vec3 R = inPlane(30, +1);
    EXPECT_NEAR(glsl::phongSpecular(kUp, L, R, 50.0f), 1.0f, 1e-5f);
    // V = N: R.V = cos 30 ; (cos 30)^10 = 0.2373046875
    EXPECT_NEAR(glsl::phongSpecular(kUp, L, kUp, 10.0f), 0.2373046875f, 1e-6f);
    // Behind the mirror direction by more than 90 degrees: max(0, R.V) = 0.
    EXPECT_EQ(glsl::phongSpecular(kUp, L, -R, 10.0f), 0.0f);
}

TEST(Lighting, BlinnPhongUsesTheHalfVector) {
    glm::vec3 L = inPlane(40, -1);
    glm::vec3 V = inPlane(20, +1);
    // H bisects L (40 degrees on one side) and V (20 on the other): 10 degrees to L's side of N,
    // so N.H = cos 10.
    expectVec(glsl::halfVector(L, V), inPlane(10, -1), 1e-6f);
    EXPECT_NEAR(glsl::blinnPhongSpecular(kUp, L, V, 32.0f), std::pow(std::cos(glm::radians(10.0f)), 32.0f), 3e-6f);
}

TEST(Lighting, SpecularIsZeroWhereTheLightIsBehindTheSurface) {
    glm::vec3 L = inPlane(95, -1); // N.L < 0
    glm::vec3 V = inPlane(85, +1);
    for (int model : {glsl::BRDF_PHONG, glsl::BRDF_BLINN_PHONG, glsl::BRDF_COOK_TORRANCE}) {
        EXPECT_EQ(glsl::specularFactor(kUp, L, V, 10.0f, brdf(model)), 0.0f) << "brdf " << model;
    }
    EXPECT_EQ(glsl::specularFactor(kUp, glm::vec3(1, 0, 0), V, 10.0f, brdf(glsl::BRDF_PHONG)), 0.0f); // N.L = 0
}

//----------------------------------------------------------------------------------------
// Cook-Torrance terms
//----------------------------------------------------------------------------------------

TEST(Lighting, F0IsFourPercentAtIor15) {
    EXPECT_NEAR(glsl::fresnelF0(1.5f), 0.04f, 1e-7f);
    EXPECT_NEAR(glsl::fresnelF0(1.0f), 0.0f, 1e-7f);
}

TEST(Lighting, FullFresnelAgainstSchlick) {
    struct Case {
        float deg, full, schlick;
    };
    // python: full(cos a, 1.5), 0.04 + 0.96 (1 - cos a)^5
    const Case cases[] = {{0, 0.04f, 0.04f},
                          {30, 0.04152263f, 0.04004144f},
                          {60, 0.08918671f, 0.07f},
                          {80, 0.3877044f, 0.4099101f}};
    for (const Case& c : cases) {
        float cosI = std::cos(glm::radians(c.deg));
        EXPECT_NEAR(glsl::fresnelDielectric(cosI, 1.5f), c.full, 2e-6f) << c.deg << " degrees";
        EXPECT_NEAR(glsl::fresnelSchlick(cosI, 0.04f), c.schlick, 2e-6f) << c.deg << " degrees";
        // Schlick's approximation stays within 0.025 of the exact term for glass.
        EXPECT_NEAR(glsl::fresnelDielectric(cosI, 1.5f), glsl::fresnelSchlick(cosI, 0.04f), 0.025f);
    }
    // Both reach 1 at grazing incidence.
    EXPECT_NEAR(glsl::fresnelDielectric(0.0f, 1.5f), 1.0f, 1e-6f);
    EXPECT_NEAR(glsl::fresnelSchlick(0.0f, 0.04f), 1.0f, 1e-6f);
}

TEST(Lighting, FullFresnelAtBrewsterAngleIsHalfOfRs) {
    // At tan(theta) = n, Rp = 0 and F = ((n^2 - 1)/(n^2 + 1))^2 / 2 = 0.0739645.
    float cosB = std::cos(std::atan(1.5f));
    EXPECT_NEAR(glsl::fresnelDielectric(cosB, 1.5f), 0.5f * std::pow(1.25f / 3.25f, 2.0f), 1e-6f);
}

TEST(Lighting, FullFresnelTotalInternalReflection) {
    // From glass into air (relative index 1/1.5): the critical angle is asin(2/3) = 41.8 degrees.
    EXPECT_EQ(glsl::fresnelDielectric(std::cos(glm::radians(60.0f)), 1.0f / 1.5f), 1.0f);
    EXPECT_LT(glsl::fresnelDielectric(std::cos(glm::radians(30.0f)), 1.0f / 1.5f), 1.0f);
}

TEST(Lighting, DistributionsAtHandValues) {
    // python: beck(0.9, 0.5), gauss(0.9, 0.5), ggx(0.9, 0.5)
    EXPECT_NEAR(glsl::distributionBeckmann(0.9f, 0.5f), 0.7593708f, 1e-5f);
    EXPECT_NEAR(glsl::distributionGaussian(0.9f, 0.5f), 0.5643186f, 1e-5f);
    EXPECT_NEAR(glsl::distributionGGX(0.9f, 0.5f), 0.5165482f, 1e-5f);
    // At N.H = 1 all three are 1/(pi m^2).
    for (float m : {0.1f, 0.3f, 0.7f}) {
        float peak = 1.0f / (glm::pi<float>() * m * m);
        // Float precision: GGX forms (m^2 - 1) + 1, which loses a few ulps for small m.
        EXPECT_NEAR(glsl::distributionBeckmann(1.0f, m), peak, peak * 1e-5f);
        EXPECT_NEAR(glsl::distributionGaussian(1.0f, m), peak, peak * 1e-5f);
        EXPECT_NEAR(glsl::distributionGGX(1.0f, m), peak, peak * 1e-5f);
    }
    // No facet faces away from the normal.
    EXPECT_EQ(glsl::distributionBeckmann(-0.2f, 0.3f), 0.0f);
    EXPECT_EQ(glsl::distributionGaussian(0.0f, 0.3f), 0.0f);
    EXPECT_EQ(glsl::distributionGGX(-0.5f, 0.3f), 0.0f);
}

// The integral of D(h) (N.h) over the hemisphere: 2 pi * integral of D(cos t) cos t sin t dt.
double projectedIntegral(float (*D)(float, float), float m) {
    const int steps = 200000;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        double t = (i + 0.5) * (glm::half_pi<double>() / steps);
        sum += double(D(static_cast<float>(std::cos(t)), m)) * std::cos(t) * std::sin(t);
    }
    return 2.0 * glm::pi<double>() * sum * (glm::half_pi<double>() / steps);
}

TEST(Lighting, BeckmannAndGgxAreNormalized) {
    for (float m : {0.1f, 0.3f, 0.6f, 1.0f}) {
        EXPECT_NEAR(projectedIntegral(glsl::distributionBeckmann, m), 1.0, 2e-3) << "m = " << m;
        EXPECT_NEAR(projectedIntegral(glsl::distributionGGX, m), 1.0, 2e-3) << "m = " << m;
    }
}

TEST(Lighting, GaussianIsNormalizedOnlyForSmoothSurfaces) {
    // exp(-(alpha/m)^2)/(pi m^2) integrates to about 1 while the lobe is narrow (small m) and
    // drifts away as it widens: the classic form is not normalized, the lab shows it as written.
    EXPECT_NEAR(projectedIntegral(glsl::distributionGaussian, 0.05f), 1.0, 0.01);
    EXPECT_NEAR(projectedIntegral(glsl::distributionGaussian, 0.1f), 1.0, 0.02);
    EXPECT_GT(std::abs(projectedIntegral(glsl::distributionGaussian, 0.8f) - 1.0), 0.1);
}

TEST(Lighting, GeometryTermMasksAndShadows) {
    // min(1, 2(N.H)(N.V)/(V.H), 2(N.H)(N.L)/(V.H))
    EXPECT_NEAR(glsl::geometryCookTorrance(0.9f, 0.5f, 0.8f, 0.7f), 1.0f, 1e-6f);          // 1.286, 2.057 -> 1
    EXPECT_NEAR(glsl::geometryCookTorrance(0.9f, 0.2f, 0.8f, 0.7f), 2 * 0.9f * 0.2f / 0.7f, 1e-6f); // masking
    EXPECT_NEAR(glsl::geometryCookTorrance(0.9f, 0.8f, 0.1f, 0.7f), 2 * 0.9f * 0.1f / 0.7f, 1e-6f); // shadowing
    EXPECT_EQ(glsl::geometryTerm(0.9f, 0.2f, 0.8f, 0.7f, brdf(glsl::BRDF_COOK_TORRANCE, 0, 0, 0.3f, 1.5f, false)), 1.0f);
}

TEST(Lighting, CookTorranceAtHandValues) {
    glm::vec3 L = inPlane(40, -1);
    glm::vec3 V = inPlane(20, +1);
    // python: D F G / (4 N.V) with N.H = cos 10
    EXPECT_NEAR(glsl::cookTorranceSpecular(kUp, L, V, brdf(glsl::BRDF_COOK_TORRANCE)), 0.02835536f, 2e-6f);
    EXPECT_NEAR(glsl::cookTorranceSpecular(
                    kUp, L, V, brdf(glsl::BRDF_COOK_TORRANCE, glsl::DISTRIBUTION_GGX, glsl::FRESNEL_FULL)),
                0.02294566f, 2e-6f);
    EXPECT_EQ(glsl::specularFactor(kUp, L, V, 1.0f, brdf(glsl::BRDF_COOK_TORRANCE)),
              glsl::cookTorranceSpecular(kUp, L, V, brdf(glsl::BRDF_COOK_TORRANCE)));
}

//----------------------------------------------------------------------------------------
// Attenuation and spot lights
//----------------------------------------------------------------------------------------

TEST(Lighting, AttenuationIsClampedInverseQuadratic) {
    EXPECT_EQ(glsl::attenuation(glm::vec3(1, 0, 0), 5.0f), 1.0f);           // none
    EXPECT_FLOAT_EQ(glsl::attenuation(glm::vec3(0, 1, 0), 2.0f), 0.5f);      // 1/d
    EXPECT_FLOAT_EQ(glsl::attenuation(glm::vec3(0, 0, 1), 2.0f), 0.25f);     // 1/d^2
    EXPECT_FLOAT_EQ(glsl::attenuation(glm::vec3(1, 0.5f, 0.25f), 2.0f), 1.0f / 3.0f);
    EXPECT_EQ(glsl::attenuation(glm::vec3(0, 0, 1), 0.5f), 1.0f);            // 1/0.25 = 4, clamped to 1
    EXPECT_EQ(glsl::attenuation(glm::vec3(0, 0, 1), 0.0f), 1.0f);            // the limit at d = 0
}

TEST(Lighting, SpotCutoffAndExponent) {
    glm::vec3 S(0, -1, 0); // pointing down
    auto L = [](float deg) { // from a surface point, towards a light gamma degrees off the spot axis
        float r = glm::radians(deg);
        return glm::vec3(-std::sin(r), std::cos(r), 0.0f);
    };
    float cos30 = std::cos(glm::radians(30.0f));
    EXPECT_FLOAT_EQ(glsl::spotFactor(L(0), S, cos30, 8.0f), 1.0f);
    EXPECT_NEAR(glsl::spotFactor(L(20), S, cos30, 8.0f), std::pow(std::cos(glm::radians(20.0f)), 8.0f), 1e-6f);
    EXPECT_EQ(glsl::spotFactor(L(31), S, cos30, 8.0f), 0.0f);
    EXPECT_EQ(glsl::spotFactor(L(20), S, cos30, 0.0f), 1.0f); // exponent 0: a hard-edged cone
    EXPECT_EQ(glsl::spotFactor(L(29.9f), S, cos30, 0.0f), 1.0f);
}

//----------------------------------------------------------------------------------------
// The whole model
//----------------------------------------------------------------------------------------

Preset handPreset() {
    Preset p;
    p.material.emissive = {0.1f, 0.0f, 0.0f};
    p.material.ambient = {0.2f, 0.3f, 0.4f};
    p.material.diffuse = {0.5f, 0.6f, 0.7f};
    p.material.specular = {0.3f, 0.3f, 0.3f};
    p.material.shininess = 20.0f;
    p.ambientLight = glm::vec3(0.1f);
    LightDesc l;
    l.position = {1.0f, 2.0f, -1.0f};
    l.ambient = glm::vec3(0.05f);
    l.diffuse = {0.9f, 0.8f, 0.7f};
    l.specular = glm::vec3(1.0f);
    l.attenuation = {1.0f, 0.1f, 0.02f};
    p.lights = {l};
    return p;
}

TEST(Lighting, ShadeSumsTheTermsAsDocumented) {
    // An identity view keeps the light where it is written. python: d = 3, Att = 0.6756757,
    // N.L = 2/3, (R.V)^20 = 0.0003007287.
    Preset p = handPreset();
    ShadingInputs in = packShading(p, glm::mat4(1.0f));
    glm::vec3 c = shade(in, glm::vec3(0, 0, -3), glm::vec3(0, 0, 1));
    expectVec(c, glm::vec3(0.3327637f, 0.2612772f, 0.2807817f), 2e-6f);
}

TEST(Lighting, TermSwitchesDropTheirPart) {
    Preset p = handPreset();
    glm::vec3 pos(0, 0, -3), N(0, 0, 1);
    auto only = [&](bool e, bool a, bool d, bool s) {
        Preset q = p;
        q.terms = {e, a, d, s};
        return shade(packShading(q, glm::mat4(1.0f)), pos, N);
    };
    const float att = 0.6756757f, NoL = 2.0f / 3.0f, spec = 0.0003007287f;
    expectVec(only(true, false, false, false), p.material.emissive);
    expectVec(only(false, true, false, false), (glm::vec3(0.1f) + glm::vec3(0.05f)) * p.material.ambient);
    expectVec(only(false, false, true, false), att * p.lights[0].diffuse * p.material.diffuse * NoL, 1e-6f);
    expectVec(only(false, false, false, true), att * spec * p.material.specular, 1e-7f);
    expectVec(only(false, false, false, false), glm::vec3(0.0f));
    // Nothing here saturates, so the parts add up to the whole.
    expectVec(only(true, false, false, false) + only(false, true, false, false) + only(false, false, true, false) +
                  only(false, false, false, true),
              only(true, true, true, true), 1e-6f);
}

TEST(Lighting, ColourIsClampedPerChannel) {
    Preset p = handPreset();
    p.material.emissive = {1.0f, 0.5f, 0.0f};
    p.lights[0].diffuse = {4.0f, 4.0f, 0.0f};
    glm::vec3 c = shade(packShading(p, glm::mat4(1.0f)), glm::vec3(0, 0, -3), glm::vec3(0, 0, 1));
    EXPECT_EQ(c.r, 1.0f);
    EXPECT_EQ(c.g, 1.0f);
    EXPECT_LT(c.b, 1.0f);
}

TEST(Lighting, DirectionalLightTravelsAlongItsDirection) {
    Preset p;
    p.terms = {false, false, true, false};
    p.material.diffuse = glm::vec3(1.0f);
    LightDesc sun;
    sun.type = LightType::Directional;
    sun.direction = {0.0f, -1.0f, 0.0f}; // shining straight down: L = (0, 1, 0)
    sun.attenuation = {0.0f, 0.0f, 1.0f}; // ignored: no distance to a directional light
    p.lights = {sun};
    ShadingInputs in = packShading(p, glm::mat4(1.0f));
    expectVec(shade(in, glm::vec3(0, -100, -3), glm::vec3(0, 1, 0)), glm::vec3(1.0f));
    expectVec(shade(in, glm::vec3(0, 0, -3), glm::normalize(glm::vec3(1, 1, 0))), glm::vec3(std::sqrt(0.5f)));
}

TEST(Lighting, DisabledLightsAreNotPacked) {
    Preset p;
    p.lights.resize(3);
    p.lights[1].enabled = false;
    p.lights[2].diffuse = {0.25f, 0.5f, 0.75f};
    ShadingInputs in = packShading(p, glm::mat4(1.0f));
    EXPECT_EQ(in.lightCount, 2);
    expectVec(in.lights[1].diffuse, glm::vec3(0.25f, 0.5f, 0.75f));
}

TEST(Lighting, LightsMoveIntoEyeSpaceWithTheView) {
    Preset p;
    p.lights[0].type = LightType::Spot;
    p.lights[0].position = {0, 5, 0};
    p.lights[0].direction = {0, -2, 0};
    Transforms t = computeTransforms(p, 1.0f); // eye (0, 0, 4) looking at the origin
    ShadingInputs in = packShading(p, t.view);
    expectVec(in.lights[0].position, glm::vec3(0, 5, -4), 1e-5f);
    expectVec(in.lights[0].direction, glm::vec3(0, -1, 0), 1e-6f); // rotated and normalized
    EXPECT_NEAR(in.lights[0].cosCutoff, std::cos(glm::radians(30.0f)), 1e-7f);
}

// fovy_deg is the field of view of the view's narrower side: a point seen fovy/2 off the axis
// lands on the edge of the narrower side, vertical when wider than tall, horizontal when taller.
TEST(Lighting, FovyIsTheFieldOfViewOfTheNarrowerSide) {
    Preset p; // eye (0, 0, 4) looking at the origin, fovy 45
    float edge = 4.0f * std::tan(glm::radians(22.5f)); // at the target's depth
    auto ndc = [&](float aspect, glm::vec3 world) {
        Transforms t = computeTransforms(p, aspect);
        glm::vec4 clip = t.projection * t.view * glm::vec4(world, 1.0f);
        return glm::vec2(clip) / clip.w;
    };
    for (float aspect : {1.0f, 16.0f / 9.0f, 3.0f}) { // wide: vertical, as glm::perspective takes it
        SCOPED_TRACE(aspect);
        EXPECT_NEAR(ndc(aspect, {0, edge, 0}).y, 1.0f, 1e-5f);
        EXPECT_NEAR(ndc(aspect, {edge, 0, 0}).x, 1.0f / aspect, 1e-5f);
    }
    for (float aspect : {0.5f, 9.0f / 16.0f, 0.999f}) { // tall: horizontal
        SCOPED_TRACE(aspect);
        EXPECT_NEAR(ndc(aspect, {edge, 0, 0}).x, 1.0f, 1e-5f);
        EXPECT_NEAR(ndc(aspect, {0, edge, 0}).y, aspect, 1e-5f);
    }
}

TEST(Lighting, NormalMatrixUnderNonUniformScale) {
    Preset p;
    p.camera.eye = {0, 0, 1};
    p.camera.target = {0, 0, 0};
    p.model.scale = {3, 1, 1};
    // The surface x + y = 0 has normal (1, 1, 0). After scaling x by 3 the surface is x/3 + y = 0,
    // whose normal is (1, 3, 0): the inverse-transpose gets it, the model-view matrix does not.
    glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
    Transforms right = computeTransforms(p, 1.0f);
    expectVec(glm::normalize(right.normalMatrix * n), glm::normalize(glm::vec3(1, 3, 0)), 1e-6f);
    p.normalMatrix = NormalMatrixMode::ModelView;
    Transforms wrong = computeTransforms(p, 1.0f);
    expectVec(glm::normalize(wrong.normalMatrix * n), glm::normalize(glm::vec3(3, 1, 0)), 1e-6f);
}

TEST(Lighting, ModelMatrixIsTRzRyRxS) {
    Model m;
    m.scale = {2, 1, 1};
    m.rotateDeg = {0, 0, 90};
    m.translate = {0, 0, 5};
    // S stretches x to 2, Rz(90) turns x into y, T moves along z.
    glm::vec4 p = modelMatrix(m) * glm::vec4(1, 0, 0, 1);
    expectVec(glm::vec3(p), glm::vec3(0, 2, 5), 1e-6f);
    m.rotateDeg = {90, 90, 0}; // Rx first, then Ry: y -> z -> x
    expectVec(glm::vec3(modelMatrix(m) * glm::vec4(0, 1, 0, 0)), glm::vec3(1, 0, 0), 1e-6f);
}

} // namespace
} // namespace lab
