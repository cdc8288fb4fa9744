// text_raster.cpp — stb_truetype glyphs (and stb_easy_font's strokes as the fallback) blended into
// an Image. The one place STB_TRUETYPE_IMPLEMENTATION is defined. STBTT_STATIC keeps its
// functions inside this file, so they can never clash with the copy Debian's libstb carries;
// the browser build (LAB_STB_TRUETYPE_EXTERN, cmake/web.cmake) exports them instead, with the
// stb_rect_pack they pack glyphs with, for ImGui's font atlas: the page holds one of each, not two.
#include "core/plots/text_raster.h"

#include "core/io/file_io.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#ifdef LAB_STB_TRUETYPE_EXTERN
#define STB_RECT_PACK_IMPLEMENTATION // before stb_truetype.h, which packs with it when it is there
#include <stb_rect_pack.h>
#else
#define STBTT_STATIC // (stb_truetype.h reads this name; its functions stay inside this file)
#endif
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_truetype.h>
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace lab {

namespace {

constexpr std::size_t kMaxFontBytes = std::size_t{32} << 20;
constexpr char32_t kReplacement = 0xFFFD;

// stb_easy_font's strokes live on a 12-unit line: capitals from 0 to 7, descenders to 10. The
// fallback maps `pixelSize` to 11 units so its capitals are about as tall as DejaVu's.
constexpr float kEasyUnitsPerLine = 11.0f;
constexpr float kEasyBaselineUnits = 8.0f;

void blend(Image& image, int px, int py, float coverage, TextColor c) {
    if (px < 0 || py < 0 || px >= image.width || py >= image.height || coverage <= 0.0f) {
        return;
    }
    float a = std::min(coverage, 1.0f);
    std::uint8_t* p = &image.rgb[(std::size_t(py) * std::size_t(image.width) + std::size_t(px)) * 3];
    const std::uint8_t src[3] = {c.r, c.g, c.b};
    for (int k = 0; k < 3; ++k) {
        p[k] = static_cast<std::uint8_t>(std::lround(p[k] + (src[k] - p[k]) * a));
    }
}

// The ASCII text stb_easy_font can draw: printable characters, '?' for everything else.
std::string easyText(std::string_view utf8) {
    std::string out;
    for (char32_t c : decodeUtf8(utf8)) {
        out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
    }
    return out;
}

} // namespace

std::vector<char32_t> decodeUtf8(std::string_view s) {
    std::vector<char32_t> out;
    out.reserve(s.size());
    std::size_t i = 0;
    while (i < s.size()) {
        auto b = static_cast<unsigned char>(s[i]);
        int extra = b < 0x80 ? 0 : (b >> 5) == 0x6 ? 1 : (b >> 4) == 0xE ? 2 : (b >> 3) == 0x1E ? 3 : -1;
        if (extra < 0 || i + std::size_t(extra) >= s.size()) { // a stray or cut-off byte
            out.push_back(kReplacement);
            ++i;
            continue;
        }
        char32_t c = extra == 0 ? b : extra == 1 ? (b & 0x1Fu) : extra == 2 ? (b & 0x0Fu) : (b & 0x07u);
        bool ok = true;
        for (int k = 1; k <= extra; ++k) {
            auto cont = static_cast<unsigned char>(s[i + std::size_t(k)]);
            if ((cont & 0xC0) != 0x80) {
                ok = false;
                break;
            }
            c = (c << 6) | (cont & 0x3Fu);
        }
        // Overlong forms, surrogates and values past U+10FFFF are not characters.
        static constexpr char32_t kMin[4] = {0, 0x80, 0x800, 0x10000};
        if (!ok || c < kMin[extra] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) {
            out.push_back(kReplacement);
            ++i;
            continue;
        }
        out.push_back(c);
        i += std::size_t(extra) + 1;
    }
    return out;
}

std::vector<std::filesystem::path> defaultFontFiles() {
    return {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/fonts/DejaVuSans-ui.ttf"};
}

struct TextFont::Face {
    std::string bytes;
    stbtt_fontinfo info{};
    int ascent = 0, descent = 0; // font units
};

TextFont::TextFont(TextFont&&) noexcept = default;
TextFont& TextFont::operator=(TextFont&&) noexcept = default;
TextFont::~TextFont() = default;

TextFont TextFont::builtIn() {
    TextFont font;
    font.loadError_ = "the built-in fallback font was asked for";
    return font;
}

TextFont TextFont::load(const std::vector<std::filesystem::path>& files) {
    TextFont font;
    std::string errors;
    for (const std::filesystem::path& file : files) {
        std::string error;
        std::optional<std::string> bytes = readFile(file, kMaxFontBytes, error);
        if (bytes) {
            auto face = std::make_unique<Face>();
            face->bytes = std::move(*bytes);
            const auto* data = reinterpret_cast<const unsigned char*>(face->bytes.data());
            int offset = stbtt_GetFontOffsetForIndex(data, 0);
            if (offset >= 0 && stbtt_InitFont(&face->info, data, offset)) {
                int lineGap = 0;
                stbtt_GetFontVMetrics(&face->info, &face->ascent, &face->descent, &lineGap);
                if (face->ascent > face->descent) {
                    font.face_ = std::move(face);
                    font.file_ = file;
                    return font;
                }
            }
            error = "not a TrueType font";
        }
        errors += (errors.empty() ? "" : "; ") + file.string() + ": " + error;
    }
    font.loadError_ = files.empty() ? "no font file was named" : errors;
    return font;
}

bool TextFont::fallback() const { return !face_; }

float TextFont::lineHeightPerEm() const {
    if (!face_) {
        return 1.164f; // DejaVu Sans's (2048 units an em, ascent 1901, descent 483)
    }
    return stbtt_ScaleForMappingEmToPixels(&face_->info, 1.0f) / stbtt_ScaleForPixelHeight(&face_->info, 1.0f);
}

TextBox TextFont::measure(std::string_view utf8, float pixelSize) const {
    if (utf8.empty() || !(pixelSize > 0.0f) || pixelSize > kMaxTextPixelSize) {
        return {};
    }
    if (!face_) {
        std::string text = easyText(utf8);
        float unit = pixelSize / kEasyUnitsPerLine;
        return {static_cast<float>(stb_easy_font_width(text.data())) * unit, pixelSize, kEasyBaselineUnits * unit};
    }
    const stbtt_fontinfo& info = face_->info;
    float scale = stbtt_ScaleForPixelHeight(&info, pixelSize);
    float width = 0.0f;
    int previous = 0;
    for (char32_t c : decodeUtf8(utf8)) {
        int glyph = stbtt_FindGlyphIndex(&info, static_cast<int>(c));
        int advance = 0, bearing = 0;
        stbtt_GetGlyphHMetrics(&info, glyph, &advance, &bearing);
        if (previous) {
            width += scale * static_cast<float>(stbtt_GetGlyphKernAdvance(&info, previous, glyph));
        }
        width += scale * static_cast<float>(advance);
        previous = glyph;
    }
    return {width, scale * static_cast<float>(face_->ascent - face_->descent), scale * static_cast<float>(face_->ascent)};
}

TextBox TextFont::draw(Image& image, std::string_view utf8, float x, float y, float pixelSize, TextColor color) const {
    TextBox box = measure(utf8, pixelSize);
    if (box.width <= 0.0f || image.width <= 0 || image.height <= 0) {
        return box;
    }
    if (!face_) {
        // The strokes are axis-aligned quads: each pixel gets the area it shares with them.
        std::string text = easyText(utf8);
        std::vector<char> vertices(text.size() * 300 + 64);
        int quads = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, vertices.data(), static_cast<int>(vertices.size()));
        float unit = pixelSize / kEasyUnitsPerLine;
        for (int q = 0; q < quads; ++q) {
            const auto* v = reinterpret_cast<const float*>(vertices.data() + std::size_t(q) * 64);
            float x0 = x + v[0] * unit, y0 = y + v[1] * unit;          // vertex 0: top-left
            float x1 = x + v[2 * 4] * unit, y1 = y + v[2 * 4 + 1] * unit; // vertex 2: bottom-right
            for (int py = static_cast<int>(std::floor(y0)); py < static_cast<int>(std::ceil(y1)); ++py) {
                float cy = std::min(y1, py + 1.0f) - std::max(y0, static_cast<float>(py));
                for (int px = static_cast<int>(std::floor(x0)); px < static_cast<int>(std::ceil(x1)); ++px) {
                    float cx = std::min(x1, px + 1.0f) - std::max(x0, static_cast<float>(px));
                    blend(image, px, py, cx * cy, color);
                }
            }
        }
        return box;
    }
    const stbtt_fontinfo& info = face_->info;
    float scale = stbtt_ScaleForPixelHeight(&info, pixelSize);
    float baseline = y + box.baseline;
    int by = static_cast<int>(std::floor(baseline));
    float shiftY = baseline - static_cast<float>(by);
    float pen = x;
    int previous = 0;
    std::vector<unsigned char> bitmap;
    for (char32_t c : decodeUtf8(utf8)) {
        int glyph = stbtt_FindGlyphIndex(&info, static_cast<int>(c));
        if (previous) {
            pen += scale * static_cast<float>(stbtt_GetGlyphKernAdvance(&info, previous, glyph));
        }
        int bx = static_cast<int>(std::floor(pen));
        float shiftX = pen - static_cast<float>(bx);
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        stbtt_GetGlyphBitmapBoxSubpixel(&info, glyph, scale, scale, shiftX, shiftY, &x0, &y0, &x1, &y1);
        int w = x1 - x0, h = y1 - y0;
        if (w > 0 && h > 0) {
            bitmap.assign(std::size_t(w) * std::size_t(h), 0);
            stbtt_MakeGlyphBitmapSubpixel(&info, bitmap.data(), w, h, w, scale, scale, shiftX, shiftY, glyph);
            for (int j = 0; j < h; ++j) {
                for (int i = 0; i < w; ++i) {
                    blend(image, bx + x0 + i, by + y0 + j, bitmap[std::size_t(j) * std::size_t(w) + std::size_t(i)] / 255.0f, color);
                }
            }
        }
        int advance = 0, bearing = 0;
        stbtt_GetGlyphHMetrics(&info, glyph, &advance, &bearing);
        pen += scale * static_cast<float>(advance);
        previous = glyph;
    }
    return box;
}

std::string TextFont::fitted(std::string_view utf8, float pixelSize, float width) const {
    if (measure(utf8, pixelSize).width <= width) {
        return std::string(utf8);
    }
    const std::string_view ellipsis = "\xe2\x80\xa6";
    std::string cut(utf8);
    while (!cut.empty()) {
        std::size_t end = cut.size() - 1; // drop the last character: its first byte is not a continuation
        while (end > 0 && (static_cast<unsigned char>(cut[end]) & 0xC0) == 0x80) {
            --end;
        }
        cut.resize(end);
        if (measure(cut + std::string(ellipsis), pixelSize).width <= width) {
            return cut + std::string(ellipsis);
        }
    }
    return std::string(ellipsis);
}

const TextFont& sharedTextFont() {
    static const TextFont font = TextFont::load();
    return font;
}

} // namespace lab
