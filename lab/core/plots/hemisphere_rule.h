// hemisphere_rule.h — the quadrature over the hemisphere of view directions about the mirror
// direction R, for specular lobes: the albedo's (core/plots/energy.h) and the fit's (core/plots/fit.h).
//
// For light from θi in the plots' plane of incidence (N = (0, 1, 0), L = (−sin θi, cos θi, 0)),
// directions V = cos α R + sin α (cos φ e1 + sin φ e2), e1 in the plane of incidence towards the
// horizon and e2 across it, dω = sin α dα dφ. In α, Gauss-Legendre panels graded geometrically from
// π/4096 to π (specularPanelEdges: a lobe cos^n α is about 1/√n wide, so from n ≈ 1 to n ≈ 10^6 it
// spans a few panels); in φ on [0, π], doubled (every lobe of an isotropic BRDF lit in the plane of
// incidence is symmetric about it), the midpoint rule, or Gauss-Legendre from where the horizon cuts
// the circle at α (N·V = cos α cos θi − sin α sin θi cos φ > 0 for cos φ < cot α cot θi) to π, so
// that no panel has a kink inside. Only directions above the horizon are visited.
#pragma once

#include "core/plots/energy.h"

#include <glm/gtc/constants.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <vector>

namespace lab {

// The panels' edges in α: 0, π/4096, π/2048, …, and where the horizon starts and stops cutting the
// circle at α (90° − θi, 90° + θi: the last edge). `ti` in radians.
std::vector<double> specularPanelEdges(double ti);

// Calls visit(V, w) for each node above the horizon, w its share of dω (the φ symmetry's 2 included),
// so that Σ w f(V) ≈ ∫ f dω over the hemisphere for f symmetric about the plane of incidence.
template <class Visit>
void forEachSpecularNode(double ti, const AlbedoRule& rule, Visit&& visit) {
    std::vector<double> x, w, xPhi, wPhi;
    gaussLegendre(rule.nodes, x, w);
    gaussLegendre(rule.phiSteps, xPhi, wPhi);
    const double pi = glm::pi<double>(), dPhi = pi / rule.phiSteps;
    std::vector<double> cosPhi, sinPhi;
    for (int j = 0; j < rule.phiSteps; ++j) {
        const double phi = (j + 0.5) * dPhi;
        cosPhi.push_back(std::cos(phi));
        sinPhi.push_back(std::sin(phi));
    }
    const double sinTi = std::sin(ti), cosTi = std::cos(ti);
    const glm::dvec3 R(sinTi, cosTi, 0.0), e1(cosTi, -sinTi, 0.0), e2(0.0, 0.0, 1.0);
    const std::vector<double> edges = specularPanelEdges(ti);
    for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
        const double a = edges[k], b = edges[k + 1];
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double alpha = a + 0.5 * (b - a) * (x[i] + 1.0);
            const double sinA = std::sin(alpha), cosA = std::cos(alpha);
            const double weight = 0.5 * (b - a) * w[i] * sinA * 2.0;
            auto at = [&](double cosP, double sinP, double dw) {
                const glm::dvec3 V = cosA * R + sinA * (cosP * e1 + sinP * e2);
                if (V.y > 0.0) {
                    visit(V, dw);
                }
            };
            const double cut = cosA * cosTi, across = sinA * sinTi; // N·V = cut − across·cos φ
            if (cut >= across) {
                for (std::size_t j = 0; j < cosPhi.size(); ++j) {
                    at(cosPhi[j], sinPhi[j], weight * dPhi);
                }
            } else if (cut > -across) {
                const double phi0 = std::acos(cut / across), half = 0.5 * (pi - phi0);
                for (std::size_t j = 0; j < xPhi.size(); ++j) {
                    const double phi = phi0 + half * (xPhi[j] + 1.0);
                    at(std::cos(phi), std::sin(phi), weight * half * wPhi[j]);
                }
            }
        }
    }
}

} // namespace lab
