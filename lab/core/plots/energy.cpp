// energy.cpp — the albedo of each term by quadrature over the hemisphere (see energy.h).
#include "core/plots/energy.h"

#include "core/io/number_format.h"
#include "core/lighting/lighting.h"
#include "core/plots/hemisphere_rule.h"

#include <glm/gtc/constants.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace lab {

// The specular panels' edges in α, the angle from R: 0, π/4096, π/2048, …, π/2, π. A Phong lobe
// cos^n α is about 1/√n wide, so from n ≈ 1 to n ≈ 10^6 it spans a few panels at any shininess.
// Two more edges where the horizon starts and ends cutting the circle of directions at α from R
// (90° − θi and 90° + θi, the last edge: beyond it everything is below the horizon), so that each
// panel's integrand is smooth.
std::vector<double> specularPanelEdges(double ti) {
    const double pi = glm::pi<double>(), first = pi / 2 - ti, last = pi / 2 + ti;
    std::vector<double> edges{0.0};
    for (int k = 12; k >= 0; --k) {
        double e = std::ldexp(pi, -k);
        if (first > edges.back() && first < e && first < last) {
            edges.push_back(first);
        }
        if (e >= last) {
            break;
        }
        edges.push_back(e);
    }
    edges.push_back(last);
    return edges;
}

namespace {

void solveGaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
    nodes.assign(static_cast<std::size_t>(n), 0.0);
    weights.assign(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
        // Newton's iteration from the Chebyshev-like first guess; P_n and P_n' by the recurrence.
        double x = std::cos(glm::pi<double>() * (i + 0.75) / (n + 0.5));
        double dp = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= n; ++k) {
                double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (x * p1 - p0) / (x * x - 1.0); // P_n'(x); p1 = P_n(x), p0 = P_{n-1}(x)
            double step = p1 / dp;
            x -= step;
            if (std::fabs(step) < 1e-16) {
                break;
            }
        }
        nodes[static_cast<std::size_t>(i)] = x;
        weights[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
}

} // namespace

void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
    // The rules asked for are few (8 and 64 nodes) and solving one takes up to 100 Newton steps a
    // node: each thread keeps the ones it solved (the same numbers, found rather than solved again;
    // the plots' albedo asks three times per call, during a drag every 0.5 s).
    struct Solved {
        int n;
        std::vector<double> nodes, weights;
    };
    thread_local std::vector<Solved> solved;
    for (const Solved& s : solved) {
        if (s.n == n) {
            nodes = s.nodes;
            weights = s.weights;
            return;
        }
    }
    solveGaussLegendre(n, nodes, weights);
    if (solved.size() < 8) {
        solved.push_back({n, nodes, weights});
    }
}

float albedoOf(const Albedo& a, PlotComponent c) {
    return c == PlotComponent::Total ? luminance(a.total()) : componentOf(luminance(a.diffuse), luminance(a.specular), c);
}

std::optional<Albedo> albedo(const LobeInputs& inputs, const AlbedoRule& rule) {
    // core/plots/plot_data.cpp's unit white directional light in the plane of incidence, from L.
    const float ti = glm::radians(std::fabs(inputs.incidentDeg));
    const LobeVectors v = lobeVectors(std::fabs(inputs.incidentDeg));
    const glm::vec3 &N = v.N, &L = v.L;
    const float NoL = glm::dot(N, L); // as lightContribution computes it
    if (!(std::fabs(inputs.incidentDeg) < 90.0f) || !(NoL > 0.0f) || rule.nodes < 1 || rule.phiSteps < 1) {
        return std::nullopt;
    }
    const glsl::Light light = unitLightFrom(L);
    auto terms = [&](const glm::dvec3& V) {
        return glsl::lightContribution(inputs.material, inputs.brdf, inputs.terms, light, glm::vec3(0.0f), N,
                                       glm::vec3(V));
    };
    std::vector<double> x, w;
    gaussLegendre(rule.nodes, x, w);
    // φ on [0, π] by midpoints, doubled: every term is symmetric about the plane of incidence.
    const double dPhi = glm::pi<double>() / rule.phiSteps;
    std::vector<double> cosPhi, sinPhi;
    for (int j = 0; j < rule.phiSteps; ++j) {
        double phi = (j + 0.5) * dPhi;
        cosPhi.push_back(std::cos(phi));
        sinPhi.push_back(std::sin(phi));
    }

    // Diffuse, about N: dω = d(cos θo) dφ, cos θo = μ on [0, 1].
    glm::dvec3 diffuse(0.0);
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double mu = 0.5 * (x[i] + 1.0), s = std::sqrt(1.0 - mu * mu), weight = 0.5 * w[i] * 2.0 * dPhi * mu;
        for (std::size_t j = 0; j < cosPhi.size(); ++j) {
            diffuse += weight * glm::dvec3(terms({s * cosPhi[j], mu, s * sinPhi[j]}).diffuse);
        }
    }

    // Specular, about R (hemisphere_rule.h): each direction above the horizon with its dω.
    glm::dvec3 specular(0.0);
    forEachSpecularNode(double(ti), rule, [&](const glm::dvec3& V, double dw) {
        specular += dw * V.y * glm::dvec3(terms(V).specular);
    });

    const double scale = 1.0 / (glm::pi<double>() * NoL);
    return Albedo{glm::vec3(diffuse * scale), glm::vec3(specular * scale)};
}

std::vector<AlbedoSample> albedoCurve(LobeInputs inputs, const AlbedoRule& rule) {
    std::vector<AlbedoSample> samples;
    samples.reserve(90);
    for (int deg = 0; deg < 90; ++deg) {
        inputs.incidentDeg = static_cast<float>(deg);
        samples.push_back({inputs.incidentDeg, albedo(inputs, rule).value_or(Albedo{})});
    }
    return samples;
}

std::string albedoCsv(const std::vector<AlbedoSample>& samples) {
    std::string out = "theta_in_deg,diffuse,specular,total,total_r,total_g,total_b\n";
    for (const AlbedoSample& s : samples) {
        const glm::vec3 total = s.albedo.total();
        for (float v : {s.incidentDeg, luminance(s.albedo.diffuse), luminance(s.albedo.specular), luminance(total),
                        total.r, total.g}) {
            out += shortestFloat(v);
            out += ',';
        }
        out += shortestFloat(total.b);
        out += '\n';
    }
    return out;
}

} // namespace lab
