// viewport.cpp — gestures, light markers and overlay text of the model's viewport.
#include "ui/viewport/viewport.h"

#include "core/scene/transforms.h"
#include "core/io/safe_text.h"
#include "core/lighting/lighting.h"
#include "core/scene/camera.h"
#include "core/scene/limits.h"
#include "core/scene/preset_choices.h"
#include "ui/viewport/point_lobe.h"
#include "ui/viewport/view_legend.h"
#include "ui/widgets.h"

#include <imgui.h>

#include <glm/common.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace lab::ui {

namespace {

// Screen position (window units) of a world point in view rectangle r; nullopt behind the eye.
std::optional<ImVec2> project(const Preset& scene, const glm::vec3& world, const Rect& r) {
    Transforms t = computeTransforms(scene, r.w / r.h);
    glm::vec4 clip = t.projection * t.view * glm::vec4(world, 1.0f);
    if (clip.w <= 1e-4f) {
        return std::nullopt;
    }
    glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return ImVec2(r.x + (ndc.x * 0.5f + 0.5f) * r.w, r.y + (0.5f - ndc.y * 0.5f) * r.h);
}

// The light whose marker is under the mouse, or -1.
int lightUnderMouse(const Preset& scene, const Rect& r, ImVec2 mouse) {
    float pick = 10.0f * ImGui::GetFontSize() / 13.0f;
    int found = -1;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const LightDesc& l = scene.lights[i];
        std::optional<ImVec2> at = l.type == LightType::Directional ? std::nullopt : project(scene, l.position, r);
        if (at && std::hypot(at->x - mouse.x, at->y - mouse.y) < pick) {
            found = static_cast<int>(i);
        }
    }
    return found;
}

// Moves the light in the plane through it, parallel to the image, by a mouse delta in pixels.
// `shownAt` is where the light is shown (its place in its orbit, else its position); a moving
// light's step is turned back by its orbit's angle, so the shown light moves with the mouse.
void dragLight(Preset& scene, int index, ImVec2 delta, const Rect& r, const LightMotion* motion) {
    const Camera& camera = scene.camera;
    LightDesc& l = scene.lights[static_cast<std::size_t>(index)];
    double seconds = motion ? motion->secondsOf(static_cast<std::size_t>(index)) : 0.0;
    glm::vec3 shownAt = motion ? orbitedLight(l, motion->centre, seconds).position : l.position;
    glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    glm::vec3 up = glm::cross(right, forward);
    float depth = glm::dot(shownAt - camera.eye, forward);
    // fovy_deg spans the view's narrower side (core/lighting/lighting.h).
    float perPixel = 2.0f * std::max(depth, 0.01f) * std::tan(glm::radians(camera.fovyDeg) / 2.0f) / std::min(r.w, r.h);
    glm::vec3 step = (delta.x * right - delta.y * up) * perPixel;
    if (l.orbit.on) {
        step = orbitUnrotate(l.orbit, seconds, step);
    }
    l.position = glm::clamp(l.position + step, glm::vec3(limits::kCoordinate.min), glm::vec3(limits::kCoordinate.max));
}

// On the probe's marker: within its cross's arms (ui::probeMarker), and a finger's margin on a touch screen.
bool onProbeMarker(const Preset& scene, const Rect& r, const glm::vec3* probePoint, ImVec2 mouse) {
    if (!probePoint) {
        return false;
    }
    const std::optional<ImVec2> at = project(scene, *probePoint, r);
    if (!at || !r.contains(at->x, at->y)) {
        return false;
    }
    float pick = 16.0f * ImGui::GetFontSize() / 13.0f + ImGui::GetStyle().TouchExtraPadding.x;
    return std::hypot(at->x - mouse.x, at->y - mouse.y) < pick;
}

void startGesture(const Preset& scene, const Rect& active, ViewportControls& s, const glm::vec3* probePoint,
                  const float* wipeAt) {
    ImGuiIO& io = ImGui::GetIO();
    s.pressX = io.MousePos.x;
    s.pressY = io.MousePos.y;
    s.pressMoved = false;
    s.button = ImGui::IsMouseClicked(0) ? 0 : ImGui::IsMouseClicked(1) ? 1 : 2;
    s.drag = s.button == 0 ? ViewportControls::Drag::Orbit : ViewportControls::Drag::Pan; // touch: two fingers are the middle button
    if (s.drag == ViewportControls::Drag::Orbit && onProbeMarker(scene, active, probePoint, io.MousePos)) {
        s.drag = ViewportControls::Drag::Probe; // the marker is drawn over the lights' markers: it is picked first
    } else if (s.drag == ViewportControls::Drag::Orbit && wipeAt &&
               std::abs(io.MousePos.x - (active.x + *wipeAt * active.w)) <= wipeGrabDistance()) {
        s.drag = ViewportControls::Drag::Wipe;
    } else if (s.drag == ViewportControls::Drag::Orbit) {
        s.light = lightUnderMouse(scene, active, io.MousePos);
        if (s.light >= 0) {
            s.drag = ViewportControls::Drag::Light;
        }
    }
}

} // namespace

ViewportEvents viewportControls(Preset& scene, const Rect& active, const Rect& whole, ViewportControls& s,
                        const std::vector<std::pair<float, float>>& clicks, const LightMotion* motion,
                        const glm::vec3* probePoint, float* wipeAt) {
    ImGuiIO& io = ImGui::GetIO();
    ViewportEvents events;
    for (const auto& [x, y] : clicks) {
        if (!events.probed && !io.WantCaptureMouse && active.contains(x, y)) {
            events.probed = active;
            events.probeX = x;
            events.probeY = y;
        }
    }
    bool hovered = !io.WantCaptureMouse && whole.contains(io.MousePos.x, io.MousePos.y);
    if (hovered && io.MouseWheel != 0.0f) {
        zoomCamera(scene.camera, std::pow(0.9f, io.MouseWheel));
    }
    if (hovered && s.drag == ViewportControls::Drag::None && (ImGui::IsMouseClicked(0) || ImGui::IsMouseClicked(1) || ImGui::IsMouseClicked(2))) {
        startGesture(motion ? orbitedScene(scene, *motion) : scene, active, s, probePoint, wipeAt); // picked where shown
    }
    if (s.drag == ViewportControls::Drag::None) {
        return events;
    }
    ImVec2 delta = io.MouseDelta;
    s.pressMoved = s.pressMoved || std::hypot(io.MousePos.x - s.pressX, io.MousePos.y - s.pressY) > 3.0f;
    if (s.pressMoved && (delta.x != 0.0f || delta.y != 0.0f)) {
        if (s.drag == ViewportControls::Drag::Orbit) {
            orbitCamera(scene.camera, -delta.x * 0.35f, delta.y * 0.35f);
        } else if (s.drag == ViewportControls::Drag::Pan) {
            float side = std::min(active.w, active.h); // panCamera's unit: the view's narrower side
            panCamera(scene.camera, delta.x / side, -delta.y / side);
        } else if (s.drag == ViewportControls::Drag::Wipe) {
            if (wipeAt) {
                *wipeAt = std::clamp((io.MousePos.x - active.x) / std::max(active.w, 1.0f), 0.0f, 1.0f);
            }
        } else if (s.drag == ViewportControls::Drag::Probe) {
            events.probed = active; // the pixel under the pointer, probed again (app/pixel_probe.h)
            events.probeX = io.MousePos.x;
            events.probeY = io.MousePos.y;
            events.probeDragged = true;
        } else if (s.light < static_cast<int>(scene.lights.size())) {
            dragLight(scene, s.light, delta, active, motion);
        }
    }
    bool released = ImGui::IsMouseReleased(s.button);
    if (released) { // a release without a move was a click: the queued clicks above probe it
        s.drag = ViewportControls::Drag::None;
        s.light = -1;
    }
    events.gesture = s.drag != ViewportControls::Drag::None;
    return events;
}

namespace {

float uiUnit() { return ImGui::GetFontSize() / 13.0f; }

ImU32 lightColor(const LightDesc& l, int alpha) {
    glm::vec3 c = glm::clamp(l.diffuse, glm::vec3(0.0f), glm::vec3(1.0f));
    return l.enabled ? IM_COL32(int(c.r * 255), int(c.g * 255), int(c.b * 255), alpha) : IM_COL32(90, 90, 90, alpha);
}

// Where a light's marker goes: its projection when inside `r`, else the point of r's edge (less a
// margin) in its direction from the centre, with `outside` set.
ImVec2 markerPosition(const Preset& scene, const glm::vec3& world, const Rect& r, bool& outside) {
    Transforms t = computeTransforms(scene, r.w / r.h);
    glm::vec4 clip = t.projection * t.view * glm::vec4(world, 1.0f);
    glm::vec2 ndc = glm::vec2(clip) / std::max(std::abs(clip.w), 1e-6f);
    if (clip.w < 0.0f) {
        ndc = -ndc; // behind the eye: the other way round
    }
    outside = clip.w <= 1e-4f || std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f;
    if (outside) {
        float margin = 14.0f * uiUnit();
        glm::vec2 half(std::max(r.w * 0.5f - margin, 1.0f), std::max(r.h * 0.5f - margin, 1.0f));
        glm::vec2 d = ndc * glm::vec2(r.w * 0.5f, r.h * 0.5f);
        float k = std::min(half.x / std::max(std::abs(d.x), 1e-6f), half.y / std::max(std::abs(d.y), 1e-6f));
        d *= k;
        return ImVec2(r.x + r.w * 0.5f + d.x, r.y + r.h * 0.5f - d.y);
    }
    return ImVec2(r.x + (ndc.x * 0.5f + 0.5f) * r.w, r.y + (0.5f - ndc.y * 0.5f) * r.h);
}

// Two unit vectors perpendicular to `axis` and to each other.
void basis(const glm::vec3& axis, glm::vec3& u, glm::vec3& v) {
    u = glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    v = glm::cross(axis, u);
}

// The spot's cone: from the light along its direction to the depth of the camera's target.
void spotCone(const Preset& scene, const LightDesc& l, const Rect& r, ImDrawList* dl) {
    if (glm::length(l.direction) < 1e-6f) {
        return;
    }
    glm::vec3 S = glm::normalize(l.direction), u, v;
    basis(S, u, v);
    float length = std::max(glm::dot(scene.camera.target - l.position, S), 0.5f);
    float radius = length * std::tan(glm::radians(std::min(l.cutoffDeg, 80.0f)));
    ImU32 color = lightColor(l, 170);
    std::optional<ImVec2> apex = project(scene, l.position, r);
    std::vector<ImVec2> rim;
    for (int i = 0; i <= 32; ++i) {
        float a = glm::two_pi<float>() * static_cast<float>(i) / 32.0f;
        std::optional<ImVec2> p = project(scene, l.position + S * length + radius * (std::cos(a) * u + std::sin(a) * v), r);
        if (!p) {
            return; // the cone reaches behind the eye: leave it out rather than draw it wrong
        }
        rim.push_back(*p);
    }
    dl->AddPolyline(rim.data(), static_cast<int>(rim.size()), color, 0, 1.5f * uiUnit());
    for (int i = 0; apex && i < 32; i += 8) {
        dl->AddLine(*apex, rim[static_cast<std::size_t>(i)], color, 1.5f * uiUnit());
    }
}

// A directional light: three parallel rays towards the camera's target, in its direction.
void directionalRays(const Preset& scene, const LightDesc& l, const Rect& r, int number, ImDrawList* dl) {
    if (glm::length(l.direction) < 1e-6f) {
        return;
    }
    glm::vec3 d = glm::normalize(l.direction), u, v;
    basis(d, u, v);
    ImU32 color = lightColor(l, 220);
    float width = 2.0f * uiUnit();
    for (float offset : {-0.5f, 0.0f, 0.5f}) {
        glm::vec3 end = scene.camera.target - d * 1.1f + u * offset;
        std::optional<ImVec2> a = project(scene, end - d * 0.9f, r), b = project(scene, end, r);
        if (!a || !b || (a->x == b->x && a->y == b->y)) {
            continue;
        }
        glm::vec2 dir = glm::normalize(glm::vec2(b->x - a->x, b->y - a->y)), n(-dir.y, dir.x);
        float head = 9.0f * uiUnit();
        dl->AddLine(*a, *b, color, width);
        dl->AddTriangleFilled(*b, ImVec2(b->x - dir.x * head + n.x * head * 0.5f, b->y - dir.y * head + n.y * head * 0.5f),
                              ImVec2(b->x - dir.x * head - n.x * head * 0.5f, b->y - dir.y * head - n.y * head * 0.5f), color);
        if (offset == 0.0f) {
            dl->AddText(ImVec2(a->x + 4, a->y - ImGui::GetFontSize()), IM_COL32(255, 255, 255, 220), std::to_string(number).c_str());
        }
    }
}

Rect marker(const LightDesc& l, ImVec2 at, bool outside, bool dragged, int number, ImDrawList* dl) {
    float radius = 7.0f * uiUnit();
    ImU32 ring = dragged ? IM_COL32(255, 255, 0, 255) : IM_COL32(255, 255, 255, 200);
    if (outside) { // hollow, at the edge: the light is out there
        dl->AddCircle(at, radius, lightColor(l, 255), 0, 3.0f * uiUnit());
    } else {
        dl->AddCircleFilled(at, radius, lightColor(l, 255));
    }
    dl->AddCircle(at, radius + 1.5f, ring, 0, 2.0f);
    std::string label = std::to_string(number);
    dl->AddText(ImVec2(at.x + radius + 3, at.y - radius - 3), IM_COL32(255, 255, 255, 220), label.c_str());
    const float edge = 4.0f; // the ring's stroke and the number's lift
    const Rect r{at.x - radius - edge, at.y - radius - edge, 2 * (radius + edge) + 3 + ImGui::CalcTextSize(label.c_str()).x, 2 * (radius + edge)};
    widgets().set("view.light" + std::to_string(number), {at.x - radius, at.y - radius, 2 * radius, 2 * radius});
    return r; // with its number
}

} // namespace

std::vector<Rect> lightMarkers(const Preset& scene, const Rect& r, int draggedLight, bool shapes) {
    std::vector<Rect> markers;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), true);
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const LightDesc& l = scene.lights[i];
        int number = static_cast<int>(i) + 1;
        if (l.type == LightType::Directional) {
            if (shapes) {
                directionalRays(scene, l, r, number, dl);
            }
            continue;
        }
        if (shapes && l.type == LightType::Spot) {
            spotCone(scene, l, r, dl);
        }
        bool outside = false;
        ImVec2 at = markerPosition(scene, l.position, r, outside);
        markers.push_back(marker(l, at, outside, draggedLight == static_cast<int>(i), number, dl));
    }
    dl->PopClipRect();
    return markers;
}

namespace {

// "shading Phong  |  BRDF Blinn-Phong", with "A: " or "B: " in front in compare mode.
std::string setSummary(const char* name, const Preset& p) {
    return std::string(name) + "shading " + label(p.shading) + "  |  BRDF " + label(p.brdf);
}

// The strips' text is inset by this much from their edges (window units).
float inset() { return 0.4f * ImGui::GetFontSize(); }

ImVec2 wrapped(const char* text, float width, float size = 0.0f) {
    return ImGui::GetFont()->CalcTextSizeA(size > 0.0f ? size : ImGui::GetFontSize(), width, width, text);
}

// `text` cut to fit `width` with "..." at its end (at a character's boundary), or whole.
std::string fitText(const std::string& text, float width) {
    if (ImGui::CalcTextSize(text.c_str()).x <= width) {
        return text;
    }
    float room = width - ImGui::CalcTextSize("...").x;
    std::size_t end = 0;
    for (std::size_t next = 0; next < text.size(); end = next) {
        do {
            ++next; // to the next UTF-8 lead byte
        } while (next < text.size() && (static_cast<unsigned char>(text[next]) & 0xC0) == 0x80);
        if (ImGui::CalcTextSize(text.c_str(), text.c_str() + next).x > room) {
            break;
        }
    }
    return text.substr(0, end) + "...";
}

// What the header says after the file's name: the set (outside compare mode, where each half's
// label says it; `brief`: "Phong shading | Cook-Torrance"), the view when it is not the lit image,
// what differs from the file.
std::string headerRest(const CaptionStrips& m, bool brief) {
    const std::string bar = brief ? " | " : "  |  ";
    std::string rest;
    if (!m.b) {
        rest += brief ? bar + label(m.a->shading) + " shading" + bar + label(m.a->brdf) : bar + setSummary("", *m.a);
    }
    if (m.viewMode != ViewMode::Lit) {
        rest += bar + (brief ? "" : "view ") + toString(m.viewMode);
    }
    if (!m.edited.empty()) { // the description and the goldens are of the file's
        rest += bar + "edited: " + m.edited;
    }
    return rest;
}

// The header: which file and what the model shows, on one line whatever the window, so that the
// model's viewport keeps its size from preset to preset. Where the line is too long the file's name
// gives way first ("13-cook-torr... *"), then the words ("Phong shading | Cook-Torrance"), then
// the name altogether (the caption and the panel say it), and last what the model shows, at its
// end: `restCut` says so.
std::string headerText(const CaptionStrips& m, float width, bool& restCut) {
    const std::string dirty = m.dirty ? " *" : "";
    const float dots = ImGui::CalcTextSize("...").x;
    // Whether `after` fits behind the name given way to "..." (as fitText leaves it, a margin to spare).
    auto fits = [&](const std::string& after) { return ImGui::CalcTextSize((dirty + after).c_str()).x + dots * 1.5f <= width; };
    std::string rest = headerRest(m, false);
    if (!fits(rest)) {
        rest = headerRest(m, true);
    }
    restCut = false;
    if (!fits(rest) && rest.size() > 3) {
        std::string alone = dirty.empty() ? rest.substr(3) : "*" + rest; // "Phong shading | ..." without the name
        std::string shown = fitText(alone, width);
        restCut = shown != alone;
        return shown;
    }
    const float restWidth = ImGui::CalcTextSize((dirty + rest).c_str()).x;
    const std::string shown = fitText(rest, width - dots * 1.5f);
    restCut = shown != rest;
    return fitText(m.documentName, width - restWidth) + dirty + shown;
}

// The frame time, and the room it takes at the footer's right while it is shown.
std::string frameTimeText(float ms) {
    char text[48];
    std::snprintf(text, sizeof text, "%.1f ms/frame", std::min(ms, 9999.9f));
    return text;
}
float frameTimeRoom(const CaptionStrips& m) {
    return m.frameMs ? ImGui::CalcTextSize(frameTimeText(*m.frameMs).c_str()).x + 2.0f * inset() : 0.0f;
}

constexpr ImU32 kStrip = IM_COL32(30, 32, 40, 255); // the text's places: darker than the panels, apart from the model

// Text is drawn clipped to its place (a small view may give it less than it needs), and its
// widget is what shows of it.
void textWidget(const std::string& name, Rect text, const Rect& place) {
    float x1 = std::min(text.x + text.w, place.x + place.w), y1 = std::min(text.y + text.h, place.y + place.h);
    text.x = std::max(text.x, place.x);
    text.y = std::max(text.y, place.y);
    widgets().set(name, {text.x, text.y, std::max(x1 - text.x, 0.0f), std::max(y1 - text.y, 0.0f)});
}

struct Clip {
    Clip(ImDrawList* dl, const Rect& r) : dl_(dl) { dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), true); }
    ~Clip() { dl_->PopClipRect(); }
    Clip(const Clip&) = delete;
    Clip& operator=(const Clip&) = delete;
    ImDrawList* dl_;
};

// The preset's name (larger) and description, wrapped: the lecture's story. Its size at `width`,
// its text at `scale` of the UI's font. A scene that differs from its file says so after its name:
// the description may no longer hold.
ImVec2 captionSize(const Preset& p, bool edited, float width, float scale = 1.0f) {
    float size = ImGui::GetFontSize() * scale, pad = inset();
    const std::string name = printable(p.name, true) + (edited ? " (edited)" : ""), description = printable(p.description); // from the file
    float inner = std::max(width - 2 * pad, 1.0f);
    ImVec2 title = wrapped(name.c_str(), inner, size * 1.35f);
    ImVec2 text = description.empty() ? ImVec2(0, 0) : wrapped(description.c_str(), inner, size);
    return {std::max(title.x, text.x) + 2 * pad, title.y + (description.empty() ? 0.0f : text.y + 0.3f * size) + 2 * pad};
}

// Where the strip has less room than the caption takes (at most half the model's height), its text
// is drawn smaller, down to 0.6 of the UI's font, rather than cut; smaller than that it is cut.
void caption(const Preset& p, bool edited, const Rect& r, ImDrawList* dl) {
    Clip clip(dl, r);
    float scale = 1.0f;
    while (scale > 0.6f && captionSize(p, edited, r.w, scale).y > r.h + 1.0f) {
        scale -= 0.05f;
    }
    ImFont* font = ImGui::GetFont();
    float size = ImGui::GetFontSize() * scale, pad = inset(), inner = std::max(r.w - 2 * pad, 1.0f);
    const std::string name = printable(p.name, true) + (edited ? " (edited)" : ""), description = printable(p.description);
    ImVec2 title = wrapped(name.c_str(), inner, size * 1.35f);
    dl->AddText(font, size * 1.35f, ImVec2(r.x + pad, r.y + pad), IM_COL32(255, 255, 255, 255), name.c_str(), nullptr, inner);
    if (!description.empty()) {
        dl->AddText(font, size, ImVec2(r.x + pad, r.y + pad + title.y + 0.3f * size), IM_COL32(225, 225, 225, 255),
                    description.c_str(), nullptr, inner);
    }
    ImVec2 used = captionSize(p, edited, r.w, scale);
    textWidget("view.caption", {r.x, r.y, used.x, used.y}, r);
    if (used.y > r.h + 1.0f) { // still more than its room at 0.6: its end is cut
        widgets().set("clipped:view.caption", r);
    }
}

void strip(const Rect& r, ImDrawList* dl) {
    if (r.w > 0.0f && r.h > 0.0f) {
        dl->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), kStrip);
    }
}

void header(const CaptionStrips& m, const Rect& r, ImDrawList* dl) {
    Clip clip(dl, r);
    float pad = inset();
    // What the model shows is never cut while a smaller text (down to 0.75 of the font) holds it.
    bool cut = false;
    float scale = 1.0f;
    std::string head = headerText(m, r.w - 2 * pad, cut);
    while (cut && scale > 0.75f) {
        scale -= 0.05f;
        head = headerText(m, (r.w - 2 * pad) / scale, cut);
    }
    const float size = ImGui::GetFontSize() * scale;
    const ImVec2 text = ImGui::CalcTextSize(head.c_str());
    const ImVec2 used(text.x * scale, text.y * scale);
    dl->AddText(ImGui::GetFont(), size, ImVec2(r.x + pad, r.y + pad + (ImGui::GetFontSize() - size) * 0.5f),
                IM_COL32(255, 255, 255, 215), head.c_str());
    textWidget("view.header", {r.x + pad, r.y + pad, used.x, used.y}, r);
    if (cut) { // what the model shows, cut even so
        widgets().set("clipped:view.header", r);
    }
}

// The toast at the footer's left, wrapped to its width; the frame time at its right while shown.
void footer(const CaptionStrips& m, const Rect& r, ImDrawList* dl) {
    Clip clip(dl, r);
    float pad = inset();
    if (m.frameMs) {
        std::string text = frameTimeText(*m.frameMs);
        ImVec2 size = ImGui::CalcTextSize(text.c_str());
        ImVec2 at(r.x + r.w - size.x - pad, r.y + pad);
        dl->AddText(at, IM_COL32(255, 255, 255, 200), text.c_str());
        textWidget("view.frame-time", {at.x, at.y, size.x, size.y}, r);
    }
    if (m.toast) {
        float width = std::max(r.w - 2 * pad - frameTimeRoom(m), 1.0f);
        ImVec2 size = wrapped(m.toast, width);
        dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(r.x + pad, r.y + pad), IM_COL32(255, 255, 255, 255), m.toast,
                    nullptr, width);
        textWidget("view.toast", {r.x + pad, r.y + pad, size.x, size.y}, r);
    }
}

void compareLabels(const CaptionStrips& m, const Layout& layout, ImDrawList* dl) {
    // The line between the halves, at the top (stacked) or the left of B's label and model.
    const Rect &b = layout.halves[1], &bLabel = layout.labels[1];
    ImVec2 end = layout.compareStacked ? ImVec2(b.x + b.w, bLabel.y) : ImVec2(b.x, b.y + b.h);
    dl->AddLine(ImVec2(b.x, bLabel.y), end, IM_COL32(255, 255, 255, 160), 2.0f);
    const char* names[2] = {"label-a", "label-b"};
    const Preset* sets[2] = {m.a, m.b};
    const ImU32 colors[2] = {IM_COL32(255, 255, 255, 230), IM_COL32(230, 90, 220, 255)};
    for (std::size_t i = 0; i < 2; ++i) {
        const Rect& r = layout.labels[i];
        strip(r, dl);
        float pad = inset();
        // "A: shading Gouraud  |  BRDF Phong", or where that is too wide "A: Gouraud, Phong".
        // Where the sets differ in other fields too, those: "A: normal matrix: model-view (wrong)".
        const std::string& differs = i == 0 ? m.labelA : m.labelB;
        std::string text = m.exercise ? (i == 0 ? "Your attempt" : "Target")
                           : differs.empty() ? setSummary(i == 0 ? "A: " : "B: ", *sets[i])
                                             : std::string(i == 0 ? "A: " : "B: ") + differs;
        if (!m.exercise && i == 1 && !m.fitNote.empty()) { // what the fit found, its error first
            text = "B: " + m.fitNote;
        } else if (!m.exercise && differs.empty() && ImGui::CalcTextSize(text.c_str()).x > r.w - 2 * pad) {
            text = std::string(i == 0 ? "A: " : "B: ") + label(sets[i]->shading) + ", " + label(sets[i]->brdf);
        }
        text = fitText(text, r.w - 2 * pad);
        ImVec2 size = ImGui::CalcTextSize(text.c_str());
        Clip clip(dl, r);
        dl->AddText(ImVec2(r.x + pad, r.y + pad), colors[i], text.c_str());
        textWidget(std::string("view.") + names[i], {r.x + pad, r.y + pad, size.x, size.y}, r);
    }
}

// A ring and a cross at the probed point.
void probeMarker(const Preset& scene, const glm::vec3& world, const Rect& r, ImDrawList* dl) {
    std::optional<ImVec2> at = project(scene, world, r);
    if (!at || !r.contains(at->x, at->y)) {
        return;
    }
    float s = 8.0f * uiUnit(), w = 2.0f * uiUnit();
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), true); // on the model, never on the text
    dl->AddCircle(*at, s, IM_COL32(0, 0, 0, 200), 0, w + 2.0f);
    dl->AddCircle(*at, s, IM_COL32(255, 255, 80, 255), 0, w);
    dl->AddLine(ImVec2(at->x - 2 * s, at->y), ImVec2(at->x - s, at->y), IM_COL32(255, 255, 80, 255), w);
    dl->AddLine(ImVec2(at->x + s, at->y), ImVec2(at->x + 2 * s, at->y), IM_COL32(255, 255, 80, 255), w);
    dl->AddLine(ImVec2(at->x, at->y - 2 * s), ImVec2(at->x, at->y - s), IM_COL32(255, 255, 80, 255), w);
    dl->AddLine(ImVec2(at->x, at->y + s), ImVec2(at->x, at->y + 2 * s), IM_COL32(255, 255, 80, 255), w);
    dl->PopClipRect();
    widgets().set("view.probe-marker", {at->x - s, at->y - s, 2 * s, 2 * s});
}

} // namespace

TextRoom measureText(const CaptionStrips& m, const Rect& view) {
    TextRoom room;
    float line = ImGui::GetFontSize(), pad = inset();
    room.header = line + 2 * pad; // one line (headerText)
    float toastLines = m.toast ? wrapped(m.toast, std::max(view.w - 2 * pad - frameTimeRoom(m), 1.0f)).y : line;
    room.footer = std::max(line, toastLines) + 2 * pad;
    room.label = m.b ? line + 2 * pad : 0.0f;
    room.legend = m.legend ? legendStripHeight() : 0.0f;
    if (m.caption) {
        const Preset* p = m.a;
        room.captionHeight = [p, edited = !m.edited.empty()](float width) { return captionSize(*p, edited, width).y; };
        room.captionWidth = line * 36.0f;
        room.sideWidth = line * 18.0f;
    }
    return room;
}

void captionStrips(const CaptionStrips& m, const Layout& layout) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    for (const Rect* r : {&layout.header, &layout.captionBand, &layout.legend, &layout.footer}) {
        strip(*r, dl);
    }
    if (m.legend) {
        legendStrip(*m.legend, layout.legend, dl);
    }
    if (m.wipeAt) {
        wipeDivider(*m.wipeAt, m.b ? layout.halves[0] : layout.viewport, m.wipeDragged, dl);
        if (m.b) {
            wipeDivider(*m.wipeAt, layout.halves[1], m.wipeDragged, dl);
        }
    }
    header(m, layout.header, dl);
    if (m.caption && layout.caption.w > 0.0f) {
        caption(*m.a, !m.edited.empty(), layout.caption, dl);
    }
    footer(m, layout.footer, dl);
    if (m.probePoint) {
        const Rect& active = m.b ? layout.halves[0] : layout.viewport;
        if (m.probeLobe) {
            pointLobe(*m.a, *m.probeLobe, active, dl); // under the marker, which stays the thing to grab
        }
        probeMarker(*m.a, *m.probePoint, active, dl);
    }
    if (m.b) {
        compareLabels(m, layout, dl);
    }
}

} // namespace lab::ui
