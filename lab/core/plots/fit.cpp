// fit.cpp — least-squares fits of one reflection model to another's specular reflection (fit.h).
#include "core/plots/fit.h"

#include "core/lighting/lighting.h"
#include "core/plots/hemisphere_rule.h"
#include "core/plots/plot_data.h"
#include "core/scene/limits.h"
#include "core/scene/preset_choices.h"
#include "core/scene/view_mode.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace lab {

namespace {

// The quadrature the objective sums with: 4 Gauss-Legendre nodes per α panel and 24 steps of φ over
// [0, π], about 1,000 directions per incident angle (README "Fitting": with 12 nodes and 64 steps the
// fitted values of the README's cases move by 0.2% at most).
constexpr AlbedoRule kFitRule{4, 24};

// One incident angle's directions: V with its weight dω·cos θo, and the target's value there.
struct AngleNodes {
    glm::vec3 N, L;
    std::vector<glm::vec3> V;
    std::vector<double> weight, target;
};

// The objective for one candidate model (fit.h): the sums that fix the best scale s in closed form.
class Objective {
public:
    Objective(const Preset& target, const Preset& candidate) : candidate_(packSurfaceUniforms(candidate)) {
        const SurfaceUniforms t = packSurfaceUniforms(target);
        ksLuminance_ = luminance(target.material.specular);
        const float largest = std::max({target.material.specular.r, target.material.specular.g, target.material.specular.b});
        sMax_ = largest > 0.0f ? 1.0 / largest : 0.0;
        const bool on = target.terms.specular;
        for (float deg : fitIncidentAngles()) {
            const LobeVectors v = lobeVectors(deg);
            AngleNodes a{v.N, v.L, {}, {}, {}};
            forEachSpecularNode(glm::radians(double(deg)), kFitRule, [&](const glm::dvec3& V, double dw) {
                const glm::vec3 Vf(V);
                a.V.push_back(Vf);
                a.weight.push_back(dw * V.y);
                const float s = on ? glsl::specularFactor(a.N, a.L, Vf, t.material.shininess, t.brdf) : 0.0f;
                a.target.push_back(double(ksLuminance_) * s);
            });
            for (std::size_t k = 0; k < a.V.size(); ++k) {
                targetSquares_ += a.weight[k] * a.target[k] * a.target[k];
            }
            angles_.push_back(std::move(a));
        }
    }

    double targetSquares() const { return targetSquares_; }
    double largestScale() const { return sMax_; }
    int evaluations() const { return evaluations_; }

    struct Value {
        double E = 0.0, scale = 0.0;
        bool scaleAtBound = false;
    };
    // E at the best scale for shininess n (Phong, Blinn-Phong) or roughness and ior (Cook-Torrance);
    // at `scale` instead when one is given.
    Value operator()(float shininess, float roughness, float ior, std::optional<double> scale = std::nullopt) {
        ++evaluations_;
        glsl::Brdf b = candidate_.brdf;
        b.roughness = roughness;
        b.ior = ior;
        double gg = 0.0, gt = 0.0;
        for (const AngleNodes& a : angles_) {
            for (std::size_t k = 0; k < a.V.size(); ++k) {
                const double g = double(ksLuminance_) * glsl::specularFactor(a.N, a.L, a.V[k], shininess, b);
                gg += a.weight[k] * g * g;
                gt += a.weight[k] * g * a.target[k];
            }
        }
        Value v;
        v.scale = scale ? *scale : gg > 0.0 ? gt / gg : 0.0;
        if (!scale && v.scale > sMax_) {
            v.scale = sMax_;
            v.scaleAtBound = true;
        }
        v.E = std::max(0.0, v.scale * v.scale * gg - 2.0 * v.scale * gt + targetSquares_);
        return std::isfinite(v.E) ? v : Value{targetSquares_, 0.0, false};
    }

private:
    SurfaceUniforms candidate_;
    std::vector<AngleNodes> angles_;
    double targetSquares_ = 0.0, sMax_ = 0.0;
    float ksLuminance_ = 0.0f;
    int evaluations_ = 0;
};

// The minimum of f on [lo, hi] by a scan every `step`, then golden-section search about the scan's
// best to `tolerance`.
template <class F>
double minimize1d(F&& f, double lo, double hi, double step, double tolerance) {
    double best = lo, bestValue = f(lo);
    for (double x = lo + step; x <= hi + 1e-9; x += step) {
        const double v = f(std::min(x, hi));
        if (v < bestValue) {
            best = std::min(x, hi);
            bestValue = v;
        }
    }
    double a = std::max(lo, best - step), b = std::min(hi, best + step);
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
    while (b - a > tolerance) {
        if (fc < fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    const double x = 0.5 * (a + b);
    return f(x) <= bestValue ? x : best;
}

// F0 = ((ior − 1)/(ior + 1))² and back, for ior ≥ 1.
double iorOf(double f0) {
    const double r = std::sqrt(std::clamp(f0, 0.0, 0.999));
    return (1.0 + r) / (1.0 - r);
}
double f0Of(double ior) { return std::pow((ior - 1.0) / (ior + 1.0), 2.0); }

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

// `x` on the bound `lo` or `hi` of a search (to the search's last step).
bool onBound(double x, double lo, double hi) { return x <= lo + 1e-4 || x >= hi - 1e-4; }

std::string boundText(const char* what, double x, double lo, const limits::Range& range) {
    return x <= lo + 1e-4 ? std::string(what) + " ended on its smallest value, " + number(range.min)
                          : std::string(what) + " ended on its largest value, " + number(range.max);
}

} // namespace

std::vector<float> fitIncidentAngles() {
    std::vector<float> angles;
    for (int deg = 0; deg <= 75; deg += 5) {
        angles.push_back(static_cast<float>(deg));
    }
    return angles;
}

namespace {

Preset candidateFor(const Preset& target, const FitRequest& request) {
    Preset c = target;
    c.brdf = request.brdf;
    if (request.brdf == BrdfModel::CookTorrance) {
        c.cookTorrance.distribution = request.distribution;
        if (target.brdf != BrdfModel::CookTorrance) { // the target's own Fresnel and G where it has them
            c.cookTorrance.fresnel = FresnelMode::Schlick;
            c.cookTorrance.geometry = true;
        }
    }
    c.terms.specular = true;
    // The views `lab check` renders that the fitted model does not have (D, F, G for Phong): they
    // would be ERROR cases of the fit's own check.
    std::erase_if(c.check.views, [&](const CheckView& v) {
        std::optional<ViewMode> mode = viewFromName(v.view);
        return !mode || !notApplicable(*mode, c, v.light - 1).empty();
    });
    return c;
}

// Why `target` reflects no specular light the fit could measure, in words (fitSpecular's error).
std::string nothingToFit(const Preset& target) {
    if (!target.terms.specular) {
        return "nothing to fit: the preset's specular term is switched off";
    }
    if (target.material.specular == glm::vec3(0.0f)) {
        return "nothing to fit: the preset reflects no specular light (its specular colour is 0)";
    }
    const CookTorrance& ct = target.cookTorrance;
    if (target.brdf == BrdfModel::CookTorrance && ct.fresnel == FresnelMode::Full && ct.ior == 1.0f) {
        return "nothing to fit: the preset reflects no specular light (Cook-Torrance's Fresnel term F is 0 at every "
               "angle: the full Fresnel equations with ior 1, a surface with the index of the air)";
    }
    return "nothing to fit: the preset's specular lobe is too small to measure (below the rule's floor at every "
           "angle the fit samples)";
}

void fitPhongLike(Objective& objective, FitResult& r) {
    const double lo = std::log10(double(limits::kShininess.min)), hi = std::log10(double(limits::kShininess.max));
    auto E = [&](double x) { return objective(static_cast<float>(std::pow(10.0, x)), 1.0f, 1.0f).E; };
    const double x = minimize1d(E, lo, hi, 0.25, 1e-6);
    const float n = static_cast<float>(std::pow(10.0, x));
    const Objective::Value v = objective(n, 1.0f, 1.0f);
    r.fitted.material.shininess = n;
    r.fitted.material.specular *= static_cast<float>(v.scale);
    r.parameters.push_back({"material.shininess", n, onBound(x, lo, hi) ? boundText("the shininess", x, lo, limits::kShininess) : ""});
    r.parameters.push_back({"specular scale", static_cast<float>(v.scale),
                            v.scaleAtBound ? "the specular colour's largest channel reached 1" : ""});
    r.error = std::sqrt(v.E / objective.targetSquares());
}

void fitCookTorrance(Objective& objective, const Preset& target, FitResult& r) {
    const double lo = std::log10(double(limits::kRoughness.min)), hi = std::log10(double(limits::kRoughness.max));
    const double fMax = f0Of(double(limits::kIor.max));
    auto E = [&](double x, double f0) {
        return objective(1.0f, static_cast<float>(std::pow(10.0, x)), static_cast<float>(iorOf(f0))).E;
    };
    // The roughness first, at the target's F0 (Cook-Torrance's own, else glass's 0.04), then a
    // compass search in (log m, F0) from there, halving its steps to 1e-6.
    double f0 = std::clamp(target.brdf == BrdfModel::CookTorrance ? f0Of(std::max(1.0, double(target.cookTorrance.ior))) : 0.04, 0.0, fMax);
    double x = minimize1d([&](double t) { return E(t, f0); }, lo, hi, 0.25, 1e-3);
    double best = E(x, f0);
    for (double sx = 0.0625, sf = 0.05; sx > 1e-6 || sf > 1e-6;) {
        bool moved = false;
        const double tries[4][2] = {{sx, 0.0}, {-sx, 0.0}, {0.0, sf}, {0.0, -sf}};
        for (const auto& t : tries) {
            const double tx = std::clamp(x + t[0], lo, hi), tf = std::clamp(f0 + t[1], 0.0, fMax);
            const double v = E(tx, tf);
            if (v < best) {
                x = tx;
                f0 = tf;
                best = v;
                moved = true;
                break;
            }
        }
        if (!moved) {
            sx *= 0.5;
            sf *= 0.5;
        }
    }
    const float m = static_cast<float>(std::pow(10.0, x)), ior = static_cast<float>(iorOf(f0));
    const Objective::Value v = objective(1.0f, m, ior);
    r.fitted.cookTorrance.roughness = m;
    r.fitted.cookTorrance.ior = ior;
    r.fitted.material.specular *= static_cast<float>(v.scale);
    r.parameters.push_back({"cook_torrance.roughness", m, onBound(x, lo, hi) ? boundText("the roughness", x, lo, limits::kRoughness) : ""});
    r.parameters.push_back({"cook_torrance.ior", ior,
                            f0 <= 1e-6 ? "the ior ended on 1 (no reflection at normal incidence)"
                            : f0 >= fMax - 1e-6 ? "the ior ended on its largest value, 100" : ""});
    r.parameters.push_back({"specular scale", static_cast<float>(v.scale),
                            v.scaleAtBound ? "the specular colour's largest channel reached 1" : ""});
    r.error = std::sqrt(v.E / objective.targetSquares());
}

} // namespace

std::optional<FitResult> fitSpecular(const Preset& target, const FitRequest& request, std::string& error) {
    const Preset candidate = candidateFor(target, request);
    Objective objective(target, candidate);
    if (!(objective.targetSquares() > 1e-20)) {
        error = nothingToFit(target);
        return std::nullopt;
    }
    FitResult r;
    r.fitted = candidate;
    r.fitted.terms.specular = target.terms.specular;
    if (request.brdf == BrdfModel::CookTorrance) {
        fitCookTorrance(objective, target, r);
    } else {
        fitPhongLike(objective, r);
    }
    r.evaluations = objective.evaluations();
    // Named for what it is, so that a figure's or the lab's "B: …" does not pass it off as the target.
    r.fitted.name = (target.name.empty() ? std::string("Untitled") : target.name) + " (" + r.modelText() + " fit)";
    return r;
}

double fitError(const Preset& target, const Preset& candidate) {
    Objective objective(target, candidate); // the candidate's BRDF, distribution, Fresnel and G
    const float ks = luminance(target.material.specular);
    if (!(objective.targetSquares() > 1e-20) || !(ks > 0.0f)) {
        return 0.0;
    }
    // The objective scales the target's Ks: the candidate's own is that scale, by luminance.
    const double scale = candidate.terms.specular ? double(luminance(candidate.material.specular)) / ks : 0.0;
    const Objective::Value v =
        objective(candidate.material.shininess, candidate.cookTorrance.roughness, candidate.cookTorrance.ior, scale);
    return std::sqrt(v.E / objective.targetSquares());
}

std::string FitResult::modelText() const {
    std::string s = std::string(label(fitted.brdf));
    if (fitted.brdf == BrdfModel::CookTorrance) {
        s += " (" + std::string(toString(fitted.cookTorrance.distribution)) + ")";
    }
    return s;
}

std::string FitResult::parametersText() const {
    std::string s;
    for (const FitParameter& p : parameters) {
        const std::string name = p.name == "specular scale" ? "specular \xc3\x97" : p.name.substr(p.name.find('.') + 1);
        s += (s.empty() ? "" : ", ") + name + " " + number(p.value);
    }
    return s;
}

std::string FitResult::errorText() const { return number(100.0 * error) + "%"; }

std::string FitResult::summary() const {
    return modelText() + ": " + parametersText() + "; remaining error " + errorText();
}

std::vector<std::string> FitResult::boundsThatBind() const {
    std::vector<std::string> out;
    for (const FitParameter& p : parameters) {
        if (!p.bound.empty()) {
            out.push_back(p.bound);
        }
    }
    return out;
}

} // namespace lab
