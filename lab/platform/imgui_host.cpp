// imgui_host.cpp — ImGui context, OpenGL3 backend, fonts and the frame order.
#include "platform/imgui_host.h"

#include "render/gl.h"
#include "render/renderer.h"
#include "ui/actions.h"
#include "ui/keyboard.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cfloat>
#include <filesystem>

namespace lab {

namespace {

// The mouse as this frame's events leave it. Platform backends set io.MousePos and MouseDown
// from polled state in their NewFrame; these are written over them.
struct Pointer {
    ImVec2 pos{-FLT_MAX, -FLT_MAX};
    bool down[3] = {};
};

// A frame's share of the queued input (app/input.h) into ImGui's state, in order.
void feed(const std::vector<InputEvent>& events, Pointer& p) {
    ImGuiIO& io = ImGui::GetIO();
    for (const InputEvent& e : events) {
        switch (e.kind) {
        case InputEvent::Kind::Move: p.pos = ImVec2(e.x, e.y); break;
        case InputEvent::Kind::Leave:
            if (!p.down[0] && !p.down[1] && !p.down[2]) { // a drag goes on outside the window
                p.pos = ImVec2(-FLT_MAX, -FLT_MAX);
            }
            break;
        case InputEvent::Kind::Button:
            p.pos = ImVec2(e.x, e.y);
            if (e.code >= 0 && e.code < 3) {
                p.down[e.code] = e.down;
            }
            break;
        case InputEvent::Kind::Scroll:
            io.MouseWheelH += e.x;
            io.MouseWheel += e.y;
            break;
        case InputEvent::Kind::Key:
            if (e.code >= 0 && e.code < IM_ARRAYSIZE(io.KeysDown) && !e.repeat) {
                io.KeysDown[e.code] = e.down;
            }
            break;
        case InputEvent::Kind::Char: io.AddInputCharacter(static_cast<unsigned>(e.code)); break;
        }
    }
    io.MousePos = p.pos;
    for (int i = 0; i < 3; ++i) {
        io.MouseDown[i] = p.down[i];
    }
    io.KeyCtrl = io.KeysDown[keys::LeftControl] || io.KeysDown[keys::RightControl];
    io.KeyShift = io.KeysDown[keys::LeftShift] || io.KeysDown[keys::RightShift];
    io.KeyAlt = io.KeysDown[keys::LeftAlt] || io.KeysDown[keys::RightAlt];
    io.KeySuper = io.KeysDown[keys::LeftSuper] || io.KeysDown[keys::RightSuper];
}

// Everything ImGui's draw data would put on screen (vertices, indices, commands) and the
// framebuffer's size, as bytes: two equal snapshots draw the same picture. Hovering where
// nothing reacts, or a cursor move over the model, then costs no drawing at all.
std::string snapshot(const ImDrawData& data, const FrameInput& in) {
    std::string bytes;
    auto add = [&](const void* p, std::size_t n) { bytes.append(static_cast<const char*>(p), n); };
    add(&in.framebufferWidth, sizeof in.framebufferWidth);
    add(&in.framebufferHeight, sizeof in.framebufferHeight);
    for (int i = 0; i < data.CmdListsCount; ++i) {
        const ImDrawList& list = *data.CmdLists[i];
        add(list.VtxBuffer.Data, list.VtxBuffer.size_in_bytes());
        add(list.IdxBuffer.Data, list.IdxBuffer.size_in_bytes());
        for (const ImDrawCmd& c : list.CmdBuffer) {
            add(&c.ClipRect, sizeof c.ClipRect);
            add(&c.TextureId, sizeof c.TextureId);
            add(&c.VtxOffset, sizeof c.VtxOffset);
            add(&c.IdxOffset, sizeof c.IdxOffset);
            add(&c.ElemCount, sizeof c.ElemCount);
        }
    }
    return bytes;
}

// The frame's key presses (auto-repeats too), with their places in `events`, and whether a mouse
// button went down: for the keyboard's owner (ui/keyboard.h).
std::vector<ui::KeyPress> keyPresses(const std::vector<InputEvent>& events, std::vector<std::size_t>& at,
                                     bool& mousePressed) {
    std::vector<ui::KeyPress> presses;
    mousePressed = false;
    for (std::size_t i = 0; i < events.size(); ++i) {
        const InputEvent& e = events[i];
        if (e.kind == InputEvent::Kind::Key && e.down) {
            presses.push_back({e.code, e.modifiers});
            at.push_back(i);
        }
        mousePressed = mousePressed || (e.kind == InputEvent::Kind::Button && e.down);
    }
    return presses;
}

// This frame's input as ImGui and the app are to see it: who the keys are for, and without the
// presses the keyboard's owner took (an Esc that closed a tooltip).
FrameInput routed(const FrameInput& in, ui::KeyboardFocus& keyboard) {
    FrameInput out = in;
    std::vector<std::size_t> at;
    bool mousePressed = false;
    std::vector<ui::KeyPress> presses = keyPresses(in.events, at, mousePressed);
    out.keys = keyboard.beforeNewFrame(presses, mousePressed);
    for (std::size_t i = presses.size(); i-- > 0;) {
        if (presses[i].used) {
            out.events.erase(out.events.begin() + static_cast<std::ptrdiff_t>(at[i]));
        }
    }
    return out;
}

// ImGui's named keys as the lab's key codes, which are GLFW's on every platform (app/input.h); the
// GLFW backend sets the same, the headless app has no backend.
void mapKeys(ImGuiIO& io) {
    // clang-format off
    const std::pair<ImGuiKey, int> map[] = {
        {ImGuiKey_Tab, keys::Tab},           {ImGuiKey_LeftArrow, keys::Left}, {ImGuiKey_RightArrow, keys::Right},
        {ImGuiKey_UpArrow, keys::Up},        {ImGuiKey_DownArrow, keys::Down}, {ImGuiKey_PageUp, keys::PageUp},
        {ImGuiKey_PageDown, keys::PageDown}, {ImGuiKey_Home, keys::Home},      {ImGuiKey_End, keys::End},
        {ImGuiKey_Insert, keys::Insert},     {ImGuiKey_Delete, keys::Delete},  {ImGuiKey_Backspace, keys::Backspace},
        {ImGuiKey_Space, keys::Space},       {ImGuiKey_Enter, keys::Enter},    {ImGuiKey_Escape, keys::Escape},
        {ImGuiKey_KeyPadEnter, keys::KeypadEnter},
        {ImGuiKey_A, 'A'}, {ImGuiKey_C, 'C'}, {ImGuiKey_V, 'V'}, {ImGuiKey_X, 'X'}, {ImGuiKey_Y, 'Y'}, {ImGuiKey_Z, 'Z'},
    };
    // clang-format on
    for (const auto& [key, code] : map) {
        io.KeyMap[key] = code;
    }
}

} // namespace

namespace {

// The characters the UI can show: Latin-1, the Greek letters (θ, ω, ...; not the accented ones, which
// took 4.5 KB of the page's font), dashes and the ellipsis (which ImGui
// uses for clipped text), arrows, minus, <= and >=. The browser's font is cut down to exactly these
// (cmake/web.cmake): keep the two lists the same.
const ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0391, 0x03A9, 0x03B1, 0x03C9, 0x2010, 0x2027, 0x2190, 0x2193,
                                0x2212, 0x2212, 0x2264, 0x2265, 0xFFFD, 0xFFFD, 0};

} // namespace

void loadUiFont(const std::vector<std::string>& fontFiles, FallbackFont fallback, float pixels) {
    ImGuiIO& io = ImGui::GetIO();
    bool loaded = false;
    for (const std::string& f : fontFiles) {
        std::error_code ec;
        if (!loaded && std::filesystem::is_regular_file(f, ec)) {
            loaded = io.Fonts->AddFontFromFileTTF(f.c_str(), pixels, nullptr, kGlyphRanges) != nullptr;
        }
    }
    if (!loaded && fallback) {
        fallback(pixels * 13.0f / 15.0f); // ProggyClean is drawn for 13 pixels
    }
}

void imguiBuiltinFont(float pixels) {
    ImFontConfig config;
    config.SizePixels = pixels;
    ImGui::GetIO().Fonts->AddFontDefault(&config);
}

struct ImGuiHost::Impl {
    std::vector<std::string> fontFiles;
    FallbackFont fallback = nullptr;
    App* app = nullptr;
    ImGuiStyle baseStyle;
    float scale = 0.0f;
    bool touch = false;
    bool backend = false;
    Pointer pointer;
    ui::KeyboardFocus keyboard; // the model's or a window's widget's (ui/keyboard.h)
    std::string lastDrawn;      // the last frame's draw data (snapshot())

    // Rebuilds the font atlas at `s` and scales a copy of the base style, instead of stretching;
    // for a finger (`t`), taller fields, wider grabs and scrollbars, and a margin around each
    // widget that still counts as a hit.
    void applyScale(float s, bool t) {
        scale = s;
        touch = t;
        ImGui::GetIO().Fonts->Clear();
        loadUiFont(fontFiles, fallback, 15.0f * s);
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
        ImGuiStyle& style = ImGui::GetStyle();
        style = baseStyle;
        if (t) {
            style.FramePadding.y = 7.0f;
            style.ItemSpacing.y = 7.0f;
            style.ItemInnerSpacing.x = 6.0f;
            style.GrabMinSize = 22.0f;
            style.ScrollbarSize = 22.0f;
            style.TouchExtraPadding = ImVec2(3.0f, 3.0f);
        }
        style.ScaleAllSizes(s);
    }
};

ImGuiHost::ImGuiHost(std::vector<std::string> fontFiles, FallbackFont fallback) : impl_(std::make_unique<Impl>()) {
    impl_->fontFiles = std::move(fontFiles);
    impl_->fallback = fallback;
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // the layout is the app's, not a file's
    // A steady caret: a blinking one would need a frame twice a second in an idle lab.
    ImGui::GetIO().ConfigInputTextCursorBlink = false;
    mapKeys(ImGui::GetIO());
    ImGui::StyleColorsDark();
    impl_->baseStyle = ImGui::GetStyle();
}

ImGuiHost::~ImGuiHost() {
    if (impl_->backend) {
        ImGui_ImplOpenGL3_Shutdown();
    }
    ImGui::DestroyContext();
}

bool ImGuiHost::start(App& app, std::string& error) {
    Impl& m = *impl_;
    if (!ImGui_ImplOpenGL3_Init("#version 300 es")) {
        error = "ImGui's OpenGL3 backend did not start";
        return false;
    }
    m.backend = true;
    m.applyScale(1.0f, false);
    Diagnostics diagnostics;
    if (!app.init(diagnostics)) {
        error = "the lab cannot start:\n" + toString(diagnostics);
        return false;
    }
    m.app = &app;
    return true;
}

void ImGuiHost::setTabEntersWindows(bool on) { impl_->keyboard.tabEntersWindows(on); }

FrameOutput ImGuiHost::frame(const FrameInput& in, const std::function<void()>& platformNewFrame) {
    Impl& m = *impl_;
    ImGui_ImplOpenGL3_NewFrame();
    platformNewFrame();
    const FrameInput input = routed(in, m.keyboard);
    feed(input.events, m.pointer);
    ImGui::NewFrame();
    m.keyboard.afterNewFrame();
    FrameOutput out = m.app->frame(input);
    out.keys = input.keys;
    ImGui::Render();
    std::string drawn = snapshot(*ImGui::GetDrawData(), in);
    out.presented = in.repaint || out.viewportDrawn || drawn != m.lastDrawn;
    m.lastDrawn = std::move(drawn);
    if (out.presented) {
        m.app->compose(in.targetFramebuffer, in.framebufferWidth, in.framebufferHeight);
        glViewport(0, 0, in.framebufferWidth, in.framebufferHeight);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    if (out.uiScale != m.scale || out.touch != m.touch) {
        m.applyScale(out.uiScale, out.touch);
        out.redrawIn = 0.0f; // the next frame shows the new sizes
    }
    return out;
}

} // namespace lab
