// viewport.h — the model's viewport's ImGui side: mouse gestures, light markers and the text drawn over it.
//
// viewportControls() edits the camera and the light positions of the preset it is given, in place,
// like the panel edits the rest (left drag orbits, right or middle drag pans, the wheel zooms, a drag on a
// light marker moves that light in the plane parallel to the image), and reports a click that
// did not move as a probe, and a drag that starts on the probe's marker as the pixels it passes. lightMarkers() draws the lights: numbered markers (at the view's edge
// for lights outside it), spot cones and directional lights' rays, clipped to the model's
// viewport. captionStrips() draws the header (file, shading, BRDF, view mode), the caption, the
// footer (toast, frame time) and the compare labels, each in its own strip beside the model
// (ui/layout.h placeText), and the probe's marker on the model, with the point's lobe in "plots at
// the probe" mode (ui/viewport/point_lobe.h). All of it goes under ImGui's
// windows and dialogs (the background draw list). ImGui only: the model's viewport itself is
// drawn by the renderer.
#pragma once

#include "core/plots/probe_lobe.h"
#include "core/scene/light_orbit.h"
#include "core/scene/preset.h"
#include "core/scene/view_mode.h"
#include "ui/layout.h"
#include "ui/viewport/view_legend.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lab::ui {

// What a gesture remembers between frames.
struct ViewportControls {
    enum class Drag { None, Orbit, Pan, Light, Probe, Wipe } drag = Drag::None;
    bool pressMoved = false;
    float pressX = 0, pressY = 0;
    int light = -1;  // the light being dragged
    int button = 0;  // the mouse button that started the drag
};

struct ViewportEvents {
    std::optional<Rect> probed;  // a click: the pixel is probeX/probeY in this rectangle
    float probeX = 0, probeY = 0; // window units
    bool probeDragged = false;    // ... not a click: the probe's marker dragged there (it stays put off the model)
    bool gesture = false;         // a drag is in progress (one undo step when it ends)
};

// `active` is where A is drawn (the whole view, or its half in compare mode); `whole` the view.
// `clicks` are the frame's left clicks as the platform queued them (window units): the first in
// `active`, away from ImGui's windows, is the probe. `motion`, while lights orbit
// (core/scene/light_orbit.h), is where they are shown: a marker is picked where it is shown, and a
// dragged one moves the preset's light by the inverse turn, so the shown light follows the mouse.
// `probePoint` is the probed point (world) while the probe is open: a left drag that starts on its
// marker moves the probe (the pixel under the pointer, each frame it moves) instead of orbiting.
// `wipeAt`, while the wipe is shown, is its divider (a share of `active`'s width): a left drag that
// starts on it moves it.
ViewportEvents viewportControls(Preset& scene, const Rect& active, const Rect& whole, ViewportControls& state,
                        const std::vector<std::pair<float, float>>& clicks, const LightMotion* motion = nullptr,
                        const glm::vec3* probePoint = nullptr, float* wipeAt = nullptr);

// Numbered markers at the point and spot lights (window units, named for the GUI tests), and
// with `shapes` the spot cones and the directional lights' rays; returns where the markers are
// (each with its number), which the presenter's equation leaves seen.
std::vector<Rect> lightMarkers(const Preset& scene, const Rect& r, int draggedLight, bool shapes);

struct CaptionStrips {
    std::string documentName;
    bool dirty = false;
    const Preset* a = nullptr;
    const Preset* b = nullptr; // compare mode's B, else nullptr
    ViewMode viewMode = ViewMode::Lit;
    std::optional<float> frameMs;              // what a frame costs while the model changes (app/frame_speed.h), if shown
    const char* toast = nullptr;               // a short message in the footer, else nullptr
    bool caption = false;                      // the preset's name and description beside the model
    std::optional<glm::vec3> probePoint;       // the probed point (world), marked while the probe is open
    const ProbeLobe* probeLobe = nullptr;      // plots at the probe: the point's lobe, drawn there
    std::optional<LegendModel> legend;         // a value view's legend (ui/viewport/view_legend.h), in its strip
    std::optional<float> wipeAt;               // the wipe's divider, while the wipe is on
    bool exercise = false;                     // compare mode's halves are an exercise's attempt and target: their labels say so, not the target's settings
    bool wipeDragged = false;
    std::string fitNote;                       // B is a fit of A (app/workspace.h fitNote): B's label says so
    std::string labelA, labelB;                // compare mode: the fields that differ, each set's value
                                               // (core/exercise/preset_fields.h differenceLabels); empty: the summary
    std::string edited;                        // the caption's "(edited: shininess n, shading)"; empty when as opened
};

// What the caption strips' text needs, measured with the current font: placeText (ui/layout.h) gives
// each piece its place around the model's viewport.
TextRoom measureText(const CaptionStrips& model, const Rect& view);

// The text in the places placeText gave it, on strips of their own, and the probe's marker (and
// lobe) on the model. Nothing of it is drawn over the model's viewport but those.
void captionStrips(const CaptionStrips& model, const Layout& layout);

} // namespace lab::ui
