// viewport.cpp — gestures, light markers and overlay text of the model's viewport.
#include "ui/viewport.h"

#include "core/io/safe_text.h"
#include "core/lighting/lighting.h"
#include "core/scene/camera.h"
#include "core/scene/limits.h"
#include "core/scene/preset_choices.h"
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

void startGesture(const Preset& scene, const Rect& active, ViewportControls& s) {
    ImGuiIO& io = ImGui::GetIO();
    s.pressX = io.MousePos.x;
    s.pressY = io.MousePos.y;
    s.pressMoved = false;
    s.button = ImGui::IsMouseClicked(0) ? 0 : ImGui::IsMouseClicked(1) ? 1 : 2;
    s.drag = s.button == 0 ? ViewportControls::Drag::Orbit : ViewportControls::Drag::Pan; // touch: two fingers are the middle button
    if (s.drag == ViewportControls::Drag::Orbit) {
        s.light = lightUnderMouse(scene, active, io.MousePos);
        if (s.light >= 0) {
            s.drag = ViewportControls::Drag::Light;
        }
    }
}

} // namespace

ViewportEvents viewportControls(Preset& scene, const Rect& active, const Rect& whole, ViewportControls& s,
                        const std::vector<std::pair<float, float>>& clicks, const LightMotion* motion) {
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
        startGesture(motion ? orbitedScene(scene, *motion) : scene, active, s); // picked where shown
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

void marker(const LightDesc& l, ImVec2 at, bool outside, bool dragged, int number, ImDrawList* dl) {
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
    widgets().set("view.light" + std::to_string(number), {at.x - radius, at.y - radius, 2 * radius, 2 * radius});
}

} // namespace

void lightMarkers(const Preset& scene, const Rect& r, int draggedLight, bool shapes) {
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
        marker(l, at, outside, draggedLight == static_cast<int>(i), number, dl);
    }
    dl->PopClipRect();
}

namespace {

// "shading Phong  |  BRDF Blinn-Phong", with "A: " or "B: " in front in compare mode.
std::string setSummary(const char* name, const Preset& p) {
    return std::string(name) + "shading " + label(p.shading) + "  |  BRDF " + label(p.brdf);
}

void compareLabels(const OverlayModel& m, const Layout& layout, ImDrawList* dl) {
    const Rect &a = layout.halves[0], &b = layout.halves[1];
    ImVec2 end = layout.compareStacked ? ImVec2(b.x + b.w, b.y) : ImVec2(b.x, b.y + b.h);
    dl->AddLine(ImVec2(b.x, b.y), end, IM_COL32(255, 255, 255, 160), 2.0f);
    float line = ImGui::GetFontSize() * 1.5f;
    dl->AddText(ImVec2(b.x + 8, b.y + b.h - line), IM_COL32(230, 90, 220, 255), setSummary("B: ", *m.b).c_str());
    dl->AddText(ImVec2(a.x + 8, a.y + a.h - line), IM_COL32(255, 255, 255, 230), setSummary("A: ", *m.a).c_str());
}

void toast(const char* text, const Rect& v, ImDrawList* dl) {
    ImVec2 size = ImGui::CalcTextSize(text);
    ImVec2 at(v.x + (v.w - size.x) * 0.5f, v.y + v.h - size.y * 3.0f);
    dl->AddRectFilled(ImVec2(at.x - 8, at.y - 4), ImVec2(at.x + size.x + 8, at.y + size.y + 4), IM_COL32(0, 0, 0, 180), 4.0f);
    dl->AddText(at, IM_COL32(255, 255, 255, 255), text);
}

// The preset's name (larger) and description, wrapped, on a dark band: the lecture's story.
// Returns the height used.
float caption(const Preset& p, ImVec2 at, float width, ImDrawList* dl) {
    ImFont* font = ImGui::GetFont();
    float size = ImGui::GetFontSize(), big = size * 1.35f, pad = 0.5f * size;
    width -= 2 * pad; // the text's own width inside the band
    const std::string name = printable(p.name, true), description = printable(p.description); // from the file
    ImVec2 title = font->CalcTextSizeA(big, width, width, name.c_str());
    ImVec2 text = description.empty() ? ImVec2(0, 0) : font->CalcTextSizeA(size, width, width, description.c_str());
    float height = title.y + (description.empty() ? 0.0f : text.y + 0.3f * size) + 2 * pad;
    float w = std::max(title.x, text.x) + 2 * pad;
    dl->AddRectFilled(at, ImVec2(at.x + w, at.y + height), IM_COL32(0, 0, 0, 170), 4.0f);
    dl->AddText(font, big, ImVec2(at.x + pad, at.y + pad), IM_COL32(255, 255, 255, 255), name.c_str(), nullptr, width);
    if (!description.empty()) {
        dl->AddText(font, size, ImVec2(at.x + pad, at.y + pad + title.y + 0.3f * size), IM_COL32(225, 225, 225, 255),
                    description.c_str(), nullptr, width);
    }
    widgets().set("view.caption", {at.x, at.y, w, height});
    return height;
}

// A ring and a cross at the probed point.
void probeMarker(const Preset& scene, const glm::vec3& world, const Rect& r, ImDrawList* dl) {
    std::optional<ImVec2> at = project(scene, world, r);
    if (!at || !r.contains(at->x, at->y)) {
        return;
    }
    float s = 8.0f * uiUnit(), w = 2.0f * uiUnit();
    dl->AddCircle(*at, s, IM_COL32(0, 0, 0, 200), 0, w + 2.0f);
    dl->AddCircle(*at, s, IM_COL32(255, 255, 80, 255), 0, w);
    dl->AddLine(ImVec2(at->x - 2 * s, at->y), ImVec2(at->x - s, at->y), IM_COL32(255, 255, 80, 255), w);
    dl->AddLine(ImVec2(at->x + s, at->y), ImVec2(at->x + 2 * s, at->y), IM_COL32(255, 255, 80, 255), w);
    dl->AddLine(ImVec2(at->x, at->y - 2 * s), ImVec2(at->x, at->y - s), IM_COL32(255, 255, 80, 255), w);
    dl->AddLine(ImVec2(at->x, at->y + s), ImVec2(at->x, at->y + 2 * s), IM_COL32(255, 255, 80, 255), w);
    widgets().set("view.probe-marker", {at->x - s, at->y - s, 2 * s, 2 * s});
}

// The header: which file, then what the model shows; the frame time at the right. Returns the
// height used.
float header(const OverlayModel& m, const Rect& v, ImDrawList* dl) {
    char text[160];
    std::snprintf(text, sizeof text, "%.1f ms", m.frameMs);
    ImVec2 size = ImGui::CalcTextSize(text);
    dl->AddText(ImVec2(v.x + v.w - size.x - 8, v.y + 6), IM_COL32(255, 255, 255, 200), text);
    widgets().set("view.frame-time", {v.x + v.w - size.x - 8, v.y + 6, size.x, size.y});
    std::string head = m.documentName + (m.dirty ? " *" : "") + "  |  " + setSummary("", *m.a);
    float wrap = std::max(v.w - size.x - 32.0f, 40.0f);
    ImVec2 headSize = ImGui::GetFont()->CalcTextSizeA(ImGui::GetFontSize(), wrap, wrap, head.c_str());
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(v.x + 8, v.y + 6), IM_COL32(255, 255, 255, 200), head.c_str(),
                nullptr, wrap);
    widgets().set("view.header", {v.x + 8, v.y + 6, headSize.x, headSize.y});
    return 6.0f + headSize.y + 0.3f * ImGui::GetFontSize();
}

} // namespace

void viewOverlay(const OverlayModel& m, const Layout& layout) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const Rect& v = layout.viewport;
    float y = v.y + header(m, v, dl);
    if (m.caption) {
        y += caption(*m.a, ImVec2(v.x + 8, y), std::min(v.w - 16.0f, ImGui::GetFontSize() * 36.0f), dl) + 6.0f;
    }
    if (m.viewMode != ViewMode::Lit) {
        dl->AddText(ImVec2(v.x + 8, y), IM_COL32(255, 220, 120, 230), toString(m.viewMode));
    }
    if (m.probePoint) {
        probeMarker(*m.a, *m.probePoint, m.b ? layout.halves[0] : v, dl);
    }
    if (m.b) {
        compareLabels(m, layout, dl);
    }
    if (m.toast) {
        toast(m.toast, v, dl);
    }
}

} // namespace lab::ui
