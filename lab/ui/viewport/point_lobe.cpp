// point_lobe.cpp — the probed point's lobe, projected onto the model's viewport.
#include "ui/viewport/point_lobe.h"

#include "core/scene/transforms.h"

#include "ui/plots/plot_kit.h"

#include <imgui.h>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace lab::ui {

namespace {

using plotkit::ink; // the plots' colours: the same lobe, the same inks

constexpr float kShare = 0.18f;  // the lobe's reach: this share of the view's narrower side
constexpr int kPlanes = 4;       // the plane of incidence and three more, 45° apart
constexpr ImU32 kOutline = IM_COL32(0, 0, 0, 170);

// The view's projection of world points into `r` (window units).
struct Projector {
    glm::mat4 viewProjection;
    Rect r;
    std::optional<ImVec2> operator()(const glm::vec3& world) const {
        const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
        if (clip.w <= 1e-4f) {
            return std::nullopt;
        }
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return ImVec2(r.x + (ndc.x * 0.5f + 0.5f) * r.w, r.y + (0.5f - ndc.y * 0.5f) * r.h);
    }
};

// A line with a dark edge, legible over any colour of the model.
void stroke(ImDrawList* dl, const std::vector<ImVec2>& points, ImU32 color, float width) {
    const int n = static_cast<int>(points.size());
    dl->AddPolyline(points.data(), n, kOutline, 0, width + 2.0f);
    dl->AddPolyline(points.data(), n, color, 0, width);
}

// The world length that spans kShare of the view's narrower side at the point's depth.
float worldReach(const Preset& scene, const glm::vec3& point, const Rect& r) {
    const Transforms t = computeTransforms(scene, r.w / r.h);
    const float depth = std::max(-(t.view * glm::vec4(point, 1.0f)).z, 1e-3f);
    const float perUnit = r.h / (2.0f * depth * std::tan(verticalFovRadians(scene.camera, r.w / r.h) * 0.5f));
    return kShare * std::min(r.w, r.h) / perUnit;
}

} // namespace

void pointLobe(const Preset& scene, const ProbeLobe& at, const Rect& r, ImDrawList* dl) {
    const Transforms t = computeTransforms(scene, r.w / r.h);
    const Projector project{t.projection * t.view, r};
    const PointFrame& f = at.world;
    const float reach = worldReach(scene, f.origin, r);
    auto world = [&](const glm::vec3& q) { return f.origin + reach * (q.x * f.tangent + q.y * f.N + q.z * f.across); };
    // Every point projected, or nothing drawn (a lobe reaching behind the eye would be drawn wrong).
    auto polyline = [&](const std::vector<glm::vec3>& plotPoints, std::vector<ImVec2>& out) {
        out.clear();
        for (const glm::vec3& q : plotPoints) {
            const std::optional<ImVec2> p = project(world(q));
            if (!p) {
                return false;
            }
            out.push_back(*p);
        }
        return true;
    };
    const float unit = ImGui::GetFontSize() / 13.0f;
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), true);
    std::vector<ImVec2> line;
    // The tangent plane: a ring about the point.
    std::vector<glm::vec3> ring;
    for (int k = 0; k <= 48; ++k) {
        const float a = glm::two_pi<float>() * static_cast<float>(k) / 48.0f;
        ring.emplace_back(0.7f * std::cos(a), 0.0f, 0.7f * std::sin(a));
    }
    if (polyline(ring, line)) {
        stroke(dl, line, ink(Ink::Grid), 1.0f * unit);
    }
    // The lobe: the other planes thin and first, the plane of incidence filled and bold over them
    // (a fan from the point: a polar curve is seen whole from its origin).
    const std::vector<std::vector<glm::vec3>> curves = lobeWireframe(probeLobeInputs(scene, at), kPlanes);
    const ImU32 total = ink(Ink::Total), faint = (total & 0x00FFFFFFu) | 0x90000000u, fill = (total & 0x00FFFFFFu) | 0x48000000u;
    for (std::size_t k = curves.size(); k-- > 0;) {
        if (!polyline(curves[k], line)) {
            continue;
        }
        if (k == 0) {
            const std::optional<ImVec2> o = project(f.origin);
            for (std::size_t i = 0; o && i + 1 < line.size(); ++i) {
                dl->AddTriangleFilled(*o, line[i], line[i + 1], fill);
            }
        }
        stroke(dl, line, k == 0 ? total : faint, (k == 0 ? 2.5f : 1.2f) * unit);
    }
    // N and L (L where the light really is, below the surface when it is behind it).
    const float ti = glm::radians(at.incidentDeg);
    const glm::vec3 N(0.0f, 1.0f, 0.0f), L(-std::sin(ti), std::cos(ti), 0.0f);
    struct Arrow {
        glm::vec3 tip;
        ImU32 color;
        const char* name;
    };
    for (const Arrow& a : {Arrow{0.9f * N, ink(Ink::Axis), "N"}, Arrow{1.15f * L, ink(Ink::Light), "L"}}) {
        if (polyline({glm::vec3(0.0f), a.tip}, line)) {
            stroke(dl, line, a.color, 2.0f * unit);
            dl->AddText(ImVec2(line[1].x + 3.0f * unit, line[1].y - ImGui::GetFontSize() * 0.5f), a.color, a.name);
        }
    }
    dl->PopClipRect();
}

} // namespace lab::ui
