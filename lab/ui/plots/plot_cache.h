// plot_cache.h — what the plots computed in earlier frames, kept for the next ones.
//
// The plots are drawn every frame, but what they show changes only when the preset, the plot
// settings or the window do. The cache keeps
//   * each lobe's samples, keyed on everything they are computed from (core/plots/plot_data.h's LobeInputs:
//     material, BRDF, term switches, incident angle), and its albedo (core/plots/energy.h, about 0.5 ms);
//   * each curve as the screen points that are drawn, thinned to the points a line needs
//     (thinPolyline, within kCurveTolerance pixels), keyed on its samples' inputs, the component,
//     the outer ring's intensity, the radial scale and where it lies on screen; likewise Att(d).
// Entries are found by value, never by "which plot": an edit changes the key, so a stale entry
// is never found again, and the least recently used entries make room for new ones. Values are
// shared and immutable, so what a frame holds stays valid while the cache changes.
#pragma once

#include "core/plots/energy.h"
#include "core/plots/plot_data.h"
#include "core/plots/plot_drawing.h"

#include <glm/vec2.hpp>
#include <imgui.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lab::ui {

// How far, in pixels, a thinned curve may pass from a point it leaves out.
inline constexpr float kCurveTolerance = 0.2f;

// Where a curve's unit coordinates go on screen: screen = offset + scale × unit, where a polar
// plot's unit point is r·(sin θo, cos θo) and a Cartesian plot's ((θo + 90) / 180, r). For
// Att(d), unit is (d / maxDistance, Att).
struct CurvePlacement {
    bool polar = true;
    glm::vec2 offset{0.0f}, scale{1.0f};
    glm::vec2 at(glm::vec2 unit) const { return offset + scale * unit; }
};
bool operator==(const CurvePlacement& x, const CurvePlacement& y);

// A mesh kept between frames in the form ImGui's draw list holds it: each vertex with the font
// atlas's white pixel as its texture coordinate, the triangles by index from 0. A frame copies it
// (plot_kit.h's drawMesh) rather than writing it vertex by vertex: the 3D lobe's surface and map and
// the slice's images are 8,281 vertices and 48,600 indices each.
struct KeptMesh {
    std::vector<ImDrawVert> vertices;
    std::vector<ImDrawIdx> indices;
    // Where drawMesh copied it last. ImGui keeps a window's draw list buffers from frame to frame and
    // only appends to them, so a mesh copied in the frame before to the same place (the same context,
    // list, buffers, offsets and first index) is still there, byte for byte: that frame copies nothing.
    struct Placed {
        const void* context = nullptr;
        const ImDrawList* list = nullptr;
        const ImDrawVert* vertexData = nullptr;
        const ImDrawIdx* indexData = nullptr;
        int vertexAt = -1, indexAt = -1, frame = -1;
        unsigned base = 0;
        ImVec2 uv;
    };
    mutable Placed placed; // where it is, not what it is: a value kept in a cache is still the same mesh
};

// Lines as ImGui painted them (anti-aliased polylines, a dash's dots), kept with everything the
// painting depends on: the points, the dash, the width, the colour, the draw list's flags and the
// font atlas's texture coordinates for fills and lines. A line unchanged since an earlier frame is
// copied (plot_kit.h's drawMesh) rather than painted again: a dotted lobe is a hundred small discs.
class PaintedLines {
public:
    struct Key {
        float width = 0.0f;
        ImU32 color = 0;
        int flags = 0;
        ImVec2 fillUv;
        ImVec4 lineUv;
    };
    // The kept painting of `points` dashed by `dash` under `key`, or null.
    const KeptMesh* find(const std::vector<glm::vec2>& points, const std::vector<float>& dash, const Key& key);
    // Keeps a painting, in place of the least recently used one when full.
    void keep(const std::vector<glm::vec2>& points, const std::vector<float>& dash, const Key& key, KeptMesh mesh);

    // Whole figures as painted (plot_kit.h's paintWhole: a canvas's grid, arrows and labels), with
    // what their text depends on besides: the clip rectangle (ImGui leaves out glyphs outside it),
    // the font and its size, and the atlas (its texture and size: a rebuilt atlas at another UI
    // scale has another size; at the same scale it is built the same).
    struct FigureKey {
        Key lines;
        ImVec4 clip;
        const ImFont* font = nullptr;
        float fontSize = 0.0f;
        ImTextureID texture{};
        int atlasW = 0, atlasH = 0;
    };
    const KeptMesh* find(const Figure& figure, const FigureKey& key);
    void keep(const Figure& figure, const FigureKey& key, KeptMesh mesh);
    // Anything else painted the same way from the same description, written out as bytes (a
    // readout's tokens, plot_kit.h's Readout::draw): the painting of `description`, or null.
    const KeptMesh* find(const std::string& description);
    void keep(const std::string& description, KeptMesh mesh);

private:
    struct Entry {
        std::vector<glm::vec2> points;
        std::vector<float> dash;
        Key key;
        KeptMesh mesh;
        std::uint64_t used = 0;
    };
    struct FigureEntry {
        Figure figure;
        FigureKey key;
        KeptMesh mesh;
        std::uint64_t used = 0;
    };
    struct DescribedEntry {
        std::string description;
        KeptMesh mesh;
        std::uint64_t used = 0;
    };
    static constexpr std::size_t kCapacity = 64; // a frame paints about 30 lines long or dashed enough to keep
    static constexpr std::size_t kFigures = 16;  // a view paints at most 8 figures whole
    static constexpr std::size_t kDescribed = 12; // the Plane view's three readouts; the 3D lobe's, rings, wireframe, map marks
    std::vector<Entry> entries_;
    std::vector<FigureEntry> figures_;
    std::vector<DescribedEntry> described_;
    std::uint64_t clock_ = 0;
};

// A few values by key, the least recently used one replaced when full. Key needs ==.
template <class Key, class Value> class RecentlyUsed {
public:
    explicit RecentlyUsed(std::size_t capacity) : capacity_(capacity) {}

    // The value for `key`, made by make() (and kept) when there is none.
    template <class Make> std::shared_ptr<const Value> get(const Key& key, Make&& make) {
        if (std::shared_ptr<const Value> found = find(key)) {
            return found;
        }
        ++made_;
        std::shared_ptr<const Value> value = std::make_shared<const Value>(make());
        Entry fresh{key, value, ++clock_};
        if (entries_.size() < capacity_) {
            entries_.push_back(std::move(fresh));
        } else {
            Entry* oldest = &entries_.front();
            for (Entry& e : entries_) {
                oldest = e.used < oldest->used ? &e : oldest;
            }
            *oldest = std::move(fresh);
        }
        return value;
    }
    // The value for `key` when it is kept, else null (nothing is made).
    std::shared_ptr<const Value> find(const Key& key) {
        for (Entry& e : entries_) {
            if (e.key == key) {
                e.used = ++clock_;
                return e.value;
            }
        }
        return nullptr;
    }
    // How many values make() made: the look-ups that found nothing.
    std::size_t made() const { return made_; }

private:
    struct Entry {
        Key key;
        std::shared_ptr<const Value> value;
        std::uint64_t used = 0;
    };
    std::vector<Entry> entries_;
    std::size_t capacity_;
    std::uint64_t clock_ = 0;
    std::size_t made_ = 0;
};

// A readout that may lag: the value shown, and whether it is an earlier one than its inputs ask for.
template <class Value> struct Lagged {
    std::shared_ptr<const Value> value;
    bool stale = false;
};

// Whether one plot's inputs are in the middle of a change, as during a drag:
//   * Changed: they differ from the ones the previous frame asked for (a view just opened, or back
//     after frames without it, is not changing: it computes at once);
//   * Held: the same as the previous frame's, but the pointer still holds the widget of a change
//     that was going on (a drag paused: it is not over until the release, which is an input and so
//     draws a frame);
//   * Still: otherwise — the change is over.
// Inputs with a NaN equal nothing, not even themselves: they are never a change (a readout computes
// at once rather than owing frames for ever).
enum class Change { Still, Changed, Held };
class ChangeWatch {
public:
    // This frame's inputs (and whether the pointer holds a widget): records them, says which it is.
    Change observe(const LobeInputs& inputs, std::uint64_t frame, bool held) {
        const bool consecutive = last_ && lastFrame_ + 1 == frame;
        const bool differs = consecutive && !(*last_ == inputs) && inputs == inputs;
        const bool paused = held && consecutive && change_ != Change::Still && *last_ == inputs;
        change_ = differs ? Change::Changed : paused ? Change::Held : Change::Still;
        last_ = inputs;
        lastFrame_ = frame;
        return change_;
    }

private:
    std::optional<LobeInputs> last_;
    std::uint64_t lastFrame_ = 0;
    Change change_ = Change::Still;
};

class PlotCache {
public:
    // The expensive readouts (the albedo, about 0.5 ms; ρ(θi), 90 albedos) lag during a change (a
    // drag: ChangeWatch): the frame shows the latest value computed (stale), computed again once the
    // change is over (or at once when the previous frame did not ask: a view just opened) — or, for
    // the albedo at one angle, at most every kAlbedoLagSeconds during the change. A stale value in a
    // frame whose inputs changed makes the cache owed(): the app draws another frame, so the exact
    // value is on screen within one frame of the end of the change, with no input to ask for it (the
    // page has no threads: this is how it is done there too); while a paused drag holds, the release
    // draws that frame. Each readout has its own slot (each view's A and B), so that A's changes do
    // not keep B's waiting and one view's inputs do not make another's look changed.
    static constexpr double kAlbedoLagSeconds = 0.5;
    enum class Slot { PlaneA, PlaneB, EnergyA, EnergyB };
    // Clears owed(); plotsPanel calls it first each frame, saying whether the pointer holds a widget
    // (a mouse button or finger down on an active one).
    void beginFrame(bool held = false) {
        owed_ = false;
        held_ = held;
        ++frame_;
    }
    // Some readout drawn since beginFrame() was stale: another frame is due.
    bool owed() const { return owed_; }
    // For views that keep their own coarse plots (the 3D lobe): where `inputs` stand in a change (observed
    // by `watch`), and whether to draw a coarse plot: during a change, unless the full result is kept; a
    // coarse in a frame whose inputs changed owes the frame after (a paused drag's release draws it).
    Change observe(ChangeWatch& watch, const LobeInputs& inputs) { return watch.observe(inputs, frame_, held_); }
    bool coarse(Change change, bool keptInFull) {
        const bool drawCoarse = change != Change::Still && !keptInFull;
        owed_ = owed_ || (drawCoarse && change == Change::Changed);
        return drawCoarse;
    }

    using Samples = std::shared_ptr<const std::vector<PlotSample>>;
    using Points = std::shared_ptr<const std::vector<glm::vec2>>;

    // reflectedIntensity(inputs), or a coarse copy of it: every kCoarseStepDeg degrees (kept apart, so that
    // coarse plots never push out what the plots keep).
    static constexpr int kCoarseStepDeg = 3;
    Samples samples(const LobeInputs& inputs, bool coarse = false);
    // Whether lobes drawn together (the overlay's three) are drawn from coarse plots: coarse() for the
    // change of any of them (observed by its watch), kept in full when all are.
    bool coarseSet(std::array<ChangeWatch, 3>& watches, const std::array<LobeInputs, 3>& inputs);
    using AlbedoCurve = std::shared_ptr<const std::vector<AlbedoSample>>;
    // The screen points of one component of the lobe `inputs`, the outer ring at `outer`, thinned.
    Points lobe(const LobeInputs& inputs, PlotComponent component, float outer, RadialScale scale,
                const CurvePlacement& at, bool coarse = false);
    // Att(d) for d in [0, maxDistance] (attenuationCurve, 200 samples), thinned.
    Points attenuation(const glm::vec3& coefficients, float maxDistance, const CurvePlacement& at);
    // The albedo (core/plots/energy.h: the energy readouts' numbers, nullopt at ±90°) and ρ(θi) for
    // θi = 0°…89° (the Energy view; inputs.incidentDeg is not part of its key), as readouts that lag
    // during a change (above); `now` in seconds.
    Lagged<std::optional<Albedo>> laggingAlbedo(Slot slot, const LobeInputs& inputs, double now);
    Lagged<std::vector<AlbedoSample>> laggingAlbedoCurve(Slot slot, LobeInputs inputs, double now);

    // The polar grid (core/plots/plot_drawing.h polarGrid, without a caption) of the half-disc `frame` in
    // `style`, kept by everything it is drawn from: its rings, spokes, values and labels as a Figure.
    std::shared_ptr<const Figure> polarGrid(const Polar& frame, float outer, RadialScale scale, const PlotStyle& style);
    // The lines painted in earlier frames (plot_kit.h's paint).
    PaintedLines& painted() { return painted_; }

    // How many sample sets and curves were computed rather than found (for the tests).
    std::size_t computed() const { return samples_.made() + coarse_.made() + coarseLobes_.made() + albedo_.made() + albedoCurves_.made() + lobes_.made() + attenuation_.made(); }

private:
    struct LobeKey {
        LobeInputs inputs;
        PlotComponent component;
        float outer;
        RadialScale scale;
        CurvePlacement at;
    };
    struct AttenuationKey {
        glm::vec3 coefficients;
        float maxDistance;
        CurvePlacement at;
    };
    struct GridKey {
        glm::vec2 origin;
        float radius, outer;
        RadialScale scale;
        float styleScale, arcStep;
        const Palette* palette;
        TextMeasure measure;
        bool operator==(const GridKey& o) const {
            return origin == o.origin && radius == o.radius && outer == o.outer && scale == o.scale &&
                   styleScale == o.styleScale && arcStep == o.arcStep && palette == o.palette && measure == o.measure;
        }
    };
    // What one readout showed last: its inputs in the latest frame and the value shown.
    template <class Value> struct LagSlot {
        ChangeWatch watch;
        std::shared_ptr<const Value> shown;
        double computedAt = 0.0;
    };
    template <class Value, class Make>
    Lagged<Value> lagging(LagSlot<Value>& slot, RecentlyUsed<LobeInputs, Value>& kept, const LobeInputs& inputs,
                          double now, double interval, Make&& make);

    friend bool operator==(const LobeKey& x, const LobeKey& y);
    friend bool operator==(const AttenuationKey& x, const AttenuationKey& y);

    // A frame uses at most 5 sample sets (A, B, three incident angles) and 7 curves; room for
    // more, so that switching back and forth (A and B, polar and Cartesian) finds them again.
    RecentlyUsed<LobeInputs, std::vector<PlotSample>> samples_{16};
    RecentlyUsed<LobeInputs, std::vector<PlotSample>> coarse_{3};     // the overlay's three, while they change
    RecentlyUsed<LobeKey, std::vector<glm::vec2>> coarseLobes_{3};
    RecentlyUsed<LobeInputs, std::optional<Albedo>> albedo_{8}; // A and B at the lobe's angle
    RecentlyUsed<LobeInputs, std::vector<AlbedoSample>> albedoCurves_{4}; // A and B, against θi
    RecentlyUsed<LobeKey, std::vector<glm::vec2>> lobes_{32};
    RecentlyUsed<AttenuationKey, std::vector<glm::vec2>> attenuation_{4};
    RecentlyUsed<GridKey, Figure> grids_{4}; // the lobe's and the overlay's (not in computed(): a frame's scale)
    std::array<LagSlot<std::optional<Albedo>>, 4> albedoSlots_;
    std::array<LagSlot<std::vector<AlbedoSample>>, 4> curveSlots_;
    PaintedLines painted_;
    bool owed_ = false, held_ = false;
    std::uint64_t frame_ = 0;
};

// What a coarse plot shows during a change, lagging like the albedo: the inputs taken when it was
// drafted, drafted again from the frame's inputs at most every `interval` (ImGui's time; the
// albedo's PlotCache::kAlbedoLagSeconds unless told), or at once where `retake` (what must show at
// once: the overlay's own angles).
template <class Inputs> class LaggingDraft {
public:
    LaggingDraft(double interval = PlotCache::kAlbedoLagSeconds) : interval_(interval) {} // not explicit: a view's state is made with {}
    double interval() const { return interval_; }

    const Inputs& take(const Inputs& now, double time, bool retake = false) {
        if (!made_ || retake || time - at_ >= interval_) {
            inputs_ = now;
            at_ = time;
            made_ = true;
        }
        return inputs_;
    }
    bool made() const { return made_; }
    const Inputs& inputs() const { return inputs_; }

private:
    double interval_;
    bool made_ = false;
    Inputs inputs_{};
    double at_ = 0.0;
};

} // namespace lab::ui
