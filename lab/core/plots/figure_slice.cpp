// figure_slice.cpp — the (θh, θd) slice as a figure (figures.h, core/plots/slice.h): the image of one
// component in the view palette with θh across and θd up, its colour bar with values, and in compare
// mode A, B (on A's and B's common scale) and A − B in a diverging palette.
#include "core/plots/figure_page.h"
#include "core/plots/figures.h"
#include "core/plots/slice.h"

#include "core/lighting/lighting.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace lab {

namespace {

using namespace figure_page;

constexpr float kAxisRoom = 46.0f;  // left of an image: θd's tick values and name
constexpr float kBarHeight = 12.0f; // the colour bar

const char* componentName(PlotComponent c) {
    return c == PlotComponent::Diffuse ? "diffuse" : c == PlotComponent::Specular ? "specular" : "total";
}

std::uint8_t byte(float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// The image, θd = 90° in the top row (θd grows upwards, as on the axes).
Image sliceRaster(const std::vector<float>& values, int side, const auto& colourOf) {
    Image image;
    image.width = image.height = side;
    image.rgb.resize(static_cast<std::size_t>(side * side * 3));
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            const glm::vec3 c = colourOf(values[static_cast<std::size_t>(row * side + column)]);
            std::uint8_t* p = &image.rgb[static_cast<std::size_t>(((side - 1 - row) * side + column) * 3)];
            p[0] = byte(c.r);
            p[1] = byte(c.g);
            p[2] = byte(c.b);
        }
    }
    return image;
}

Image barRaster(const auto& colourOf) {
    Image bar;
    bar.width = 256;
    bar.height = 1;
    for (int i = 0; i < 256; ++i) {
        const glm::vec3 c = colourOf(static_cast<float>(i) / 255.0f);
        bar.rgb.insert(bar.rgb.end(), {byte(c.r), byte(c.g), byte(c.b)});
    }
    return bar;
}

// One panel: a title above, the image in its axes (cells centred on whole degrees), the colour bar
// with its ticks under the axes' values.
struct Panel {
    glm::vec2 corner; // the image's top left
    float side;
};

void panel(Page& page, const Panel& p, const std::string& title, Image image, Image bar,
           const std::vector<AxisTick>& barTicks, const std::string& id) {
    const float half = 0.5f / kSliceSide; // half a cell: the axes' 0° and 90° at the first and last cells' centres
    Box box{{p.corner.x, p.corner.y + p.side}, {p.corner.x + p.side, p.corner.y}};
    if (!title.empty()) { // above θd's name
        page.canvas.text({p.corner.x - kAxisRoom, p.corner.y - 2.0f * kPad - kTextSize * 1.5f},
                         fitted(title, kTextSize, p.side + kAxisRoom), kTextSize, Ink::Text, TextAnchor::Start, true);
    }
    std::vector<AxisTick> ticks;
    for (int deg = 0; deg <= 90; deg += 30) {
        ticks.push_back({half + static_cast<float>(deg) / 90.0f * (1.0f - 2.0f * half), static_cast<float>(deg)});
    }
    const std::string theta = kTheta;
    axes(page.canvas, box, ticks, ticks, theta + "h (" + kDeg + ")", theta + "d (" + kDeg + ")", true);
    // The image over the axes' grid lines, framed.
    page.f.shapes.push_back(FigureImage{p.corner, {p.side, p.side}, std::make_shared<const Image>(std::move(image)), id});
    page.canvas.line({box.at(0, 0), box.at(1, 0), box.at(1, 1), box.at(0, 1), box.at(0, 0)}, kStyle.thin(), Ink::Axis);
    const float barTop = box.lo.y + 2.0f * kTextSize + 3.0f * kPad;
    page.f.shapes.push_back(
        FigureImage{{p.corner.x, barTop}, {p.side, kBarHeight}, std::make_shared<const Image>(std::move(bar)), id + "-bar"});
    for (std::size_t k = 0; k < barTicks.size(); ++k) {
        const AxisTick& t = barTicks[k];
        const float x = p.corner.x + t.at * p.side;
        page.canvas.line({{x, barTop + kBarHeight}, {x, barTop + kBarHeight + kPad}}, kStyle.thin(), Ink::Axis);
        if (barTicks.size() > 3 && p.side < 300.0f && k != 0 && k + 1 != barTicks.size()) {
            continue; // a narrow bar: its ends' values only (the marks show the decades)
        }
        const TextAnchor anchor = t.at < 0.01f ? TextAnchor::Start : t.at > 0.99f ? TextAnchor::End : TextAnchor::Middle;
        page.canvas.text({x, barTop + kBarHeight + kPad + kTextSize * 0.6f}, t.text.empty() ? tickText(t.value) : t.text,
                         kStyle.small(), Ink::Muted, anchor);
    }
}

std::vector<AxisTick> valueTicks(float top, RadialScale scale) {
    if (scale == RadialScale::Log) {
        std::vector<AxisTick> ticks;
        for (int decade = static_cast<int>(kLogDecades); decade >= 0; --decade) {
            const float v = top * std::pow(10.0f, -static_cast<float>(decade));
            ticks.push_back({plotRadius(v, top, scale), v});
        }
        return ticks;
    }
    return {{0.0f, 0.0f}, {0.5f, 0.5f * top}, {1.0f, top}};
}

} // namespace

FigureResult sliceFigure(const Preset& a, const Preset* b, const FigureRequest& r) {
    FigureResult out;
    Page page(r.theme);
    page.f.width = kWidth;
    const SliceImage sa = sampleSlice(packSurfaceUniforms(a));
    const SliceImage sb = b ? sampleSlice(packSurfaceUniforms(*b)) : SliceImage{};
    const PlotComponent c = r.component;
    const float top = outerRing(std::max(sa.largest(c), b ? sb.largest(c) : 0.0f));
    page.f.title = "BRDF slice (" + std::string(kTheta) + "h, " + kTheta + "d): " + a.name;
    const std::string subtitle = brdfText(a) + " \xc2\xb7 " + componentName(c) + " at \xcf\x86" + "d = 90" + kDeg +
                                 ", unit white light" +
                                 (r.scale == RadialScale::Log ? " \xc2\xb7 log scale" : "");
    const float y = header(page, page.f.title, subtitle, {}) + (b ? 2.0f : 1.0f) * (kTextSize + kPad);
    const float gap = 14.0f;
    const float side = b ? (kWidth - 2.0f * kMargin - 3.0f * kAxisRoom - 2.0f * gap) / 3.0f : 400.0f;
    auto palette = [&](float v) { return paletteColor(r.palette, plotRadius(v, top, r.scale)); };
    auto unitPalette = [&](float t) { return paletteColor(r.palette, t); };
    const float left = b ? kMargin + kAxisRoom : 0.5f * (kWidth - side + kAxisRoom); // one image: in the middle
    auto at = [&](int i) { return Panel{{left + static_cast<float>(i) * (side + kAxisRoom + gap), y}, side}; };
    panel(page, at(0), b ? "A: " + a.name : "", sliceRaster(sa.component(c), sa.side(), palette),
          barRaster(unitPalette), valueTicks(top, r.scale), "slice-a");
    if (b) {
        panel(page, at(1), "B: " + b->name, sliceRaster(sb.component(c), sb.side(), palette), barRaster(unitPalette),
              valueTicks(top, r.scale), "slice-b");
        const SliceImage d = sliceDifference(sa, sb);
        float largest = 0.0f;
        for (float v : d.component(c)) {
            largest = std::max(largest, std::fabs(v));
        }
        const float m = outerRing(largest);
        panel(page, at(2), "A \xe2\x88\x92 B",
              sliceRaster(d.component(c), d.side(), [&](float v) { return divergingColor(differencePosition(v, m, r.scale)); }),
              barRaster([](float t) { return divergingColor(2.0f * t - 1.0f); }),
              {{0.0f, -m, "\xe2\x88\x92" + tickText(m) + " B"}, {0.5f, 0.0f}, {1.0f, m, tickText(m) + " A"}}, "slice-difference");
    }
    page.f.height = y + side + 2.0f * kTextSize + 3.0f * kPad + kBarHeight + kPad + kTextSize * 1.2f + kMargin;
    out.figure = std::move(page.f);
    out.csv = sliceCsv(sa);
    out.offset = at(0).corner;
    out.scale = {side, side};
    out.outer = top;
    return out;
}

} // namespace lab
