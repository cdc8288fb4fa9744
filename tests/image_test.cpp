// image_test.cpp — the screenshot comparison's thresholds, and PNG round trips.
#include "core/io/image.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <csignal>
#include <sys/resource.h>
#include <sys/stat.h>

namespace lab {
namespace {

Image flat(int w, int h, std::uint8_t v) { return Image{w, h, std::vector<std::uint8_t>(std::size_t(w * h * 3), v)}; }

TEST(ImageCompare, IdenticalImagesPass) {
    Comparison c = compareImages(flat(100, 100, 40), flat(100, 100, 40), Tolerance{});
    EXPECT_TRUE(c.passes(Tolerance{}));
    EXPECT_EQ(c.maxDifference, 0);
    EXPECT_EQ(c.failingPixels, 0u);
}

TEST(ImageCompare, ThreeLevelsOnFewPixelsPassFourDoNot) {
    // 100 x 100 = 10000 pixels; the limit is 0.1% = 10 failing pixels.
    Image a = flat(100, 100, 100);
    Image b = a;
    for (int i = 0; i < 20; ++i) {
        b.rgb[std::size_t(3 * i * 37)] = 103; // 20 pixels off by 3: within the pixel tolerance
    }
    EXPECT_TRUE(compareImages(b, a, Tolerance{}).passes(Tolerance{}));
    for (int i = 0; i < 10; ++i) {
        b.rgb[std::size_t(3 * i * 37)] = 104; // 10 pixels off by 4: exactly 0.1%, still allowed
    }
    Comparison c = compareImages(b, a, Tolerance{});
    EXPECT_EQ(c.failingPixels, 10u);
    EXPECT_TRUE(c.passes(Tolerance{}));
    b.rgb[3 * 5000 + 2] = 0; // an 11th failing pixel
    c = compareImages(b, a, Tolerance{});
    EXPECT_EQ(c.failingPixels, 11u);
    EXPECT_EQ(c.maxDifference, 100);
    EXPECT_FALSE(c.passes(Tolerance{}));
    EXPECT_EQ(c.diff.rgb[3 * 5000], 255); // failing pixels are magenta in the diff image
    EXPECT_EQ(c.diff.rgb[3 * 5000 + 1], 0);
}

TEST(ImageCompare, MeanDifferenceAloneCanFail) {
    // Every channel off by 1: no pixel fails, but the mean 1.0 exceeds 0.5 levels.
    Comparison c = compareImages(flat(10, 10, 11), flat(10, 10, 10), Tolerance{});
    EXPECT_EQ(c.failingPixels, 0u);
    EXPECT_DOUBLE_EQ(c.meanDifference, 1.0);
    EXPECT_FALSE(c.passes(Tolerance{}));
}

TEST(ImageCompare, DifferentSizesFail) {
    Comparison c = compareImages(flat(10, 10, 0), flat(10, 11, 0), Tolerance{});
    EXPECT_FALSE(c.sameSize);
    EXPECT_FALSE(c.passes(Tolerance{}));
}

TEST(Png, RoundTrips) {
    TempFolder dir;
    Image a{3, 2, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18}};
    std::string error;
    ASSERT_TRUE(writePng(a, dir.path() / "a.png", error)) << error;
    std::optional<Image> b = readPng(dir.path() / "a.png", error);
    ASSERT_TRUE(b) << error;
    EXPECT_EQ(b->width, 3);
    EXPECT_EQ(b->height, 2);
    EXPECT_EQ(b->rgb, a.rgb);
}

// `lab render` writes its PNGs without the fsync (WriteSafety::Renewable): still atomic, with
// the usual permissions, and a write that fails leaves the old file as it was.
TEST(Png, RenewableWritesAreStillAtomic) {
    TempFolder dir;
    const std::filesystem::path file = dir.path() / "render.png";
    std::string error;
    ASSERT_TRUE(writePng(flat(4, 4, 10), file, error, WriteSafety::Renewable)) << error;
    std::optional<Image> back = readPng(file, error);
    ASSERT_TRUE(back) << error;
    EXPECT_EQ(back->rgb, flat(4, 4, 10).rgb);
    mode_t mask = ::umask(0);
    ::umask(mask);
    struct stat st {};
    ASSERT_EQ(::stat(file.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);

    // A file-size limit makes the next, larger write fail halfway (EFBIG, for root too).
    const std::string before = readText(file);
    Image noisy{256, 256, std::vector<std::uint8_t>(256 * 256 * 3)};
    for (std::size_t i = 0; i < noisy.rgb.size(); ++i) {
        noisy.rgb[i] = static_cast<std::uint8_t>((i * 2654435761u) >> 13); // does not compress
    }
    struct rlimit old {};
    ::getrlimit(RLIMIT_FSIZE, &old);
    struct rlimit small = old;
    small.rlim_cur = before.size() + 100;
    auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    ::setrlimit(RLIMIT_FSIZE, &small);
    bool written = writePng(noisy, file, error, WriteSafety::Renewable);
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);
    EXPECT_FALSE(written);
    EXPECT_EQ(readText(file), before);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), std::filesystem::directory_iterator{}), 1);
}

TEST(Png, AHeaderClaimingAHugeImageIsRefusedBeforeDecoding) {
    // A PNG signature and an IHDR, and nothing else: the sizes come from the header alone.
    auto header = [](std::uint32_t w, std::uint32_t h) {
        const unsigned char bytes[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                       (unsigned char)(w >> 24), (unsigned char)(w >> 16), (unsigned char)(w >> 8), (unsigned char)w,
                                       (unsigned char)(h >> 24), (unsigned char)(h >> 16), (unsigned char)(h >> 8), (unsigned char)h,
                                       8, 2, 0, 0, 0, 0, 0, 0, 0};
        return std::string(reinterpret_cast<const char*>(bytes), sizeof bytes);
    };
    TempFolder dir;
    std::string error;
    writeText(dir.path() / "wide.png", header(20000, 100)); // beyond the lab's 16384 per side
    EXPECT_FALSE(readPng(dir.path() / "wide.png", error));
    EXPECT_NE(error.find("20000x100 is larger than allowed"), std::string::npos) << error;
    writeText(dir.path() / "huge.png", header(100000, 100000)); // 30 GB decoded: stb's own check refuses it first
    error.clear();
    EXPECT_FALSE(readPng(dir.path() / "huge.png", error));
    EXPECT_NE(error.find("not a readable PNG"), std::string::npos) << error;
}

TEST(Png, TheSizeIsReadFromTheHeaderAloneAndDecodingIsBoundedByTheCaller) {
    const unsigned char bytes[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                   0, 0, 0x40, 0, 0, 0, 0x20, 0, 8, 2, 0, 0, 0, 0, 0, 0, 0}; // 16384 x 8192, no data
    TempFolder dir;
    writeText(dir.path() / "claims.png", std::string(reinterpret_cast<const char*>(bytes), sizeof bytes));
    std::string error;
    EXPECT_EQ(readPngSize(dir.path() / "claims.png", error), (ImageSize{16384, 8192})) << error;
    // A caller that expects at most 512 a side refuses it before decoding (the data would not decode).
    EXPECT_FALSE(readPng(dir.path() / "claims.png", error, 512));
    EXPECT_NE(error.find("16384x8192 is larger than allowed (at most 512 a side)"), std::string::npos) << error;
    // A real image reads back whole under a limit of its own size.
    Image a{3, 2, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18}};
    ASSERT_TRUE(writePng(a, dir.path() / "a.png", error)) << error;
    EXPECT_EQ(readPngSize(dir.path() / "a.png", error), (ImageSize{3, 2}));
    std::optional<Image> back = readPng(dir.path() / "a.png", error, 3);
    ASSERT_TRUE(back) << error;
    EXPECT_EQ(back->rgb, a.rgb);
    EXPECT_FALSE(readPngSize(dir.path() / "missing.png", error));
}

TEST(Png, BrokenFilesAreRefused) {
    TempFolder dir;
    writeText(dir.path() / "bad.png", "\x89PNG\r\n\x1a\n garbage");
    std::string error;
    EXPECT_FALSE(readPng(dir.path() / "bad.png", error));
    EXPECT_FALSE(error.empty());
    EXPECT_FALSE(readPng(dir.path() / "missing.png", error));
}

} // namespace
} // namespace lab
