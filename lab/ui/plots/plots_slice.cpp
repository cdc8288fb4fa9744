// plots_slice.cpp — the Slice view: the (θh, θd) images, their legends and readout, drawn with
// ImDrawList.
//
// One frame: the images of A (and B, and A − B) from the state's cache (core/plots/slice.h, computed
// when the surfaces change), the options row, the layout of the images (side by side, stacked or
// two by two, whichever gives them the largest side) above their legends, the readout strip (what
// is under the pointer, where the marker is), then the images: the axes, the kept vertices copied
// into the draw list, the outlines, the titles and the markers over them.
//
// Each image is a mesh with a vertex at each sample, in the sample's colour, and two triangles between
// four neighbours: 8,281 vertices a full image, so that three (24,843) stay within ImGui's 16-bit
// indices in one draw list, where a quad of four vertices per sample would need 99,372. On screen
// a cell is 2–6 pixels, and the colour between two samples is their mix.
#include "ui/plots/plots_slice.h"
#include "ui/plots/plot_kit.h"
#include "ui/plots/slice_parts.h"
#include "ui/widgets.h"

#include "core/lighting/lighting.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace lab::ui {

bool operator==(const SliceKey& x, const SliceKey& y) {
    auto same = [](const ImVec4& p, const ImVec4& q) { return p.x == q.x && p.y == q.y && p.z == q.z && p.w == q.w; };
    return x.a == y.a && x.hasB == y.hasB && (!x.hasB || x.b == y.b) && x.coarse == y.coarse &&
           x.component == y.component && x.scale == y.scale && x.palette == y.palette && same(x.rects[0], y.rects[0]) &&
           same(x.rects[1], y.rects[1]) && same(x.rects[2], y.rects[2]);
}

namespace {

ImU32 rgb(const glm::vec3& c) {
    const glm::vec3 k = glm::clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f;
    return IM_COL32(static_cast<int>(k.r), static_cast<int>(k.g), static_cast<int>(k.b), 255);
}

} // namespace

std::vector<ImU32> sliceColors(const std::vector<float>& values, float largest, RadialScale scale, ValuePalette palette) {
    const float outer = outerRing(largest);
    std::vector<ImU32> colors;
    colors.reserve(values.size());
    for (float v : values) {
        colors.push_back(rgb(paletteColor(palette, plotRadius(v, outer, scale))));
    }
    return colors;
}

std::vector<ImU32> differenceColors(const std::vector<float>& values, float largestAbs, RadialScale scale) {
    std::vector<ImU32> colors;
    colors.reserve(values.size());
    for (float v : values) {
        colors.push_back(rgb(divergingColor(differencePosition(v, largestAbs, scale))));
    }
    return colors;
}

float largestMagnitude(const std::vector<float>& values) {
    float m = 0.0f;
    for (float v : values) {
        m = std::max(m, std::fabs(v));
    }
    return m;
}

namespace {

using namespace plotkit;
using namespace slice;

//----------------------------------------------------------------------------------------
// The images, from the cache
//----------------------------------------------------------------------------------------

// The stronger of two changes: Changed, else Held, else Still.
Change stronger(Change x, Change y) {
    return x == Change::Changed || y == Change::Changed ? Change::Changed
           : x == Change::Held || y == Change::Held     ? Change::Held
                                                        : Change::Still;
}

// A's image (and B's and A − B), full, or coarse while A or B changes and the full ones are not kept
// (both coarse then, so that A − B has the same samples). The coarse images lag as the albedo does
// (PlotCache::kAlbedoLagSeconds): during a change they are those of the inputs of the latest draft,
// drawn again at most every 0.5 s; the frame after the change draws the full images of the inputs
// then. Every component: the scales are scaled().
Images images(const Preset& a, const Preset* b, PlotSettings& s) {
    SliceState& st = s.slice;
    Images im;
    im.inA = lobeInputs(a, 0.0f);
    Change change = s.cache.observe(st.watchA, im.inA);
    bool kept = st.images.find({im.inA, false}) != nullptr;
    if (b) {
        im.inB = lobeInputs(*b, 0.0f);
        change = stronger(change, s.cache.observe(st.watchB, im.inB));
        kept = kept && st.images.find({im.inB, false}) != nullptr;
    }
    im.coarse = s.cache.coarse(change, kept);
    im.imageA = im.inA;
    im.imageB = im.inB;
    if (im.coarse) {
        const std::array<LobeInputs, 2>& drafted = st.draft.take({im.inA, im.inB}, ImGui::GetTime(), st.draftHasB != (b != nullptr));
        st.draftHasB = b != nullptr;
        im.imageA = drafted[0];
        im.imageB = drafted[1];
    }
    auto sample = [&](const LobeInputs& in) {
        return st.images.get({in, im.coarse}, [&] { return sampleSlice(in, im.coarse ? kSliceCoarseStepDeg : 1); });
    };
    im.a = sample(im.imageA);
    if (b) {
        im.b = sample(im.imageB);
        im.difference = st.differences.get({{im.imageA, im.coarse}, {im.imageB, im.coarse}},
                                           [&] { return sliceDifference(*im.a, *im.b); });
    }
    return im;
}

// The images' scales for component `c`: the larger maximum of A and B, the largest |A − B|.
void scaled(Images& im, PlotComponent c, SliceState& st) {
    SliceState::Scales& kept = st.scales;
    if (kept.a != im.a || kept.b != im.b || kept.difference != im.difference || kept.component != c) {
        kept = {im.a, im.b, im.difference, c, im.a->largest(c), 0.0f};
        if (im.b) {
            kept.largest = std::max(kept.largest, im.b->largest(c));
            kept.largestDifference = largestMagnitude(im.difference->component(c));
        }
    }
    im.largest = kept.largest;
    im.largestDifference = kept.largestDifference;
}

// The vertices of the shown images, each at its rectangle.
void addImage(SliceMesh& m, const std::vector<ImU32>& colors, int side, const ImVec4& r) {
    const unsigned base = static_cast<unsigned>(m.vertices.size()), n = static_cast<unsigned>(side);
    const float last = static_cast<float>(side - 1);
    const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            const ImVec2 at(r.x + r.z * static_cast<float>(column) / last, r.y + r.w * (1.0f - static_cast<float>(row) / last)); // θd up
            m.vertices.push_back(ImDrawVert{at, uv, colors[static_cast<std::size_t>(row * side + column)]});
        }
    }
    for (unsigned row = 0; row + 1 < n; ++row) {
        for (unsigned column = 0; column + 1 < n; ++column) {
            const unsigned k = base + row * n + column;
            for (unsigned v : {k, k + 1, k + n + 1, k, k + n + 1, k + n}) {
                m.indices.push_back(static_cast<ImDrawIdx>(v)); // three images of 8,281: under 65536
            }
        }
    }
}

SliceMesh meshOf(const Images& im, const SliceKey& key) {
    SliceMesh m;
    const int side = im.a->side();
    const float largest = im.largest;
    const std::shared_ptr<const SliceImage> values[2] = {im.a, im.b};
    for (int i = 0; i < 2; ++i) {
        if (values[i] && key.rects[static_cast<std::size_t>(i)].z > 0.0f) {
            addImage(m, sliceColors(values[i]->component(key.component), largest, key.scale, key.palette), side,
                     key.rects[static_cast<std::size_t>(i)]);
        }
    }
    if (im.difference && key.rects[2].z > 0.0f) {
        addImage(m, differenceColors(im.difference->component(key.component), im.largestDifference, key.scale), side, key.rects[2]);
    }
    return m;
}

//----------------------------------------------------------------------------------------
// The options row
//----------------------------------------------------------------------------------------

constexpr const char* kFull[] = {"diffuse###slice.d", "specular###slice.s", "total###slice.t", "lin###slice.linear",
                                 "log###slice.log", "A | B###slice.both", "A \xe2\x88\x92 B###slice.difference"};
constexpr const char* kBrief[] = {"diff###slice.d", "spec###slice.s", "total###slice.t", "lin###slice.linear",
                                  "log###slice.log", "A|B###slice.both", ("A\xe2\x88\x92" "B###slice.difference")};
constexpr int kOptionCount = 7;

float radioWidth(const char* label, const Pens& p) {
    return ImGui::GetFrameHeight() + p.inner + ImGui::CalcTextSize(label, nullptr, true).x;
}

// The labels that fit one line where they can (else the short ones), and how high the row is,
// wrapped as sameLineIfFitsRadio wraps it; or, where it would take more than two lines (or two that
// leave the images fewer than ten), one button that opens the choices in a popup (a phone at a large UI scale).
struct OptionsRow {
    const char* const* labels;
    int count;
    float height;
    bool popup = false;
};
OptionsRow optionsRow(ImVec2 room, bool selector, const Pens& p) {
    const int count = selector ? kOptionCount : kOptionCount - 2;
    float full = 0.0f;
    for (int i = 0; i < count; ++i) {
        full += radioWidth(kFull[i], p) + (i > 0 ? p.gapX : 0.0f);
    }
    OptionsRow row{full <= room.x ? kFull : kBrief, count, 0.0f};
    int lines = 1;
    float x = 0.0f;
    for (int i = 0; i < count; ++i) {
        const float w = radioWidth(row.labels[i], p);
        if (i > 0 && x + p.gapX + w > room.x) {
            ++lines;
            x = 0.0f;
        } else if (i > 0) {
            x += p.gapX;
        }
        x += w;
    }
    row.height = static_cast<float>(lines) * p.frame + static_cast<float>(lines - 1) * p.gap;
    if (lines > 2 || (lines > 1 && room.y - row.height < 10.0f * p.line)) {
        row = {kFull, count, p.frame, true};
    }
    return row;
}

void drawOptions(PlotSettings& s, const OptionsRow& row) {
    static const char* const marks[kOptionCount] = {"plot.slice.diffuse", "plot.slice.specular", "plot.slice.total",
                                                    "plot.slice.linear",  "plot.slice.log",      "plot.slice.both",
                                                    "plot.slice.difference"};
    if (row.popup) {
        const std::string label = format("%s, %s%s \xe2\x96\xbe###slice.options", componentName(s.slice.component),
                                         s.scale == RadialScale::Linear ? "lin" : "log",
                                         row.count < kOptionCount                   ? ""
                                         : s.slice.compare == SliceCompare::Both ? ", A | B"
                                                                                 : ", A \xe2\x88\x92 B");
        const float w = ImGui::CalcTextSize(label.c_str(), nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
        if (ImGui::Button(label.c_str(), ImVec2(std::min(w, std::max(ImGui::GetContentRegionAvail().x, 1.0f)), 0.0f))) {
            ImGui::OpenPopup("slice.options");
        }
        mark("plot.slice.options");
        if (!ImGui::BeginPopup("slice.options")) {
            return;
        }
    }
    int component = static_cast<int>(s.slice.component);
    int scale = s.scale == RadialScale::Linear ? 0 : 1;
    int compare = s.slice.compare == SliceCompare::Both ? 0 : 1;
    int* targets[kOptionCount] = {&component, &component, &component, &scale, &scale, &compare, &compare};
    const int values[kOptionCount] = {0, 1, 2, 0, 1, 0, 1};
    for (int i = 0; i < row.count; ++i) {
        if (i > 0 && !row.popup) {
            sameLineIfFitsRadio(row.labels[i]);
        }
        ImGui::RadioButton(row.labels[i], targets[i], values[i]);
        if (!row.popup) {
            mark(marks[i]);
        }
    }
    s.slice.component = static_cast<PlotComponent>(component);
    s.scale = scale == 0 ? RadialScale::Linear : RadialScale::Log;
    if (row.count == kOptionCount) {
        s.slice.compare = compare == 0 ? SliceCompare::Both : SliceCompare::Difference;
    }
    if (row.popup) {
        ImGui::EndPopup();
    }
}

//----------------------------------------------------------------------------------------
// The images on screen
//----------------------------------------------------------------------------------------

// Each image's title: the component alone, or which set.
std::string titleOf(const Frame& f, std::size_t i) {
    if (f.shown == Shown::A) {
        return componentName(f.component);
    }
    return i == 0 ? "A" : i == 1 ? "B" : "A \xe2\x88\x92 B";
}

// What a frame draws over the kept vertices: each image's axes (their grid under the image), its
// outline, title and the marker.
void drawImages(ImDrawList* dl, const Pens& p, const Frame& f, const SliceMesh& mesh) {
    static const char* const names[3] = {"plot.slice.a", "plot.slice.b", "plot.slice.difference-image"};
    ScreenPlot under;
    for (std::size_t i = 0; i < 3; ++i) {
        const ImVec4& r = f.layout.images[i];
        if (r.z > 0.0f) {
            widgets().set(names[i], {r.x, r.y, r.z, r.w});
            imageAxes(under, r, titleOf(f, i));
        }
    }
    under.paint(dl);
    drawMesh(dl, mesh);
    for (const ImVec4& r : f.layout.images) {
        if (r.z > 0.0f) {
            dl->AddRect(ImVec2(r.x, r.y), ImVec2(r.x + r.z, r.y + r.w), ink(Ink::Axis), 0.0f, 0, p.thin);
            drawMarker(dl, p, r, f.marker);
        }
    }
}

SliceKey keyOf(const Frame& f, const PlotSettings& s) {
    SliceKey key;
    key.a = f.images.imageA;
    key.hasB = f.images.b != nullptr;
    key.b = f.images.imageB;
    key.coarse = f.images.coarse;
    key.component = f.component;
    key.scale = s.scale;
    key.palette = s.palette;
    key.rects = f.layout.images;
    return key;
}

// The frame's readout, images and legends in the region left below the options row.
void drawView(PlotSettings& s, const Pens& p, Frame& f, ImVec2 origin, ImVec2 room) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const Placement at = placeReadout(f, origin, room, p);
    f.brief = at.brief;
    f.layout = arrangeImages(at.images, f.shown, p);
    // The readout: what is under the pointer (found before the images are submitted).
    if (at.strip.w >= 1.0f) {
        const Readout r = readout(f, hoverOf(f.layout), p);
        const ImVec4& q = at.strip;
        dl->PushClipRect(ImVec2(q.x, q.y), ImVec2(q.x + q.z, q.y + q.w), true);
        r.draw(dl, p, ImVec2(q.x, q.y), q.z);
        dl->PopClipRect();
        ImGui::SetCursorScreenPos(ImVec2(q.x, q.y));
        ImGui::Dummy(ImVec2(q.z, q.w));
        mark("plot.slice.readout");
    }
    if (at.cut) { // lines left out below the strip (or all of them): cut text, a "clipped:" name (ui/widget_map.h)
        widgets().set("clipped:plot.slice.readout", {at.strip.x, at.strip.y, at.strip.z, std::max(at.strip.w, 1.0f)});
    }
    const ImVec4& area = f.layout.area;
    if (area.z < 1.0f || area.w < 1.0f) {
        return;
    }
    ImGui::SetCursorScreenPos(ImVec2(area.x, area.y));
    const Canvas canvas = beginCanvas("slice", "plot.slice", area.z, area.w);
    if (!canvas.shown()) {
        return;
    }
    const SliceKey key = keyOf(f, s);
    const std::shared_ptr<const SliceMesh> mesh = s.slice.meshes.get(key, [&] { return meshOf(f.images, key); });
    dl->PushClipRect(canvas.corner, ImVec2(canvas.corner.x + canvas.width, canvas.corner.y + canvas.height), true);
    drawImages(dl, p, f, *mesh);
    dl->PopClipRect();
    drawLegends(dl, p, f, s.scale, s.palette);
}

} // namespace

void slicePanel(const Preset& a, const Preset* b, PlotSettings& s) {
    const Pens p = pens();
    Frame f;
    f.state = &s.slice;
    f.images = images(a, b, s);
    f.component = s.slice.component;
    scaled(f.images, f.component, s.slice);
    f.marker = planeToSlice(a.plotIncidentDeg, s.viewerDeg);
    f.incidentDeg = a.plotIncidentDeg;
    f.viewerDeg = s.viewerDeg;
    f.shown = b ? Shown::All : Shown::A;

    // Three images where they fit at a useful size; else A | B or A − B, as the selector says.
    const ImVec2 full = ImGui::GetContentRegionAvail();
    bool selector = false;
    if (b) {
        const float rowH = optionsRow(full, false, p).height + p.gap;
        selector = !threeFit(placeReadout(f, ImVec2(0.0f, 0.0f), ImVec2(full.x, full.y - rowH), p).images, p);
    }
    drawOptions(s, optionsRow(full, selector, p));
    f.component = s.slice.component; // the row may have chosen another
    scaled(f.images, f.component, s.slice);
    if (selector) {
        f.shown = s.slice.compare == SliceCompare::Both ? Shown::AB : Shown::Difference;
    }

    const ImVec2 room = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    widgets().set("plots.area", {origin.x, origin.y, room.x, room.y});
    if (room.x < 1.0f || room.y < 1.0f) {
        return;
    }
    ImGui::PushClipRect(origin, ImVec2(origin.x + room.x, origin.y + room.y), true);
    drawView(s, p, f, origin, room);
    ImGui::PopClipRect();
}

} // namespace lab::ui
