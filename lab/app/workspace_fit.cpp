// workspace_fit.cpp — the workspace's Fit commands: B becomes a model fitted to A's specular lobe
// (core/plots/fit.h), shown beside A in compare mode, its remaining error in B's label.
#include "app/workspace.h"

#include "core/plots/fit.h"
#include "core/scene/preset_choices.h"

#include <chrono>
#include <cstdio>

namespace lab {

bool Workspace::runFit(const Request& r) {
    FitRequest request;
    switch (r.command) {
    case Command::FitPhong: request.brdf = BrdfModel::Phong; break;
    case Command::FitBlinnPhong: request.brdf = BrdfModel::BlinnPhong; break;
    case Command::FitCookTorrance:
        request.brdf = BrdfModel::CookTorrance;
        request.distribution = r.index >= 0 && r.index < static_cast<int>(kDistributions.size())
                                   ? kDistributions[static_cast<std::size_t>(r.index)]
                               : doc_.preset.brdf == BrdfModel::CookTorrance ? doc_.preset.cookTorrance.distribution
                                                                             : Distribution::Beckmann;
        break;
    default: return false;
    }
    if (exercise_) { // B is the target there
        notes_.push_back("In an exercise B is the target: leave the exercise to fit a model");
        return true;
    }
    const auto start = std::chrono::steady_clock::now();
    std::string error;
    std::optional<FitResult> fit = fitSpecular(doc_.preset, request, error);
    if (!fit) {
        notes_.push_back("Cannot fit " + std::string(label(request.brdf)) + ": " + error);
        return true;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fit->fitted.camera = doc_.preset.camera;
    doc_.compare = fit->fitted;
    view.compare = true;
    view.editingB = false;
    fit_ = {packSurfaceUniforms(doc_.preset), doc_.compare,
            fit->modelText() + " fitted to A, error " + fit->errorText() + ": " + fit->parametersText()};
    char took[48];
    std::snprintf(took, sizeof took, " (%.2f s)", seconds);
    std::string bounds;
    for (const std::string& b : fit->boundsThatBind()) {
        bounds += "; " + b;
    }
    notes_.push_back("B: " + fit_.note + took + bounds);
    return true;
}

const std::string& Workspace::fitNote() {
    if (!fit_.note.empty() && (!view.compare || exercise_ || !(packSurfaceUniforms(doc_.preset) == fit_.a) ||
                               !(packSurfaceUniforms(doc_.compare) == packSurfaceUniforms(fit_.b)))) {
        fit_.note.clear(); // A or B changed since: the numbers no longer say what B is
    }
    return fit_.note;
}

} // namespace lab
