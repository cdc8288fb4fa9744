// pixel_probe.h — the pixel probe as the app keeps it from frame to frame.
//
// A click on the model probes its pixel (core/lighting/probe.h); a click beside it closes the
// probe. A drag that starts on the probe's marker moves it: the pixel under the pointer is probed
// again each frame, and where the pointer leaves the model the probe stays where it last was. With
// "plots at the probe" on (DisplaySettings::plotsAtProbe) the probed point is followed: evaluated
// again at the same point of the mesh for the scene as it is now shown (the camera orbited, a light
// moved or moving), and its lobe (core/plots/probe_lobe.h) made for the view's light, which the
// plots and the model's viewport then show. What it does not do: draw, or change the scene.
#pragma once

#include "core/lighting/probe.h"
#include "core/plots/probe_lobe.h"
#include "core/scene/view_mode.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>

namespace lab {

class PixelProbe {
public:
    // Probes the pixel at `ndc` (normalized device coordinates) of a view of aspect `aspect`
    // showing `shown` (the preset as the view shows it: its term view, its lights where their orbits
    // have them). `scene` is Workspace::scenesOpened(). A click that misses closes the probe and
    // returns the message to show; `dragged` (the marker dragged off the model) keeps it as it was.
    std::string probe(const Preset& shown, const Mesh& mesh, glm::vec2 ndc, float aspect, bool dragged, unsigned scene);

    // Once a frame, after the frame's edits: forgets a probe of an earlier scene and, with plots
    // at the probe on and the probe open, follows the point in `shown` and makes its lobe. True
    // when what the plots or the viewport show of it changed: the frame drawn before did not show it.
    bool follow(const Preset& shown, const DisplaySettings& view, unsigned scene);

    const ProbeResult* result() const { return result_ ? &*result_ : nullptr; }
    bool& open() { return open_; }
    bool shown() const { return result_ && open_; }
    // The point's lobe while plots at the probe are on, the probe is open and its light is on.
    const ProbeLobe* lobe() const { return lobe_ ? &*lobe_ : nullptr; }

private:
    std::optional<ProbeResult> result_;
    bool open_ = false;
    unsigned scene_ = 0; // the scene the probe belongs to
    std::optional<ProbeLobe> lobe_;
};

} // namespace lab
