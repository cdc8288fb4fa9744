// qr_encoder.h — the seam between the share links' QR codes (qr_code.h) and libqrencode, one
// implementation compiled: linked (qr_linked.cpp: the desktop, the command line, the tests) or
// fetched on demand (qr_fetched.cpp: the page, which leaves the encoder out of its first load —
// 7 KB of gzip that only the QR code window needs — and loads lab/platform/web_qr_module.cpp's
// module once, the first time the window asks for a code).
#pragma once

#include "core/io/fetched_module.h"
#include "core/share/qr_code.h"

#include <optional>
#include <string>
#include <string_view>

namespace lab {

// Ready where it is linked; in the page, as fetched (core/io/fetched_module.h): the next link tries
// again after a failure, which qrEncoderProblem() explains.
ModuleState qrEncoderState();
std::string qrEncoderProblem();

// Starts fetching the encoder where it is not here yet (the page); nothing where it is linked.
void loadQrEncoder();

// The symbol libqrencode makes of `text`: byte mode, level M, the smallest version that holds it
// (no limit here: encodeQr checks the version). nullopt with `error` when it makes none, or when
// the encoder is not Ready.
std::optional<QrCode> runQrEncoder(std::string_view text, std::string& error);

#ifdef __EMSCRIPTEN__
// The page: the module's answer to loadQrEncoder (lab_qr_loaded, lab/platform/web_window.cpp).
void qrEncoderLoaded(bool ok, const std::string& problem);
#endif

} // namespace lab
