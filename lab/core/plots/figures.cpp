// figures.cpp — the four plot figures as Figures (figures.h): the page's frame (title, subtitle,
// legend), the polar grid and the Cartesian axes, and the curves from core/plots/plot_data.h and
// core/plots/energy.h. Layout in pixels at scale 1; text measured with the font the PNG draws with.
#include "core/plots/figures.h"

#include "core/plots/energy.h"
#include "core/scene/preset_choices.h"
#include "core/io/file_io.h"
#include "core/lighting/lighting.h"
#include "core/io/number_format.h"
#include "core/plots/plot_layout.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lab {

namespace {

//----------------------------------------------------------------------------------------
// The page: sizes, colours, text
//----------------------------------------------------------------------------------------

constexpr float kWidth = 720.0f;
constexpr float kPolarHeight = 500.0f;
constexpr float kCartesianHeight = 460.0f;
constexpr float kMargin = 18.0f;
constexpr float kTitleSize = 18.0f;
constexpr float kTextSize = 14.0f;
constexpr float kSmallSize = 12.5f;
constexpr float kPad = 6.0f;
constexpr float kThin = 1.0f;
constexpr float kStroke = 2.0f;
constexpr float kBold = 3.0f;

// Dark ink on white, the on-screen plots' hues (ui/plot_kit.h) darkened where white would wash
// them out; the total is black, as white is on screen.
constexpr FigureColor kInk{25, 25, 30};
constexpr FigureColor kMuted{90, 90, 100};
constexpr FigureColor kGrid{200, 200, 210};
constexpr FigureColor kAxis{60, 60, 70};
constexpr FigureColor kDiffuse{30, 110, 220};
constexpr FigureColor kSpecular{225, 120, 10};
constexpr FigureColor kTotal{20, 20, 20};
constexpr FigureColor kCompare{200, 40, 180};
constexpr FigureColor kLight{190, 140, 0};
constexpr FigureColor kMirror{40, 150, 60};
constexpr FigureColor kOverlay[3] = {{215, 50, 50}, {40, 160, 60}, {50, 100, 230}};

const char* const kDeg = "\xc2\xb0";
const char* const kTheta = "\xce\xb8";

std::string format(const char* f, double v) {
    char text[64];
    std::snprintf(text, sizeof text, f, v);
    return text;
}
std::string tickText(float v) { return format("%.3g", double(v)); }
std::string degrees(float deg) { return format("%.0f", double(deg)) + kDeg; }

float textWidth(const std::string& text, float size) {
    const TextFont& font = sharedTextFont();
    return font.measure(text, size * font.lineHeightPerEm()).width;
}

// `text` cut (with "…") to at most `width` pixels at the SVG font size `size`.
std::string fitted(const std::string& text, float size, float width) {
    const TextFont& font = sharedTextFont();
    return font.fitted(text, size * font.lineHeightPerEm(), width);
}

struct Page {
    Figure f;

    void line(std::vector<glm::vec2> pts, float width, FigureColor c, std::string id = {}) {
        f.shapes.emplace_back(std::in_place_type<FigureLine>, FigureLine{std::move(pts), width, c, std::move(id)});
    }
    // Text whose capitals are centred on y (DejaVu's cap height is 0.73 em).
    void text(glm::vec2 at, std::string t, float size, FigureColor c, TextAnchor anchor = TextAnchor::Start, bool bold = false) {
        f.shapes.emplace_back(std::in_place_type<FigureText>, FigureText{{at.x, at.y + 0.365f * size}, std::move(t), size, c, anchor, bold});
    }
    void disc(glm::vec2 c, float r, FigureColor color) { f.shapes.emplace_back(std::in_place_type<FigureDisc>, FigureDisc{c, r, color}); }
    void arrow(glm::vec2 from, glm::vec2 to, FigureColor c, float width, const std::string& label) {
        glm::vec2 d = to - from;
        float len = glm::length(d);
        if (len < 1.0f) {
            return;
        }
        d /= len;
        glm::vec2 n(-d.y, d.x);
        float head = std::min(11.0f, len * 0.5f);
        glm::vec2 base = to - d * head;
        line({from, base}, width, c);
        f.shapes.emplace_back(std::in_place_type<FigurePolygon>, FigurePolygon{{to, base + n * head * 0.45f, base - n * head * 0.45f}, c});
        if (!label.empty()) {
            // Beside the tip, on the side away from the arrow's own line.
            float x = d.x >= 0.0f ? to.x + kPad : to.x - kPad;
            text({x, to.y - kTextSize * 0.6f}, label, kTextSize, c, d.x >= 0.0f ? TextAnchor::Start : TextAnchor::End, true);
        }
    }
};

struct LegendItem {
    std::string text;
    FigureColor color;
    float width = kStroke;
};

// Title (bold), subtitle (muted) and a legend of coloured swatches that wraps; the y below them.
float header(Page& page, const std::string& title, const std::string& subtitle, const std::vector<LegendItem>& legend) {
    const float usable = page.f.width - 2.0f * kMargin;
    float y = kMargin + kTitleSize * 0.5f;
    page.text({kMargin, y}, fitted(title, kTitleSize, usable), kTitleSize, kInk, TextAnchor::Start, true);
    y += kTitleSize * 0.5f + kPad + kTextSize * 0.5f;
    page.text({kMargin, y}, fitted(subtitle, kTextSize, usable), kTextSize, kMuted);
    y += kTextSize * 0.5f + kPad;
    if (!legend.empty()) {
        const float swatch = 26.0f;
        std::vector<float> widths;
        for (const LegendItem& item : legend) {
            widths.push_back(swatch + kPad + textWidth(item.text, kTextSize));
        }
        std::vector<FlowPlace> places = flowTokens(widths, 2.0f * kPad + 10.0f, usable);
        const float row = kTextSize + kPad;
        int lines = 0;
        for (std::size_t i = 0; i < legend.size(); ++i) {
            float x = kMargin + places[i].x, cy = y + row * (static_cast<float>(places[i].line) + 0.5f);
            page.line({{x, cy}, {x + swatch, cy}}, std::max(legend[i].width, 2.5f), legend[i].color);
            page.text({x + swatch + kPad, cy}, legend[i].text, kTextSize, kInk);
            lines = std::max(lines, places[i].line + 1);
        }
        y += row * static_cast<float>(lines);
    }
    return y + kPad;
}

std::string brdfText(const Preset& p) {
    std::string s = label(p.brdf);
    if (p.brdf == BrdfModel::CookTorrance) {
        s += " (" + std::string(toString(p.cookTorrance.distribution)) + ", roughness " + tickText(p.cookTorrance.roughness) + ")";
    } else {
        s += " (shininess " + tickText(p.material.shininess) + ")";
    }
    return s;
}

//----------------------------------------------------------------------------------------
// Polar figures
//----------------------------------------------------------------------------------------

struct Polar {
    glm::vec2 origin;
    float radius;
    glm::vec2 at(glm::vec2 unit) const { return {origin.x + unit.x * radius, origin.y - unit.y * radius}; }
};

glm::vec2 dirFromDeg(float deg, float side) {
    float r = glm::radians(deg);
    return {side * std::sin(r), std::cos(r)};
}

std::vector<glm::vec2> arc(const Polar& p, float r) {
    std::vector<glm::vec2> pts;
    const int n = 120;
    for (int i = 0; i <= n; ++i) {
        float a = glm::pi<float>() * static_cast<float>(i) / n;
        pts.push_back(p.at({-std::cos(a) * r, std::sin(a) * r}));
    }
    return pts;
}

// The half-disc under the header, with room for the angle labels and the ring values and the
// caption under the surface line.
Polar polarFrame(float top, float height) {
    float side = textWidth("90" + std::string(kDeg), kTextSize) + kPad;
    PlotMargins m{side, side, kTextSize + 2.0f * kPad, 2.0f * (kTextSize + kPad) + kPad};
    LobeFrame lf = lobeFrame(kMargin, top, kWidth - 2.0f * kMargin, height - top - kMargin, m);
    return {{lf.originX, lf.originY}, lf.radius};
}

// Rings with their values under the surface line, spokes every 30° with their angles outside the
// rim, the surface line, a log scale's 2…9 marks, and the caption: what the radius is.
void polarGrid(Page& page, const Polar& p, float outer, RadialScale scale) {
    const std::vector<RadialRing> rings = radialRings(outer, scale); // the screen's rings (core/plots/plot_data.h)
    const float below = p.origin.y + kPad + kTextSize * 0.5f;
    for (float side : {-1.0f, 1.0f}) {
        page.text({p.origin.x + side * (p.radius + kPad), below}, degrees(90.0f), kTextSize, kInk, TextAnchor::Middle);
    }
    const float limit = p.origin.x + p.radius + kPad - textWidth(degrees(90.0f), kTextSize) * 0.5f - kPad;
    float labelsEnd = p.origin.x;
    for (auto [v, r] : rings) {
        if (r < 0.999f) {
            page.line(arc(p, r), kThin, kGrid);
        }
        std::string t = tickText(v);
        float w = textWidth(t, kSmallSize), x = p.origin.x + r * p.radius;
        if (x - w * 0.5f > labelsEnd + kPad && x + w * 0.5f < limit) {
            page.text({x, below}, t, kSmallSize, kMuted, TextAnchor::Middle);
            labelsEnd = x + w * 0.5f;
        }
    }
    for (int deg = -60; deg <= 60; deg += 30) {
        glm::vec2 d = dirFromDeg(static_cast<float>(deg), 1.0f);
        page.line({p.at({0, 0}), p.at(d)}, kThin, kGrid);
        std::string t = degrees(static_cast<float>(std::abs(deg)));
        glm::vec2 rim = p.at(d);
        float out = kPad + 0.5f * (std::abs(d.x) * textWidth(t, kTextSize) + std::abs(d.y) * kTextSize);
        page.text({rim.x + d.x * out, rim.y - d.y * out}, t, kTextSize, kInk, TextAnchor::Middle);
    }
    page.line(arc(p, 1.0f), kThin, kAxis);
    if (scale == RadialScale::Log) {
        for (float decade : decadeTicks(outer * 10.0f, kLogDecades + 1.0f)) {
            for (int k = 2; k <= 9; ++k) {
                float r = plotRadius(decade * 0.1f * static_cast<float>(k), outer, scale);
                if (r > 0.0f && r < 1.0f) {
                    for (float side : {-1.0f, 1.0f}) {
                        glm::vec2 m = p.at({side * r, 0});
                        page.line({{m.x, m.y - (k == 5 ? 8.0f : 5.0f)}, m}, kThin, kAxis);
                    }
                }
            }
        }
    }
    page.line({p.at({-1.02f, 0}), p.at({1.02f, 0})}, kStroke, kAxis);
    std::string caption = "radius: reflected intensity, " +
                          std::string(scale == RadialScale::Linear ? "linear" : "logarithmic (3 decades)") +
                          "; outer circle " + tickText(outer);
    page.text({p.origin.x, below + kTextSize + kPad}, caption, kSmallSize, kMuted, TextAnchor::Middle);
}

std::vector<glm::vec2> placed(const std::vector<glm::vec2>& unit, const Polar& p) {
    std::vector<glm::vec2> out;
    for (const glm::vec2& u : unit) {
        out.push_back(p.at(u));
    }
    return out;
}

std::string angleText(float deg) { return std::string(kTheta) + "i = " + degrees(deg); }

FigureResult lobeFigure(const Preset& a, const Preset* b, const FigureRequest& r) {
    FigureResult out;
    Page page;
    page.f.width = kWidth;
    page.f.height = kPolarHeight;
    std::vector<PlotSample> sa = reflectedIntensity(a, r.incidentDeg), sb;
    std::vector<LegendItem> legend{{"diffuse", kDiffuse}, {"specular", kSpecular}, {"total", kTotal, kBold}};
    if (b) {
        sb = reflectedIntensity(*b, r.incidentDeg);
        legend.back().text = "total A";
        legend.push_back({"total B: " + fitted(b->name, kTextSize, 220.0f), kCompare});
    }
    const float outer = outerRing(b ? maxTotal({sa, sb}) : maxTotal({sa})); // as the lab's lobe plot
    page.f.title = "Reflection lobe: " + a.name;
    float top = header(page, page.f.title, brdfText(a) + " \xc2\xb7 incident angle " + angleText(r.incidentDeg) +
                                               " \xc2\xb7 plane of incidence", legend);
    Polar p = polarFrame(top, page.f.height);
    polarGrid(page, p, outer, r.scale);
    auto curve = [&](const std::vector<PlotSample>& s, PlotComponent c, float width, FigureColor color, const char* id) {
        page.line(placed(lobePoints(s, c, outer, r.scale), p), width, color, id);
    };
    curve(sa, PlotComponent::Diffuse, kStroke, kDiffuse, "lobe-diffuse");
    curve(sa, PlotComponent::Specular, kStroke, kSpecular, "lobe-specular");
    curve(sa, PlotComponent::Total, kBold, kTotal, "lobe-total");
    if (b) {
        curve(sb, PlotComponent::Total, kStroke, kCompare, "lobe-total-b");
    }
    page.arrow(p.at({0, 0}), p.at({0, 0.8f}), kAxis, kStroke, "N");
    page.arrow(p.at({0, 0}), p.at(dirFromDeg(r.incidentDeg, -1.0f) * 0.92f), kLight, kBold, "L");
    page.arrow(p.at({0, 0}), p.at(dirFromDeg(r.incidentDeg, 1.0f) * 0.8f), kMirror, kStroke, "R");
    out.figure = std::move(page.f);
    out.csv = plotCsv(sa);
    out.offset = p.origin;
    out.scale = {p.radius, -p.radius};
    out.outer = outer;
    return out;
}

FigureResult overlayFigure(const Preset& a, const FigureRequest& r) {
    FigureResult out;
    Page page;
    page.f.width = kWidth;
    page.f.height = kPolarHeight;
    std::array<std::vector<PlotSample>, 3> sets;
    std::vector<LegendItem> legend;
    for (int i = 0; i < 3; ++i) {
        sets[std::size_t(i)] = reflectedIntensity(a, r.overlayDeg[i]);
        legend.push_back({"total at " + angleText(r.overlayDeg[i]), kOverlay[i], kStroke});
    }
    const float outer = outerRing(maxTotal({sets.begin(), sets.end()}));
    page.f.title = "Lobes at three incident angles: " + a.name;
    float top = header(page, page.f.title, brdfText(a) + " \xc2\xb7 total reflected intensity \xc2\xb7 L for each angle",
                       legend);
    Polar p = polarFrame(top, page.f.height);
    polarGrid(page, p, outer, r.scale);
    std::string csv = "theta_out_deg";
    for (int i = 0; i < 3; ++i) {
        csv += ",total_at_" + shortestFloat(r.overlayDeg[i]);
        page.line(placed(lobePoints(sets[std::size_t(i)], PlotComponent::Total, outer, r.scale), p), kStroke, kOverlay[i],
                  "overlay-total-" + std::to_string(i + 1));
        page.arrow(p.at({0, 0}), p.at(dirFromDeg(r.overlayDeg[i], -1.0f) * 0.9f), kOverlay[i], kStroke, "");
    }
    csv += '\n';
    for (std::size_t k = 0; k < sets[0].size(); ++k) {
        csv += shortestFloat(sets[0][k].thetaOutDeg);
        for (const auto& s : sets) {
            csv += ',' + shortestFloat(s[k].total);
        }
        csv += '\n';
    }
    page.arrow(p.at({0, 0}), p.at({0, 0.8f}), kAxis, kStroke, "N");
    out.figure = std::move(page.f);
    out.csv = std::move(csv);
    out.offset = p.origin;
    out.scale = {p.radius, -p.radius};
    out.outer = outer;
    return out;
}

//----------------------------------------------------------------------------------------
// Cartesian figures
//----------------------------------------------------------------------------------------

// The plot box: lo the bottom left, hi the top right (pixels); unit (u, v) in [0, 1]².
struct Box {
    glm::vec2 lo, hi;
    glm::vec2 at(float u, float v) const { return {lo.x + u * (hi.x - lo.x), lo.y + v * (hi.y - lo.y)}; }
};

// Axes with grid lines, tick values, and the axes' names: y's above its axis, x's under the
// middle of its tick values.
Box cartesian(Page& page, float top, const std::vector<std::pair<float, float>>& xTicks,
              const std::vector<std::pair<float, float>>& yTicks, const std::string& xName, const std::string& yName) {
    float yLabels = 0.0f;
    for (auto [v, t] : yTicks) {
        yLabels = std::max(yLabels, textWidth(tickText(t), kTextSize));
    }
    Box b{{kMargin + yLabels + 2.0f * kPad, page.f.height - kMargin - 2.0f * (kTextSize + kPad)},
          {page.f.width - kMargin - 2.0f * kTextSize, top + 2.0f * kTextSize + 2.0f * kPad}};
    for (auto [v, t] : yTicks) {
        glm::vec2 y = b.at(0, v);
        if (v > 0.0f) {
            page.line({y, b.at(1, v)}, kThin, kGrid);
        }
        page.text({b.lo.x - kPad, y.y}, tickText(t), kTextSize, kInk, TextAnchor::End);
    }
    for (auto [u, t] : xTicks) {
        glm::vec2 x = b.at(u, 0);
        if (u > 0.0f) {
            page.line({x, b.at(u, 1)}, kThin, kGrid);
        }
        page.text({x.x, b.lo.y + kPad + kTextSize * 0.5f}, tickText(t), kTextSize, kInk, TextAnchor::Middle);
    }
    page.line({b.at(0, 0), b.at(1.0f, 0)}, kStroke, kAxis);
    page.line({b.at(0, 0), b.at(0, 1.0f)}, kStroke, kAxis);
    page.text({b.lo.x, b.hi.y - kTextSize - kPad}, yName, kTextSize, kInk, TextAnchor::Middle, true);
    page.text({b.at(0.5f, 0).x, b.lo.y + 2.0f * kPad + kTextSize * 1.5f}, xName, kTextSize, kInk, TextAnchor::Middle, true);
    return b;
}

std::optional<FigureResult> attenuationFigure(const Preset& a, const FigureRequest& r, std::string& error) {
    if (r.light < 0 || static_cast<std::size_t>(r.light) >= a.lights.size()) {
        error = a.lights.empty() ? "the preset has no lights"
                                 : "light " + std::to_string(r.light + 1) + " does not exist (the preset has " +
                                       std::to_string(a.lights.size()) + ")";
        return std::nullopt;
    }
    const LightDesc& light = a.lights[std::size_t(r.light)];
    const bool directional = light.type == LightType::Directional;
    const auto [distance, maxD] = attenuationSpan(light, a.model); // as the lab's attenuation plot

    const glm::vec3 k = light.attenuation;
    FigureResult out;
    Page page;
    page.f.width = kWidth;
    page.f.height = kCartesianHeight;
    page.f.title = "Attenuation: " + a.name;
    std::string formula = directional ? "directional: Att = 1 at every distance"
                                      : "Att(d) = 1 / (" + tickText(k.x) + " + " + tickText(k.y) + "\xc2\xb7" + "d + " +
                                            tickText(k.z) + "\xc2\xb7" + "d\xc2\xb2)";
    std::vector<LegendItem> legend{{"Att(d)", kTotal, kBold}};
    if (!directional) {
        legend.push_back({"the model, at d = " + format("%.2f", double(distance)), kSpecular});
    }
    float top = header(page, page.f.title,
                       "light " + std::to_string(r.light + 1) + " (" + std::string(toString(light.type)) + ") \xc2\xb7 " + formula,
                       legend);
    std::vector<std::pair<float, float>> xs, ys;
    for (float d : linearTicks(maxD, 10)) {
        xs.push_back({d / maxD, d});
    }
    xs.push_back({0.0f, 0.0f});
    for (float v : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
        ys.push_back({v, v});
    }
    Box b = cartesian(page, top, xs, ys, "distance d", "Att");
    // 201 samples either way (a directional light's Att is 1: the constant c0 = 1).
    std::vector<glm::vec2> curve = attenuationCurve(directional ? glm::vec3(1.0f, 0.0f, 0.0f) : k, maxD, 201);
    std::vector<glm::vec2> pts;
    std::string csv = "distance,attenuation\n";
    for (glm::vec2 c : curve) {
        pts.push_back(b.at(c.x / maxD, c.y));
        csv += shortestFloat(c.x) + ',' + shortestFloat(c.y) + '\n';
    }
    page.line(std::move(pts), kBold, kTotal, "attenuation");
    if (!directional && distance <= maxD) {
        float att = glsl::attenuation(k, distance);
        glm::vec2 m = b.at(distance / maxD, att);
        page.line({b.at(distance / maxD, 0), m}, kThin, kSpecular);
        page.disc(m, 5.0f, kSpecular);
        // Above the marker, or below it near the top of the box.
        float dy = att > 0.85f ? kTextSize * 0.9f : -kTextSize * 0.8f;
        page.text({m.x + 2.0f * kPad, m.y + dy}, "Att = " + format("%.3f", double(att)), kTextSize, kSpecular);
    }
    out.figure = std::move(page.f);
    out.csv = std::move(csv);
    out.offset = b.lo;
    out.scale = b.hi - b.lo;
    out.maxDistance = maxD;
    return out;
}

FigureResult albedoFigure(const Preset& a, const Preset* b, const FigureRequest& r) {
    FigureResult out;
    Page page;
    page.f.width = kWidth;
    page.f.height = kCartesianHeight;
    std::vector<AlbedoSample> ca = albedoCurve(lobeInputs(a, r.incidentDeg)), cb;
    float largest = 0.0f;
    for (const AlbedoSample& s : ca) {
        largest = std::max(largest, luminance(s.albedo.total()));
    }
    std::vector<LegendItem> legend{{"diffuse", kDiffuse}, {"specular", kSpecular}, {"total", kTotal, kBold}};
    if (b) {
        cb = albedoCurve(lobeInputs(*b, r.incidentDeg));
        for (const AlbedoSample& s : cb) {
            largest = std::max(largest, luminance(s.albedo.total()));
        }
        legend.back().text = "total A";
        legend.push_back({"total B: " + fitted(b->name, kTextSize, 220.0f), kCompare});
    }
    // At least 0 to 1 (1: all the light reflected); the ticks' nice step above that.
    std::vector<float> ticks = linearTicks(std::max(1.0f, largest * 1.02f), 6);
    float yMax = std::max(std::max(1.0f, largest * 1.02f), ticks.empty() ? 1.0f : ticks.back());
    page.f.title = "Albedo against the incident angle: " + a.name;
    float top = header(page, page.f.title, brdfText(a) + " \xc2\xb7 reflected / incident flux (luminance), white light",
                       legend);
    std::vector<std::pair<float, float>> xs, ys{{0.0f, 0.0f}};
    for (int deg = 0; deg <= 90; deg += 15) {
        xs.push_back({static_cast<float>(deg) / 90.0f, static_cast<float>(deg)});
    }
    for (float t : ticks) {
        ys.push_back({t / yMax, t});
    }
    Box box = cartesian(page, top, xs, ys, "incident angle " + std::string(kTheta) + "i (" + kDeg + ")", "albedo");
    if (yMax > 1.0f) {
        page.line({box.at(0, 1.0f / yMax), box.at(1, 1.0f / yMax)}, kThin, kAxis); // all light reflected
    }
    float marker = std::min(std::fabs(r.incidentDeg), 90.0f);
    page.line({box.at(marker / 90.0f, 0), box.at(marker / 90.0f, 1)}, kThin, kLight);
    page.text({box.at(marker / 90.0f, 1).x + kPad, box.hi.y + kTextSize * 0.5f}, angleText(marker), kTextSize, kLight);
    auto curve = [&](const std::vector<AlbedoSample>& c, int term, float width, FigureColor color, const char* id) {
        std::vector<glm::vec2> pts;
        for (const AlbedoSample& s : c) {
            float v = luminance(term == 0 ? s.albedo.diffuse : term == 1 ? s.albedo.specular : s.albedo.total());
            pts.push_back(box.at(s.incidentDeg / 90.0f, v / yMax));
        }
        page.line(std::move(pts), width, color, id);
    };
    curve(ca, 0, kStroke, kDiffuse, "albedo-diffuse");
    curve(ca, 1, kStroke, kSpecular, "albedo-specular");
    curve(ca, 2, kBold, kTotal, "albedo-total");
    if (b) {
        curve(cb, 2, kStroke, kCompare, "albedo-total-b");
    }
    out.figure = std::move(page.f);
    out.csv = albedoCsv(ca);
    out.offset = box.lo;
    out.scale = box.hi - box.lo;
    out.outer = yMax;
    return out;
}

} // namespace

std::string_view toString(FigureKind kind) {
    switch (kind) {
    case FigureKind::Lobe: return "lobe";
    case FigureKind::Overlay: return "overlay";
    case FigureKind::Attenuation: return "attenuation";
    case FigureKind::Albedo: return "albedo";
    }
    return "lobe";
}

std::optional<FigureKind> figureKindFrom(std::string_view name) {
    for (FigureKind k : kFigureKinds) {
        if (toString(k) == name) {
            return k;
        }
    }
    return std::nullopt;
}

std::optional<FigureResult> makeFigure(const Preset& a, const Preset* b, const FigureRequest& r, std::string& error) {
    switch (r.kind) {
    case FigureKind::Lobe: return lobeFigure(a, b, r);
    case FigureKind::Overlay: return overlayFigure(a, r);
    case FigureKind::Attenuation: return attenuationFigure(a, r, error);
    case FigureKind::Albedo: return albedoFigure(a, b, r);
    }
    error = "unknown figure";
    return std::nullopt;
}

bool writeFigure(const FigureResult& figure, const FigureFiles& files, std::string& error) {
    auto write = [&](const std::filesystem::path& file, std::string_view bytes) {
        std::string why;
        if (!writeFileAtomic(file, bytes, why)) {
            error = why;
            return false;
        }
        return true;
    };
    if (files.svg && !write(*files.svg, figureSvg(figure.figure))) {
        return false;
    }
    if (files.png) {
        std::string bytes = encodePng(rasterizeFigure(figure.figure, files.pngScale));
        if (bytes.empty()) {
            error = files.png->string() + ": cannot encode the PNG";
            return false;
        }
        if (!write(*files.png, bytes)) {
            return false;
        }
    }
    return !files.csv || write(*files.csv, figure.csv);
}

} // namespace lab
