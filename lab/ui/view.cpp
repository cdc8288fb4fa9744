// view.cpp — gestures, light markers and overlay text of the 3D view.
#include "ui/view.h"

#include "core/camera.h"
#include "core/lighting.h"
#include "ui/widgets.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

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
void dragLight(Preset& scene, int index, ImVec2 delta, const Rect& r) {
    const Camera& camera = scene.camera;
    LightDesc& l = scene.lights[static_cast<std::size_t>(index)];
    glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    glm::vec3 up = glm::cross(right, forward);
    float depth = glm::dot(l.position - camera.eye, forward);
    float perPixel = 2.0f * std::max(depth, 0.01f) * std::tan(glm::radians(camera.fovyDeg) / 2.0f) / r.h;
    l.position += (delta.x * right - delta.y * up) * perPixel;
}

void startGesture(const Preset& scene, const Rect& active, ViewControls& s) {
    ImGuiIO& io = ImGui::GetIO();
    s.pressX = io.MousePos.x;
    s.pressY = io.MousePos.y;
    s.pressMoved = false;
    s.drag = ImGui::IsMouseClicked(1) ? ViewControls::Drag::Pan : ViewControls::Drag::Orbit;
    if (s.drag == ViewControls::Drag::Orbit) {
        s.light = lightUnderMouse(scene, active, io.MousePos);
        if (s.light >= 0) {
            s.drag = ViewControls::Drag::Light;
        }
    }
}

} // namespace

ViewEvents viewControls(Preset& scene, const Rect& active, const Rect& whole, ViewControls& s) {
    ImGuiIO& io = ImGui::GetIO();
    ViewEvents events;
    bool hovered = !io.WantCaptureMouse && whole.contains(io.MousePos.x, io.MousePos.y);
    if (hovered && io.MouseWheel != 0.0f) {
        zoomCamera(scene.camera, std::pow(0.9f, io.MouseWheel));
    }
    if (hovered && s.drag == ViewControls::Drag::None && (ImGui::IsMouseClicked(0) || ImGui::IsMouseClicked(1))) {
        startGesture(scene, active, s);
    }
    if (s.drag == ViewControls::Drag::None) {
        return events;
    }
    ImVec2 delta = io.MouseDelta;
    s.pressMoved = s.pressMoved || std::hypot(io.MousePos.x - s.pressX, io.MousePos.y - s.pressY) > 3.0f;
    if (s.pressMoved && (delta.x != 0.0f || delta.y != 0.0f)) {
        if (s.drag == ViewControls::Drag::Orbit) {
            orbitCamera(scene.camera, -delta.x * 0.35f, delta.y * 0.35f);
        } else if (s.drag == ViewControls::Drag::Pan) {
            panCamera(scene.camera, delta.x / active.h, -delta.y / active.h);
        } else if (s.light < static_cast<int>(scene.lights.size())) {
            dragLight(scene, s.light, delta, active);
        }
    }
    bool released = s.drag == ViewControls::Drag::Pan ? ImGui::IsMouseReleased(1) : ImGui::IsMouseReleased(0);
    if (released) {
        if (!s.pressMoved && s.drag == ViewControls::Drag::Orbit && active.contains(io.MousePos.x, io.MousePos.y)) {
            events.probed = active;
            events.probeX = io.MousePos.x;
            events.probeY = io.MousePos.y;
        }
        s.drag = ViewControls::Drag::None;
        s.light = -1;
    }
    events.gesture = s.drag != ViewControls::Drag::None;
    return events;
}

void lightMarkers(const Preset& scene, const Rect& r, int draggedLight) {
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    float radius = 7.0f * ImGui::GetFontSize() / 13.0f;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const LightDesc& l = scene.lights[i];
        std::optional<ImVec2> at = l.type == LightType::Directional ? std::nullopt : project(scene, l.position, r);
        if (!at || !r.contains(at->x, at->y)) {
            continue; // a directional light, behind the eye or outside the view
        }
        glm::vec3 c = glm::clamp(l.diffuse, glm::vec3(0.0f), glm::vec3(1.0f));
        ImU32 fill = l.enabled ? ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1.0f)) : IM_COL32(60, 60, 60, 255);
        ImU32 ring = draggedLight == static_cast<int>(i) ? IM_COL32(255, 255, 0, 255) : IM_COL32(255, 255, 255, 200);
        dl->AddCircleFilled(*at, radius, fill);
        dl->AddCircle(*at, radius + 1.5f, ring, 0, 2.0f);
        std::string label = std::to_string(i + 1);
        dl->AddText(ImVec2(at->x + radius + 3, at->y - radius - 3), IM_COL32(255, 255, 255, 220), label.c_str());
        widgets().set("view.light" + label, {at->x - radius, at->y - radius, 2 * radius, 2 * radius});
    }
}

namespace {

std::string setSummary(const char* name, const Preset& p) {
    return std::string(name) + ": " + std::string(toString(p.shading)) + ", " + std::string(toString(p.brdf));
}

void compareLabels(const OverlayModel& m, const Layout& layout, ImDrawList* dl) {
    const Rect &a = layout.viewA, &b = layout.viewB;
    ImVec2 end = layout.compareStacked ? ImVec2(b.x + b.w, b.y) : ImVec2(b.x, b.y + b.h);
    dl->AddLine(ImVec2(b.x, b.y), end, IM_COL32(255, 255, 255, 160), 2.0f);
    float line = ImGui::GetFontSize() * 1.5f;
    dl->AddText(ImVec2(b.x + 8, b.y + b.h - line), IM_COL32(230, 90, 220, 255), setSummary("B", *m.b).c_str());
    dl->AddText(ImVec2(a.x + 8, a.y + a.h - line), IM_COL32(255, 255, 255, 230), setSummary("A", *m.a).c_str());
}

void toast(const char* text, const Rect& v, ImDrawList* dl) {
    ImVec2 size = ImGui::CalcTextSize(text);
    ImVec2 at(v.x + (v.w - size.x) * 0.5f, v.y + v.h - size.y * 3.0f);
    dl->AddRectFilled(ImVec2(at.x - 8, at.y - 4), ImVec2(at.x + size.x + 8, at.y + size.y + 4), IM_COL32(0, 0, 0, 180), 4.0f);
    dl->AddText(at, IM_COL32(255, 255, 255, 255), text);
}

} // namespace

void viewOverlay(const OverlayModel& m, const Layout& layout) {
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const Rect& v = layout.view;
    char text[160];
    std::snprintf(text, sizeof text, "%.1f ms", m.frameMs);
    ImVec2 size = ImGui::CalcTextSize(text);
    dl->AddText(ImVec2(v.x + v.w - size.x - 8, v.y + 6), IM_COL32(255, 255, 255, 200), text);
    widgets().set("view.frame-time", {v.x + v.w - size.x - 8, v.y + 6, size.x, size.y});
    std::snprintf(text, sizeof text, "%s%s  |  %s  |  %s", m.documentName.c_str(), m.dirty ? " *" : "",
                  std::string(toString(m.a->shading)).c_str(), std::string(toString(m.a->brdf)).c_str());
    dl->AddText(ImVec2(v.x + 8, v.y + 6), IM_COL32(255, 255, 255, 200), text);
    if (m.viewMode != ViewMode::Lit) {
        dl->AddText(ImVec2(v.x + 8, v.y + 6 + ImGui::GetFontSize() * 1.3f), IM_COL32(255, 220, 120, 230), toString(m.viewMode));
    }
    if (m.b) {
        compareLabels(m, layout, dl);
    }
    if (m.toast) {
        toast(m.toast, v, dl);
    }
}

} // namespace lab::ui
