// qr_symbol.h — a QR code's modules, and libqrencode's symbol of a text (qr_symbol.cpp, target
// lab_qr_symbol): what qr_code.h's encodeQr runs where libqrencode is linked (qr_linked.cpp), and
// what the page's QR module runs (lab/platform/web_qr_module.cpp). The page itself calls neither.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

struct QrCode {
    int version = 0; // 1 to 40: the code has 17 + 4 * version modules a side
    int size = 0;    // modules a side
    std::vector<std::uint8_t> modules; // size*size, 1 = dark, row-major, top first

    // Whether module (x, y) is dark; outside the code (the quiet zone) it is light.
    bool dark(int x, int y) const {
        return x >= 0 && y >= 0 && x < size && y < size && modules[std::size_t(y) * std::size_t(size) + std::size_t(x)];
    }
};

// The symbol libqrencode makes of `text`: byte mode, level M, the smallest version that holds it
// (no limit here: encodeQr checks the version). nullopt with `error` when it makes none.
std::optional<QrCode> qrSymbol(std::string_view text, std::string& error);

} // namespace lab
