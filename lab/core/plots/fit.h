// fit.h — fitting one reflection model to another: the parameters of Phong, Blinn-Phong or
// Cook-Torrance whose specular reflection comes closest to a preset's, by least squares.
//
// The objective (README "Fitting one model to another"): for the incident angles θi = 0°, 5°, …, 75°
// (the plots' unit white directional light, core/plots/plot_data.h),
//     E = Σ_θi ∫_Ω (f(V) − t(V))² cos θo dω_o,
// f the fitted model's specular luminance (what the lobe plot's specular column shows), t the
// preset's. The remaining error is √(E / Σ_θi ∫ t² cos θo dω). The integral over the hemisphere of
// view directions is core/plots/energy.h's specular rule about R (hemisphere_rule.h), one rule for
// every evaluation, so the objective is a smooth function of the parameters.
//
// The parameters: Phong and Blinn-Phong, the shininess n and the specular colour's scale s (the
// fitted Ks is s × the preset's Ks, its hue kept); Cook-Torrance with a chosen distribution, the
// roughness m, the ior and the scale. For fixed shape parameters the best s is linear least squares,
// so the search is over log n (one dimension) or (log m, ior) (two), and s follows in closed form
// (variable projection). The optimiser is deterministic: a scan of a fixed grid over the range, then
// golden-section search (one dimension) or a compass search with halving steps (two) from the scan's
// best. Every value stays in the preset's ranges (scene/limits.h; s × Ks ≤ 1 per channel, the ior
// searched in [1, 100] where F0 covers [0, 1)); a parameter that ends on a bound says so.
//
// Not here: what the GUI does with the result (ui/panel: B in compare mode) or the files (lab/cli).
#pragma once

#include "core/scene/preset.h"

#include <optional>
#include <string>
#include <vector>

namespace lab {

struct FitRequest {
    BrdfModel brdf = BrdfModel::BlinnPhong;
    Distribution distribution = Distribution::Beckmann; // Cook-Torrance's
};

struct FitParameter {
    std::string name;  // the preset's field: "material.shininess", "cook_torrance.roughness", …, "specular scale"
    float value = 0.0f;
    std::string bound; // empty, or which bound it ended on ("the shininess's largest, 1000000")
};

struct FitResult {
    Preset fitted;      // the target with the fitted model and parameters, named "<target's name> (<model> fit)"; else unchanged
    double error = 0.0; // √(E / Σ ∫ t² cos θo dω), 0 … (1 is as far as fitting nothing)
    std::vector<FitParameter> parameters;
    int evaluations = 0; // of the objective (each one 16 incident angles × the rule's directions)

    // One line: "Blinn-Phong: shininess 68.3, specular × 0.97; remaining error 4.2%".
    std::string summary() const;
    // Its parts: "Blinn-Phong" ("Cook-Torrance (ggx)"), "shininess 68.3, specular × 0.97" and "4.2%".
    std::string modelText() const;
    std::string parametersText() const;
    std::string errorText() const;
    // Each bound that binds, one sentence each (empty when none does).
    std::vector<std::string> boundsThatBind() const;
};

// The fit of `request`'s model to `target`'s specular reflection; nullopt with `error` (one line)
// when there is nothing to fit: the target reflects no specular light (its specular term off, its
// Ks 0, Cook-Torrance's F 0 everywhere, or a lobe that leaves nothing above the quadrature's floor).
// The fitted preset is the target with the fitted model: its camera, lights and `check` as the
// target's, less the views `lab check` cannot render for the fitted model (D, F, G for Phong).
std::optional<FitResult> fitSpecular(const Preset& target, const FitRequest& request, std::string& error);

// The incident angles the objective sums over: 0°, 5°, …, 75°.
std::vector<float> fitIncidentAngles();

// The objective's remaining error of `candidate`'s specular reflection against `target`'s, by the
// same rule, at the candidate's own specular colour (what fitSpecular minimises over that colour's
// scale: the tests check that a fit's written preset has the error its result reports).
double fitError(const Preset& target, const Preset& candidate);

} // namespace lab
