// image.h — 8-bit RGB images: PNG in and out, and the screenshot-test comparison.
#pragma once

#include "core/io/file_io.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lab {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb; // row-major, top row first, 3 bytes a pixel
};

inline constexpr int kMaxImageSide = 16384;
inline constexpr std::size_t kMaxPngBytes = std::size_t{256} << 20; // the largest PNG file read

// PNG bytes in memory; empty on failure.
std::string encodePng(const Image& image);
// Encodes to PNG in memory and writes it atomically (file_io.h: WriteSafety).
bool writePng(const Image& image, const std::filesystem::path& file, std::string& error,
              WriteSafety safety = WriteSafety::Durable);

struct ImageSize {
    int width = 0;
    int height = 0;
    bool operator==(const ImageSize&) const = default;
};

// The size a PNG file's header claims, read without decoding it (a 780 KB file can claim 16384 x
// 16384, 800 MB decoded); nullopt with `error` when it is no PNG.
std::optional<ImageSize> readPngSize(const std::filesystem::path& file, std::string& error);

// Decodes a PNG file, refused before decoding (nullopt, `error`) when its header claims more than
// `maxSide` pixels a side.
std::optional<Image> readPng(const std::filesystem::path& file, std::string& error, int maxSide = kMaxImageSide);

// The screenshot tests' thresholds. A pixel fails when any channel differs by more than
// `pixelTolerance` levels; an image fails when more than `maxFailingShare` of its pixels fail or
// its mean channel difference exceeds `maxMeanDifference` levels.
struct Tolerance {
    int pixelTolerance = 3;
    double maxFailingShare = 0.001;
    double maxMeanDifference = 0.5;
};

struct Comparison {
    bool sameSize = false;
    int maxDifference = 0;       // levels, over all channels
    double meanDifference = 0.0; // levels, mean over all channels of all pixels
    std::size_t failingPixels = 0;
    double failingShare = 0.0;
    Image diff; // |a - b| amplified 16×; failing pixels in full magenta

    bool passes(const Tolerance& t) const {
        return sameSize && failingShare <= t.maxFailingShare && meanDifference <= t.maxMeanDifference;
    }
};

Comparison compareImages(const Image& actual, const Image& expected, const Tolerance& tolerance);

} // namespace lab
