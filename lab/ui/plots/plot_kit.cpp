// plot_kit.cpp — the screen's style, the painter of Figures onto ImGui's draw list, readouts and
// canvases.
#include "ui/plots/plot_kit.h"

#include "ui/theme_style.h"
#include "ui/widget_map.h"
#include "ui/widgets.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

namespace lab::ui::plotkit {

//----------------------------------------------------------------------------------------
// Style, colours, painting
//----------------------------------------------------------------------------------------

PlotStyle screenStyle() {
    // The figures' text is 14 pixels; the UI's is ImGui's font size.
    // The rings get about a segment every 4 pixels.
    return PlotStyle{&currentColors().plot, ImGui::GetFontSize() / 14.0f,
                     [](std::string_view text, float size) {
                         return ImGui::GetFont()->CalcTextSizeA(size, FLT_MAX, 0.0f, text.data(), text.data() + text.size()).x;
                     },
                     4.0f};
}

namespace {

ImU32 imColor(FigureColor c) { return IM_COL32(c.r, c.g, c.b, 255); }

} // namespace

ImU32 ink(Ink i) { return imColor(colorOf(currentColors().plot, i)); }

namespace {

// The points as ImGui takes them, in a buffer kept for the next call (no allocation a line).
const std::vector<ImVec2>& imPoints(const std::vector<glm::vec2>& points) {
    static std::vector<ImVec2> buffer;
    buffer.clear();
    for (glm::vec2 p : points) {
        buffer.push_back(toImVec2(p));
    }
    return buffer;
}

// A dot: ImGui's AddCircleFilled with 8 segments, its unit octagon taken once from ImGui's own arc
// (the same points, without a sine and cosine for each of them each frame).
void dot(ImDrawList* dl, glm::vec2 centre, float radius, ImU32 color) {
    constexpr int kSegments = 8;
    static const std::vector<ImVec2> unit = [dl] {
        dl->_Path.clear();
        const float pi = 3.14159265358979323846f; // imgui_internal.h IM_PI
        dl->PathArcTo(ImVec2(0.0f, 0.0f), 1.0f, 0.0f, (pi * 2.0f) * (kSegments - 1.0f) / kSegments, kSegments - 1);
        std::vector<ImVec2> points(dl->_Path.begin(), dl->_Path.end());
        dl->_Path.clear();
        return points;
    }();
    if ((color & IM_COL32_A_MASK) == 0 || radius <= 0.0f) {
        return;
    }
    for (const ImVec2& u : unit) {
        dl->_Path.push_back(ImVec2(centre.x + u.x * radius, centre.y + u.y * radius));
    }
    dl->PathFillConvex(color);
}

// A polyline, dashed as the figures' PNG dashes it (figure.h forEachDashRun). ImGui's lines end square
// at their points, so a dash's round dot is a disc.
void polyline(ImDrawList* dl, const std::vector<glm::vec2>& points, ImU32 color, float width, const std::vector<float>& dash) {
    static std::vector<glm::vec2> run; // kept for the next call: no allocation a dash
    forEachDashRun(points, dash, run, [&](const std::vector<glm::vec2>& piece) {
        if (piece.size() == 2 && glm::distance(piece[0], piece[1]) < 0.5f * width) {
            dot(dl, 0.5f * (piece[0] + piece[1]), 0.5f * width, color);
        } else if (piece.size() >= 2) {
            const std::vector<ImVec2>& pts = imPoints(piece);
            dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), color, 0, width);
        }
    });
}

void paintText(ImDrawList* dl, const FigureText& t) {
    ImFont* font = ImGui::GetFont();
    const char* begin = t.text.c_str();
    const char* end = begin + t.text.size();
    const float width = font->CalcTextSizeA(t.size, FLT_MAX, 0.0f, begin, end).x;
    float x = t.at.x - (t.anchor == TextAnchor::Middle ? width * 0.5f : t.anchor == TextAnchor::End ? width : 0.0f);
    // `at` is on the baseline; ImGui places the line's top.
    const float y = t.at.y - font->Ascent * t.size / font->FontSize;
    const ImU32 color = imColor(t.color);
    x = std::round(x);
    dl->AddText(font, t.size, ImVec2(x, std::round(y)), color, begin, end);
    if (t.bold) { // twice, a pixel apart, as the figures' PNG draws bold text
        dl->AddText(font, t.size, ImVec2(x + std::max(1.0f, std::round(t.size / 14.0f)), std::round(y)), color, begin, end);
    }
}

// A line as the draw list's last vertices and indices (from `vertices`, `indices` and vertex index
// `base` on), or nothing where painting it began a command (a renderer with vertex offsets: the
// indices start again from 0).
std::optional<KeptMesh> painting(const ImDrawList* dl, int vertices, int indices, unsigned base, int commands) {
    const int count = dl->VtxBuffer.Size - vertices;
    if (dl->CmdBuffer.Size != commands || dl->_VtxCurrentIdx != base + static_cast<unsigned>(count)) {
        return std::nullopt;
    }
    KeptMesh m;
    m.vertices.assign(dl->VtxBuffer.Data + vertices, dl->VtxBuffer.Data + dl->VtxBuffer.Size);
    m.indices.reserve(static_cast<std::size_t>(dl->IdxBuffer.Size - indices));
    for (int i = indices; i < dl->IdxBuffer.Size; ++i) {
        m.indices.push_back(static_cast<ImDrawIdx>(dl->IdxBuffer.Data[i] - base));
    }
    return m;
}

// A line, copied from `kept` where it holds the same line's painting (lines long or dashed: a short
// solid one costs less to paint than to look up), else painted and kept.
void line(ImDrawList* dl, const FigureLine& l, PaintedLines* kept) {
    const ImU32 color = imColor(l.color);
    if (!kept || (l.points.size() < 8 && l.dash.empty())) {
        polyline(dl, l.points, color, l.width, l.dash);
        return;
    }
    // What ImGui's polyline and disc write depends on besides the line (imgui_draw.cpp): the white
    // pixel (fills) and, for a textured anti-aliased line of a whole width, its row of the atlas.
    const int thickness = static_cast<int>(std::max(l.width, 1.0f));
    const ImVec4 lineUv = thickness < IM_DRAWLIST_TEX_LINES_WIDTH_MAX ? ImGui::GetIO().Fonts->TexUvLines[thickness] : ImVec4();
    const PaintedLines::Key key{l.width, color, dl->Flags, ImGui::GetFontTexUvWhitePixel(), lineUv};
    if (const KeptMesh* m = kept->find(l.points, l.dash, key)) {
        drawMesh(dl, *m, false);
        return;
    }
    const int vertices = dl->VtxBuffer.Size, indices = dl->IdxBuffer.Size, commands = dl->CmdBuffer.Size;
    const unsigned base = dl->_VtxCurrentIdx;
    polyline(dl, l.points, color, l.width, l.dash);
    if (std::optional<KeptMesh> m = painting(dl, vertices, indices, base, commands)) {
        kept->keep(l.points, l.dash, key, std::move(*m));
    }
}

// What a painting depends on besides its shapes: the list's flags and clip rectangle, the font and the atlas.
PaintedLines::FigureKey drawState(const ImDrawList* dl) {
    const ImFontAtlas* atlas = ImGui::GetIO().Fonts;
    return {{0.0f, 0, dl->Flags, ImGui::GetFontTexUvWhitePixel(), ImVec4()},
            dl->_CmdHeader.ClipRect,
            ImGui::GetFont(),
            ImGui::GetFontSize(),
            dl->_CmdHeader.TextureId,
            atlas->TexWidth,
            atlas->TexHeight};
}

// Paints by `draw`, or copies an earlier frame's painting found by `find`; a new painting is kept by `keep`.
template <class Find, class Draw, class Keep> void paintKept(ImDrawList* dl, Find&& find, Draw&& draw, Keep&& keep) {
    if (const KeptMesh* m = find()) {
        drawMesh(dl, *m, false);
        return;
    }
    const int vertices = dl->VtxBuffer.Size, indices = dl->IdxBuffer.Size, commands = dl->CmdBuffer.Size;
    const unsigned base = dl->_VtxCurrentIdx;
    draw();
    if (std::optional<KeptMesh> m = painting(dl, vertices, indices, base, commands)) {
        keep(std::move(*m));
    }
}

} // namespace

void paintWhole(ImDrawList* dl, const Figure& figure, PaintedLines& kept) {
    const PaintedLines::FigureKey key = drawState(dl);
    paintKept(
        dl, [&] { return kept.find(figure, key); }, [&] { paint(dl, figure, &kept); },
        [&](KeptMesh m) { kept.keep(figure, key, std::move(m)); });
}

void drawKept(ImDrawList* dl, std::string& description, PaintedLines& kept, const std::function<void()>& draw) {
    const PaintedLines::FigureKey k = drawState(dl);
    describe(description, k.lines.flags, k.lines.fillUv.x, k.lines.fillUv.y, k.clip.x, k.clip.y, k.clip.z, k.clip.w,
             k.font, k.fontSize, k.texture, k.atlasW, k.atlasH);
    paintKept(
        dl, [&] { return kept.find(description); }, draw, [&](KeptMesh m) { kept.keep(description, std::move(m)); });
}

void paint(ImDrawList* dl, const Figure& figure, PaintedLines* kept) {
    for (const FigureShape& shape : figure.shapes) {
        if (const auto* l = std::get_if<FigureLine>(&shape)) {
            line(dl, *l, kept);
        } else if (const auto* g = std::get_if<FigurePolygon>(&shape)) {
            const std::vector<ImVec2>& pts = imPoints(g->points);
            dl->AddConvexPolyFilled(pts.data(), static_cast<int>(pts.size()), imColor(g->fill));
        } else if (const auto* d = std::get_if<FigureDisc>(&shape)) {
            dl->AddCircleFilled(toImVec2(d->centre), d->radius, imColor(d->fill));
        } else if (const auto* t = std::get_if<FigureText>(&shape)) {
            paintText(dl, *t);
        }
    }
}

void drawKeptLines(ImDrawList* dl, std::string& description, const std::vector<std::vector<ImVec2>>& lines, float width,
                   FigureColor color, PaintedLines& kept) {
    describe(description, width, color.r, color.g, color.b);
    drawKept(dl, description, kept, [&] {
        Figure figure;
        for (const std::vector<ImVec2>& line : lines) {
            FigureLine l;
            l.width = width;
            l.color = color;
            l.points.resize(line.size());
            std::transform(line.begin(), line.end(), l.points.begin(), toVec2);
            figure.shapes.push_back(std::move(l));
        }
        paint(dl, figure, &kept);
    });
}

Pens pens() {
    const ImGuiStyle& style = ImGui::GetStyle();
    Pens p;
    p.font = ImGui::GetFontSize();
    p.s = p.font / 13.0f;
    p.line = ImGui::GetTextLineHeight();
    p.frame = ImGui::GetFrameHeight();
    p.gap = style.ItemSpacing.y;
    p.gapX = style.ItemSpacing.x;
    p.inner = style.ItemInnerSpacing.x;
    p.pad = 4.0f * p.s;
    p.thin = std::max(1.0f, 1.0f * p.s);
    p.stroke = 2.0f * p.s;
    p.bold = 3.0f * p.s;
    return p;
}

void drawMesh(ImDrawList* dl, const KeptMesh& mesh, bool whitePixel) {
    const int vtx = static_cast<int>(mesh.vertices.size()), idx = static_cast<int>(mesh.indices.size());
    if (vtx == 0 || idx == 0) {
        return;
    }
    dl->PrimReserve(idx, vtx); // may start a command with its own vertex offset (a renderer that has them)
    const unsigned base = dl->_VtxCurrentIdx;
    if (sizeof(ImDrawIdx) == 2 && base + static_cast<unsigned>(vtx) > 0xFFFFu) {
        dl->PrimUnreserve(idx, vtx);
        return;
    }
    const ImVec2 uv = whitePixel ? ImGui::GetFontTexUvWhitePixel() : ImVec2(0.0f, 0.0f);
    const KeptMesh::Placed here{ImGui::GetCurrentContext(), dl, dl->VtxBuffer.Data, dl->IdxBuffer.Data,
                                static_cast<int>(dl->_VtxWritePtr - dl->VtxBuffer.Data),
                                static_cast<int>(dl->_IdxWritePtr - dl->IdxBuffer.Data), ImGui::GetFrameCount(), base, uv};
    const KeptMesh::Placed& was = mesh.placed;
    const bool stillThere = was.context == here.context && was.list == here.list && was.vertexData == here.vertexData &&
                            was.indexData == here.indexData && was.vertexAt == here.vertexAt && was.indexAt == here.indexAt &&
                            was.frame + 1 == here.frame && was.base == here.base && was.uv.x == uv.x && was.uv.y == uv.y;
    mesh.placed = here;
    if (stillThere) {
        dl->_VtxWritePtr += vtx;
        dl->_IdxWritePtr += idx;
        dl->_VtxCurrentIdx += static_cast<unsigned>(vtx);
        return;
    }
    ImDrawVert* v = dl->_VtxWritePtr;
    std::memcpy(v, mesh.vertices.data(), mesh.vertices.size() * sizeof(ImDrawVert));
    if (whitePixel && (mesh.vertices.front().uv.x != uv.x || mesh.vertices.front().uv.y != uv.y)) { // the atlas was built again
        for (int k = 0; k < vtx; ++k) {
            v[k].uv = uv;
        }
    }
    // The indices moved to where the vertices went: eight or four at a time (GCC's and Clang's
    // vector extension: GCC 12 at -O2 leaves the plain loop scalar), the rest one by one.
    using Lanes = ImDrawIdx __attribute__((vector_size(16)));
    constexpr std::size_t lanes = sizeof(Lanes) / sizeof(ImDrawIdx);
    const ImDrawIdx* in = mesh.indices.data();
    ImDrawIdx* out = dl->_IdxWritePtr;
    const std::size_t n = mesh.indices.size();
    const ImDrawIdx shift = static_cast<ImDrawIdx>(base);
    std::size_t i = 0;
    for (; i + lanes <= n; i += lanes) {
        Lanes chunk;
        std::memcpy(&chunk, in + i, sizeof chunk);
        chunk += shift;
        std::memcpy(out + i, &chunk, sizeof chunk);
    }
    for (; i < n; ++i) {
        out[i] = static_cast<ImDrawIdx>(in[i] + shift);
    }
    dl->_VtxWritePtr += vtx;
    dl->_IdxWritePtr += idx;
    dl->_VtxCurrentIdx += static_cast<unsigned>(vtx);
}

ImVec2 textSize(const std::string& t) { return ImGui::CalcTextSize(t.c_str(), t.c_str() + t.size()); }

//----------------------------------------------------------------------------------------
// Readouts
//----------------------------------------------------------------------------------------

void Readout::measure(const Pens& p) {
    widths.clear();
    for (Token& t : tokens) {
        t.width = t.text.empty() ? kLineBreak : textSize(t.text).x + (t.swatch ? 1.4f * p.font + p.pad : 0.0f);
        widths.push_back(t.width);
    }
}

const Readout& Readout::flowed(float width, Readout& scratch) const {
    auto tooWide = [&](const Token& t) { return t.width != kLineBreak && !t.swatch && t.width > width; };
    if (std::none_of(tokens.begin(), tokens.end(), tooWide)) {
        return *this;
    }
    scratch.tokens.clear();
    scratch.widths.clear();
    for (const Token& t : tokens) {
        if (!tooWide(t)) {
            scratch.tokens.push_back(t);
            scratch.widths.push_back(t.width);
            continue;
        }
        // As many words to a piece as fit in `width`, a space apart, as the text was.
        std::string piece;
        auto endPiece = [&] {
            if (!piece.empty()) {
                const float w = textSize(piece).x;
                scratch.tokens.push_back({std::move(piece), t.ink, false, w});
                scratch.widths.push_back(w);
                piece.clear();
            }
        };
        for (std::string_view word : spaceSeparated(t.text)) {
            const std::string longer = piece.empty() ? std::string(word) : piece + " " + std::string(word);
            if (!piece.empty() && textSize(longer).x > width) {
                endPiece();
                piece = word;
            } else {
                piece = longer;
            }
        }
        endPiece();
    }
    return scratch;
}

float Readout::height(const Pens& p, float width) const {
    Readout scratch;
    return static_cast<float>(flowLines(flowed(width, scratch).widths, p.font * 0.5f, width)) * p.line;
}

void Readout::draw(ImDrawList* dl, const Pens& p, ImVec2 at, float width, PaintedLines* kept) const {
    // A word wider than the plots is cut at their side: named in the widget map as cut text
    // ("clipped:readout", ui/widget_map.h), on every frame, painted or kept.
    Readout scratch;
    const Readout& f = flowed(width, scratch);
    if (std::any_of(f.widths.begin(), f.widths.end(), [&](float w) { return w != kLineBreak && w > width + 1.0f; })) {
        widgets().set("clipped:readout", {at.x, at.y, width, p.line});
    }
    if (!kept) {
        f.drawTokens(dl, p, at, width);
        return;
    }
    // Everything the tokens' painting is made from.
    std::string d;
    describe(d, at.x, at.y, width, p.font, p.line, p.pad, p.bold);
    for (const Token& t : tokens) {
        const ImU32 color = ink(t.ink);
        const std::size_t length = t.text.size();
        describe(d, t.ink, color, t.swatch, t.width, length);
        d += t.text;
    }
    drawKept(dl, d, *kept, [&] { f.drawTokens(dl, p, at, width); });
}

void Readout::drawTokens(ImDrawList* dl, const Pens& p, ImVec2 at, float width) const {
    std::vector<FlowPlace> places = flowTokens(widths, p.font * 0.5f, width);
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        if (t.width == kLineBreak) {
            continue;
        }
        ImVec2 c(at.x + places[i].x, at.y + static_cast<float>(places[i].line) * p.line);
        if (t.swatch) {
            float y = c.y + p.line * 0.5f;
            polyline(dl, {{c.x, y}, {c.x + 1.4f * p.font, y}}, ink(t.ink), p.bold, dashOf(t.ink, p.font / 14.0f));
            c.x += 1.4f * p.font + p.pad;
        }
        dl->AddText(c, ink(t.ink), t.text.c_str(), t.text.c_str() + t.text.size());
    }
}

void scaleTokens(Readout& r, float outer, float largest, bool locked, const char* what, Ink ink) {
    if (!locked && !(largest > kNothingLit)) {
        r.add("all 0 (terms switched off?)", ink);
        return;
    }
    r.add(format("outer ring %s", tickText(outer).c_str()), ink);
    if (locked) {
        r.add("(locked)", ink);
        if (largest > outer * 1.001f) {
            r.add(format("peak %s beyond it", tickText(largest).c_str()), Ink::Warning);
        }
    } else {
        r.add(format("= %s", what), ink);
    }
}

//----------------------------------------------------------------------------------------
// Canvases
//----------------------------------------------------------------------------------------

Canvas beginCanvas(const char* id, const char* name, float width, float height) {
    Canvas c;
    if (width < 1.0f || height < 1.0f) {
        return c;
    }
    c.width = width;
    c.height = height;
    c.corner = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton(id, ImVec2(width, height));
    mark(name);
    c.dl = ImGui::GetWindowDrawList();
    c.dl->AddRectFilled(c.corner, ImVec2(c.corner.x + width, c.corner.y + height), ink(Ink::Background));
    return c;
}

std::optional<Box> canvasBox(const Canvas& c, const PlotStyle& style, const std::string& yLabel, const std::string& xLabel) {
    const float text = style.text(), pad = style.pad();
    Box b{{c.corner.x + style.width(yLabel, text) + 2.0f * pad, c.corner.y + c.height - text - 2.0f * pad},
          {c.corner.x + c.width - style.width(xLabel, text) * 0.5f - pad, c.corner.y + text * 0.6f}};
    if (b.hi.x - b.lo.x < text || b.lo.y - b.hi.y < text) {
        return std::nullopt;
    }
    return b;
}

//----------------------------------------------------------------------------------------
// A plot's block: readout strip, canvas, controls
//----------------------------------------------------------------------------------------

Block placeBlock(const PlotBox& box, ImVec2 origin, const Pens& p, const Readout& r, const char* readoutMark,
                 bool cramped, bool controls, float minCanvas, const std::function<float(float)>& maxCanvas,
                 PaintedLines* kept) {
    const ImVec2 top(origin.x + box.x, origin.y + box.y);
    const float controlsH = controls ? p.frame + p.gap : 0.0f;
    Block b;
    float stripW = box.w, stripH = r.height(p, box.w);
    ImVec2 strip = top;
    if (cramped) {
        // Too low for the controls too: the canvas takes the whole height (drag L and V in it).
        // Else the controls take the bottom row, across the whole width: the text stays above it.
        const bool controlsShown = controls && box.h - controlsH - p.gap >= 3.0f * p.line;
        const float textRoom = controlsShown ? box.h - controlsH : box.h;
        // The narrowest column (from 30% to 60% of the width) whose text fits the height.
        for (float share = 0.3f; share <= 0.61f; share += 0.05f) {
            stripW = box.w * share;
            stripH = r.height(p, stripW);
            if (stripH <= textRoom) {
                break;
            }
        }
        stripH = std::min(stripH, textRoom); // what still does not fit is clipped, never scrolled to
        strip = ImVec2(top.x + box.w - stripW, top.y);
        b.canvas = top;
        b.canvasW = box.w - stripW - p.gapX;
        float room = controlsShown ? box.h - controlsH - p.gap : box.h;
        b.canvasH = std::clamp(room, 0.0f, maxCanvas(b.canvasW));
    } else {
        float canvasH = box.canvas;
        if (canvasH < minCanvas) {
            // One plot at a time in a column too low for its wrapped readout (a narrow column at a
            // large UI scale): the readout gives way, clipped, so that the canvas keeps its minimum.
            canvasH = std::min(minCanvas, std::max(box.h - controlsH - p.gap, 0.0f));
            stripH = std::max(box.h - controlsH - p.gap - canvasH, 0.0f);
        }
        b.canvas = ImVec2(top.x, top.y + stripH + p.gap);
        b.canvasW = box.w;
        b.canvasH = canvasH;
    }
    // Below the canvas and the text, whichever ends lower (beside a short canvas the text may).
    b.controls = ImVec2(top.x, std::max(b.canvas.y + b.canvasH, strip.y + stripH) + p.gap);
    b.controlsFit = b.controls.y + p.frame <= top.y + box.h + 0.5f;
    ImGui::SetCursorScreenPos(strip);
    ImGui::Dummy(ImVec2(stripW, std::max(stripH, 1.0f)));
    mark(readoutMark);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(strip, ImVec2(strip.x + stripW, strip.y + std::max(stripH, 1.0f)), true);
    r.draw(dl, p, strip, stripW, kept);
    dl->PopClipRect();
    ImGui::SetCursorScreenPos(b.canvas);
    return b;
}

} // namespace lab::ui::plotkit
