// figure_png.cpp — a Figure painted into an Image on the CPU (figure.h). Each shape's coverage of
// every pixel is gathered first (the largest over its segments, so the joints of a polyline are
// not painted twice), then blended once in the shape's colour.
#include "core/plots/figure.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace lab {

namespace {

// Coverage of one shape, in [0, 1] per pixel, over the bounding box it touched.
struct Coverage {
    int width = 0, height = 0;
    std::vector<float> value;
    int x0 = kNone, y0 = kNone, x1 = -1, y1 = -1; // the box touched, inclusive (none yet)
    static constexpr int kNone = 1 << 30;

    Coverage(int w, int h) : width(w), height(h), value(std::size_t(w) * std::size_t(h), 0.0f) {}

    // The pixels (inclusive) of [lo, hi], clipped to the image; false when none.
    bool box(glm::vec2 lo, glm::vec2 hi, int& bx0, int& by0, int& bx1, int& by1) const {
        bx0 = std::max(0, static_cast<int>(std::floor(lo.x)));
        by0 = std::max(0, static_cast<int>(std::floor(lo.y)));
        bx1 = std::min(width - 1, static_cast<int>(std::ceil(hi.x)));
        by1 = std::min(height - 1, static_cast<int>(std::ceil(hi.y)));
        return bx0 <= bx1 && by0 <= by1;
    }
    void put(int x, int y, float c) {
        float& v = value[std::size_t(y) * std::size_t(width) + std::size_t(x)];
        v = std::max(v, std::min(c, 1.0f));
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x);
        y1 = std::max(y1, y);
    }
    // Blends the gathered coverage in `c` and clears it for the next shape.
    void paint(Image& image, FigureColor c) {
        const float src[3] = {float(c.r), float(c.g), float(c.b)};
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                float& a = value[std::size_t(y) * std::size_t(width) + std::size_t(x)];
                if (a > 0.0f) {
                    std::uint8_t* p = &image.rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
                    for (int k = 0; k < 3; ++k) {
                        p[k] = static_cast<std::uint8_t>(std::lround(p[k] + (src[k] - p[k]) * a));
                    }
                    a = 0.0f;
                }
            }
        }
        x0 = y0 = kNone;
        x1 = y1 = -1;
    }
};

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    glm::vec2 ab = b - a;
    float len2 = glm::dot(ab, ab);
    float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

// A line `width` pixels wide with round caps: a pixel is covered by how far its centre lies
// inside the stroke, within half a pixel either side of the edge. Lines thinner than a pixel are
// drawn one pixel wide and lighter, as they would average out.
void line(Coverage& cov, const std::vector<glm::vec2>& pts, float width) {
    float half = std::max(width, 1.0f) * 0.5f;
    float weight = std::min(width, 1.0f);
    for (std::size_t i = 0; i + 1 < pts.size() || (pts.size() == 1 && i == 0); ++i) {
        glm::vec2 a = pts[i], b = pts.size() == 1 ? pts[i] : pts[i + 1];
        int bx0, by0, bx1, by1;
        if (!cov.box(glm::min(a, b) - half - 1.0f, glm::max(a, b) + half + 1.0f, bx0, by0, bx1, by1)) {
            continue;
        }
        for (int y = by0; y <= by1; ++y) {
            for (int x = bx0; x <= bx1; ++x) {
                float d = distanceToSegment({x + 0.5f, y + 0.5f}, a, b);
                float c = std::clamp(half + 0.5f - d, 0.0f, 1.0f) * weight;
                if (c > 0.0f) {
                    cov.put(x, y, c);
                }
            }
        }
    }
}

bool inside(const std::vector<glm::vec2>& poly, glm::vec2 p) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::vec2 &a = poly[i], &b = poly[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
            in = !in;
        }
    }
    return in;
}

// 4 × 4 samples a pixel (the polygons are small: arrowheads and swatches).
void polygon(Coverage& cov, const std::vector<glm::vec2>& poly) {
    if (poly.size() < 3) {
        return;
    }
    glm::vec2 lo = poly[0], hi = poly[0];
    for (const glm::vec2& p : poly) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    int bx0, by0, bx1, by1;
    if (!cov.box(lo, hi, bx0, by0, bx1, by1)) {
        return;
    }
    for (int y = by0; y <= by1; ++y) {
        for (int x = bx0; x <= bx1; ++x) {
            int hits = 0;
            for (int sy = 0; sy < 4; ++sy) {
                for (int sx = 0; sx < 4; ++sx) {
                    hits += inside(poly, {x + (sx + 0.5f) / 4.0f, y + (sy + 0.5f) / 4.0f});
                }
            }
            if (hits) {
                cov.put(x, y, hits / 16.0f);
            }
        }
    }
}

void disc(Coverage& cov, glm::vec2 c, float r) {
    int bx0, by0, bx1, by1;
    if (!cov.box(c - r - 1.0f, c + r + 1.0f, bx0, by0, bx1, by1)) {
        return;
    }
    for (int y = by0; y <= by1; ++y) {
        for (int x = bx0; x <= bx1; ++x) {
            float a = std::clamp(r + 0.5f - glm::length(glm::vec2(x + 0.5f, y + 0.5f) - c), 0.0f, 1.0f);
            if (a > 0.0f) {
                cov.put(x, y, a);
            }
        }
    }
}

} // namespace

void forEachDashRun(const std::vector<glm::vec2>& points, const std::vector<float>& dash, std::vector<glm::vec2>& run,
                    const std::function<void(const std::vector<glm::vec2>&)>& draw) {
    float period = 0.0f;
    for (float d : dash) {
        period += std::max(d, 0.0f);
    }
    if (points.size() < 2 || dash.size() < 2 || dash.size() % 2 != 0 || !(period >= 0.5f)) {
        draw(points);
        return;
    }
    run.assign(1, points[0]);
    std::size_t k = 0; // the pattern's element the walk is in: even ones draw
    float left = std::max(dash[0], 0.0f);
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const glm::vec2 a = points[i], b = points[i + 1];
        const float length = glm::length(b - a);
        float at = 0.0f;
        while (length - at > left) { // the element ends inside this segment (length > 0 here)
            at += left;
            const glm::vec2 p = a + (b - a) * (at / length);
            if (k % 2 == 0) {
                run.push_back(p);
            }
            k = (k + 1) % dash.size();
            left = std::max(dash[k], 0.0f);
            if (k % 2 == 0) { // a dash begins: the one before is whole (it ended with a point)
                draw(run);
                run.assign(1, p);
            }
        }
        left -= length - at;
        if (k % 2 == 0) {
            run.push_back(b);
        }
    }
    if (run.size() >= 2) { // a dash that begins exactly at the line's end draws nothing
        draw(run);
    }
}

std::vector<std::vector<glm::vec2>> dashRuns(const std::vector<glm::vec2>& points, const std::vector<float>& dash) {
    std::vector<std::vector<glm::vec2>> runs;
    std::vector<glm::vec2> run;
    forEachDashRun(points, dash, run, [&](const std::vector<glm::vec2>& piece) { runs.push_back(piece); });
    return runs;
}

namespace {

// Every pixel whose centre lies in the image's rectangle takes the image pixel under that centre.
void paintImage(Image& out, const FigureImage& shape, float scale) {
    if (!shape.image) {
        return;
    }
    const FigureImage& i = shape;
    const Image& source = *shape.image;
    if (source.width < 1 || source.height < 1 || !(i.size.x > 0.0f) || !(i.size.y > 0.0f) ||
        source.rgb.size() != std::size_t(source.width) * std::size_t(source.height) * 3) {
        return;
    }
    const glm::vec2 lo = i.at * scale, hi = (i.at + i.size) * scale;
    const int x0 = std::max(0, static_cast<int>(std::ceil(lo.x - 0.5f))), x1 = std::min(out.width, static_cast<int>(std::ceil(hi.x - 0.5f)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(lo.y - 0.5f))), y1 = std::min(out.height, static_cast<int>(std::ceil(hi.y - 0.5f)));
    for (int y = y0; y < y1; ++y) {
        const int v = std::clamp(static_cast<int>((y + 0.5f - lo.y) / (hi.y - lo.y) * source.height), 0, source.height - 1);
        for (int x = x0; x < x1; ++x) {
            const int u = std::clamp(static_cast<int>((x + 0.5f - lo.x) / (hi.x - lo.x) * source.width), 0, source.width - 1);
            const std::uint8_t* from = &source.rgb[(std::size_t(v) * std::size_t(source.width) + std::size_t(u)) * 3];
            std::uint8_t* to = &out.rgb[(std::size_t(y) * std::size_t(out.width) + std::size_t(x)) * 3];
            to[0] = from[0];
            to[1] = from[1];
            to[2] = from[2];
        }
    }
}

} // namespace

Image rasterizeFigure(const Figure& f, float scale, const TextFont& font) {
    scale = std::clamp(std::isfinite(scale) ? scale : 1.0f, kMinFigureScale, kMaxFigureScale);
    Image image;
    image.width = std::clamp(static_cast<int>(std::lround(f.width * scale)), 1, kMaxImageSide);
    image.height = std::clamp(static_cast<int>(std::lround(f.height * scale)), 1, kMaxImageSide);
    image.rgb.resize(std::size_t(image.width) * std::size_t(image.height) * 3);
    for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
        image.rgb[i] = f.background.r;
        image.rgb[i + 1] = f.background.g;
        image.rgb[i + 2] = f.background.b;
    }
    Coverage cov(image.width, image.height);
    auto scaled = [&](const std::vector<glm::vec2>& pts) {
        std::vector<glm::vec2> out;
        out.reserve(pts.size());
        for (const glm::vec2& p : pts) {
            out.push_back(p * scale);
        }
        return out;
    };
    for (const FigureShape& shape : f.shapes) {
        if (const auto* l = std::get_if<FigureLine>(&shape)) {
            for (const std::vector<glm::vec2>& run : dashRuns(l->points, l->dash)) {
                line(cov, scaled(run), l->width * scale);
            }
            cov.paint(image, l->color);
        } else if (const auto* p = std::get_if<FigurePolygon>(&shape)) {
            polygon(cov, scaled(p->points));
            cov.paint(image, p->fill);
        } else if (const auto* d = std::get_if<FigureDisc>(&shape)) {
            disc(cov, d->centre * scale, d->radius * scale);
            cov.paint(image, d->fill);
        } else if (const auto* t = std::get_if<FigureText>(&shape)) {
            float size = t->size * scale * font.lineHeightPerEm();
            TextBox box = font.measure(t->text, size);
            float x = t->at.x * scale;
            x -= t->anchor == TextAnchor::Middle ? box.width * 0.5f : t->anchor == TextAnchor::End ? box.width : 0.0f;
            float y = t->at.y * scale - box.baseline;
            font.draw(image, t->text, x, y, size, t->color);
            if (t->bold) {
                font.draw(image, t->text, x + 0.6f * scale, y, size, t->color);
            }
        } else if (const auto* i = std::get_if<FigureImage>(&shape)) {
            paintImage(image, *i, scale);
        }
    }
    return image;
}

} // namespace lab
