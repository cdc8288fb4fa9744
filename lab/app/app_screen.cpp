// app_screen.cpp — what one frame hands the UI: the screen's model, from the workspace and the
// app's own state (app_impl.h).
#include "app/app_impl.h"

#include "core/exercise/preset_fields.h"

namespace lab {

namespace {

// What the speaker's notes say of where the lecture is (ui/tools/notes.h).
ui::NotesModel notesModel(const Workspace& ws) {
    ui::NotesModel m;
    const int at = ws.currentSlide();
    if (at >= 0 && at < ws.slideCount()) {
        m.position = "Slide " + std::to_string(at + 1) + " of " + std::to_string(ws.slideCount()) + ": " + ws.slideName(at);
    } else {
        m.position = ws.document().displayName();
    }
    m.notes = ws.notes();
    m.next = ws.nextSlideTitle();
    m.clock = ui::wallClock();
    return m;
}

} // namespace

//----------------------------------------------------------------------------------------
// The UI's model and what comes back from it
//----------------------------------------------------------------------------------------

ui::ScreenModel App::Impl::screenModel() {
    Document& doc = workspace.document();
    ui::ScreenModel m;
    m.a = &workspace.a();
    m.b = workspace.view.compare ? &workspace.b() : nullptr;
    m.edited = &workspace.edited();
    m.view = &workspace.view;
    const std::string name = printable(doc.displayName(), true); // the file's name, shown in three places
    m.panelInfo = {workspace.slideNames(), workspace.currentSlide(), workspace.deck() ? workspace.deck()->title : "",
                   name, doc.dirty(), doc.canUndo(), doc.canRedo(), false, options.saveByDownload};
    m.panelInfo.exerciseFiles = &workspace.exerciseFiles();
    m.panelInfo.lightsPaused = orbits.paused();
    m.panel = &panel;
    m.plots = &plots;
    m.shaderEditor = &shaderEditor;
    m.sweep = &sweep;
    m.lightingSource = shaderSource("lighting.glsl");
    m.viewportControls = &viewportControls;
    m.probe = probe.result();
    m.probeOpen = &probe.open();
    m.probeLobe = probe.lobe();
    m.showHelp = &showHelp;
    m.problem = problem ? &*problem : nullptr;
    m.unsavedQuestion = workspace.question() ? &*workspace.question() : nullptr;
    m.captions = {name, doc.dirty(), m.a, m.b, workspace.view.mode, frameTimeShown() ? speed.shownMs(clock) : std::nullopt,
                 toastLeft > 0.0f ? toast.c_str() : nullptr, caption,
                 probe.shown() ? std::optional<glm::vec3>(probe.result()->positionWorld) : std::nullopt, probe.lobe(),
                 readout.legend(workspace.view, workspace.a(), renders[0].range()), std::nullopt, false, false,
                 workspace.fitNote(), {}, {}, {}};
    if (m.b && !workspace.exercise()) {
        const DifferenceLabels& labels = compareLabels.of(*m.a, *m.b, 3);
        m.captions.labelA = printable(labels.a, true);
        m.captions.labelB = printable(labels.b, true);
    }
    if (doc.edited() && !workspace.exercise()) {
        const DifferenceLabels& changed = editedLabels.of(doc.saved(), doc.preset, 2);
        m.captions.edited = changed.b.empty() ? std::string("set B") : printable(changed.b, true);
    }
    m.showNotes = &showNotes;
    m.equation = presenter; // the room reads the equation over the model
    m.pointer = pointer;
    if (showNotes || notesWindow) {
        m.notes = notesModel(workspace);
    }
    m.lightShapes = lightShapes;
    m.motion = anyOrbit(workspace.a()) ? &orbits.motion(0) : nullptr;
    if (const std::optional<ExerciseSession>& ex = workspace.exercise()) {
        exerciseView = exercisePanelModel(*ex, scorer.score());
        m.panelInfo.exercise = &exerciseView;
        m.captions.exercise = true;
    } else if (workspace.draft()) {
        draftView = draftPanelModel(workspace);
        m.panelInfo.draft = &draftView;
    }
    if (shareCode.shown) {
        m.shareCode = &shareCode.update(options.shareBase, workspace, static_cast<bool>(options.shareBaseChosen));
        if (std::string why = shareCode.newProblem(); !why.empty()) {
            news.say(std::move(why)); // in the page's message log too
        }
    }
    return m;
}

} // namespace lab
