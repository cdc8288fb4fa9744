// pixel_probe.cpp — probing, moving and following the probed point.
#include "app/pixel_probe.h"

namespace lab {

namespace {

// What the screen shows of a probe: its point, its colour and the point's lobe. A follow that
// changes none of them owes no frame.
bool sameShown(const std::optional<ProbeResult>& a, const std::optional<ProbeResult>& b) {
    if (a.has_value() != b.has_value()) {
        return false;
    }
    return !a || (a->positionWorld == b->positionWorld && a->N == b->N && a->V == b->V && a->color == b->color);
}

} // namespace

std::string PixelProbe::probe(const Preset& shown, const Mesh& mesh, glm::vec2 ndc, float aspect, bool dragged,
                              unsigned scene) {
    std::optional<ProbeResult> hit = probePixel(shown, mesh, ndc, aspect);
    if (!hit && dragged) {
        return ""; // off the model's edge: the marker waits there for the pointer to come back
    }
    result_ = std::move(hit);
    open_ = result_.has_value(); // a click beside the model closes the probe
    scene_ = scene;
    lobe_.reset(); // follow() makes it again for the new point
    return result_ ? "" : "No surface under the mouse: the probe is closed";
}

bool PixelProbe::follow(const Preset& shown, const DisplaySettings& view, unsigned scene) {
    if (result_ && scene_ != scene) {
        result_.reset(); // it belonged to the scene before
    }
    std::optional<ProbeLobe> lobe;
    bool changed = false;
    if (view.plotsAtProbe && result_ && open_) {
        std::optional<ProbeResult> now = probeSurface(shown, result_->positionModel, result_->normalModel);
        changed = !sameShown(result_, now);
        result_ = std::move(now);
        lobe = probeLobe(*result_, shown, view.light);
    }
    changed = changed || lobe != lobe_;
    lobe_ = std::move(lobe);
    return changed;
}

} // namespace lab
