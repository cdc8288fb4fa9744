// web_window.cpp — the browser platform: Emscripten's GLFW on a WebGL2 canvas, Dear ImGui,
// and the page's glue (web/index.html).
//
// Implemented features:
//   * the loop is the browser's (emscripten_set_main_loop): an animation frame draws a frame
//     (imgui_host.h) only when one is due (app/frame_pacer.h: input, a resize, the app's timer)
//     and returns at once otherwise, so an idle page costs (close to) nothing;
//   * the canvas fills the page, follows resizes and renders at the device pixel ratio, while
//     ImGui works in CSS pixels (so the UI is sharp and the usual size on high-DPI screens);
//   * files dropped on the canvas or chosen in the page's file picker land in /presets (next to
//     the bundled presets, so a preset's relative model paths resolve) and go to the app as drops;
//   * downloads (presets, screenshots) become browser downloads;
//   * touch: the page hands every finger to the lab (lab_touch), which turns them into mouse
//     events (app/touch.h); on a touch screen the UI is touch-sized, and while a text field has
//     the keyboard the page focuses a hidden text input so that the screen's keyboard shows
//     (its text comes back through lab_text and lab_backspace);
//   * the mouse wheel in notches, as desktop GLFW gives it (up +1): the page reads the browser's
//     wheel event and hands it to lab_wheel (Debian's Emscripten 3.1.6 GLFW passes the raw deltaY:
//     reversed, 100 a notch; its listener never sees the event);
//   * "Copy link" puts the page's address, whose fragment is the scene, on the clipboard;
//   * the current scene is kept in the URL fragment (history.replaceState, a shareable link)
//     and in localStorage, so a reload restores it; a hashchange opens the new link. A fragment
//     longer than kMaxLinkChars is refused by the page before it reaches the lab (it says so), and
//     a scene whose link would be longer is kept in localStorage only;
//   * the error dialog's text is mirrored into the page (a live region), for screen readers;
//   * the lab describes itself for the page's parallel DOM (app/page_model.h, web/access.js):
//     native controls that a screen reader reads and the keyboard drives, whose edits, commands and
//     focus come back through lab_page_field, lab_page_command and lab_page_focus.
// Not here: anything about presets, rendering or the UI's content.
#include "platform/window.h"

#include "app/frame_pacer.h"
#include "app/touch.h"
#include "core/gltf/draco_decoder.h"
#include "core/io/site_files.h"
#include "core/share/qr_encoder.h"
#include "core/plots/theme.h"
#include "core/share/share_link.h" // kMaxLinkChars
#include "platform/imgui_glfw.h"
#include "platform/imgui_host.h"
#include "render/gl.h"
#include "ui/widget_map.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>

#include <cstdio>
#include <filesystem>

namespace lab {

namespace {

namespace fs = std::filesystem;

// clang-format off
// One download every 250 ms: Chromium drops anchor downloads past ten started at once, and an
// export hands over twelve files (four figures as SVG, PNG and CSV).
EM_JS(void, labJsDownload, (const char* name, const char* data, int size), {
    const bytes = HEAPU8.slice(data, data + size);
    const file = UTF8ToString(name);
    const types = {png: 'image/png', svg: 'image/svg+xml', csv: 'text/csv', json: 'application/json'};
    const type = types[file.slice(file.lastIndexOf('.') + 1)] || 'application/octet-stream';
    const queue = Module.labDownloads || (Module.labDownloads = []);
    queue.push({file: file, blob: new Blob([bytes], {type: type})});
    const next = () => {
        const d = queue.shift();
        if (!d) {
            Module.labDownloading = false;
            return;
        }
        const url = URL.createObjectURL(d.blob);
        const a = document.createElement('a');
        a.href = url;
        a.download = d.file;
        document.body.appendChild(a);
        a.click();
        a.remove();
        setTimeout(() => URL.revokeObjectURL(url), 1000);
        setTimeout(next, 250);
    };
    if (!Module.labDownloading) {
        Module.labDownloading = true;
        next();
    }
});

// The scene's link in the address bar and the saved state; one too long to be a link (`fits` 0) is
// kept in the saved state only, and the address loses its fragment (a reload then opens the saved
// state rather than an older link).
EM_JS(void, labJsSetLink, (const char* link, int fits), {
    const text = UTF8ToString(link);
    const address = fits ? "#" + text : location.pathname + location.search;
    if (fits ? location.hash.substring(1) !== text : location.hash !== "") {
        history.replaceState(null, "", address);
    }
    try { localStorage.setItem('lighting-lab/link', text); } catch (e) {}
});

// The link to open at start: the address's fragment, or else the saved state (then *saved = 1). A
// fragment longer than `limit` is refused here, before it is copied or decoded: the page says so
// and the lab opens its default scene. The page's hashchange handler keeps to the same limit.
EM_JS(char*, labJsInitialLink, (int limit, int* saved), {
    Module.labMaxLinkChars = limit;
    let text = location.hash.length > 1 ? location.hash.substring(1) : "";
    if (text.length > limit) {
        if (Module.labLinkRefused) Module.labLinkRefused(text.length, false);
        text = "";
    } else if (!text) {
        try { text = localStorage.getItem("lighting-lab/link") || ""; } catch (e) {}
        HEAP32[saved >> 2] = text ? 1 : 0;
    }
    return stringToNewUTF8(text);
});

// The error dialog's text ("" when it closes), mirrored into the page for screen readers and tests.
EM_JS(void, labJsProblem, (const char* text), {
    if (Module.labProblem) Module.labProblem(UTF8ToString(text));
});

// Whether the page takes the lab's descriptions (access.js registered Module.labPage; a page opened
// with window.labParallelDom = false, the benchmark's baseline, has none and is never described).
EM_JS(int, labJsTakesDescriptions, (), { return Module.labPage ? 1 : 0; });

// The lab described for the page's parallel DOM (web/access.js), when the description changed.
EM_JS(void, labJsPage, (const char* json), {
    if (Module.labPage) Module.labPage(UTF8ToString(json));
});

// How the page's controls send a field's new value (web/access.js): path and text as UTF-8 on the
// heap, each with its length (lab_page_field below). A ccall "string" would end both at a NUL, and
// copies them onto the stack, which a pasted megabyte overflows.
EM_JS(void, labJsFieldSender, (), {
    Module.labPageField = (path, text) => {
        const encoder = new TextEncoder(), p = encoder.encode(path), v = encoder.encode(text);
        const at = _malloc(p.length + v.length + 1);
        if (!at) return;
        HEAPU8.set(p, at);
        HEAPU8.set(v, at + p.length);
        _lab_page_field(at, p.length, at + p.length, v.length);
        _free(at);
    };
});

EM_JS(void, labJsPickFile, (), {
    const input = document.getElementById('file-input');
    if (input) input.click();
});

EM_JS(int, labJsCoarsePointer, (), {
    return matchMedia('(pointer: coarse)').matches ? 1 : 0;
});

EM_JS(void, labJsKeyboard, (int on), {
    if (Module.labKeyboard) Module.labKeyboard(on !== 0);
});

EM_JS(void, labJsCopyLink, (), {
    if (Module.labCopyLink) Module.labCopyLink(location.href);
});

// When start-up reached `what`, in ms from navigation (window.labTimes: the browser tests report them).
EM_JS(void, labJsMark, (const char* what), {
    (window.labTimes = window.labTimes || {})[UTF8ToString(what)] = performance.now();
});

EM_JS(void, labJsReady, (), {
    if (Module.onLabReady) Module.onLabReady();
});
// clang-format on

const std::vector<std::string> kFonts = {"/fonts/DejaVuSans-ui.ttf"}; // cut to the UI's glyphs (cmake/web.cmake)

struct WebState : PlatformInput {
    explicit WebState(const AppOptions& options) : app(options) {}
    App app;
    ImGuiHost host{kFonts, nullptr}; // no fallback: runLab checks the font is here
    GLFWwindow* window = nullptr;
    std::unique_ptr<GlfwBackend> backend;
    double last = 0.0;
    float lastCost = 0.0f;
    FramePacer pacer;
    TouchGestures touch;
    bool touchScreen = false; // a finger was seen, or the page's pointer is coarse
    bool typing = false;      // the screen's keyboard was asked for
    int canvasWidth = 0, canvasHeight = 0;
    std::string lastLink, lastTitle, lastProblem, lastPage;
    std::vector<PageEdit> pageEdits;       // from the page's own controls, for the next frame
    std::optional<std::string> pageFocus;  // the page's focused control, when it changed
    std::optional<std::string> pendingLink;
    std::vector<std::string> heldForDraco; // opened files that wait for the Draco decoder (lab_open_file)
    std::vector<std::string> notes;        // for the next frame's toast (FrameInput::notes)
    bool pendingLinkSaved = false; // pendingLink is the saved state, not an address
    int frames = 0;
    double describedAt = -1e9; // when the lab last described itself for the page (FrameInput::describePage)
    bool describeOwed = false; // the last frame drawn was not described: one is drawn when the interval is up
};

// The page's parallel DOM follows the lab at most this often (app/page_model.h): a drag's frames
// between two descriptions are not described, and the frame that ends it is, after this delay.
constexpr double kDescribeInterval = 0.2;

WebState* gState = nullptr;

// A file from outside (dropped or picked) moves next to the bundled presets.
std::string adopt(const std::string& path) {
    fs::path from(path);
    fs::path to = fs::path("/presets") / from.filename();
    std::error_code ec;
    for (int i = 2; fs::exists(to, ec) && !fs::equivalent(from, to, ec); ++i) {
        to = fs::path("/presets") / (from.stem().string() + "-" + std::to_string(i) + from.extension().string());
    }
    fs::rename(from, to, ec);
    return ec ? path : to.string();
}

// The canvas follows its CSS size at the device pixel ratio; true when it changed.
bool fitCanvas(WebState& s, double dpr) {
    double cssWidth = 0, cssHeight = 0;
    emscripten_get_element_css_size("#canvas", &cssWidth, &cssHeight);
    int pixelWidth = std::max(1, static_cast<int>(cssWidth * dpr + 0.5));
    int pixelHeight = std::max(1, static_cast<int>(cssHeight * dpr + 0.5));
    int currentW = 0, currentH = 0;
    emscripten_get_canvas_element_size("#canvas", &currentW, &currentH);
    if (currentW != pixelWidth || currentH != pixelHeight) {
        // Not glfwSetWindowSize: Emscripten's GLFW asks for fullscreen when the size equals the
        // screen's. ImGui's display size and scale are set below, so GLFW's idea does not matter.
        emscripten_set_canvas_element_size("#canvas", pixelWidth, pixelHeight);
    }
    bool changed = pixelWidth != s.canvasWidth || pixelHeight != s.canvasHeight;
    s.canvasWidth = pixelWidth;
    s.canvasHeight = pixelHeight;
    return changed;
}

// The frame's input in CSS pixels (the queued events are converted as they arrive: cursorScale).
FrameInput nextInput(WebState& s, double dpr) {
    FrameInput in;
    in.framebufferWidth = s.canvasWidth;
    in.framebufferHeight = s.canvasHeight;
    in.windowWidth = static_cast<float>(std::max(1.0, s.canvasWidth / dpr));
    in.windowHeight = static_cast<float>(std::max(1.0, s.canvasHeight / dpr));
    double now = glfwGetTime();
    in.deltaTime = static_cast<float>(std::max(now - s.last, 1e-4));
    in.lastFrameSeconds = s.lastCost;
    s.last = now;
    takeQueuedInput(s, in);
    for (std::string& f : in.droppedFiles) {
        f = adopt(f);
    }
    in.openLink = std::exchange(s.pendingLink, std::nullopt);
    in.openLinkSaved = std::exchange(s.pendingLinkSaved, false);
    in.touch = s.touchScreen;
    in.pageEdits = std::exchange(s.pageEdits, {});
    in.pageFocus = std::exchange(s.pageFocus, std::nullopt);
    in.notes = std::exchange(s.notes, {});
    return in;
}

// What the frame asks of the page: downloads, the file picker, the title, the link.
void deliver(WebState& s, const FrameOutput& out) {
    for (const Download& d : out.downloads) {
        labJsDownload(d.name.c_str(), d.bytes.data(), static_cast<int>(d.bytes.size()));
    }
    if (out.pickFile) {
        labJsPickFile();
    }
    if (out.copyLink) {
        labJsCopyLink();
    }
    if (s.touchScreen && out.typing != s.typing) {
        s.typing = out.typing;
        labJsKeyboard(out.typing ? 1 : 0);
    }
    if (out.title != s.lastTitle) {
        glfwSetWindowTitle(s.window, out.title.c_str()); // document.title
        s.lastTitle = out.title;
    }
    if (out.link != s.lastLink) {
        labJsSetLink(out.link.c_str(), out.link.size() <= kMaxLinkChars ? 1 : 0);
        s.lastLink = out.link;
    }
    if (!out.page.empty() && out.page != s.lastPage) {
        labJsPage(out.page.c_str());
        s.lastPage = out.page;
    }
    if (out.problem != s.lastProblem) {
        labJsProblem(out.problem.c_str());
        s.lastProblem = out.problem;
    }
}

// One animation frame: returns at once unless a frame is due.
void frame(void* arg) {
    WebState& s = *static_cast<WebState*>(arg);
    double dpr = emscripten_get_device_pixel_ratio();
    s.cursorScale = static_cast<float>(1.0 / dpr); // Emscripten's GLFW speaks canvas pixels, ImGui CSS pixels
    bool resized = fitCanvas(s, dpr); // always: it keeps the canvas at the page's size
    s.repaint = s.repaint || resized;
    if (resized || std::exchange(s.changed, false) || s.pendingLink) {
        s.pacer.input();
    }
    if (!s.pacer.due(glfwGetTime(), !s.queue.empty())) {
        return;
    }
    double start = glfwGetTime();
    FrameInput in = nextInput(s, dpr);
    in.framesDue = s.pacer.dueAfterThis(!s.queue.empty());
    const bool described = labJsTakesDescriptions() != 0;
    in.describePage = described && start - s.describedAt >= kDescribeInterval;
    FrameOutput out = s.host.frame(in, [&] {
        ImGui_ImplGlfw_NewFrame();
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(in.windowWidth, in.windowHeight);
        io.DisplayFramebufferScale = ImVec2(static_cast<float>(dpr), static_cast<float>(dpr));
        io.DeltaTime = in.deltaTime;
    });
    deliver(s, out);
    s.describeOwed = described && !out.pageDescribed;
    if (out.pageDescribed) {
        s.describedAt = start;
    } else if (described) { // a frame drawn when the interval is up describes what this one changed
        // (one that waited for a drag tries again an interval later, if no input comes first)
        double left = s.describedAt + kDescribeInterval - start;
        left = left > 0.0 ? left : kDescribeInterval;
        out.redrawIn = out.redrawIn < 0.0f ? static_cast<float>(left) : std::min(out.redrawIn, static_cast<float>(left));
    }
    s.lastCost = static_cast<float>(glfwGetTime() - start);
    s.pacer.drawn(glfwGetTime(), out.redrawIn, !s.queue.empty());
    if (++s.frames == 1) {
        glFinish(); // once: the mark is when the first frame's pixels are done, not when its commands were sent
        labJsMark("firstFrame");
    }
    if (s.frames == 2) {
        labJsReady(); // the page (and its tests) know the first frames are drawn
    }
}

} // namespace

// Called by the page: a file it wrote into the in-memory file system, or a new URL fragment.
extern "C" {
// A model that names KHR_draco_mesh_compression waits while the page fetches the Draco decoder
// (core/gltf/draco_decoder.h), with a message; it opens when the decoder is here, or is refused
// with the reason when it could not be loaded.
EMSCRIPTEN_KEEPALIVE void lab_open_file(const char* path) {
    if (!gState) {
        return;
    }
    if (dracoDecoderState() != ModuleState::Ready && mentionsDraco(path)) {
        gState->heldForDraco.push_back(path);
        loadDracoDecoder();
        gState->notes.push_back("Loading the Draco decoder to open " + fs::path(path).filename().string() + "…");
    } else {
        gState->queue.drop(path);
    }
    gState->changed = true;
}
// The Draco decoder's module is loaded (ok 1) or could not be (ok 0, why): the files held for it open.
EMSCRIPTEN_KEEPALIVE void lab_draco_loaded(int ok, const char* why) {
    dracoDecoderLoaded(ok != 0, why ? why : "");
    if (!gState) {
        return;
    }
    for (std::string& path : std::exchange(gState->heldForDraco, {})) {
        gState->queue.drop(std::move(path));
    }
    gState->changed = true;
}
// The QR encoder's module is loaded (ok 1) or could not be (ok 0, why): the QR code window shows
// the code, or why there is none.
EMSCRIPTEN_KEEPALIVE void lab_qr_loaded(int ok, const char* why) {
    qrEncoderLoaded(ok != 0, why ? why : "");
    if (gState) {
        gState->changed = true;
    }
}
// A file of the site the lab asked for (core/io/site_files.h: a bundled model) is in the file
// system (ok 1), or could not be fetched (ok 0, why): the open that waited for it goes on.
EMSCRIPTEN_KEEPALIVE void lab_site_file_fetched(const char* path, int ok, const char* why) {
    siteFileFetched(path, ok != 0, why ? why : "");
    if (gState) {
        gState->changed = true;
    }
}
// A finger (CSS pixels from the canvas's corner): phase 0 down, 1 moved, 2 up, 3 cancelled.
EMSCRIPTEN_KEEPALIVE void lab_touch(int phase, int id, float x, float y) {
    if (!gState) {
        return;
    }
    std::vector<InputEvent> events;
    if (phase == 0) {
        gState->touch.start(id, x, y, events);
    } else if (phase == 1) {
        gState->touch.move(id, x, y, events);
    } else if (phase == 2) {
        gState->touch.end(id, x, y, events);
    } else {
        gState->touch.cancel(id, events);
    }
    for (const InputEvent& e : events) {
        gState->queue.push(e);
    }
    gState->touchScreen = true;
    gState->changed = true;
}
// Text from the screen's keyboard (UTF-8), and its Backspace.
EMSCRIPTEN_KEEPALIVE void lab_text(const char* utf8) {
    if (!gState) {
        return;
    }
    const auto* p = reinterpret_cast<const unsigned char*>(utf8);
    while (*p) {
        unsigned c = *p++;
        int more = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
        c &= more == 3 ? 0x07u : more == 2 ? 0x0Fu : more == 1 ? 0x1Fu : 0x7Fu;
        for (; more > 0 && (*p & 0xC0) == 0x80; --more) {
            c = (c << 6) | (*p++ & 0x3Fu);
        }
        gState->queue.push(InputEvent::character(c));
    }
    gState->changed = true;
}
EMSCRIPTEN_KEEPALIVE void lab_backspace() {
    if (gState) {
        gState->queue.push(InputEvent::key(GLFW_KEY_BACKSPACE, true));
        gState->queue.push(InputEvent::key(GLFW_KEY_BACKSPACE, false));
        gState->changed = true;
    }
}
// A new fragment in the address bar (the page refuses one longer than kMaxLinkChars first).
EMSCRIPTEN_KEEPALIVE void lab_open_link(const char* link) {
    if (gState && gState->lastLink != link) {
        gState->pendingLink = std::string(link);
        gState->pendingLinkSaved = false;
    }
}
// The page refused a new fragment (too long): the address shows the scene's own link again.
EMSCRIPTEN_KEEPALIVE void lab_restore_link() {
    if (gState) {
        gState->lastLink.clear(); // delivered again by the next frame
        gState->changed = true;
    }
}
// One wheel event from the page, in notches, signed as desktop GLFW reports a mouse wheel (up positive).
EMSCRIPTEN_KEEPALIVE void lab_wheel(float dx, float dy) {
    if (gState) {
        gState->queue.push(InputEvent::scroll(dx, dy));
        gState->changed = true;
    }
}
// The page's own controls (web/access.js): a field's new value as text, a command with its
// argument (-1 none), the control that has the keyboard (a field's path, "" for none). A field's
// path and text come with their lengths in bytes: a NUL in either is part of it (and refused by the
// field's check, core/scene/field_edit.h), never the end of a shorter, valid one.
EMSCRIPTEN_KEEPALIVE void lab_page_field(const char* path, int pathBytes, const char* value, int valueBytes) {
    if (gState && path && value && pathBytes >= 0 && valueBytes >= 0) {
        gState->pageEdits.push_back({std::string(path, static_cast<std::size_t>(pathBytes)),
                                     std::string(value, static_cast<std::size_t>(valueBytes))});
        gState->changed = true;
    }
}
EMSCRIPTEN_KEEPALIVE void lab_page_command(int command, int index) {
    if (gState) {
        gState->pageEdits.push_back({{}, {}, command, index});
        gState->changed = true;
    }
}
EMSCRIPTEN_KEEPALIVE void lab_page_focus(const char* path) {
    if (gState) {
        gState->pageFocus = std::string(path);
        gState->changed = true;
    }
}
// The page's theme: the system's while the visitor has not chosen one, or the page's own control
// ("dark", "light"); as the panel's choice, but not remembered as one by the lab.
EMSCRIPTEN_KEEPALIVE void lab_set_theme(const char* name) {
    if (std::optional<Theme> theme = themeFrom(name); gState && theme) {
        gState->app.setTheme(*theme);
        gState->changed = true;
    }
}
// For browser tests: the frames drawn so far (an idle page draws none).
EMSCRIPTEN_KEEPALIVE int lab_frames() { return gState ? gState->frames : 0; }
// For browser tests: 1 when the lab has handled everything it was given, owes no frame and the page
// has its description of the last frame.
EMSCRIPTEN_KEEPALIVE int lab_settled() {
    // A file held for the Draco decoder is one the lab was given and has not handled yet; a site
    // file being fetched, one an open waits for; the QR encoder being fetched, a code the window waits for.
    return gState && !gState->changed && !gState->pendingLink && gState->queue.empty() && gState->heldForDraco.empty() &&
           !siteFilesFetching() && qrEncoderState() != ModuleState::Loading &&
           !gState->describeOwed &&
           !gState->pacer.due(glfwGetTime(), false);
}
// For browser tests: the screen rectangles of the main widgets, in CSS pixels ("name x y w h").
EMSCRIPTEN_KEEPALIVE const char* lab_widgets() {
    static std::string text;
    text = ui::widgets().text();
    return text.c_str();
}
}

WindowResult runLab(const AppOptions& options, const WindowOptions&, std::string& error) {
    labJsMark("main");
    if (std::error_code ec; !fs::is_regular_file(kFonts.front(), ec)) {
        error = "the page's font " + kFonts.front() + " is not in lab.data (rebuild the page)";
        return WindowResult::Failed;
    }
    if (!glfwInit()) {
        error = "GLFW did not start";
        return WindowResult::Failed;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    GLFWwindow* window = glfwCreateWindow(1280, 720, "Lighting Lab", nullptr, nullptr);
    if (!window) {
        error = "this browser cannot create a WebGL2 context";
        return WindowResult::Failed;
    }
    glfwMakeContextCurrent(window);
    // Lives as long as the page: the main loop below never returns to here.
    auto* s = new WebState(options);
    s->window = window;
    s->backend = std::make_unique<GlfwBackend>(window, s);
    gState = s;
    labJsMark("context");
    if (!s->host.start(s->app, error)) {
        return WindowResult::Failed;
    }
    s->host.setTabEntersWindows(false); // Tab leaves the canvas for the page's controls (web/access.js)
    labJsFieldSender();
    labJsMark("started");
    int saved = 0;
    char* link = labJsInitialLink(static_cast<int>(kMaxLinkChars), &saved);
    if (link && *link) {
        s->pendingLink = std::string(link);
        s->pendingLinkSaved = saved != 0;
    }
    std::free(link);
    s->touchScreen = labJsCoarsePointer() != 0;
    s->last = glfwGetTime();
    emscripten_set_main_loop_arg(frame, s, 0, true);
    return WindowResult::Closed; // not reached
}

} // namespace lab
