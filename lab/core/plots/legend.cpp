// legend.cpp — the legend band under a value view's render.
#include "core/plots/legend.h"

#include "core/lighting/lighting.h"
#include "core/plots/text_raster.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lab {

std::string legendNumber(float value, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(value == 0.0f ? 0.0f : value)); // no "-0"
    return text;
}

int legendDigits(const ValueRange& r) {
    int digits = 3;
    while (digits < 7 && legendNumber(r.lo, digits) == legendNumber(r.hi, digits)) {
        ++digits;
    }
    return digits;
}

std::vector<float> legendTicks(const ValueRange& r) { return {r.lo, 0.5f * (r.lo + r.hi), r.hi}; }

std::string legendTitle(ViewMode mode, int light) {
    std::string title = toString(mode);
    return isFactor(mode) ? title + ", light " + std::to_string(light + 1) : title;
}

int legendHeight(int width) { return std::max(48, width / 8); }

Image withLegend(const Image& render, const LegendSpec& spec) {
    const int w = render.width, band = legendHeight(w);
    Image out{w, render.height + band, std::vector<std::uint8_t>(std::size_t(w) * std::size_t(render.height + band) * 3, 0)};
    std::copy(render.rgb.begin(), render.rgb.end(), out.rgb.begin());
    const float text = 0.24f * static_cast<float>(band);
    const float pad = 0.12f * static_cast<float>(band);
    const TextFont& font = sharedTextFont();
    const TextColor white{235, 235, 235};
    const float top = static_cast<float>(render.height);
    const std::string said = constantWords(spec.title, spec.range); // what a constant is, in place of its name
    font.draw(out, font.fitted(said.empty() ? spec.title : said, text, static_cast<float>(w) - 2 * pad), pad, top + 0.5f * pad, text, white);
    // The bar: each column the palette's colour at its place between lo and hi.
    const int x0 = static_cast<int>(pad), x1 = std::max(x0 + 1, w - static_cast<int>(pad));
    const int y0 = static_cast<int>(top + 0.5f * pad + 1.15f * text), y1 = y0 + static_cast<int>(0.55f * text) + 1;
    for (int x = x0; x < x1; ++x) {
        glm::vec3 c = paletteColor(spec.palette, static_cast<float>(x - x0) / static_cast<float>(std::max(1, x1 - x0 - 1)));
        for (int y = y0; y < std::min(y1, out.height); ++y) {
            std::uint8_t* px = out.rgb.data() + (std::size_t(y) * std::size_t(w) + std::size_t(x)) * 3;
            px[0] = static_cast<std::uint8_t>(std::lround(255.0f * c.r));
            px[1] = static_cast<std::uint8_t>(std::lround(255.0f * c.g));
            px[2] = static_cast<std::uint8_t>(std::lround(255.0f * c.b));
        }
    }
    // The ticks' values under the bar: the first left-aligned, the last right-aligned, the middle centred.
    std::vector<float> ticks = legendTicks(spec.range);
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        std::string label = legendNumber(ticks[i], legendDigits(spec.range));
        float width = font.measure(label, text).width;
        float share = static_cast<float>(i) / static_cast<float>(ticks.size() - 1);
        float x = static_cast<float>(x0) + share * static_cast<float>(x1 - x0) - share * width;
        font.draw(out, label, x, static_cast<float>(y1) + 0.15f * text, text, white);
    }
    return out;
}

std::string constantWords(const std::string& title, const ValueRange& range) {
    if (!range.constant) {
        return {};
    }
    const std::string symbol = title.substr(0, title.find(':'));
    const std::size_t light = title.rfind(", light ");
    const std::string which = light == std::string::npos ? "" : " (" + title.substr(light + 2) + ")";
    char text[160];
    if (range.spread > 0.0f) { // one significant digit, written out: "± 0.000005"
        const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(range.spread))), 0, 9);
        std::snprintf(text, sizeof text, "%s = %.4f on the whole model, \u00b1 %.*f%s", symbol.c_str(),
                      static_cast<double>(*range.constant), decimals, static_cast<double>(range.spread), which.c_str());
    } else {
        std::snprintf(text, sizeof text, "%s = %.4f on the whole model%s", symbol.c_str(), static_cast<double>(*range.constant),
                      which.c_str());
    }
    return text;
}

} // namespace lab
