// value_readout.cpp — the legend's range and the value under the pointer.
#include "app/value_readout.h"

#include "core/plots/legend.h"

#include <cmath>
#include <utility>

namespace lab {

void ValueReadout::update(Renderer& renderer, const CachedViewport& a, const Viewport& dest, float toPixels,
                          float windowHeight, float x, float y, const DisplaySettings& view) {
    const std::optional<ViewportKey>& key = a.key();
    std::optional<std::pair<int, int>> pixel;
    if (key && key->mesh && showsValue(view.mode) && dest.width > 0 && dest.height > 0) {
        // The pointer in the render's own pixels (it is smaller than `dest` while dragging).
        float px = (x * toPixels - static_cast<float>(dest.x)) * static_cast<float>(key->width) / static_cast<float>(dest.width);
        float py = ((windowHeight - y) * toPixels - static_cast<float>(dest.y)) * static_cast<float>(key->height) /
                   static_cast<float>(dest.height);
        bool litSide = key->draw.wipe && px < key->draw.options.fromX * static_cast<float>(key->width);
        if (px >= 0.0f && py >= 0.0f && px < static_cast<float>(key->width) && py < static_cast<float>(key->height) && !litSide) {
            pixel = std::pair{static_cast<int>(px), static_cast<int>(py)};
        }
    }
    if (pixel == pixel_ && key == key_) {
        return;
    }
    std::optional<float> value;
    if (pixel) {
        DrawOptions options = key->draw.options;
        if (a.range()) {
            options.range = *a.range();
        }
        value = renderer.valueAt(key->preset, key->mesh, key->width, key->height, pixel->first, pixel->second, options);
    }
    changed_ = changed_ || value != value_;
    value_ = value;
    pixel_ = pixel;
    key_ = key;
}

std::optional<ui::LegendModel> ValueReadout::legend(const DisplaySettings& view, const Preset& preset,
                                                    const std::optional<ValueRange>& range) const {
    if (!showsValue(view.mode)) {
        return std::nullopt;
    }
    ui::LegendModel m;
    m.title = legendTitle(view.mode, view.light);
    m.palette = view.palette;
    m.automatic = !view.range;
    m.note = notApplicable(view.mode, preset, view.light);
    if (m.note.empty()) {
        m.range = range;
        m.value = value_;
    } else {
        m.note += ": the lit model is shown";
    }
    return m;
}

std::string legendWords(const std::optional<ui::LegendModel>& legend) {
    if (!legend) {
        return {};
    }
    std::string text = legend->title;
    char buffer[96];
    if (legend->range) {
        std::snprintf(buffer, sizeof buffer, ": colours from %g to %g%s", static_cast<double>(legend->range->lo),
                      static_cast<double>(legend->range->hi), legend->automatic ? " (found on the model)" : "");
        text += buffer;
        if (legend->range->constant) {
            text += "; " + ui::constantWords(*legend);
        }
    }
    if (legend->value) {
        std::snprintf(buffer, sizeof buffer, "; under the pointer %.3f", static_cast<double>(*legend->value));
        text += buffer;
    }
    return legend->note.empty() ? text : text + ". " + legend->note;
}

} // namespace lab
