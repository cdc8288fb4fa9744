// figure_svg.cpp — a Figure as an SVG document (figure.h). Text only: the caller writes the file
// (file_io.h's atomic write).
#include "core/plots/figure.h"

#include "core/io/safe_text.h"

#include <algorithm>
#include <cstdio>
#include <string_view>

namespace lab {

namespace {

// Two decimals: a hundredth of a pixel, finer than any PNG the figure is rasterized to.
std::string num(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", double(v));
    std::string s = text;
    return s == "-0.00" ? "0.00" : s;
}

std::string colour(FigureColor c) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
    return text;
}

// Character data and attribute values, one line each (core/io/safe_text.h).
std::string xml(std::string_view text) { return xmlEscaped(text, true); }

std::string points(const std::vector<glm::vec2>& ps) {
    std::string out;
    for (const glm::vec2& p : ps) {
        if (!out.empty()) {
            out += ' ';
        }
        out += num(p.x) + ',' + num(p.y);
    }
    return out;
}

// RFC 4648 base64 with padding, for the <image>'s data: URI.
std::string base64(std::string_view bytes) {
    static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        unsigned v = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        }
        for (std::size_t k = 0; k < 4; ++k) {
            out += k <= n ? digits[(v >> (18 - 6 * k)) & 63u] : '=';
        }
    }
    return out;
}

} // namespace

std::string figureSvg(const Figure& f) {
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(f.width) + "px\" height=\"" + num(f.height) +
           "px\" viewBox=\"0 0 " + num(f.width) + ' ' + num(f.height) + "\">\n";
    out += "<title>" + xml(f.title) + "</title>\n";
    out += "<rect x=\"0\" y=\"0\" width=\"" + num(f.width) + "\" height=\"" + num(f.height) + "\" fill=\"" +
           colour(f.background) + "\"/>\n";
    out += "<g font-family=\"DejaVu Sans, Verdana, sans-serif\">\n";
    for (const FigureShape& shape : f.shapes) {
        if (const auto* l = std::get_if<FigureLine>(&shape)) {
            out += "<polyline";
            if (!l->id.empty()) {
                out += " id=\"" + xml(l->id) + "\"";
            }
            out += " fill=\"none\" stroke=\"" + colour(l->color) + "\" stroke-width=\"" + num(l->width) + "\"";
            if (!l->dash.empty()) {
                std::string dashes;
                for (float d : l->dash) {
                    dashes += (dashes.empty() ? "" : " ") + num(d);
                }
                out += " stroke-dasharray=\"" + dashes + "\"";
            }
            out += " stroke-linecap=\"round\" stroke-linejoin=\"round\" points=\"" + points(l->points) + "\"/>\n";
        } else if (const auto* p = std::get_if<FigurePolygon>(&shape)) {
            out += "<polygon fill=\"" + colour(p->fill) + "\" points=\"" + points(p->points) + "\"/>\n";
        } else if (const auto* d = std::get_if<FigureDisc>(&shape)) {
            out += "<circle cx=\"" + num(d->centre.x) + "\" cy=\"" + num(d->centre.y) + "\" r=\"" + num(d->radius) +
                   "\" fill=\"" + colour(d->fill) + "\"/>\n";
        } else if (const auto* t = std::get_if<FigureText>(&shape)) {
            const char* anchor = t->anchor == TextAnchor::Start ? "start" : t->anchor == TextAnchor::Middle ? "middle" : "end";
            out += "<text x=\"" + num(t->at.x) + "\" y=\"" + num(t->at.y) + "\" font-size=\"" + num(t->size) +
                   "\" fill=\"" + colour(t->color) + "\" text-anchor=\"" + anchor + "\"" +
                   (t->bold ? " font-weight=\"bold\"" : "") + ">" + xml(t->text) + "</text>\n";
        } else if (const auto* i = std::get_if<FigureImage>(&shape)) {
            out += "<image";
            if (!i->id.empty()) {
                out += " id=\"" + xml(i->id) + "\"";
            }
            out += " x=\"" + num(i->at.x) + "\" y=\"" + num(i->at.y) + "\" width=\"" + num(i->size.x) + "\" height=\"" +
                   num(i->size.y) + "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" href=\"data:image/png;base64," +
                   base64(i->image ? encodePng(*i->image) : std::string()) + "\"/>\n";
        }
    }
    out += "</g>\n</svg>\n";
    return out;
}

} // namespace lab
