// app.cpp — one frame: layout, UI, requests carried out, one undo step, the model's viewport.
#include "app/app.h"
#include "app/app_impl.h"

namespace lab {

namespace fs = std::filesystem;

// What the platform and the UI asked for this frame, in order, then one undo step if a gesture ended.
void App::Impl::carryOut(const FrameInput& in, const ui::ScreenEvents& events) {
    workspace.resumeWaiting(); // an open that waited for a file of the page's site
    for (const std::string& note : in.notes) {
        workspace.note(note);
    }
    if (!in.droppedFiles.empty()) {
        workspace.drop(in.droppedFiles);
    }
    if (in.openLink && !in.openLink->empty()) {
        workspace.openLink(*in.openLink, in.openLinkSaved);
    }
    if (in.closeRequested) {
        workspace.requestQuit();
    }
    if (in.notesWindowClosed) {
        notesWindow = false;
    }
    for (const Request& r : events.requests) {
        carryOut(r);
    }
    if (events.problemClosed) {
        problem.reset();
    }
    if (events.answer) {
        workspace.answer(*events.answer);
    }
    if (events.viewport.probed) {
        probeAt(events.viewport);
    }
    collectMessages(in.deltaTime);
    workspace.endFrame(events.gesture);
    // A newly opened exercise shows its section: on a phone's tabs, one of the panel's, not the plots.
    if (const std::optional<ExerciseSession>& ex = workspace.exercise(); ex && ex->opened != exerciseShown) {
        exerciseShown = ex->opened;
        panel.tab = panel.tab == ui::PanelTab::Plots ? ui::PanelTab::Material : panel.tab;
    }
    // A preset or a slide whose display names the plots' tab opens on it; one that names none leaves it.
    if (workspace.scenesOpened() != plotsOpenedFor) {
        plotsOpenedFor = workspace.scenesOpened();
        if (std::optional<ui::PlotTab> tab = ui::plotTabNamed(workspace.openedDisplay().plots)) {
            plots.view = *tab;
        }
    }
}

// The window's own commands; everything else goes to the workspace.
void App::Impl::carryOut(const Request& r) {
    switch (r.command) {
    case Command::ToggleHelp: showHelp = !showHelp; break;
    case Command::CloseHelp: showHelp = false; break;
    case Command::TogglePanels:
        panels = panels == Panels::All ? Panels::PlotsOnly : panels == Panels::PlotsOnly ? Panels::None : Panels::All;
        break;
    case Command::TogglePresenter: setPresenter(!presenter); break;
    case Command::ToggleCaption: caption = !caption; break;
    case Command::ToggleLightShapes: lightShapes = !lightShapes; break;
    case Command::ToggleLightMotion: orbits.togglePaused(); break;
    case Command::ToggleNotes: showNotes = !showNotes; break;
    case Command::NotesWindow:
        if (options.notesWindows) {
            notesWindow = !notesWindow;
            showNotes = showNotes && !notesWindow; // not twice: the room sees the strip
        } else {
            showNotes = !showNotes;
        }
        break;
    case Command::TogglePointer: pointer = !pointer; break;
    case Command::AnswerSaveFirst: workspace.answer(UnsavedAnswer::SaveFirst); break;
    case Command::AnswerDiscard: workspace.answer(UnsavedAnswer::Discard); break;
    case Command::AnswerCancel: workspace.answer(UnsavedAnswer::Cancel); break;
    case Command::CloseProblem: problem.reset(); break;
    case Command::ToggleFrameTime: frameTimeShown() = !frameTimeShown(); break;
    case Command::PresenterLarger:
        if (!presenter) {
            setPresenter(true);
        }
        presenterScale = std::min(kMaxPresenterScale, presenterScale + kPresenterStep);
        break;
    case Command::PresenterSmaller: presenterScale = std::max(kMinPresenterScale, presenterScale - kPresenterStep); break;
    case Command::ToggleFullscreen: toggleFullscreen = true; break;
    case Command::Screenshot: screenshotRequested = true; break;
    case Command::ExportFigures:
        workspace.saveFiles(exportFigures(workspace.a(), workspace.view.compare ? &workspace.b() : nullptr, plots,
                                          panel.figureScale, theme),
                            "Figures");
        break;
    case Command::FocusOpenPath: panel.focusOpenPath = true; break;
    case Command::PickFile: pickFile = true; break;
    case Command::CopyLink: copyLink = workspace.linkShareable(); break; // the page says whether the browser allowed it
    case Command::ToggleShareCode:
        shareCode.shown = !shareCode.shown;
        shareCode.address = options.shareBase;
        shareCode.addressProblem.clear();
        break;
    case Command::SetShareBase:
        shareCode.addressProblem = shareBaseProblem(r.path);
        if (shareCode.addressProblem.empty() && r.path != options.shareBase) {
            options.shareBase = r.path; // the code is made again for it (ShareCode::update)
            if (options.shareBaseChosen) {
                options.shareBaseChosen(r.path);
            }
        }
        break;
    case Command::ToggleShaderEditor: shaderEditor.open = !shaderEditor.open; break;
    case Command::CompileShaders:
        if (shaderEditor.open) {
            compileShaders(renderer, shaderEditor, false);
        }
        break;
    case Command::RevertShaders: compileShaders(renderer, shaderEditor, true); break;
    case Command::ToggleSweep: sweep.open = !sweep.open; break;
    case Command::SaveSweep:
        if (sweepImage.image()) {
            workspace.saveScreenshot(*sweepImage.image(), "-sweep", "Sweep");
        }
        break;
    default: workspace.run(r); break;
    }
}

// A click probes its pixel; a drag of the probe's marker probes the pixel under the pointer.
void App::Impl::probeAt(const ui::ViewportEvents& viewport) {
    const ui::Rect& r = *viewport.probed;
    std::shared_ptr<const Mesh> mesh = workspace.mesh(Side::A);
    if (!mesh) {
        return;
    }
    glm::vec2 ndc(2.0f * (viewport.probeX - r.x) / r.w - 1.0f, 1.0f - 2.0f * (viewport.probeY - r.y) / r.h);
    Preset scene = orbits.shown(workspace.a(), 0); // the light where it is shown
    std::string missed = probe.probe(viewed(scene, workspace.view.mode), *mesh, ndc, r.w / r.h,
                                     viewport.probeDragged, workspace.scenesOpened());
    if (!missed.empty()) {
        show(missed);
    }
}

// The workspace's problems become the error dialog (the latest one), its notes the toast.
void App::Impl::collectMessages(float deltaTime) {
    toastLeft -= deltaTime;
    std::vector<std::string> notes = workspace.takeNotes();
    for (const std::string& note : notes) {
        show(printable(note, true));
    }
    std::vector<Problem> problems = workspace.takeProblems();
    if (!problems.empty()) {
        problem = std::move(problems.back());
    }
}

//----------------------------------------------------------------------------------------
// The model's viewport
//----------------------------------------------------------------------------------------

// A, and B in compare mode: what each shows (`orbiting`: with its lights where the orbits have
// them) and where.
std::vector<App::Impl::ShownSide> App::Impl::sides(const ui::Layout& layout, bool orbiting) {
    std::vector<ShownSide> out;
    for (Side side : kSides) {
        if (side == Side::B && !workspace.view.compare) {
            break;
        }
        const std::size_t i = indexOf(side);
        const Preset& preset = workspace.preset(side);
        out.push_back({i, orbiting ? orbits.shown(preset, i) : preset, workspace.mesh(side),
                       layout.viewportOf(static_cast<int>(i), workspace.view.compare)});
    }
    return out;
}

namespace {

// A window rectangle (window units, y down) as a GL viewport (pixels, y up) of a framebuffer
// `windowHeight` units high, shifted by (dx, dy) units.
Viewport toViewport(const ui::Rect& r, float toPixels, float windowHeight, float dx = 0.0f, float dy = 0.0f) {
    return Viewport{static_cast<int>((r.x + dx) * toPixels), static_cast<int>((windowHeight - (r.y + dy + r.h)) * toPixels),
                    std::max(1, static_cast<int>(r.w * toPixels)), std::max(1, static_cast<int>(r.h * toPixels))};
}

} // namespace

// Draws A (and B in compare mode) as the document has them at the layout's rectangles, shifted
// by (dx, dy) window units, into a framebuffer whose height is `windowHeight` window units.
void App::Impl::drawViewports(const ui::Layout& layout, float toPixels, float windowHeight, float dx, float dy) {
    const DisplaySettings& view = workspace.view;
    for (const ShownSide& side : sides(layout, false)) {
        if (side.mesh) {
            drawView(renderer, side.shown, side.mesh, toViewport(side.rect, toPixels, windowHeight, dx, dy),
                     viewDraw(view));
        }
    }
}

// The live frame's renders, with the lights where their orbits have them: each drawn into its
// offscreen copy when what it shows changed (at `scale` of its size while dragging); where they
// go in the window is kept for compose(). True when any was drawn.
bool App::Impl::updateViewports(const ui::Layout& layout, const FrameInput& in, float scale) {
    float toPixels = static_cast<float>(in.framebufferWidth) / in.windowWidth;
    const DisplaySettings& view = workspace.view;
    shown.clear();
    bool drawn = false;
    std::vector<ShownSide> live = sides(layout, true);
    for (ShownSide& side : live) {
        Viewport dest = toViewport(side.rect, toPixels, in.windowHeight);
        ViewportKey key{side.shown, std::move(side.mesh), std::max(1, static_cast<int>(std::lround(dest.width * scale))),
                        std::max(1, static_cast<int>(std::lround(dest.height * scale))), viewDraw(view),
                        renderer.generation()};
        shown.emplace_back(&renders[side.index], dest);
        drawn = renders[side.index].update(renderer, key, dest, viewportSamples) || drawn;
    }
    if (live.size() < renders.size()) {
        renders[1].reset(); // its memory back; compare mode draws it again
    }
    return drawn;
}

// After the renders: the value under the pointer (app/value_readout.h). True when the legend this
// frame showed (`shownLegend`, made before the render) is owed a frame: the range or value changed.
bool App::Impl::updateReadout(const FrameInput& in, const ui::ScreenEvents& events,
                              const std::optional<ui::LegendModel>& shownLegend) {
    if (!shown.empty()) {
        readout.update(renderer, renders[0], shown[0].second, static_cast<float>(in.framebufferWidth) / in.windowWidth,
                       in.windowHeight, events.pointerX, events.pointerY, workspace.view);
    }
    bool rangeChanged = shownLegend && shownLegend->note.empty() && shownLegend->range != renders[0].range();
    return readout.takeChanged() || rangeChanged;
}

// The model's viewport alone, at the window's pixel density, to a PNG (a download in the browser).
void App::Impl::screenshot(const ui::Layout& layout, const FrameInput& in, const ui::ScreenEvents& events) {
    const ui::Rect& v = layout.viewport;
    float toPixels = static_cast<float>(in.framebufferWidth) / in.windowWidth;
    int w = std::max(1, static_cast<int>(v.w * toPixels)), h = std::max(1, static_cast<int>(v.h * toPixels));
    Framebuffer target(w, h);
    if (!target.complete()) {
        problem = Problem{"Screenshot failed", {{"", "", "cannot create a " + std::to_string(w) + "x" + std::to_string(h) + " framebuffer"}}};
        return;
    }
    target.bind();
    clearFramebuffer(kScreenshotBackground, w, h); // (in compare mode the halves' label strips lie between the models)
    drawViewports(layout, toPixels, static_cast<float>(h) / toPixels, -v.x, -v.y);
    Image image = target.readRgb();
    bindFramebuffer(in.targetFramebuffer);
    if (pointer && v.contains(events.pointerX, events.pointerY)) { // what the room saw
        ui::pointerRing(image, (events.pointerX - v.x) * toPixels, (events.pointerY - v.y) * toPixels, ui::pointerRadius() * toPixels);
    }
    workspace.saveScreenshot(image);
}

// GUI tests: every widget's rectangle, the window, a frame counter, whether more frames are due
// without input (a test waits until the lab has settled), and what the last frame cost.
void App::Impl::writeLayoutFile(const FrameInput& in, bool settled) {
    std::string layout = ui::widgets().text();
    char window[128];
    std::snprintf(window, sizeof window, "window 0 0 %.0f %.0f\nframe %llu\nsettled %d\nlast-frame-ms %.1f\n", in.windowWidth,
                  in.windowHeight, ++frames, settled ? 1 : 0, in.lastFrameSeconds * 1000.0f);
    layout += window;
    std::string error;
    writeFileAtomic(*options.layoutFile, layout, error, WriteSafety::Renewable); // made again every frame
}

// The clock, and the last frame's cost if it drew the model while something changed it (a frame
// that only redrew the UI would show the UI's; the first frames, the start-up's, are not counted).
void App::Impl::timeLastFrame(const FrameInput& in) {
    clock += in.deltaTime;
    if (viewportDrawn && interacting) {
        speed.interactionFrame(clock, in.lastFrameSeconds);
    }
}

// The caption's strip only grows while the view and the font keep their sizes: stepping through
// the presets in presenter mode, the model stays where it is, whatever each caption's length.
ui::TextRoom App::Impl::steadyCaption(ui::TextRoom room, const ui::Rect& view) {
    std::array<float, 3> now{view.w, view.h, ui::uiScale()};
    if (now != captionView) {
        captionHeights.clear();
        captionView = now;
    }
    if (room.captionHeight) {
        room.captionHeight = [measure = std::move(room.captionHeight), this](float width) {
            float& tallest = captionHeights[static_cast<int>(width)];
            tallest = std::max(tallest, measure(width));
            return tallest;
        };
    }
    return room;
}

// When text of the view goes away by itself (the toast, then the frame time): a frame is owed
// then. < 0: none.
float App::Impl::textGoesIn() const {
    float toastGoes = toastLeft > 0.0f ? toastLeft : -1.0f;
    float timeGoes = interacting ? -1.0f : speed.hidesIn(clock);
    return timeGoes >= 0.0f && (toastGoes < 0.0f || timeGoes < toastGoes) ? timeGoes : toastGoes;
}

//----------------------------------------------------------------------------------------
// App
//----------------------------------------------------------------------------------------

App::App(AppOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}

App::~App() = default;

bool App::init(Diagnostics& diagnostics) {
    Impl& m = *impl_;
    if (!m.renderer.init(diagnostics)) {
        return false;
    }
    StageSources builtin = builtinStageSources();
    m.shaderEditor.vertex = builtin.vertex;
    m.shaderEditor.fragment = builtin.fragment;
    m.shaderEditor.lighting = builtin.lighting;
    m.viewportSamples = supportedSamples(m.options.viewportSamples);
    return true;
}

FrameOutput App::frame(const FrameInput& in) {
    Impl& m = *impl_;
    ui::widgets().clear();
    if (m.windowWidth == 0.0f && m.presenter) {
        m.windowWidth = in.windowWidth;
        m.setPresenter(true); // --presenter: as if P had been pressed in this window
    }
    m.windowWidth = in.windowWidth;
    m.timeLastFrame(in);
    Workspace& ws = m.workspace;

    //--- layout -> UI -> requests ---------------------------------------------------------
    ui::Layout layout = ui::computeLayout({in.windowWidth, in.windowHeight, ui::uiScale(), m.panels == Impl::Panels::All,
                                           m.panels != Impl::Panels::None, m.panel.tab});
    if (!m.started) {
        ws.start(absolutePath("").value_or(fs::path()), m.options.preset); // the first preset opens in the first frame
        m.started = true;
    }
    // The page's controls go first: this frame's panel shows their values.
    std::vector<Request> pageRequests = takePageInput(ws, in.pageEdits, in.pageFocus, m.pageTools(), m.panel, m.news);
    ui::ScreenModel model = m.screenModel();
    ui::placeText(layout, m.steadyCaption(ui::measureText(model.captions, layout.view), layout.view)); // beside the model, never over it
    model.clicks = clicksOf(in.events, m.pressed);
    model.panelInfo.compareStacked = layout.compareStacked;
    ui::ScreenEvents events = ui::drawScreen(layout, model);
    if (std::exchange(m.theme, m.panel.theme) != m.panel.theme) { // chosen in the panel
        m.themeChosen = true;
        if (m.options.themeChosen) {
            m.options.themeChosen(m.theme);
        }
    }
    m.panel.focusOpenPath = false;
    for (const InputEvent& k : in.events) {
        if (k.kind != InputEvent::Kind::Key || !k.down) {
            continue;
        }
        if (std::optional<Command> c = commandForKey(k.code, k.modifiers, in.keys)) {
            events.requests.push_back({*c, *c == Command::SaveAs || *c == Command::Save ? m.panel.saveAsPath : ""});
        }
    }
    events.requests.insert(events.requests.end(), pageRequests.begin(), pageRequests.end());

    //--- carried out: platform events, the UI's requests, the dialogs' answers ----------------
    m.carryOut(in, events);

    // The moving lights turn by this frame's time, unless the user is dragging or editing anything.
    bool orbiting = m.orbits.advance({&ws.a(), ws.mesh(Side::A)},
                                     {ws.view.compare ? &ws.b() : nullptr, ws.view.compare ? ws.mesh(Side::B) : nullptr},
                                     ws.scenesOpened(), in.deltaTime, events.gesture || events.dragging);
    // Plots at the probe follow the point; what the UI drawn this frame did not show yet is owed a frame.
    bool probeMoved = m.probe.follow(viewed(m.orbits.shown(ws.a(), 0), ws.view.mode), ws.view, ws.scenesOpened());

    //--- the renderer draws what the workspace holds ---------------------------------------
    if (std::exchange(m.screenshotRequested, false)) {
        m.screenshot(layout, in, events);
    }
    // A moving light is drawn within the frame budget as a drag is (ViewportResolution).
    float scale = m.resolution.update(events.dragging || orbiting, in.lastFrameSeconds, m.options.frameBudgetSeconds);
    m.viewportDrawn = m.updateViewports(layout, in, scale);
    bool legendOwed = m.updateReadout(in, events, model.captions.legend);
    bool sweepDrawn = m.sweepImage.update(m.sweep, m.renderer, ws.a(), ws.document().file(), ws.mesh(Side::A), events.dragging);
    bool scoreOwed = m.scorer.update(m.renderer, ws, events.gesture || events.dragging, m.clock, in.targetFramebuffer);
    bindFramebuffer(in.targetFramebuffer);
    // Owed a frame: a toast whose time is up, a lagging plots readout (ui/plots/plot_cache.h), the legend, the
    // score. A reduced view is drawn full by the frame that ends the motion; nothing else changes by itself.
    m.interacting = events.gesture || events.dragging || orbiting;
    bool owed = sweepDrawn || legendOwed || scoreOwed || (layout.plots.w > 0 && m.plots.cache.owed());
    float redrawIn = m.orbits.redrawIn(owed || (probeMoved && !orbiting) ? 0.0f : m.textGoesIn(),
                                       orbiting, in.deltaTime);
    if (m.options.layoutFile) {
        m.writeLayoutFile(in, in.framesDue == 0 && redrawIn != 0.0f);
    }

    // The page's description waits while a value is dragged: the frame after describes the state.
    FrameOutput out = m.output(in.touch, model, in.describePage && !events.gesture && !events.dragging);
    out.typing = events.typing;
    out.viewportScale = scale;
    out.redrawIn = redrawIn;
    return out;
}

// What the frame hands the platform: the window's title, the scene's link, files, requests.
FrameOutput App::Impl::output(bool touch, const ui::ScreenModel& drawn, bool describe) {
    FrameOutput out;
    out.quit = workspace.quit();
    out.link = workspace.link();
    out.problem = problem ? printable(toString(*problem)) : std::string();
    out.exerciseScore = workspace.exercise() ? exerciseScoreLine(scorer.score()) : std::string();
    out.movingLights = orbits.moving(workspace.a());
    out.downloads = workspace.takeDownloads();
    out.uiScale = presenter ? presenterScale : touch ? kTouchScale : 1.0f;
    out.touch = touch;
    out.title = "Lighting Lab - " + printable(workspace.document().displayName(), true) +
                (workspace.document().dirty() ? " *" : "");
    out.toggleFullscreen = std::exchange(toggleFullscreen, false);
    out.pickFile = std::exchange(pickFile, false);
    out.copyLink = std::exchange(copyLink, false);
    out.viewportDrawn = viewportDrawn;
    out.pageDescribed = describe;
    if (notesWindow) {
        out.notesWindow = drawn.notes;
    }
    if (describe) {
        PageFacts tools = pageTools();
        const std::optional<std::string>& q = workspace.question();
        out.page = page.json(workspace, {workspace.exercise() ? &exerciseView : nullptr, out.problem,
                                         q ? ui::unsavedQuestionText(drawn.captions.documentName, *q) : std::string(),
                                         probeWords(probe.shown() ? probe.result() : nullptr),
                                         legendWords(drawn.captions.legend), out.movingLights, toString(theme),
                                         drawn.shareCode, tools.shader, tools.sweep, std::exchange(news, {}),
                                         showNotes ? &drawn.notes : nullptr});
    }
    return out;
}

Theme App::theme() const { return impl_->theme; }
void App::setTheme(Theme theme) { impl_->panel.theme = impl_->theme = theme; }
bool App::themeChosen() const { return impl_->themeChosen; }

void App::compose(unsigned targetFramebuffer, int width, int height) {
    bindFramebuffer(targetFramebuffer);
    const FigureColor w = themeColors(impl_->theme).ui.window; // between the windows, as on them
    clearFramebuffer(glm::vec3(w.r, w.g, w.b) / 255.0f, width, height);
    for (const auto& [view, dest] : impl_->shown) {
        view->present(targetFramebuffer, dest);
    }
}

} // namespace lab
