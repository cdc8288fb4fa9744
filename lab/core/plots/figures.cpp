// figures.cpp — the four plot figures as Figures (figures.h): the page (title, subtitle, legend),
// and on it the polar grid or the Cartesian axes (plot_drawing.h, as the lab's plots draw them)
// and the curves from core/plots/plot_data.h and core/plots/energy.h. Layout in pixels at scale 1,
// in the figure style of the request's theme (theme.h), text measured with the font the PNG draws with.
#include "core/plots/figures.h"

#include "core/plots/figure_page.h"

#include "core/io/file_io.h"
#include "core/io/number_format.h"
#include "core/lighting/lighting.h"
#include "core/plots/energy.h"
#include "core/plots/plot_drawing.h"
#include "core/plots/plot_layout.h"
#include "core/scene/preset_choices.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lab {

namespace {

using namespace figure_page;

//----------------------------------------------------------------------------------------
// Polar figures
//----------------------------------------------------------------------------------------

// The half-disc under the header, with room for the angle labels and the ring values and the
// caption under the surface line.
Polar figurePolar(float top, float height) {
    return polarFrame({kMargin, top}, kWidth - 2.0f * kMargin, height - top - kMargin, kStyle, true);
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
    Page page(r.theme);
    page.f.width = kWidth;
    page.f.height = kPolarHeight;
    std::vector<PlotSample> sa = reflectedIntensity(a, r.incidentDeg), sb;
    std::vector<LegendItem> legend{{"diffuse", Ink::Diffuse}, {"specular", Ink::Specular}, {"total", Ink::Total, kBold}};
    if (b) {
        sb = reflectedIntensity(*b, r.incidentDeg);
        legend.back().text = "total A";
        legend.push_back({"total B: " + fitted(b->name, kTextSize, 220.0f), Ink::Compare});
    }
    const float outer = outerRing(b ? maxTotal({sa, sb}) : maxTotal({sa})); // as the lab's lobe plot
    page.f.title = "Reflection lobe: " + a.name;
    float top = header(page, page.f.title, brdfText(a) + " \xc2\xb7 incident angle " + angleText(r.incidentDeg) +
                                               " \xc2\xb7 plane of incidence", legend);
    Polar p = figurePolar(top, page.f.height);
    polarGrid(page.canvas, p, outer, r.scale, true);
    auto curve = [&](const std::vector<PlotSample>& s, PlotComponent c, float width, Ink ink, const char* id) {
        page.canvas.line(placed(lobePoints(s, c, outer, r.scale), p), width, ink, id);
    };
    curve(sa, PlotComponent::Diffuse, kStroke, Ink::Diffuse, "lobe-diffuse");
    curve(sa, PlotComponent::Specular, kStroke, Ink::Specular, "lobe-specular");
    curve(sa, PlotComponent::Total, kBold, Ink::Total, "lobe-total");
    if (b) {
        curve(sb, PlotComponent::Total, kStroke, Ink::Compare, "lobe-total-b");
    }
    page.canvas.arrow(p.at({0, 0}), p.at({0, 0.8f}), Ink::Axis, kStroke, "N");
    page.canvas.arrow(p.at({0, 0}), p.at(dirFromDeg(r.incidentDeg, -1.0f) * 0.92f), Ink::Light, kBold, "L");
    page.canvas.arrow(p.at({0, 0}), p.at(dirFromDeg(r.incidentDeg, 1.0f) * 0.8f), Ink::Mirror, kStroke, "R");
    out.figure = std::move(page.f);
    out.csv = plotCsv(sa);
    out.offset = p.origin;
    out.scale = {p.radius, -p.radius};
    out.outer = outer;
    return out;
}

FigureResult overlayFigure(const Preset& a, const FigureRequest& r) {
    FigureResult out;
    Page page(r.theme);
    page.f.width = kWidth;
    page.f.height = kPolarHeight;
    std::array<std::vector<PlotSample>, 3> sets;
    std::vector<LegendItem> legend;
    for (int i = 0; i < 3; ++i) {
        sets[std::size_t(i)] = reflectedIntensity(a, r.overlayDeg[i]);
        legend.push_back({"total at " + angleText(r.overlayDeg[i]), overlayInk(std::size_t(i)), kStroke});
    }
    const float outer = outerRing(maxTotal({sets.begin(), sets.end()}));
    page.f.title = "Lobes at three incident angles: " + a.name;
    float top = header(page, page.f.title, brdfText(a) + " \xc2\xb7 total reflected intensity \xc2\xb7 L for each angle",
                       legend);
    Polar p = figurePolar(top, page.f.height);
    polarGrid(page.canvas, p, outer, r.scale, true);
    std::string csv = "theta_out_deg";
    for (int i = 0; i < 3; ++i) {
        csv += ",total_at_" + shortestFloat(r.overlayDeg[i]);
        page.canvas.line(placed(lobePoints(sets[std::size_t(i)], PlotComponent::Total, outer, r.scale), p), kStroke, overlayInk(std::size_t(i)),
                  "overlay-total-" + std::to_string(i + 1));
        page.canvas.arrow(p.at({0, 0}), p.at(dirFromDeg(r.overlayDeg[i], -1.0f) * 0.9f), overlayInk(std::size_t(i)), kStroke, "");
    }
    csv += '\n';
    for (std::size_t k = 0; k < sets[0].size(); ++k) {
        csv += shortestFloat(sets[0][k].thetaOutDeg);
        for (const auto& s : sets) {
            csv += ',' + shortestFloat(s[k].total);
        }
        csv += '\n';
    }
    page.canvas.arrow(p.at({0, 0}), p.at({0, 0.8f}), Ink::Axis, kStroke, "N");
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

// The plot box under the header, with room for the values and the axes' names; the axes drawn.
Box cartesian(Page& page, float top, const std::vector<AxisTick>& xTicks, const std::vector<AxisTick>& yTicks,
              const std::string& xName, const std::string& yName) {
    float yLabels = 0.0f;
    for (const AxisTick& t : yTicks) {
        yLabels = std::max(yLabels, textWidth(tickText(t.value), kTextSize));
    }
    Box b{{kMargin + yLabels + 2.0f * kPad, page.f.height - kMargin - 2.0f * (kTextSize + kPad)},
          {page.f.width - kMargin - 2.0f * kTextSize, top + 2.0f * kTextSize + 2.0f * kPad}};
    axes(page.canvas, b, xTicks, yTicks, xName, yName, true);
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
    Page page(r.theme);
    page.f.width = kWidth;
    page.f.height = kCartesianHeight;
    page.f.title = "Attenuation: " + a.name;
    std::string formula = directional ? "directional: Att = 1 at every distance"
                                      : "Att(d) = 1 / (" + tickText(k.x) + " + " + tickText(k.y) + "\xc2\xb7" + "d + " +
                                            tickText(k.z) + "\xc2\xb7" + "d\xc2\xb2)";
    std::vector<LegendItem> legend{{"Att(d)", Ink::Total, kBold}};
    if (!directional) {
        legend.push_back({"the model, at d = " + format("%.2f", double(distance)), Ink::Specular});
    }
    float top = header(page, page.f.title,
                       "light " + std::to_string(r.light + 1) + " (" + std::string(toString(light.type)) + ") \xc2\xb7 " + formula,
                       legend);
    std::vector<AxisTick> xs, ys;
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
    page.canvas.line(std::move(pts), kBold, Ink::Total, "attenuation");
    if (!directional && distance <= maxD) {
        float att = glsl::attenuation(k, distance);
        glm::vec2 m = b.at(distance / maxD, att);
        page.canvas.line({b.at(distance / maxD, 0), m}, kStyle.thin(), Ink::Specular);
        page.canvas.disc(m, 5.0f, Ink::Specular);
        // Above the marker, or below it near the top of the box.
        float dy = att > 0.85f ? kTextSize * 0.9f : -kTextSize * 0.8f;
        page.canvas.text({m.x + 2.0f * kPad, m.y + dy}, "Att = " + format("%.3f", double(att)), kTextSize, Ink::Specular);
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
    Page page(r.theme);
    page.f.width = kWidth;
    page.f.height = kCartesianHeight;
    std::vector<AlbedoSample> ca = albedoCurve(lobeInputs(a, r.incidentDeg)), cb;
    float largest = 0.0f;
    for (const AlbedoSample& s : ca) {
        largest = std::max(largest, luminance(s.albedo.total()));
    }
    std::vector<LegendItem> legend{{"diffuse", Ink::Diffuse}, {"specular", Ink::Specular}, {"total", Ink::Total, kBold}};
    if (b) {
        cb = albedoCurve(lobeInputs(*b, r.incidentDeg));
        for (const AlbedoSample& s : cb) {
            largest = std::max(largest, luminance(s.albedo.total()));
        }
        legend.back().text = "total A";
        legend.push_back({"total B: " + fitted(b->name, kTextSize, 220.0f), Ink::Compare});
    }
    // At least 0 to 1 (1: all the light reflected); the ticks' nice step above that.
    std::vector<float> ticks = linearTicks(std::max(1.0f, largest * 1.02f), 6);
    float yMax = std::max(std::max(1.0f, largest * 1.02f), ticks.empty() ? 1.0f : ticks.back());
    page.f.title = "Albedo against the incident angle: " + a.name;
    float top = header(page, page.f.title, brdfText(a) + " \xc2\xb7 reflected / incident flux (luminance), white light",
                       legend);
    std::vector<AxisTick> xs, ys{{0.0f, 0.0f}};
    for (int deg = 0; deg <= 90; deg += 15) {
        xs.push_back({static_cast<float>(deg) / 90.0f, static_cast<float>(deg)});
    }
    for (float t : ticks) {
        ys.push_back({t / yMax, t});
    }
    Box box = cartesian(page, top, xs, ys, "incident angle " + std::string(kTheta) + "i (" + kDeg + ")", "albedo");
    if (yMax > 1.0f) {
        page.canvas.line({box.at(0, 1.0f / yMax), box.at(1, 1.0f / yMax)}, kStyle.thin(), Ink::Axis); // all light reflected
    }
    float marker = std::min(std::fabs(r.incidentDeg), 90.0f);
    page.canvas.line({box.at(marker / 90.0f, 0), box.at(marker / 90.0f, 1)}, kStyle.thin(), Ink::Light);
    page.canvas.text({box.at(marker / 90.0f, 1).x + kPad, box.hi.y + kTextSize * 0.5f}, angleText(marker), kTextSize, Ink::Light);
    auto curve = [&](const std::vector<AlbedoSample>& c, int term, float width, Ink ink, const char* id) {
        std::vector<glm::vec2> pts;
        for (const AlbedoSample& s : c) {
            float v = luminance(term == 0 ? s.albedo.diffuse : term == 1 ? s.albedo.specular : s.albedo.total());
            pts.push_back(box.at(s.incidentDeg / 90.0f, v / yMax));
        }
        page.canvas.line(std::move(pts), width, ink, id);
    };
    curve(ca, 0, kStroke, Ink::Diffuse, "albedo-diffuse");
    curve(ca, 1, kStroke, Ink::Specular, "albedo-specular");
    curve(ca, 2, kBold, Ink::Total, "albedo-total");
    if (b) {
        curve(cb, 2, kStroke, Ink::Compare, "albedo-total-b");
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
    case FigureKind::Slice: return "slice";
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
    case FigureKind::Slice: return sliceFigure(a, b, r);
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
