// qr_code_test.cpp — QR codes of share links: read back by a real decoder (zbarimg, from
// zbar-tools), refused when too long with the numbers that say why, and drawn with a quiet zone.
#include "core/share/qr_code.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <sys/wait.h>

namespace lab {
namespace {

// A share link as long as a modified preset's: 200 characters.
std::string longLink() {
    std::string link = "https://lighting-lab.example.org/#p=";
    const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    for (std::size_t i = 0; link.size() < 200; ++i) {
        link += alphabet[(i * 37 + 11) % 64];
    }
    return link;
}

// What `zbarimg --raw -q` prints for a PNG, without the line feed it ends with; its exit status in
// `status`, what it wrote to stderr in `messages` (zbar may complain there about D-Bus, harmlessly).
std::string zbarimg(const std::filesystem::path& png, int& status, std::string& messages) {
    const std::filesystem::path stderrFile = png.string() + ".stderr";
    std::string command =
        std::string(LAB_ZBARIMG) + " --raw -q '" + png.string() + "' 2>'" + stderrFile.string() + "'";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) {
        status = -1;
        return {};
    }
    std::string out;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) {
        out.append(buffer, n);
    }
    int raw = ::pclose(pipe);
    status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    if (!out.empty() && out.back() == '\n') {
        out.pop_back();
    }
    messages = readText(stderrFile);
    return out;
}

TEST(QrCode, ALongShareLinkIsReadBackByZbarimgExactly) {
    const std::string link = longLink();
    ASSERT_EQ(link.size(), 200u);
    std::string error;
    std::optional<QrCode> code = encodeQr(link, error);
    ASSERT_TRUE(code) << error;
    EXPECT_EQ(code->version, 10); // 200 bytes: over version 9's 180, within version 10's 213
    TempFolder dir;
    const std::filesystem::path png = dir.path() / "link.png";
    ASSERT_TRUE(writePng(qrImage(*code, 4), png, error)) << error;
    int status = 0;
    std::string messages;
    EXPECT_EQ(zbarimg(png, status, messages), link) << "zbarimg's stderr: " << messages;
    EXPECT_EQ(status, 0) << "zbarimg's stderr: " << messages;
}

TEST(QrCode, TextTooLongForVersion20IsRefusedWithItsSizeAndTheCapacity) {
    std::string error;
    EXPECT_FALSE(encodeQr(std::string(700, 'a'), error));
    EXPECT_NE(error.find("700 bytes"), std::string::npos) << error;
    EXPECT_NE(error.find("666 bytes"), std::string::npos) << error;
    EXPECT_NE(error.find("version 20"), std::string::npos) << error;
    // 666 still fits, in version 20 exactly.
    std::optional<QrCode> full = encodeQr(std::string(666, 'a'), error);
    ASSERT_TRUE(full) << error;
    EXPECT_EQ(full->version, 20);
    EXPECT_EQ(full->size, 97);
}

TEST(QrCode, ShortTextGivesASmallCode) {
    std::string error;
    std::optional<QrCode> code = encodeQr("#preset=05-full-phong", error);
    ASSERT_TRUE(code) << error;
    EXPECT_LE(code->version, 3);
    EXPECT_GE(code->version, 1);
    EXPECT_EQ(code->size, 17 + 4 * code->version);
    EXPECT_EQ(code->modules.size(), std::size_t(code->size * code->size));
}

// The table behind the message is the standard's, and libqrencode picks the smallest version:
// each version's capacity fits it exactly, one byte more needs the next.
TEST(QrCode, CapacityAtLevelMMatchesLibqrencodeAtEveryVersion) {
    EXPECT_EQ(qrCapacityBytes(0), 0u);
    EXPECT_EQ(qrCapacityBytes(41), 0u);
    for (int version = 1; version <= 40; ++version) {
        const std::size_t capacity = qrCapacityBytes(version);
        std::string error;
        std::optional<QrCode> fits = encodeQr(std::string(capacity, 'x'), error, 40);
        ASSERT_TRUE(fits) << "version " << version << ": " << error;
        EXPECT_EQ(fits->version, version);
        EXPECT_FALSE(encodeQr(std::string(capacity + 1, 'x'), error, version)) << "version " << version;
        if (version < 40) {
            std::optional<QrCode> next = encodeQr(std::string(capacity + 1, 'x'), error, 40);
            ASSERT_TRUE(next) << error;
            EXPECT_EQ(next->version, version + 1);
        }
    }
}

TEST(QrCode, EmptyTextAndVersionsOutsideTheStandardAreRefused) {
    std::string error;
    EXPECT_FALSE(encodeQr("", error));
    EXPECT_NE(error.find("empty"), std::string::npos) << error;
    EXPECT_FALSE(encodeQr("a", error, 0));
    EXPECT_NE(error.find("1 to 40"), std::string::npos) << error;
    EXPECT_FALSE(encodeQr("a", error, 41));
    EXPECT_NE(error.find("1 to 40"), std::string::npos) << error;
}

TEST(QrCode, ImageHasTheQuietZoneAndTheFinderPatternInItsCorner) {
    std::string error;
    std::optional<QrCode> code = encodeQr(longLink(), error);
    ASSERT_TRUE(code) << error;
    const int m = 3;
    Image image = qrImage(*code, m);
    const int side = (code->size + 8) * m;
    EXPECT_EQ(image.width, side);
    EXPECT_EQ(image.height, side);
    ASSERT_EQ(image.rgb.size(), std::size_t(side * side * 3));
    auto pixel = [&](int x, int y) { return image.rgb[(std::size_t(y) * std::size_t(side) + std::size_t(x)) * 3]; };
    // The corners and the last pixel of the quiet zone before the code are white...
    EXPECT_EQ(pixel(0, 0), 255);
    EXPECT_EQ(pixel(side - 1, 0), 255);
    EXPECT_EQ(pixel(0, side - 1), 255);
    EXPECT_EQ(pixel(side - 1, side - 1), 255);
    EXPECT_EQ(pixel(4 * m - 1, 4 * m - 1), 255);
    // ...and the code starts with the top-left finder pattern's dark corner module, all its pixels.
    ASSERT_TRUE(code->dark(0, 0));
    EXPECT_EQ(pixel(4 * m, 4 * m), 0);
    EXPECT_EQ(pixel(5 * m - 1, 5 * m - 1), 0);
    // The finder's ring of light modules at 1 module in: (1, 1) is light.
    EXPECT_FALSE(code->dark(1, 1));
    EXPECT_EQ(pixel(5 * m, 5 * m), 255);
    // Outside the code is light.
    EXPECT_FALSE(code->dark(-1, 0));
    EXPECT_FALSE(code->dark(code->size, 0));
}

TEST(QrCode, ImageOfAnInvalidModuleSizeIsEmpty) {
    std::string error;
    std::optional<QrCode> code = encodeQr("a", error);
    ASSERT_TRUE(code) << error;
    for (int moduleSize : {0, -1, kMaxImageSide / 29 + 1}) { // 29: a version-1 code and its quiet zone
        Image image = qrImage(*code, moduleSize);
        EXPECT_EQ(image.width, 0) << moduleSize;
        EXPECT_EQ(image.height, 0) << moduleSize;
        EXPECT_TRUE(image.rgb.empty()) << moduleSize;
    }
}

} // namespace
} // namespace lab
