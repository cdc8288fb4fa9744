// app_impl.h — the interactive lab's state between frames (App::Impl), shared by app.cpp (the
// frame) and app_screen.cpp (what the UI is handed). Private to lab/app.
#pragma once


#include "app/app.h"
#include "app/exercise_score.h"
#include "app/shader_compile.h"
#include "app/share_code.h"
#include "app/figure_export.h"
#include "app/frame_speed.h"
#include "app/orbit_clock.h"
#include "app/pixel_probe.h"
#include "app/sweep_image.h"
#include "app/value_readout.h"
#include "app/viewport_cache.h"
#include "core/exercise/preset_fields.h"
#include "core/gltf/model_loader.h"
#include "core/io/file_io.h"
#include "core/io/paths.h"
#include "core/io/safe_text.h"
#include "core/scene/light_orbit.h"
#include "core/share/share_link.h"
#include "render/renderer.h"
#include "render/shader.h"
#include "ui/dialogs.h"
#include "ui/screen.h"
#include "ui/viewport/overlay.h"
#include "ui/widget_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

namespace lab {

namespace app_detail {

constexpr float kMinPresenterScale = 1.5f, kMaxPresenterScale = 2.5f, kPresenterStep = 0.25f;
constexpr float kToastSeconds = 4.0f;
constexpr float kTouchScale = 1.2f; // a finger's UI: larger text as well as larger widgets
const glm::vec3 kScreenshotBackground(0.09f, 0.09f, 0.11f); // between compare's halves: a model render, never themed

} // namespace app_detail
using namespace app_detail;

// differenceLabels() of the last two scenes it was asked about: the captions' labels are the same
// through the frames of a drag that changes neither field (a camera's, a light's marker).
struct LabelMemo {
    const DifferenceLabels& of(const Preset& a, const Preset& b, std::size_t most) {
        if (!valid || most != mostShown || !(a == sceneA) || !(b == sceneB)) {
            labels = differenceLabels(a, b, most);
            sceneA = a;
            sceneB = b;
            mostShown = most;
            valid = true;
        }
        return labels;
    }
    Preset sceneA, sceneB;
    std::size_t mostShown = 0;
    DifferenceLabels labels;
    bool valid = false;
};

struct App::Impl {
    AppOptions options;
    Workspace workspace;
    Renderer renderer;

    // The UI's own state: what the panels, tools and gestures remember between frames.
    ui::PanelState panel;
    ui::PlotSettings plots;
    ui::ShaderEditorState shaderEditor;
    ui::SweepViewState sweep;
    SweepImage sweepImage; // the sweep view's grid, rendered only while it is open
    ui::ViewportControls viewportControls;
    enum class Panels { All, PlotsOnly, None } panels = Panels::All; // Tab cycles
    bool showHelp = false, presenter = false, caption = false, lightShapes = true, showNotes = false, pointer = false;
    bool notesWindow = false;
    LabelMemo compareLabels, editedLabels; // the captions' A and B labels, the header's "edited: ..." // the speaker's notes in a window of their own (AppOptions::notesWindows)
    Theme theme = Theme::Dark; // the last frame's (the panel's radio buttons change panel.theme)
    bool themeChosen = false;  // by the user, in the panel
    // The frame time while the model changes, outside and in presenter mode (T toggles the one in use):
    // the room sees the model, not the lab's timings, unless asked.
    bool frameTime = true, frameTimePresenting = false;
    bool& frameTimeShown() { return presenter ? frameTimePresenting : frameTime; }
    float presenterScale = 1.75f;
    std::optional<InputEvent> pressed; // a left press whose release has not come yet
    PixelProbe probe; // the last probe, its window, and plots at the probe (app/pixel_probe.h)
    std::optional<Problem> problem;
    std::string toast;
    float toastLeft = 0.0f;
    PageNews news; // every toast and refused field edit since the page's last description
    void show(std::string text) {
        toast = std::move(text);
        toastLeft = kToastSeconds;
        news.say(toast);
    }
    FrameSpeed speed;       // the frame time shown while the model changes
    double clock = 0.0;     // seconds since the first frame (the sum of the frames' deltaTime)
    bool interacting = false;   // the last frame belonged to an interaction (a gesture, a moving light)
    bool viewportDrawn = false; // by the last frame
    bool started = false;   // the workspace opened its first preset (in the first frame, App::frame)
    std::array<CachedViewport, 2> renders; // A's and B's, kept between frames
    ValueReadout readout;                  // a value view's legend: A's range, the value under the pointer
    ViewportResolution resolution;
    int viewportSamples = 0;     // what the GL offers of AppOptions::viewportSamples
    unsigned long long frames = 0;
    bool screenshotRequested = false, toggleFullscreen = false, pickFile = false, copyLink = false;

    OrbitClock orbits{options.reducedMotion}; // the moving lights (app/orbit_clock.h)

    // Exercises: the live score, what the panel shows of the exercise and of a draft (app/exercise_score.h).
    ExerciseScorer scorer;
    PageModel page; // the browser page's parallel DOM (FrameInput::describePage)
    ui::ExercisePanelModel exerciseView;
    ui::DraftPanelModel draftView;
    ShareCode shareCode; // the scene's link as a QR code (Q)
    unsigned exerciseShown = 0; // the last exercise whose section the panel was turned to
    unsigned plotsOpenedFor = 0; // the last scene opened (Workspace::scenesOpened) whose display.plots was applied

    // A side of the comparison as this frame shows it: A, and B in compare mode.
    struct ShownSide {
        std::size_t index;                // 0: A, 1: B
        Preset shown;                     // the preset with its lights where their orbits have them
        std::shared_ptr<const Mesh> mesh; // null while its model does not load
        ui::Rect rect;                    // where it goes in the window
    };
    std::vector<ShownSide> sides(const ui::Layout& layout, bool orbiting);

    explicit Impl(AppOptions o)
        : options(std::move(o)),
          workspace({options.presetFolders, options.screenshotFolder, options.saveByDownload,
                     options.userFolder.empty() ? defaultUserFolder() : options.userFolder}),
          presenter(options.presenter), caption(options.presenter) {
        panel.theme = theme = options.theme.value_or(Theme::Dark);
    }

    float windowWidth = 0; // the last frame's, in window units

    // Presenter mode shows the caption, and on a screen narrower than 1600 units it starts with
    // the control panel hidden (Tab brings it back): at a projector's 1024 the large panel
    // would squeeze the model.
    void setPresenter(bool on) {
        presenter = on;
        caption = on;
        if (on && windowWidth < 1600.0f && panels == Panels::All) {
            panels = Panels::PlotsOnly;
        } else if (!on && panels == Panels::PlotsOnly) {
            panels = Panels::All;
        }
    }

    ui::ScreenModel screenModel();
    PageFacts pageTools() { return openTools(shaderEditor, sweep); }
    void carryOut(const FrameInput& in, const ui::ScreenEvents& events);
    void carryOut(const Request& request);
    void probeAt(const ui::ViewportEvents& viewport);
    void collectMessages(float deltaTime);
    FrameOutput output(bool touch, const ui::ScreenModel& drawn, bool describe);
    void drawViewports(const ui::Layout& layout, float toPixels, float windowHeight, float dx, float dy);
    bool updateViewports(const ui::Layout& layout, const FrameInput& in, float scale);
    std::vector<std::pair<const CachedViewport*, Viewport>> shown; // this frame's renders and where they go
    void screenshot(const ui::Layout& layout, const FrameInput& in, const ui::ScreenEvents& events);
    bool updateReadout(const FrameInput& in, const ui::ScreenEvents& events, const std::optional<ui::LegendModel>& shownLegend);
    void timeLastFrame(const FrameInput& in);
    std::map<int, float> captionHeights; // the caption's tallest strip at each width, while the view keeps its size
    std::array<float, 3> captionView{};  // that size and the font's
    ui::TextRoom steadyCaption(ui::TextRoom room, const ui::Rect& view);
    float textGoesIn() const;
    void writeLayoutFile(const FrameInput& in, bool settled);
};

} // namespace lab
