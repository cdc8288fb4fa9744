// qr_code.h — QR codes for the lab's share links: the text in, the modules and an image out.
//
// Byte mode at error-correction level M (15% of the code may be lost), the smallest version that
// holds the text, up to kMaxQrVersion. The encoding itself is libqrencode's (Debian's
// libqrencode-dev natively; in the browser build the same sources compiled by cmake/web.cmake into
// a module the page fetches when it needs a code: qr_encoder.h). In the page encodeQr fails, saying
// so, until that module is here (app/share_code.cpp asks for it and waits).
// No GL, no ImGui: the caller shows the image (a texture, a PNG file) as it likes.
#pragma once

#include "core/io/image.h"
#include "core/share/qr_symbol.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {


// The largest code the lab makes: 97x97 modules, still scannable across a classroom.
inline constexpr int kMaxQrVersion = 20;

// Byte-mode QR code of `text` at error-correction level M, the smallest version that holds it.
// nullopt, with `error` saying how many bytes it has and how many version `maxVersion` holds at
// level M (666 for 20), when it does not fit; `maxVersion` outside 1..40 is an error too.
std::optional<QrCode> encodeQr(std::string_view text, std::string& error, int maxVersion = kMaxQrVersion);

// How many bytes a byte-mode code of `version` holds at level M (ISO/IEC 18004 table 7);
// 0 outside 1..40.
std::size_t qrCapacityBytes(int version);

// The code as an image: `moduleSize` pixels a module, black on white, with the standard 4-module
// quiet zone around it: (size + 8) * moduleSize pixels a side. An empty image (0 x 0) when
// `moduleSize` is below 1, or the side would exceed kMaxImageSide.
Image qrImage(const QrCode& code, int moduleSize);

} // namespace lab
