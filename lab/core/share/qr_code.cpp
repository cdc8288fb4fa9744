// qr_code.cpp — encodeQr through libqrencode (qr_encoder.h), and the code drawn into an RGB image.
#include "core/share/qr_code.h"

#include "core/share/qr_encoder.h"

#include <array>
#include <cstring>

namespace lab {

namespace {

constexpr int kQuietZone = 4; // modules of light margin on each side (ISO/IEC 18004 7.3.7)

// Data bytes a byte-mode symbol holds at level M, versions 1 to 40 (ISO/IEC 18004 table 7).
constexpr std::array<std::size_t, 40> kCapacityM = {
    14,   26,   42,   62,   84,   106,  122,  152,  180,  213,  251,  287,  331,  362,
    412,  450,  504,  560,  624,  666,  711,  779,  857,  911,  997,  1059, 1125, 1190,
    1264, 1370, 1452, 1538, 1628, 1722, 1809, 1911, 1989, 2099, 2213, 2331};

std::string tooLong(std::size_t bytes, int maxVersion) {
    return "the text is " + std::to_string(bytes) + " bytes; a QR code of version " + std::to_string(maxVersion) +
           " (" + std::to_string(17 + 4 * maxVersion) + "x" + std::to_string(17 + 4 * maxVersion) +
           " modules, error correction M) holds at most " + std::to_string(qrCapacityBytes(maxVersion)) + " bytes";
}

} // namespace

std::size_t qrCapacityBytes(int version) {
    return version >= 1 && version <= 40 ? kCapacityM[std::size_t(version - 1)] : 0;
}

std::optional<QrCode> encodeQr(std::string_view text, std::string& error, int maxVersion) {
    if (maxVersion < 1 || maxVersion > 40) {
        error = "the largest QR code version must be 1 to 40, not " + std::to_string(maxVersion);
        return std::nullopt;
    }
    if (text.empty()) {
        error = "nothing to encode: the text is empty";
        return std::nullopt;
    }
    // Refused before encoding: the table is the standard's, and libqrencode would otherwise build
    // a larger symbol only for it to be thrown away.
    if (text.size() > qrCapacityBytes(maxVersion)) {
        error = tooLong(text.size(), maxVersion);
        return std::nullopt;
    }
    std::optional<QrCode> code = runQrEncoder(text, error);
    if (!code) {
        return std::nullopt;
    }
    if (code->version > maxVersion) { // the table above and libqrencode disagree: trust the symbol
        error = tooLong(text.size(), maxVersion);
        return std::nullopt;
    }
    return code;
}

Image qrImage(const QrCode& code, int moduleSize) {
    const int modules = code.size + 2 * kQuietZone;
    if (moduleSize < 1 || code.size < 0 || moduleSize > kMaxImageSide / modules) {
        return {};
    }
    Image image;
    image.width = image.height = modules * moduleSize;
    image.rgb.assign(std::size_t(image.width) * std::size_t(image.height) * 3, 255);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (code.dark(x / moduleSize - kQuietZone, y / moduleSize - kQuietZone)) {
                std::memset(&image.rgb[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3], 0, 3);
            }
        }
    }
    return image;
}

} // namespace lab
