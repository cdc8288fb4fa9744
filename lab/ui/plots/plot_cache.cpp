// plot_cache.cpp — the plots' samples and curves, computed when their inputs are new.
#include "ui/plots/plot_cache.h"

#include "core/plots/plot_layout.h"

#include <cmath>
#include <limits>

namespace lab::ui {

namespace {

// Unit points to screen points, thinned.
std::vector<glm::vec2> placeAndThin(const std::vector<glm::vec2>& unit, const CurvePlacement& at) {
    std::vector<glm::vec2> screen;
    screen.reserve(unit.size());
    for (const glm::vec2& u : unit) {
        screen.push_back(at.at(u));
    }
    return thinPolyline(screen, kCurveTolerance);
}

bool sameKey(const PaintedLines::Key& k, const PaintedLines::Key& key) {
    return k.width == key.width && k.color == key.color && k.flags == key.flags && k.fillUv.x == key.fillUv.x &&
           k.fillUv.y == key.fillUv.y && k.lineUv.x == key.lineUv.x && k.lineUv.y == key.lineUv.y &&
           k.lineUv.z == key.lineUv.z && k.lineUv.w == key.lineUv.w;
}

bool sameColor(FigureColor x, FigureColor y) { return x.r == y.r && x.g == y.g && x.b == y.b; }

// What paint() draws of a shape (an SVG id is not drawn).
bool sameShape(const FigureShape& x, const FigureShape& y) {
    if (x.index() != y.index()) {
        return false;
    }
    if (const auto* l = std::get_if<FigureLine>(&x)) {
        const FigureLine& m = std::get<FigureLine>(y);
        return l->width == m.width && sameColor(l->color, m.color) && l->points == m.points && l->dash == m.dash;
    }
    if (const auto* g = std::get_if<FigurePolygon>(&x)) {
        const FigurePolygon& h = std::get<FigurePolygon>(y);
        return sameColor(g->fill, h.fill) && g->points == h.points;
    }
    if (const auto* d = std::get_if<FigureDisc>(&x)) {
        const FigureDisc& e = std::get<FigureDisc>(y);
        return d->centre == e.centre && d->radius == e.radius && sameColor(d->fill, e.fill);
    }
    if (const auto* t = std::get_if<FigureText>(&x)) {
        const FigureText& u = std::get<FigureText>(y);
        return t->at == u.at && t->size == u.size && sameColor(t->color, u.color) && t->anchor == u.anchor &&
               t->bold == u.bold && t->text == u.text;
    }
    const FigureImage& i = std::get<FigureImage>(x);
    const FigureImage& j = std::get<FigureImage>(y);
    return i.at == j.at && i.size == j.size && i.image == j.image;
}

bool sameFigureKey(const PaintedLines::FigureKey& k, const PaintedLines::FigureKey& key) {
    return sameKey(k.lines, key.lines) && k.clip.x == key.clip.x && k.clip.y == key.clip.y && k.clip.z == key.clip.z &&
           k.clip.w == key.clip.w && k.font == key.font && k.fontSize == key.fontSize && k.texture == key.texture &&
           k.atlasW == key.atlasW && k.atlasH == key.atlasH;
}

// `fresh` into `entries`, in place of the least recently used one when `capacity` are kept.
template <typename Entry>
void keepRecent(std::vector<Entry>& entries, Entry fresh, std::size_t capacity) {
    if (entries.size() < capacity) {
        entries.push_back(std::move(fresh));
        return;
    }
    Entry* oldest = &entries.front();
    for (Entry& e : entries) {
        oldest = e.used < oldest->used ? &e : oldest;
    }
    *oldest = std::move(fresh);
}

} // namespace

const KeptMesh* PaintedLines::find(const std::vector<glm::vec2>& points, const std::vector<float>& dash, const Key& key) {
    for (Entry& e : entries_) {
        if (sameKey(e.key, key) && e.dash == dash && e.points == points) {
            e.used = ++clock_;
            return &e.mesh;
        }
    }
    return nullptr;
}

void PaintedLines::keep(const std::vector<glm::vec2>& points, const std::vector<float>& dash, const Key& key, KeptMesh mesh) {
    Entry fresh{points, dash, key, std::move(mesh), ++clock_};
    keepRecent(entries_, std::move(fresh), kCapacity);
}

const KeptMesh* PaintedLines::find(const Figure& figure, const FigureKey& key) {
    for (FigureEntry& e : figures_) {
        if (e.figure.shapes.size() != figure.shapes.size() || !sameFigureKey(e.key, key)) {
            continue;
        }
        bool same = true;
        for (std::size_t i = 0; same && i < figure.shapes.size(); ++i) {
            same = sameShape(e.figure.shapes[i], figure.shapes[i]);
        }
        if (same) {
            e.used = ++clock_;
            return &e.mesh;
        }
    }
    return nullptr;
}

void PaintedLines::keep(const Figure& figure, const FigureKey& key, KeptMesh mesh) {
    FigureEntry fresh{figure, key, std::move(mesh), ++clock_};
    fresh.figure.title.clear(); // not painted
    keepRecent(figures_, std::move(fresh), kFigures);
}

const KeptMesh* PaintedLines::find(const std::string& description) {
    for (DescribedEntry& e : described_) {
        if (e.description == description) {
            e.used = ++clock_;
            return &e.mesh;
        }
    }
    return nullptr;
}

void PaintedLines::keep(const std::string& description, KeptMesh mesh) {
    DescribedEntry fresh{description, std::move(mesh), ++clock_};
    keepRecent(described_, std::move(fresh), kDescribed);
}

bool operator==(const CurvePlacement& x, const CurvePlacement& y) {
    return x.polar == y.polar && x.offset == y.offset && x.scale == y.scale;
}

bool operator==(const PlotCache::LobeKey& x, const PlotCache::LobeKey& y) {
    // The inputs last: comparing them is the costly part, and most keys differ in something else.
    return x.component == y.component && x.outer == y.outer && x.scale == y.scale && x.at == y.at &&
           x.inputs == y.inputs;
}

bool operator==(const PlotCache::AttenuationKey& x, const PlotCache::AttenuationKey& y) {
    return x.coefficients == y.coefficients && x.maxDistance == y.maxDistance && x.at == y.at;
}

bool PlotCache::coarseSet(std::array<ChangeWatch, 3>& watches, const std::array<LobeInputs, 3>& inputs) {
    Change change = Change::Still; // the strongest of the three: Changed, else Held, else Still
    bool kept = true;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const Change c = observe(watches[i], inputs[i]);
        if (c == Change::Changed || (c == Change::Held && change == Change::Still)) {
            change = c;
        }
        kept = kept && samples_.find(inputs[i]) != nullptr;
    }
    return coarse(change, kept);
}

PlotCache::Samples PlotCache::samples(const LobeInputs& inputs, bool coarse) {
    if (coarse) {
        return coarse_.get(inputs, [&] { return reflectedIntensity(inputs, kCoarseStepDeg); });
    }
    return samples_.get(inputs, [&] { return reflectedIntensity(inputs); });
}

template <class Value, class Make>
Lagged<Value> PlotCache::lagging(LagSlot<Value>& slot, RecentlyUsed<LobeInputs, Value>& kept, const LobeInputs& inputs,
                                 double now, double interval, Make&& make) {
    const Change change = slot.watch.observe(inputs, frame_, held_);
    if (std::shared_ptr<const Value> found = kept.find(inputs)) {
        slot.shown = found;
        return {found, false};
    }
    if (!slot.shown || change == Change::Still || now - slot.computedAt >= interval) {
        slot.shown = kept.get(inputs, make);
        slot.computedAt = now;
        return {slot.shown, false};
    }
    owed_ = owed_ || change == Change::Changed;
    return {slot.shown, true};
}

Lagged<std::optional<Albedo>> PlotCache::laggingAlbedo(Slot slot, const LobeInputs& inputs, double now) {
    // ρ(θi) holds the albedo at every whole degree (the same function of the same inputs): where a
    // kept curve has it, the number is found rather than computed or waited for (dragging θi in the
    // Energy view).
    const float deg = std::fabs(inputs.incidentDeg);
    if (deg < 90.0f && deg == std::floor(deg) && !albedo_.find(inputs)) {
        LobeInputs anyAngle = inputs;
        anyAngle.incidentDeg = 0.0f;
        if (const AlbedoCurve curve = albedoCurves_.find(anyAngle)) {
            albedo_.get(inputs, [&] { return std::optional<Albedo>((*curve)[static_cast<std::size_t>(deg)].albedo); });
        }
    }
    return lagging(albedoSlots_[static_cast<std::size_t>(slot)], albedo_, inputs, now, kAlbedoLagSeconds,
                   [&] { return lab::albedo(inputs); });
}

Lagged<std::vector<AlbedoSample>> PlotCache::laggingAlbedoCurve(Slot slot, LobeInputs inputs, double now) {
    inputs.incidentDeg = 0.0f; // the curve covers every angle
    // ρ(θi) is 90 albedos: never during a change, only once it is over.
    return lagging(curveSlots_[static_cast<std::size_t>(slot)], albedoCurves_, inputs, now,
                   std::numeric_limits<double>::infinity(), [&] { return lab::albedoCurve(inputs); });
}

PlotCache::Points PlotCache::lobe(const LobeInputs& inputs, PlotComponent component, float outer, RadialScale scale,
                                  const CurvePlacement& at, bool coarse) {
    return (coarse ? coarseLobes_ : lobes_).get(LobeKey{inputs, component, outer, scale, at}, [&] {
        const std::vector<PlotSample>& set = *samples(inputs, coarse);
        std::vector<glm::vec2> unit;
        if (at.polar) {
            unit = lobePoints(set, component, outer, scale);
        } else {
            unit.reserve(set.size());
            for (const PlotSample& s : set) {
                unit.emplace_back((s.thetaOutDeg + 90.0f) / 180.0f, plotRadius(componentOf(s, component), outer, scale));
            }
        }
        return placeAndThin(unit, at);
    });
}

std::shared_ptr<const Figure> PlotCache::polarGrid(const Polar& frame, float outer, RadialScale scale, const PlotStyle& style) {
    const GridKey key{frame.origin, frame.radius, outer, scale, style.scale, style.arcStep, style.palette, style.measure};
    return grids_.get(key, [&] {
        Figure figure;
        PlotCanvas canvas(figure, style);
        lab::polarGrid(canvas, frame, outer, scale, false);
        return figure;
    });
}

PlotCache::Points PlotCache::attenuation(const glm::vec3& coefficients, float maxDistance, const CurvePlacement& at) {
    return attenuation_.get(AttenuationKey{coefficients, maxDistance, at}, [&] {
        std::vector<glm::vec2> unit;
        for (const glm::vec2& q : attenuationCurve(coefficients, maxDistance, 200)) {
            unit.emplace_back(q.x / maxDistance, q.y);
        }
        return placeAndThin(unit, at);
    });
}

} // namespace lab::ui
