// text_raster.h — UTF-8 text drawn into an Image on the CPU: for labels in images the lab writes
// itself (figures, sweep grids), where there is no GL and no ImGui.
//
// One font, DejaVu Sans (the UI's font), read through stb_truetype: glyphs anti-aliased by
// coverage, placed at sub-pixel positions, kerned where the font has a kern table, blended over
// the image in the given colour. When no font file can be read (a machine without
// fonts-dejavu-core), the font falls back to stb_easy_font's built-in ASCII strokes, scaled to the
// same pixel size and anti-aliased the same way: the text stays legible, `fallback()` says so and
// `loadError()` why, so a caller can mention it. Characters outside ASCII are drawn as '?' there.
//
// Not here: layout (wrapping, alignment: measure, then place), right-to-left, shaping, colour
// emoji. Pure apart from reading the font file once.
//
//     const TextFont& font = sharedTextFont();
//     TextBox box = font.measure("θ = 30°", 16.0f);
//     font.draw(image, "θ = 30°", x - box.width / 2, y, 16.0f, {20, 20, 20}); // centred on x
#pragma once

#include "core/io/image.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

inline constexpr float kMaxTextPixelSize = 1024.0f;

struct TextColor {
    std::uint8_t r = 0, g = 0, b = 0;
};

// A line of text's box, in pixels, for its top-left corner at (x, y) as draw() takes it:
// `baseline` below y, ink usually between y and y + height (descenders included).
struct TextBox {
    float width = 0.0f;    // advance of the whole string (0 for "")
    float height = 0.0f;   // ascent + descent of the font at this size (0 for "")
    float baseline = 0.0f; // ascent: from the top of the box to the baseline
};

// The font files tried in order: DejaVu Sans where Debian installs it, and where the browser
// build's page puts its cut of it (cmake/web.cmake).
std::vector<std::filesystem::path> defaultFontFiles();

class TextFont {
public:
    // The first of `files` that reads as a TrueType font; the fallback font when none does.
    static TextFont load(const std::vector<std::filesystem::path>& files = defaultFontFiles());
    // The fallback font only (for tests, and for callers that must not read files).
    static TextFont builtIn();

    TextFont(TextFont&&) noexcept;
    TextFont& operator=(TextFont&&) noexcept;
    ~TextFont();

    bool fallback() const;                             // true when drawing with stb_easy_font
    const std::string& loadError() const { return loadError_; } // why, when fallback()
    const std::filesystem::path& file() const { return file_; } // the font read, when not

    // The box `utf8` takes at `pixelSize`: the line's height in pixels (ascent + descent, as
    // ImGui sizes its fonts), in (0, kMaxTextPixelSize]; an empty box for any other size.
    TextBox measure(std::string_view utf8, float pixelSize) const;
    // The line height (pixelSize above) of text whose em is 1 px: how an SVG font-size, which is
    // the em, becomes a pixelSize here (DejaVu Sans: 1.164; the fallback says the same).
    float lineHeightPerEm() const;
    // Draws `utf8` with its box's top-left at (x, y), blended over `image` (clipped to it);
    // returns measure(utf8, pixelSize). Invalid UTF-8 bytes are drawn as U+FFFD (the fallback: '?').
    TextBox draw(Image& image, std::string_view utf8, float x, float y, float pixelSize, TextColor color) const;
    // `utf8` as it is where it is at most `width` pixels wide at `pixelSize`, else cut after a whole
    // character with "…" added to fit; "…" alone when no character fits beside it.
    std::string fitted(std::string_view utf8, float pixelSize, float width) const;

private:
    struct Face;
    TextFont() = default;
    std::unique_ptr<Face> face_; // null: the fallback
    std::string loadError_;
    std::filesystem::path file_;
};

// One font for the whole program, loaded on first use (thread-safe) from defaultFontFiles().
const TextFont& sharedTextFont();

// The code points of `utf8`; each invalid byte becomes U+FFFD.
std::vector<char32_t> decodeUtf8(std::string_view utf8);

} // namespace lab
