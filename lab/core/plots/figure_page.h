// figure_page.h — what the plot figures' pages share (figures.cpp, figure_slice.cpp): sizes, the
// page in a theme's figure style, the title, subtitle and legend, the BRDF in words. Internal to
// core/plots.
#pragma once

#include "core/plots/figure.h"
#include "core/plots/figures.h"
#include "core/plots/plot_drawing.h"
#include "core/plots/plot_layout.h"
#include "core/plots/theme.h"
#include "core/scene/preset_choices.h"

#include <algorithm>
#include <string>
#include <vector>

namespace lab::figure_page {

//----------------------------------------------------------------------------------------
// The page: sizes, colours, text
//----------------------------------------------------------------------------------------

constexpr float kWidth = 720.0f;
constexpr float kPolarHeight = 500.0f;
constexpr float kCartesianHeight = 460.0f;
constexpr float kMargin = 18.0f;
// The figures' sizes (plot_drawing.h); a Page's style adds its theme's colours.
inline constexpr const PlotStyle& kStyle = kFigureSizes;
constexpr float kTitleSize = kStyle.title();
constexpr float kTextSize = kStyle.text();
constexpr float kPad = kStyle.pad();
constexpr float kStroke = kStyle.stroke();
constexpr float kBold = kStyle.bold();

inline float textWidth(const std::string& text, float size) { return kStyle.width(text, size); }

// `text` cut (with "…") to at most `width` pixels at the SVG font size `size`.
inline std::string fitted(const std::string& text, float size, float width) {
    const TextFont& font = sharedTextFont();
    return font.fitted(text, size * font.lineHeightPerEm(), width);
}

// A figure page: its Figure, drawn on in the theme's figure style, on the plots' background.
struct Page {
    Figure f;
    PlotStyle style;
    PlotCanvas canvas{f, style};
    explicit Page(Theme theme) : style(figureStyle(theme)) { f.background = style.color(Ink::Background); }
    Page(const Page&) = delete;
};

struct LegendItem {
    std::string text;
    Ink ink;
    float width = kStroke;
};

// Title (bold), subtitle (muted) and a legend of coloured swatches that wraps; the y below them.
inline float header(Page& page, const std::string& title, const std::string& subtitle, const std::vector<LegendItem>& legend) {
    const float usable = page.f.width - 2.0f * kMargin;
    float y = kMargin + kTitleSize * 0.5f;
    page.canvas.text({kMargin, y}, fitted(title, kTitleSize, usable), kTitleSize, Ink::Text, TextAnchor::Start, true);
    y += kTitleSize * 0.5f + kPad + kTextSize * 0.5f;
    page.canvas.text({kMargin, y}, fitted(subtitle, kTextSize, usable), kTextSize, Ink::Muted);
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
            page.canvas.line({{x, cy}, {x + swatch, cy}}, std::max(legend[i].width, 2.5f), legend[i].ink);
            page.canvas.text({x + swatch + kPad, cy}, legend[i].text, kTextSize, Ink::Text);
            lines = std::max(lines, places[i].line + 1);
        }
        y += row * static_cast<float>(lines);
    }
    return y + kPad;
}

inline std::string brdfText(const Preset& p) {
    std::string s = label(p.brdf);
    if (p.brdf == BrdfModel::CookTorrance) {
        s += " (" + std::string(toString(p.cookTorrance.distribution)) + ", roughness " + tickText(p.cookTorrance.roughness) + ")";
    } else {
        s += " (shininess " + tickText(p.material.shininess) + ")";
    }
    return s;
}

} // namespace lab::figure_page

namespace lab {
// The slice figure (figure_slice.cpp), which makeFigure() dispatches to.
FigureResult sliceFigure(const Preset& a, const Preset* b, const FigureRequest& r);
} // namespace lab
