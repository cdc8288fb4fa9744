// plots_3d.cpp — the 3D lobe and the intensity map, drawn with ImDrawList.
//
// One frame: the hemisphere grids of A (and B) from the state's cache (core/plots/lobe3d.h, computed
// when the inputs change), the options row and the readout, then the two canvases, placed side
// by side in a wide region and stacked in a tall one. The meshes (the surface projected by the
// orbit camera and sorted far to near, the map's disc, B's wireframe) are made once per view and
// copied into the draw list each frame; the grid lines, arrows and labels are drawn on top.
#include "ui/plots/plots_3d.h"
#include "ui/plots/plot_kit.h"
#include "ui/theme_style.h"
#include "ui/widgets.h"

#include "core/lighting/lighting.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numeric>
#include <string>

namespace lab::ui {

bool operator==(const Lobe3dKey& x, const Lobe3dKey& y) {
    auto same = [](const ImVec4& p, const ImVec4& q) { return p.x == q.x && p.y == q.y && p.z == q.z && p.w == q.w; };
    return x.a == y.a && x.hasB == y.hasB && (!x.hasB || (x.b == y.b && x.coarseB == y.coarseB)) && x.coarseA == y.coarseA &&
           x.component == y.component &&
           x.scale == y.scale && x.outer == y.outer && x.yawDeg == y.yawDeg && x.pitchDeg == y.pitchDeg &&
           same(x.lobeRect, y.lobeRect) && same(x.mapRect, y.mapRect);
}

namespace {

using namespace plotkit;

//----------------------------------------------------------------------------------------
// The orbit camera: orthographic, about the origin
//----------------------------------------------------------------------------------------

struct Camera {
    glm::vec3 toEye, right, up; // unit: towards the viewer, screen right, screen up
    glm::vec2 origin;           // the origin's screen position
    float scale = 1.0f;         // pixels per unit

    // At yaw 0, pitch 0 the camera is on +z looking at the plane of incidence: x right, N up,
    // as the plane plot shows it.
    Camera(float yawDeg, float pitchDeg, const ImVec4& rect) {
        const float yaw = glm::radians(yawDeg), pitch = glm::radians(pitchDeg);
        toEye = glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
        right = glm::vec3(std::cos(yaw), 0.0f, -std::sin(yaw));
        up = glm::cross(toEye, right);
        // The lobe lies in the unit hemisphere: x within ±1 and, seen from this elevation, up from
        // -sin(pitch) (the disc's near edge) to 1. One scale at every elevation, so that orbiting
        // does not zoom; the content centred vertically.
        scale = std::max(std::min(rect.z, rect.w) * 0.5f, 1.0f);
        const float low = -std::sin(pitch);
        origin = glm::vec2(rect.x + rect.z * 0.5f, rect.y + rect.w * 0.5f + scale * (1.0f + low) * 0.5f);
    }
    ImVec2 at(const glm::vec3& p) const { return ImVec2(origin.x + scale * glm::dot(p, right), origin.y - scale * glm::dot(p, up)); }
    float depth(const glm::vec3& p) const { return glm::dot(p, toEye); }
};

//----------------------------------------------------------------------------------------
// Colours
//----------------------------------------------------------------------------------------

// A dark-to-bright ramp (black-violet, red, orange, yellow, white) for t in [0, 1]: monotonic in
// brightness, so that a grey projector still reads it, and distinct from the curves' colours.
glm::vec3 ramp(float t) {
    static const std::array<glm::vec3, 6> stops = {glm::vec3(0.05f, 0.03f, 0.20f), glm::vec3(0.35f, 0.07f, 0.50f),
                                                   glm::vec3(0.75f, 0.15f, 0.35f), glm::vec3(0.95f, 0.45f, 0.10f),
                                                   glm::vec3(0.98f, 0.80f, 0.25f), glm::vec3(1.00f, 1.00f, 0.90f)};
    t = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(stops.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(t), stops.size() - 2);
    return glm::mix(stops[i], stops[i + 1], t - static_cast<float>(i));
}

ImU32 rgb(const glm::vec3& c, float alpha = 1.0f) {
    const glm::vec3 k = glm::clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f;
    return IM_COL32(static_cast<int>(k.r), static_cast<int>(k.g), static_cast<int>(k.b), static_cast<int>(alpha * 255.0f));
}

// The intensity at ramp position t: plotRadius's inverse.
float valueAt(float t, float outer, RadialScale scale) {
    return scale == RadialScale::Linear ? t * outer : outer * std::pow(10.0f, (t - 1.0f) * kLogDecades);
}

//----------------------------------------------------------------------------------------
// The meshes, made once per view
//----------------------------------------------------------------------------------------

void surfaceMesh(const HemisphereGrid& grid, const Lobe3dKey& key, Lobe3dMesh& m) {
    const Camera cam(key.yawDeg, key.pitchDeg, key.lobeRect);
    const std::vector<float>& values = grid.component(key.component);
    const std::vector<glm::vec3> points = lobeSurface(grid, key.component, key.outer, key.scale);
    const std::size_t n = points.size();
    const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
    m.surface.vertices.resize(n);
    // Shading from a light above and behind the viewer's right shoulder; normals by central
    // differences over the grid (sign-free: the lobe's inside shows where a surface folds).
    const glm::vec3 light = glm::normalize(cam.toEye + 0.6f * cam.up + 0.3f * cam.right);
    std::vector<float> depth(n);
    const int rings = grid.rings(), meridians = grid.meridians();
    auto at = [&](int ring, int meridian) { return grid.index(ring, meridian); };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < meridians; ++j) {
            const std::size_t k = static_cast<std::size_t>(at(i, j));
            const int jm = j == 0 ? meridians - 2 : j - 1, jp = j == meridians - 1 ? 1 : j + 1;
            const glm::vec3 alongTheta = points[static_cast<std::size_t>(at(std::min(i + 1, rings - 1), j))] -
                                         points[static_cast<std::size_t>(at(std::max(i - 1, 0), j))];
            const glm::vec3 alongPhi = points[static_cast<std::size_t>(at(i, jp))] - points[static_cast<std::size_t>(at(i, jm))];
            glm::vec3 normal = glm::cross(alongTheta, alongPhi);
            const float len = glm::length(normal);
            float shade = 0.75f;
            if (len > 1e-12f) {
                shade = 0.35f + 0.65f * std::fabs(glm::dot(normal / len, light));
            }
            const float t = plotRadius(values[k], key.outer, key.scale);
            m.surface.vertices[k] = ImDrawVert{cam.at(points[k]), uv, rgb(ramp(t) * shade, 0.92f)};
            depth[k] = cam.depth(points[k]);
        }
    }
    // Two triangles per cell, the cells far to near by their mean depth.
    struct Cell {
        float depth;
        int k;
    };
    std::vector<Cell> cells;
    cells.reserve(static_cast<std::size_t>((rings - 1) * (meridians - 1)));
    for (int i = 0; i + 1 < rings; ++i) {
        for (int j = 0; j + 1 < meridians; ++j) {
            const int k = at(i, j);
            const float d = depth[static_cast<std::size_t>(k)] + depth[static_cast<std::size_t>(k + 1)] +
                            depth[static_cast<std::size_t>(k + meridians)] + depth[static_cast<std::size_t>(k + meridians + 1)];
            cells.push_back({d, k});
        }
    }
    std::sort(cells.begin(), cells.end(), [](const Cell& x, const Cell& y) { return x.depth < y.depth; });
    m.surface.indices.clear();
    m.surface.indices.reserve(cells.size() * 6);
    for (const Cell& c : cells) {
        const unsigned k = static_cast<unsigned>(c.k), w = static_cast<unsigned>(meridians);
        for (unsigned v : {k, k + 1, k + w + 1, k, k + w + 1, k + w}) {
            m.surface.indices.push_back(static_cast<ImDrawIdx>(v)); // 8,281 vertices
        }
    }
}

// The map: each grid direction at mapPoint(V) on the disc, coloured by its value. A grid direction's
// θo is its ring's, so the projection needs no arc tangent: radius θo/90° along (x, z)/sin θo.
void mapMesh(const HemisphereGrid& grid, const Lobe3dKey& key, Lobe3dMesh& m) {
    const ImVec4& r = key.mapRect;
    const glm::vec2 centre(r.x + r.z * 0.5f, r.y + r.w * 0.5f);
    const float radius = std::min(r.z, r.w) * 0.5f;
    const std::vector<float>& values = grid.component(key.component);
    const int rings = grid.rings(), meridians = grid.meridians();
    const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
    m.map.vertices.resize(values.size());
    for (int i = 0; i < rings; ++i) {
        const float thetaDeg = static_cast<float>(i * grid.steps.thetaDeg);
        const float sinTheta = outgoingDirections()[static_cast<std::size_t>(90 + i * grid.steps.thetaDeg)].x;
        const float along = i == 0 ? 0.0f : radius * (thetaDeg / 90.0f) / sinTheta;
        for (int j = 0; j < meridians; ++j) {
            const std::size_t k = static_cast<std::size_t>(grid.index(i, j));
            const glm::vec3& V = grid.directions[k];
            m.map.vertices[k] = ImDrawVert{ImVec2(centre.x + along * V.x, centre.y + along * V.z), uv,
                                           rgb(ramp(plotRadius(values[k], key.outer, key.scale)))};
        }
    }
    m.map.indices.clear();
    m.map.indices.reserve(static_cast<std::size_t>((rings - 1) * (meridians - 1) * 6));
    for (int i = 0; i + 1 < rings; ++i) {
        for (int j = 0; j + 1 < meridians; ++j) {
            const unsigned k = static_cast<unsigned>(grid.index(i, j)), w = static_cast<unsigned>(meridians);
            for (unsigned v : {k, k + 1, k + w + 1, k, k + w + 1, k + w}) {
                m.map.indices.push_back(static_cast<ImDrawIdx>(v));
            }
        }
    }
}

// The surface plane's rings at the radial scale's values, as the camera sees them.
void planeRings(const Lobe3dKey& key, Lobe3dMesh& m) {
    const Camera cam(key.yawDeg, key.pitchDeg, key.lobeRect);
    const float pi = glm::pi<float>();
    for (const RadialRing& ring : radialRings(key.outer, key.scale)) {
        std::vector<ImVec2>& circle = m.rings.emplace_back();
        for (int k = 0; k <= 72; ++k) {
            const float t = 2.0f * pi * static_cast<float>(k) / 72.0f;
            circle.push_back(cam.at(ring.radius * glm::vec3(std::cos(t), 0.0f, std::sin(t))));
        }
    }
}

// B as rings every 15° of θo and meridians every 24° of φ (both grids' steps divide them).
void wireframe(const HemisphereGrid& grid, const Lobe3dKey& key, Lobe3dMesh& m) {
    static_assert(15 % kLobeGrid.thetaDeg == 0 && 15 % kLobeCoarseGrid.thetaDeg == 0 && 24 % kLobeGrid.phiDeg == 0 &&
                  24 % kLobeCoarseGrid.phiDeg == 0);
    const Camera cam(key.yawDeg, key.pitchDeg, key.lobeRect);
    // The surface's points on the lines only.
    auto point = [&](int i, int j) {
        return cam.at(lobeSurfacePoint(grid, static_cast<std::size_t>(grid.index(i, j)), key.component, key.outer, key.scale));
    };
    const int rings = grid.rings(), meridians = grid.meridians();
    const int ringStep = 15 / grid.steps.thetaDeg, meridianStep = 24 / grid.steps.phiDeg;
    m.wireframe.clear();
    for (int i = ringStep; i < rings; i += ringStep) {
        std::vector<ImVec2>& line = m.wireframe.emplace_back();
        for (int j = 0; j < meridians; ++j) {
            line.push_back(point(i, j));
        }
    }
    for (int j = 0; j + 1 < meridians; j += meridianStep) {
        std::vector<ImVec2>& line = m.wireframe.emplace_back();
        for (int i = 0; i < rings; ++i) {
            line.push_back(point(i, j));
        }
    }
}

//----------------------------------------------------------------------------------------
// The canvases
//----------------------------------------------------------------------------------------

struct View {
    const Preset* a = nullptr;
    LobeInputs inA, inB;
    std::shared_ptr<const HemisphereGrid> gridA, gridB;
    bool coarseA = false, coarseB = false; // drawn from the coarse grid while the inputs change
    LobeMaximum peak;
    LobeVectors vectors;
    glm::vec3 viewer{0.0f, 1.0f, 0.0f}; // V: the plane plot's, or a probed point's (out of the plane too)
    bool atPoint = false;               // plots at the probe: V is marked on the map as well
    float outer = 1.0f, largest = 0.0f;
    Readout readout;
};

const char* componentName(PlotComponent c) {
    return c == PlotComponent::Diffuse ? "diffuse" : c == PlotComponent::Specular ? "specular" : "total";
}

Ink componentInk(PlotComponent c) {
    return c == PlotComponent::Diffuse ? Ink::Diffuse : c == PlotComponent::Specular ? Ink::Specular : Ink::Total;
}

void arrow3d(ScreenPlot& plot, const Camera& cam, const glm::vec3& dir, float length, Ink ink, const char* label,
             float width) {
    plot.canvas.arrow(toVec2(cam.at(glm::vec3(0.0f))), toVec2(cam.at(dir * length)), ink, width, label);
}

// Thin solid lines made with the mesh (`which`: its rings, B's wireframe), kept as painted by the
// mesh's serial: an unchanged frame copies them.
void meshLines(ImDrawList* dl, const Lobe3dMesh& mesh, int which, const std::vector<std::vector<ImVec2>>& lines,
               float width, Ink ink, PaintedLines& kept) {
    const FigureColor color = colorOf(currentColors().plot, ink);
    std::string d;
    describe(d, mesh.serial, which);
    drawKeptLines(dl, d, lines, width, color, kept);
}

void lobeCanvas(const Canvas& c, const Pens& p, const View& v, const Lobe3dKey& key, const Lobe3dMesh& mesh,
                PlotSettings& s) {
    ImDrawList* dl = c.dl;
    const Camera cam(key.yawDeg, key.pitchDeg, key.lobeRect);
    // The surface plane: rings at the radial scale's values, spokes every 30°, behind the lobe
    // (the camera stays above the plane). The rings and B's wireframe are kept with the mesh.
    meshLines(dl, mesh, 0, mesh.rings, p.thin, Ink::Grid, s.cache.painted());
    for (int deg = 0; deg < 360; deg += 30) {
        const float t = glm::radians(static_cast<float>(deg));
        dl->AddLine(cam.at(glm::vec3(0.0f)), cam.at(glm::vec3(std::cos(t), 0.0f, std::sin(t))),
                    deg % 180 == 0 ? ink(Ink::Axis) : ink(Ink::Grid), p.thin);
    }
    drawMesh(dl, mesh.surface);
    meshLines(dl, mesh, 1, mesh.wireframe, p.thin, Ink::Compare, s.cache.painted());
    // The vectors: N, L, R, and V (the plane plot's reading direction) with its H.
    const glm::vec3& V = v.viewer;
    ScreenPlot vectors;
    const PlotStyle& style = vectors.style;
    arrow3d(vectors, cam, v.vectors.N, 1.08f, Ink::Axis, "N", style.stroke());
    arrow3d(vectors, cam, v.vectors.L, 1.1f, Ink::Light, "L", style.bold());
    arrow3d(vectors, cam, v.vectors.R, 1.1f, Ink::Mirror, "R", style.stroke());
    arrow3d(vectors, cam, V, 0.9f, Ink::Viewer, "V", style.thin() * 1.5f);
    arrow3d(vectors, cam, glsl::halfVector(v.vectors.L, V), 0.7f, Ink::Half, "H", style.stroke());
    vectors.paintWhole(dl, s.cache.painted());
    if (v.peak.value > 0.0f && v.largest > kNothingLit) {
        const ImVec2 q = cam.at(plotRadius(v.peak.value, v.outer, key.scale) * v.peak.V);
        dl->AddCircle(q, 4.5f * p.s, ink(Ink::Text), 0, p.stroke);
    }
    // Orbiting: a drag turns the camera about N and raises or lowers it.
    if (ImGui::IsItemActive()) {
        const ImVec2 d = ImGui::GetIO().MouseDelta;
        const float perPixel = 0.5f / p.s;
        s.lobe3d.yawDeg = std::remainder(s.lobe3d.yawDeg - d.x * perPixel, 360.0f);
        s.lobe3d.pitchDeg = std::clamp(s.lobe3d.pitchDeg + d.y * perPixel, 0.0f, 90.0f);
    }
}

// The map's grid, marks and legend.
void mapMarks(const Canvas& c, const Pens& p, const View& v, const Lobe3dKey& key, float legendW) {
    ImDrawList* dl = c.dl;
    const ImVec4& r = key.mapRect;
    const ImVec2 centre(r.x + r.z * 0.5f, r.y + r.w * 0.5f);
    const float radius = std::min(r.z, r.w) * 0.5f;
    for (int deg = 30; deg <= 90; deg += 30) {
        dl->AddCircle(centre, radius * static_cast<float>(deg) / 90.0f, deg == 90 ? ink(Ink::Axis) : ink(Ink::Grid), 64, p.thin);
    }
    dl->AddLine(ImVec2(centre.x - radius, centre.y), ImVec2(centre.x + radius, centre.y), ink(Ink::Grid), p.thin);
    dl->AddLine(ImVec2(centre.x, centre.y - radius), ImVec2(centre.x, centre.y + radius), ink(Ink::Grid), p.thin);
    if (radius > 4.0f * p.font) {
        // The rings' θo down the vertical axis, inside each ring: the plane of incidence (the
        // horizontal axis) is where L, R and most peaks are marked.
        for (int deg = 30; deg <= 90; deg += 30) {
            const std::string t = degrees(static_cast<float>(deg));
            dl->AddText(ImVec2(centre.x + 2.0f, centre.y + radius * static_cast<float>(deg) / 90.0f - textSize(t).y - 1.0f),
                        ink(Ink::Text), t.c_str());
        }
    }
    auto spot = [&](const glm::vec3& dir, Ink which, const char* label, bool cross) {
        const ImU32 color = ink(which);
        const glm::vec2 q = mapPoint(dir);
        const ImVec2 m(centre.x + radius * q.x, centre.y + radius * q.y);
        if (cross) {
            const float h = 5.0f * p.s;
            dl->AddLine(ImVec2(m.x - h, m.y - h), ImVec2(m.x + h, m.y + h), color, p.stroke);
            dl->AddLine(ImVec2(m.x - h, m.y + h), ImVec2(m.x + h, m.y - h), color, p.stroke);
        } else {
            dl->AddCircleFilled(m, 3.5f * p.s, color);
        }
        if (label) {
            dl->AddText(ImVec2(m.x + p.pad, m.y - p.line), color, label);
        }
    };
    spot(v.vectors.R, Ink::Mirror, "R", false);
    if (v.vectors.L.y > 0.0f) {
        spot(v.vectors.L, Ink::Light, "L", false); // where the light is, seen from above
    }
    if (v.atPoint && v.viewer.y > 0.0f) {
        spot(v.viewer, Ink::Viewer, "V", false); // the probed point's V, wherever it lies
    }
    if (v.peak.value > 0.0f && v.largest > kNothingLit) {
        spot(v.peak.V, Ink::Text, nullptr, true);
    }
    // The legend: the ramp from 0 (bottom) to the outer value (top), five values beside it.
    if (legendW <= 0.0f) {
        return;
    }
    const float barW = 0.8f * p.font, top = c.corner.y + p.line * 0.5f, bottom = c.corner.y + c.height - p.line * 0.5f;
    const float x = c.corner.x + c.width - legendW + p.pad;
    if (bottom - top < 2.0f * p.line) {
        return;
    }
    const int steps = 32;
    for (int k = 0; k < steps; ++k) {
        const float t0 = static_cast<float>(k) / steps, t1 = static_cast<float>(k + 1) / steps;
        const ImU32 lo = rgb(ramp(t0)), hi = rgb(ramp(t1));
        dl->AddRectFilledMultiColor(ImVec2(x, bottom - (bottom - top) * t1), ImVec2(x + barW, bottom - (bottom - top) * t0),
                                    hi, hi, lo, lo);
    }
    dl->AddRect(ImVec2(x, top), ImVec2(x + barW, bottom), ink(Ink::Axis), 0.0f, 0, p.thin);
    const int labels = std::clamp(static_cast<int>((bottom - top) / (1.5f * p.line)), 2, 5);
    for (int k = 0; k < labels; ++k) {
        const float t = static_cast<float>(k) / static_cast<float>(labels - 1);
        const float y = bottom - (bottom - top) * t;
        const std::string text = t == 0.0f && key.scale == RadialScale::Linear ? "0" : tickText(valueAt(t, v.outer, key.scale));
        dl->AddLine(ImVec2(x + barW, y), ImVec2(x + barW + p.pad * 0.5f, y), ink(Ink::Axis), p.thin);
        dl->AddText(ImVec2(x + barW + p.pad, y - p.line * 0.5f), ink(Ink::Text), text.c_str());
    }
}

// The map's mesh, and its marks over it: kept as painted, found by everything mapMarks draws them from.
void mapCanvas(const Canvas& c, const Pens& p, const View& v, const Lobe3dKey& key, const Lobe3dMesh& mesh,
               float legendW, PaintedLines& kept) {
    drawMesh(c.dl, mesh.map);
    std::string d;
    describe(d, c.corner.x, c.corner.y, c.width, c.height, legendW, key.mapRect.x, key.mapRect.y, key.mapRect.z,
             key.mapRect.w, key.scale, p.s, p.font, p.line, p.pad, p.thin, p.stroke);
    for (Ink i : {Ink::Axis, Ink::Grid, Ink::Text, Ink::Mirror, Ink::Light, Ink::Viewer}) {
        describe(d, ink(i));
    }
    describe(d, v.vectors.R, v.vectors.L, v.atPoint, v.viewer, v.peak.value, v.peak.V, v.largest, v.outer);
    drawKept(c.dl, d, kept, [&] { mapMarks(c, p, v, key, legendW); });
}

// The options row: the component and the radial scale (shared with the plane plots).
void options(PlotSettings& s, const Pens& p) {
    static const PlotComponent components[3] = {PlotComponent::Diffuse, PlotComponent::Specular, PlotComponent::Total};
    static const char* const marks[3] = {"plot.lobe3d.diffuse", "plot.lobe3d.specular", "plot.lobe3d.total"};
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    auto sameLineIfFits = [&](const char* label) {
        const float w = ImGui::GetFrameHeight() + p.inner + ImGui::CalcTextSize(label, nullptr, true).x;
        if (ImGui::GetItemRectMax().x + p.gapX + w <= right) {
            ImGui::SameLine();
        }
    };
    // Full names where the row fits on one line, short ones where it does not (a low band).
    static const char* const full[3] = {"diffuse###lobe3d.d", "specular###lobe3d.s", "total###lobe3d.t"};
    static const char* const brief[3] = {"diff###lobe3d.d", "spec###lobe3d.s", "total###lobe3d.t"};
    float rowW = 4.0f * p.gapX;
    for (const char* label : {full[0], full[1], full[2], "lin", "log"}) {
        rowW += ImGui::GetFrameHeight() + p.inner + ImGui::CalcTextSize(label, nullptr, true).x;
    }
    const char* const* names = rowW <= ImGui::GetContentRegionAvail().x ? full : brief;
    int chosen = static_cast<int>(s.lobe3d.component);
    for (int i = 0; i < 3; ++i) {
        if (i > 0) {
            sameLineIfFits(names[i]);
        }
        ImGui::RadioButton(names[i], &chosen, i);
        mark(marks[i]);
    }
    s.lobe3d.component = components[chosen];
    int scale = s.scale == RadialScale::Linear ? 0 : 1;
    sameLineIfFits("lin###lobe3d.linear");
    ImGui::RadioButton("lin###lobe3d.linear", &scale, 0);
    mark("plot.lobe3d.linear");
    sameLineIfFits("log###lobe3d.log");
    ImGui::RadioButton("log###lobe3d.log", &scale, 1);
    mark("plot.lobe3d.log");
    s.scale = scale == 0 ? RadialScale::Linear : RadialScale::Log;
}

// At a probed point (plots at the probe): which light, θi, and V's place when it leaves the plane.
void pointTokens(Readout& r, const ProbeLobe& at) {
    r.add(format("at the probe, Light %d: %si %.1f%s", at.light + 1, "\xce\xb8", double(at.incidentDeg), kDeg), Ink::Light);
    if (at.outOfPlaneDeg >= 0.5f) {
        r.add(format("V is %.0f%s out of the plane of incidence", double(at.outOfPlaneDeg), kDeg), Ink::Viewer);
    }
    r.lineBreak();
}

// The grid for `inputs`: the full one, or the coarse one during a change when the full one is not kept
// (a frame whose inputs changed owes the frame after, which draws the full one). The coarse one lags
// like the albedo: it is the grid of the draft's inputs, taken again at most every 0.5 s, and `inputs`
// become those.
std::shared_ptr<const HemisphereGrid> grid(PlotSettings& s, ChangeWatch& watch, LaggingDraft<LobeInputs>& draft,
                                           LobeInputs& inputs, bool& coarse) {
    Lobe3dState& st = s.lobe3d;
    coarse = s.cache.coarse(s.cache.observe(watch, inputs), st.grids.find({inputs, false}) != nullptr);
    if (coarse) {
        inputs = draft.take(inputs, ImGui::GetTime());
    }
    return st.grids.get({inputs, coarse}, [&] { return sampleHemisphere(inputs, coarse ? kLobeCoarseGrid : kLobeGrid); });
}

View viewData(const Preset& a, const Preset* b, PlotSettings& s, const Pens& p, const ProbeLobe* point) {
    View v;
    v.a = &a;
    Lobe3dState& st = s.lobe3d;
    v.inA = point ? probeLobeInputs(a, *point) : lobeInputs(a, a.plotIncidentDeg);
    v.gridA = grid(s, st.watchA, st.draftA, v.inA, v.coarseA);
    if (b) {
        v.inB = point ? probeLobeInputs(*b, *point) : lobeInputs(*b, a.plotIncidentDeg);
        v.gridB = grid(s, st.watchB, st.draftB, v.inB, v.coarseB);
    }
    v.viewer = point ? point->viewer : outgoingDirection(std::fabs(s.viewerDeg), s.viewerDeg >= 0.0f ? 0.0f : 180.0f);
    v.atPoint = point != nullptr;
    if (point) {
        pointTokens(v.readout, *point);
    }
    v.vectors = lobeVectors(v.inA.incidentDeg);
    if (st.largest.a != v.gridA || st.largest.b != v.gridB || st.largest.component != st.component) {
        const float largestA = v.gridA->largest(st.component);
        st.largest = {v.gridA, v.gridB, st.component, v.gridB ? std::max(largestA, v.gridB->largest(st.component)) : largestA};
    }
    v.largest = st.largest.value;
    v.outer = outerRing(v.largest);
    v.peak = *st.peaks.get({{v.inA, v.coarseA}, st.component}, [&] { return lobeMaximum(v.inA, *v.gridA, st.component); });
    // The coarse lobe's peak is found from the coarse grid: muted, like a lagging number, until the full grid's.
    const Ink color = v.coarseA ? Ink::Muted : componentInk(st.component);
    if (!(v.largest > kNothingLit)) {
        v.readout.add(format("%s: 0 everywhere (term switched off?)", componentName(st.component)), Ink::Text);
    } else if (st.component == PlotComponent::Diffuse) {
        v.readout.add(format("diffuse %.3f in every direction", double(v.peak.value)), color);
    } else {
        v.readout.add(format("%s peak %.3f", componentName(st.component), double(v.peak.value)), color);
        v.readout.add(format("at %s%.1f%s, %s%.1f%s", "\xce\xb8o ", double(v.peak.thetaDeg), kDeg, "\xcf\x86 ",
                             double(v.peak.phiDeg), kDeg),
                      color);
        const float offR = glm::degrees(std::acos(glm::clamp(glm::dot(v.peak.V, v.vectors.R), -1.0f, 1.0f)));
        v.readout.add(format("(%.1f%s from R)", double(offR), kDeg), v.coarseA ? Ink::Muted : Ink::Mirror);
    }
    if (b && v.largest > kNothingLit) {
        v.readout.add("B: wireframe", Ink::Compare, true);
    }
    v.readout.lineBreak();
    scaleTokens(v.readout, v.outer, v.largest, false, b ? "max of A and B" : "max");
    v.readout.add("drag to orbit", Ink::Text);
    v.readout.measure(p);
    return v;
}

// What the canvases show and where: the lobe's rectangle inside `lobeBox` (a margin for the
// arrows' names and the ring values), the map's square inside `mapBox` beside its legend.
Lobe3dKey keyFor(const View& v, const PlotSettings& s, const ImVec4& lobeBox, const ImVec4& mapBox, float legendW,
                 const Pens& p) {
    const float margin = 0.6f * p.line + p.pad;
    Lobe3dKey key;
    key.a = v.inA;
    key.hasB = v.gridB != nullptr;
    key.b = v.inB;
    key.coarseA = v.coarseA;
    key.coarseB = v.coarseB;
    key.component = s.lobe3d.component;
    key.scale = s.scale;
    key.outer = v.outer;
    key.yawDeg = s.lobe3d.yawDeg;
    key.pitchDeg = s.lobe3d.pitchDeg;
    key.lobeRect = ImVec4(lobeBox.x + margin, lobeBox.y + margin, lobeBox.z - 2.0f * margin, lobeBox.w - 2.0f * margin);
    const float mapSide = std::min(mapBox.z - legendW, mapBox.w) - 2.0f * p.pad;
    key.mapRect = ImVec4(mapBox.x + p.pad + std::max((mapBox.z - legendW - 2.0f * p.pad - mapSide) * 0.5f, 0.0f),
                         mapBox.y + (mapBox.w - mapSide) * 0.5f, mapSide, mapSide);
    return key;
}

} // namespace

void lobe3dPanel(const Preset& a, const Preset* b, PlotSettings& s, const ProbeLobe* point) {
    const Pens p = pens();
    options(s, p);
    const View v = viewData(a, b, s, p, point);

    const ImVec2 room = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    widgets().set("plots.area", {origin.x, origin.y, room.x, room.y});
    // In a low band the canvases need the readout's room more than the readout does (the peak is
    // circled on both): the readout gives way where fewer than 12 lines would be left for them.
    float stripH = std::min(v.readout.height(p, room.x), std::max(room.y, 0.0f));
    if (room.y - stripH < 12.0f * p.line) {
        stripH = 0.0f;
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImGui::PushClipRect(origin, ImVec2(origin.x + room.x, origin.y + std::max(room.y, 1.0f)), true);
    dl->PushClipRect(origin, ImVec2(origin.x + room.x, origin.y + std::max(stripH, 1.0f)), true);
    if (stripH > 0.0f) {
        v.readout.draw(dl, p, origin, room.x, &s.cache.painted());
        ImGui::Dummy(ImVec2(std::max(room.x, 1.0f), stripH));
        mark("plot.lobe3d.readout");
    }
    dl->PopClipRect();

    // The canvases: side by side where the region is wide, else the lobe above the map. The map
    // keeps a column for its legend.
    const float top = origin.y + (stripH > 0.0f ? stripH + p.gap : 0.0f);
    const float h = room.y - (top - origin.y);
    const float legendW = 0.8f * p.font + 2.0f * p.pad + textSize("0.000").x;
    const bool wide = room.x > 1.25f * h;
    ImVec4 lobeBox, mapBox;
    if (wide) {
        const float mapW = std::min(h + legendW, room.x * 0.42f);
        lobeBox = ImVec4(origin.x, top, room.x - mapW - p.gapX, h);
        mapBox = ImVec4(origin.x + room.x - mapW, top, mapW, h);
    } else {
        const float lobeH = std::floor((h - p.gap) * 0.58f);
        lobeBox = ImVec4(origin.x, top, room.x, lobeH);
        mapBox = ImVec4(origin.x, top + lobeH + p.gap, room.x, h - lobeH - p.gap);
    }
    const Lobe3dKey key = keyFor(v, s, lobeBox, mapBox, legendW, p);
    const float mapSide = key.mapRect.z;
    const bool lobeShown = key.lobeRect.z >= 1.5f * p.font && key.lobeRect.w >= 1.5f * p.font;
    const bool mapShown = mapSide >= 2.5f * p.font;
    const std::shared_ptr<const Lobe3dMesh> mesh = s.lobe3d.meshes.get(key, [&] {
        static std::atomic<std::uint64_t> made{0};
        Lobe3dMesh m;
        m.serial = ++made;
        if (lobeShown) {
            surfaceMesh(*v.gridA, key, m);
            planeRings(key, m);
            if (v.gridB) {
                wireframe(*v.gridB, key, m);
            }
        }
        if (mapShown) {
            mapMesh(*v.gridA, key, m);
        }
        return m;
    });

    // Each canvas in its box, its drawing clipped to it.
    auto canvasIn = [&](const ImVec4& box, const char* id, const char* name, bool shown, auto&& draw) {
        if (box.z < 1.0f || box.w < 1.0f) {
            return;
        }
        ImGui::SetCursorScreenPos(ImVec2(box.x, box.y));
        const Canvas canvas = beginCanvas(id, name, box.z, box.w);
        if (canvas.shown() && shown) {
            dl->PushClipRect(canvas.corner, ImVec2(canvas.corner.x + canvas.width, canvas.corner.y + canvas.height), true);
            draw(canvas);
            dl->PopClipRect();
        }
    };
    canvasIn(lobeBox, "lobe3d", "plot.lobe3d", lobeShown, [&](const Canvas& c) { lobeCanvas(c, p, v, key, *mesh, s); });
    canvasIn(mapBox, "lobe3d.map", "plot.lobe3d.map", mapShown, [&](const Canvas& c) { mapCanvas(c, p, v, key, *mesh, legendW, s.cache.painted()); });
    ImGui::PopClipRect();
}

} // namespace lab::ui
