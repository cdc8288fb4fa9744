// qr_symbol.cpp — libqrencode's symbol of a text (qr_encoder.h qrSymbol): linked into the
// desktop and the command line (qr_linked.cpp), and into the page's QR module
// (lab/platform/web_qr_module.cpp), never into the page itself.
#include "core/share/qr_symbol.h"

#include <qrencode.h>

#include <cerrno>
#include <cstring>
#include <memory>

namespace lab {

namespace {

std::string whyNull(int error) {
    switch (error) {
    case ERANGE: return "the text is too large for any QR code";
    case ENOMEM: return "out of memory";
    case EINVAL: return "libqrencode refused the input as invalid";
    default: return std::string("libqrencode failed: ") + std::strerror(error);
    }
}

} // namespace

std::optional<QrCode> qrSymbol(std::string_view text, std::string& error) {
    // QRcode_encodeData, not encodeString8bit: the text is a string_view (no NUL at its end, and
    // it may hold NULs). Version 0 lets libqrencode pick the smallest version that holds it.
    errno = 0;
    std::unique_ptr<QRcode, void (*)(QRcode*)> encoded(
        QRcode_encodeData(int(text.size()), reinterpret_cast<const unsigned char*>(text.data()), 0, QR_ECLEVEL_M),
        QRcode_free);
    if (!encoded) {
        error = whyNull(errno);
        return std::nullopt;
    }
    QrCode code;
    code.version = encoded->version;
    code.size = encoded->width;
    code.modules.resize(std::size_t(code.size) * std::size_t(code.size));
    for (std::size_t i = 0; i < code.modules.size(); ++i) {
        code.modules[i] = encoded->data[i] & 1; // bit 0 is dark; the other bits say what the module is for
    }
    return code;
}

} // namespace lab
