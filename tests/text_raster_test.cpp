// text_raster_test.cpp — the CPU text rasterizer: ink inside the measured box, nothing for "",
// widths that grow with the text and the size, the fallback font, UTF-8 decoding.
#include "core/plots/text_raster.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lab {
namespace {

Image blank(int w, int h, std::uint8_t v = 255) { return Image{w, h, std::vector<std::uint8_t>(std::size_t(w * h * 3), v)}; }

// The bounding box of pixels that differ from the background, or an empty optional.
struct Ink {
    int count = 0, x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
Ink inkOf(const Image& image, std::uint8_t background = 255) {
    Ink ink;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.rgb[(std::size_t(y) * image.width + x) * 3];
            if (p[0] != background || p[1] != background || p[2] != background) {
                ++ink.count;
                ink.x0 = std::min(ink.x0, x), ink.y0 = std::min(ink.y0, y);
                ink.x1 = std::max(ink.x1, x), ink.y1 = std::max(ink.y1, y);
            }
        }
    }
    return ink;
}

void expectInkInsideBox(const TextFont& font, std::string_view text, float size) {
    Image image = blank(400, 120);
    const float x = 20.3f, y = 30.6f;
    TextBox box = font.draw(image, text, x, y, size, {0, 0, 0});
    Ink ink = inkOf(image);
    ASSERT_GT(ink.count, 0) << text;
    // One pixel of slack for anti-aliased edges; glyphs with overhangs stay within it.
    EXPECT_GE(ink.x0, std::floor(x) - 1) << text;
    EXPECT_GE(ink.y0, std::floor(y) - 1) << text;
    EXPECT_LE(ink.x1, std::ceil(x + box.width) + 1) << text;
    EXPECT_LE(ink.y1, std::ceil(y + box.height) + 1) << text;
    // The ink fills most of the box's width (not drawn at a quarter of the size, say).
    EXPECT_GE(ink.x1 - ink.x0 + 1, 0.8f * box.width) << text;
}

class BothFonts : public ::testing::TestWithParam<bool> {
protected:
    TextFont font = GetParam() ? TextFont::builtIn() : TextFont::load();
};

TEST_P(BothFonts, InkStaysInsideTheMeasuredBox) {
    for (float size : {9.0f, 16.0f, 31.5f}) {
        expectInkInsideBox(font, "Hg 0.25", size);
        expectInkInsideBox(font, "θ = 30° · Blinn-Phong", size);
    }
}

TEST_P(BothFonts, EmptyStringDrawsNothing) {
    Image image = blank(50, 30);
    TextBox box = font.draw(image, "", 5, 5, 16, {0, 0, 0});
    EXPECT_EQ(box.width, 0.0f);
    EXPECT_EQ(box.height, 0.0f);
    EXPECT_EQ(inkOf(image).count, 0);
}

TEST_P(BothFonts, SpacesAdvanceButDrawNothing) {
    Image image = blank(80, 30);
    TextBox box = font.draw(image, "   ", 5, 5, 16, {0, 0, 0});
    EXPECT_GT(box.width, 5.0f);
    EXPECT_EQ(inkOf(image).count, 0);
}

TEST_P(BothFonts, WidthGrowsWithTextAndSize) {
    EXPECT_LT(font.measure("ab", 16).width, font.measure("abc", 16).width);
    EXPECT_NEAR(font.measure("abc", 32).width, 2.0f * font.measure("abc", 16).width, 1.0f);
    EXPECT_NEAR(font.measure("abc", 20).height, 20.0f, 0.01f);
    EXPECT_GT(font.measure("abc", 20).baseline, 10.0f);
    EXPECT_LT(font.measure("abc", 20).baseline, 20.0f);
}

TEST_P(BothFonts, BadSizesGiveEmptyBoxesAndNoInk) {
    Image image = blank(50, 30);
    for (float size : {0.0f, -3.0f, std::nanf(""), 5000.0f, kMaxTextPixelSize + 1.0f}) {
        EXPECT_EQ(font.draw(image, "x", 5, 5, size, {0, 0, 0}).width, 0.0f);
    }
    EXPECT_EQ(inkOf(image).count, 0);
}

TEST_P(BothFonts, ClipsAtTheImageEdgesAndDrawsInTheColour) {
    Image image = blank(30, 12, 0);
    font.draw(image, "WWWWWWWWWW", -7.5f, -4.0f, 24, {255, 0, 0});
    Ink ink = inkOf(image, 0);
    EXPECT_GT(ink.count, 0);
    for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
        EXPECT_EQ(image.rgb[i + 1], 0); // only red blended over black
        EXPECT_EQ(image.rgb[i + 2], 0);
    }
    Image empty;
    font.draw(empty, "x", 0, 0, 12, {0, 0, 0}); // no pixels: nothing to do, no crash
}

INSTANTIATE_TEST_SUITE_P(TextRaster, BothFonts, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& p) { return p.param ? "Fallback" : "DejaVu"; });

TEST(TextRaster, LoadsDejaVuAndFallsBackWithAReason) {
    TextFont dejavu = TextFont::load();
    EXPECT_FALSE(dejavu.fallback()) << dejavu.loadError(); // fonts-dejavu-core is a build dependency
    TextFont none = TextFont::load({"/nonexistent/font.ttf", LAB_SOURCE_DIR "/README.md"});
    EXPECT_TRUE(none.fallback());
    EXPECT_NE(none.loadError().find("/nonexistent/font.ttf"), std::string::npos) << none.loadError();
    EXPECT_NE(none.loadError().find("not a TrueType font"), std::string::npos) << none.loadError();
    expectInkInsideBox(none, "still legible", 14);
}

TEST(TextRaster, AntiAliasedEdges) {
    Image image = blank(200, 60);
    sharedTextFont().draw(image, "Lobe", 10.4f, 10.0f, 28, {0, 0, 0});
    int partial = 0;
    for (std::uint8_t v : image.rgb) {
        partial += (v > 20 && v < 235);
    }
    EXPECT_GT(partial, 30);
}

TEST(TextRaster, DecodesUtf8AndReplacesBadBytes) {
    EXPECT_EQ(decodeUtf8("a°θ→"), (std::vector<char32_t>{U'a', U'°', U'θ', U'→'}));
    EXPECT_EQ(decodeUtf8("\xC3"), (std::vector<char32_t>{0xFFFD}));             // cut off
    EXPECT_EQ(decodeUtf8("\xC0\x80"), (std::vector<char32_t>{0xFFFD, 0xFFFD})); // overlong
    EXPECT_EQ(decodeUtf8("\xED\xA0\x80z"), (std::vector<char32_t>{0xFFFD, 0xFFFD, 0xFFFD, U'z'})); // surrogate
    EXPECT_EQ(decodeUtf8("\xFFok"), (std::vector<char32_t>{0xFFFD, U'o', U'k'}));
}

} // namespace
} // namespace lab
