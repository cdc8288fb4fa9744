// image.cpp — PNG through stb (Debian's libstb), comparison for the screenshot tests.
#include "core/io/image.h"

#include "core/io/file_io.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <cstdlib>

namespace lab {

std::string encodePng(const Image& image) {
    std::string bytes;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, image.rgb.data(), image.width * 3)) {
        return {};
    }
    return bytes;
}

bool writePng(const Image& image, const std::filesystem::path& file, std::string& error, WriteSafety safety) {
    std::string bytes = encodePng(image);
    if (bytes.empty()) {
        error = "cannot encode PNG";
        return false;
    }
    return writeFileAtomic(file, bytes, error, safety);
}

namespace {

// The header's size, from bytes in memory (stb reads the IHDR chunk only).
std::optional<ImageSize> pngSize(std::string_view bytes, std::string& error) {
    int w = 0, h = 0, channels = 0;
    if (bytes.size() > std::size_t(INT32_MAX) ||
        !stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()), &w, &h, &channels)) {
        error = std::string("not a readable PNG (") + stbi_failure_reason() + ")";
        return std::nullopt;
    }
    return ImageSize{w, h};
}

} // namespace

std::optional<ImageSize> readPngSize(const std::filesystem::path& file, std::string& error) {
    std::optional<MappedFile> bytes = MappedFile::open(file, kMaxPngBytes, error); // mapped: no copy of the file
    return bytes ? pngSize(bytes->bytes(), error) : std::nullopt;
}

std::optional<Image> readPng(const std::filesystem::path& file, std::string& error, int maxSide) {
    std::optional<MappedFile> bytes = MappedFile::open(file, kMaxPngBytes, error);
    if (!bytes) {
        return std::nullopt;
    }
    std::optional<ImageSize> size = pngSize(bytes->bytes(), error);
    if (!size) {
        return std::nullopt;
    }
    const int limit = std::min(maxSide, kMaxImageSide);
    if (size->width <= 0 || size->height <= 0 || size->width > limit || size->height > limit) {
        error = "image of " + std::to_string(size->width) + "x" + std::to_string(size->height) +
                " is larger than allowed (at most " + std::to_string(limit) + " a side)";
        return std::nullopt;
    }
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes->bytes().data()),
                                            static_cast<int>(bytes->bytes().size()), &w, &h, &channels, 3);
    if (!pixels) {
        error = std::string("cannot decode PNG: ") + stbi_failure_reason();
        return std::nullopt;
    }
    Image image{w, h, std::vector<std::uint8_t>(pixels, pixels + std::size_t(w) * std::size_t(h) * 3)};
    stbi_image_free(pixels);
    return image;
}

Comparison compareImages(const Image& actual, const Image& expected, const Tolerance& tolerance) {
    Comparison c;
    c.sameSize = actual.width == expected.width && actual.height == expected.height &&
                 actual.rgb.size() == expected.rgb.size();
    if (!c.sameSize) {
        return c;
    }
    c.diff = Image{actual.width, actual.height, std::vector<std::uint8_t>(actual.rgb.size())};
    std::uint64_t sum = 0;
    const std::size_t pixels = std::size_t(actual.width) * std::size_t(actual.height);
    for (std::size_t i = 0; i < pixels; ++i) {
        int worst = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            int d = std::abs(int(actual.rgb[3 * i + k]) - int(expected.rgb[3 * i + k]));
            sum += std::uint64_t(d);
            worst = std::max(worst, d);
            c.diff.rgb[3 * i + k] = static_cast<std::uint8_t>(std::min(255, d * 16));
        }
        c.maxDifference = std::max(c.maxDifference, worst);
        if (worst > tolerance.pixelTolerance) {
            ++c.failingPixels;
            c.diff.rgb[3 * i + 0] = 255;
            c.diff.rgb[3 * i + 1] = 0;
            c.diff.rgb[3 * i + 2] = 255;
        }
    }
    c.meanDifference = pixels ? double(sum) / double(pixels * 3) : 0.0;
    c.failingShare = pixels ? double(c.failingPixels) / double(pixels) : 0.0;
    return c;
}

} // namespace lab
