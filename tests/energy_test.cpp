// energy_test.cpp — the albedo quadrature against closed forms, and what the lectures say about it.
//
// The error bounds here are the README's ("Energy"): what the default rule (AlbedoRule{}) was
// measured to achieve against the closed forms and against a rule four times finer.
#include "core/plots/energy.h"

#include "core/plots/plot_data.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace lab {
namespace {

// The README's stated error of the default rule: absolute, on albedos that are at most about 1.
constexpr double kDiffuseError = 1e-5;  // Lambert: the rule is exact, what is left is float rounding
constexpr double kSpecularError = 1e-4; // every lobe, against the closed forms and the finer rule

Preset diffuseOnly(float kd) {
    Preset p;
    p.material.diffuse = glm::vec3(kd);
    p.terms.specular = false;
    return p;
}

Preset specularOnly(BrdfModel brdf, float shininess) {
    Preset p;
    p.brdf = brdf;
    p.material.specular = glm::vec3(1.0f);
    p.material.shininess = shininess;
    p.terms.diffuse = false;
    return p;
}

Albedo albedoAt(const Preset& p, float incidentDeg, const AlbedoRule& rule = {}) {
    std::optional<Albedo> a = albedo(lobeInputs(p, incidentDeg), rule);
    EXPECT_TRUE(a.has_value()) << "at " << incidentDeg << " degrees";
    return a.value_or(Albedo{});
}

TEST(Energy, GaussLegendreIsExactForPolynomialsOfDegree2nMinus1) {
    std::vector<double> x, w;
    for (int n : {1, 2, 5, 8, 24}) {
        gaussLegendre(n, x, w);
        for (int degree = 0; degree <= 2 * n - 1; ++degree) {
            double sum = 0;
            for (std::size_t i = 0; i < x.size(); ++i) {
                sum += w[i] * std::pow(x[i], degree);
            }
            double exact = degree % 2 == 1 ? 0.0 : 2.0 / (degree + 1);
            EXPECT_NEAR(sum, exact, 1e-13) << "n " << n << " degree " << degree;
        }
    }
}

// I_d = Kd·(N·L) does not depend on V, so ρ_d = Kd·(N·L)·∫ cos θo dω / (π·N·L) = Kd: the
// normalization is chosen to make this 1 for Kd = 1, at every angle.
TEST(Energy, LambertianKd1ReflectsExactly1AtEveryIncidentAngle) {
    for (int deg = 0; deg < 90; ++deg) {
        Albedo a = albedoAt(diffuseOnly(1.0f), static_cast<float>(deg));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(a.diffuse[c], 1.0, kDiffuseError) << deg << " degrees";
        }
        EXPECT_EQ(a.specular, glm::vec3(0.0f));
    }
    EXPECT_NEAR(albedoAt(diffuseOnly(0.25f), 40.0f).diffuse.g, 0.25, kDiffuseError);
}

// Phong at normal incidence: L = N, so R = N and R·V = cos θo. With I_s = Ks·(R·V)^n,
//   ρ_s(0) = 1/(π·1) ∫_0^{2π} ∫_0^{π/2} Ks cos^n θ · cos θ · sin θ dθ dφ
//          = 2·Ks ∫_0^1 μ^{n+1} dμ = 2·Ks/(n + 2).
TEST(Energy, PhongSpecularAtNormalIncidenceIs2KsOverNPlus2) {
    for (float n : {1.0f, 10.0f, 50.0f, 200.0f, 1000.0f}) {
        Preset p = specularOnly(BrdfModel::Phong, n);
        p.material.specular = glm::vec3(0.5f);
        Albedo a = albedoAt(p, 0.0f);
        const double exact = 2.0 * 0.5 / (n + 2.0);
        EXPECT_NEAR(a.specular.r, exact, kSpecularError * exact) << "n " << n;
        EXPECT_EQ(a.diffuse, glm::vec3(0.0f));
    }
    // Far sharper lobes still land on the panels; what is left is the lighting function's float
    // R·V (1 − cos α comes in steps of 6·10⁻⁸, and cos^n α for n = 10⁶ feels each one).
    for (float n : {1.0e4f, 1.0e5f, 1.0e6f}) {
        const double exact = 2.0 / (n + 2.0);
        EXPECT_NEAR(albedoAt(specularOnly(BrdfModel::Phong, n), 0.0f).specular.r, exact, 1e-2 * exact) << "n " << n;
    }
}

// Blinn-Phong at normal incidence: H bisects N and V, so N·H = cos(θo/2) = c. With cos θo = 2c² − 1
// and sin θo dθo = −4c dc (θo from 0 to π/2 is c from 1 to 1/√2),
//   ρ_s(0) = 2 ∫_0^{π/2} c^n (2c² − 1) sin θo dθo = 8 ∫_{1/√2}^1 (2c^{n+3} − c^{n+1}) dc
//          = 8 [2c^{n+4}/(n+4) − c^{n+2}/(n+2)] from 1/√2 to 1.
TEST(Energy, BlinnPhongSpecularAtNormalIncidenceFollowsItsClosedForm) {
    for (double n : {1.0, 10.0, 50.0, 200.0, 1000.0}) {
        auto F = [n](double c) { return 2.0 * std::pow(c, n + 4) / (n + 4) - std::pow(c, n + 2) / (n + 2); };
        double exact = 8.0 * (F(1.0) - F(std::sqrt(0.5)));
        Albedo a = albedoAt(specularOnly(BrdfModel::BlinnPhong, static_cast<float>(n)), 0.0f);
        EXPECT_NEAR(a.specular.r, exact, kSpecularError * exact) << "n " << n;
    }
}

// A Phong lobe narrow enough to stay above the horizon integrates to the same 2/(n + 2) about R at
// any incident angle (N·V = cos θi cos α + sin θi sin α cos φ, and the cos φ part integrates to 0).
TEST(Energy, NarrowPhongLobeReflects2OverNPlus2AtAnyIncidentAngle) {
    for (float deg : {10.0f, 30.0f, 50.0f, 70.0f}) {
        Albedo a = albedoAt(specularOnly(BrdfModel::Phong, 2000.0f), deg);
        EXPECT_NEAR(a.specular.r, 2.0 / 2002.0, kSpecularError * 2.0 / 2002.0) << deg << " degrees";
    }
}

// The lectures' point: the Phong highlight gets smaller as n grows but no brighter, so less light
// is reflected in all.
TEST(Energy, PhongReflectsLessAsShininessGrows) {
    for (float deg : {0.0f, 30.0f, 60.0f}) {
        float previous = 1e9f;
        for (float n : {1.0f, 5.0f, 10.0f, 20.0f, 50.0f, 100.0f, 500.0f}) {
            float rho = albedoAt(specularOnly(BrdfModel::Phong, n), deg).specular.r;
            EXPECT_LT(rho, previous) << "n " << n << " at " << deg << " degrees";
            previous = rho;
        }
    }
}

// Every BRDF, at angles from normal to grazing: the default rule agrees with one four times finer
// in each direction (which agrees with the closed forms above to 1e-7).
TEST(Energy, DefaultRuleAgreesWithAFinerOne) {
    const AlbedoRule fine{32, 128};
    std::vector<Preset> presets;
    for (BrdfModel brdf : {BrdfModel::Phong, BrdfModel::BlinnPhong}) {
        for (float n : {1.0f, 8.0f, 64.0f, 1000.0f}) {
            presets.push_back(specularOnly(brdf, n));
        }
    }
    for (Distribution d : {Distribution::Beckmann, Distribution::Ggx, Distribution::Gaussian}) {
        for (float m : {0.05f, 0.3f, 1.0f}) {
            Preset p = specularOnly(BrdfModel::CookTorrance, 1.0f);
            p.cookTorrance.distribution = d;
            p.cookTorrance.roughness = m;
            presets.push_back(p);
        }
    }
    for (const Preset& p : presets) {
        for (float deg : {0.0f, 30.0f, 60.0f, 80.0f, 89.0f}) {
            float coarse = albedoAt(p, deg).specular.r, reference = albedoAt(p, deg, fine).specular.r;
            EXPECT_NEAR(coarse, reference, kSpecularError * std::max(1.0f, reference))
                << "brdf " << int(p.brdf) << " n " << p.material.shininess << " m " << p.cookTorrance.roughness
                << " distribution " << int(p.cookTorrance.distribution) << " at " << deg << " degrees";
        }
    }
}

// Cook-Torrance is a physical BRDF f = D·F·G/(4(N·L)(N·V)) and the lab's I_s = Ks·f·(N·L), while
// its Lambert term is Kd·(N·L) without the 1/π: in this normalization a narrow lobe at normal
// incidence, without G, reflects F(0)/π = F0/π (D is normalized: ∫ D (N·H) dω_h = 1).
TEST(Energy, NarrowCookTorranceLobeReflectsF0OverPi) {
    Preset p = specularOnly(BrdfModel::CookTorrance, 1.0f);
    p.cookTorrance.roughness = 0.02f;
    p.cookTorrance.geometry = false;
    p.cookTorrance.ior = 1.5f;
    const double f0 = 0.04; // ((1.5 − 1)/(1.5 + 1))²
    EXPECT_NEAR(albedoAt(p, 0.0f).specular.r, f0 / glm::pi<double>(), 1e-3 * f0);
}

TEST(Energy, EachChannelScalesWithItsCoefficient) {
    Preset p;
    p.material.diffuse = {0.8f, 0.4f, 0.0f};
    p.material.specular = {0.0f, 0.5f, 1.0f};
    Albedo a = albedoAt(p, 35.0f);
    EXPECT_NEAR(a.diffuse.r, 0.8, kDiffuseError);
    EXPECT_NEAR(a.diffuse.g, 0.4, kDiffuseError);
    EXPECT_EQ(a.diffuse.b, 0.0f);
    EXPECT_EQ(a.specular.r, 0.0f);
    EXPECT_NEAR(a.specular.g, 0.5f * a.specular.b, 1e-6);
    EXPECT_EQ(a.total(), a.diffuse + a.specular);
}

TEST(Energy, SwitchedOffTermsReflectNothing) {
    Preset p;
    p.terms.diffuse = false;
    p.terms.specular = false;
    Albedo a = albedoAt(p, 20.0f);
    EXPECT_EQ(a.total(), glm::vec3(0.0f));
}

TEST(Energy, UndefinedAtGrazingIncidenceAndSymmetricInTheAngle) {
    Preset p;
    EXPECT_FALSE(albedo(lobeInputs(p, 90.0f)).has_value());
    EXPECT_FALSE(albedo(lobeInputs(p, -90.0f)).has_value());
    EXPECT_FALSE(albedo(lobeInputs(p, std::nanf(""))).has_value());
    EXPECT_EQ(albedoAt(p, -40.0f).specular, albedoAt(p, 40.0f).specular);
}

TEST(Energy, CurveAndCsv) {
    Preset p;
    std::vector<AlbedoSample> curve = albedoCurve(lobeInputs(p, 45.0f));
    ASSERT_EQ(curve.size(), 90u);
    EXPECT_EQ(curve.front().incidentDeg, 0.0f);
    EXPECT_EQ(curve.back().incidentDeg, 89.0f);
    EXPECT_EQ(curve[30].albedo.specular, albedoAt(p, 30.0f).specular);
    std::string csv = albedoCsv(curve);
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "theta_in_deg,diffuse,specular,total,total_r,total_g,total_b");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 91);
}

} // namespace
} // namespace lab
