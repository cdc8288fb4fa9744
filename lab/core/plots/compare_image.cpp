// compare_image.cpp — A and B side by side under their labels (compare_image.h).
#include "core/plots/compare_image.h"

#include "core/plots/text_raster.h"

#include <algorithm>
#include <cmath>

namespace lab {

namespace {

constexpr std::uint8_t kStrip[3] = {30, 32, 40}; // the GUI's caption strips (ui/viewport/viewport.cpp kStrip)
constexpr std::uint8_t kLine[3] = {200, 200, 200};
const TextColor kLabelA{255, 255, 255};
const TextColor kLabelB{230, 90, 220};
constexpr int kGap = 2;

float labelSize(int height) { return std::clamp(std::round(static_cast<float>(height) * 0.045f), 12.0f, 48.0f); }

void fill(Image& image, int x0, int y0, int x1, int y1, const std::uint8_t (&rgb)[3]) {
    for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y) {
        for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) {
            std::uint8_t* p = image.rgb.data() + (static_cast<std::size_t>(y) * image.width + x) * 3;
            std::copy(rgb, rgb + 3, p);
        }
    }
}

void place(Image& image, const Image& half, int left, int top) {
    for (int y = 0; y < half.height; ++y) {
        const std::uint8_t* from = half.rgb.data() + static_cast<std::size_t>(y) * half.width * 3;
        std::uint8_t* to = image.rgb.data() + (static_cast<std::size_t>(top + y) * image.width + left) * 3;
        std::copy(from, from + static_cast<std::size_t>(half.width) * 3, to);
    }
}

} // namespace

int compareLabelHeight(int height) {
    const float size = labelSize(height);
    return static_cast<int>(std::ceil(sharedTextFont().measure("Ag", size).height + size * 0.8f));
}

Image composeComparison(const Image& a, const Image& b, const std::string& labelA, const std::string& labelB) {
    const TextFont& font = sharedTextFont();
    const int strip = compareLabelHeight(a.height), halfWidth = a.width;
    Image image;
    image.width = 2 * halfWidth + kGap;
    image.height = a.height + strip;
    image.rgb.assign(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3, 0);
    fill(image, 0, 0, image.width, strip, kStrip);
    fill(image, halfWidth, 0, halfWidth + kGap, image.height, kLine);
    place(image, a, 0, strip);
    if (b.width == a.width && b.height == a.height) {
        place(image, b, halfWidth + kGap, strip);
    }
    const float size = labelSize(a.height), pad = std::floor(size * 0.4f);
    const float room = static_cast<float>(halfWidth) - 2.0f * pad;
    font.draw(image, font.fitted(labelA, size, room), pad, pad, size, kLabelA);
    font.draw(image, font.fitted(labelB, size, room), static_cast<float>(halfWidth + kGap) + pad, pad, size, kLabelB);
    return image;
}

} // namespace lab
