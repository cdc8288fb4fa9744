// web_qr_module.cpp — the page's QR encoder, a WebAssembly module of its own (qr.js, qr.wasm):
// libqrencode, which the page fetches the first time the QR code window asks for a code
// (core/share/qr_fetched.cpp) instead of carrying it in every first load. Its one function: the
// text in, libqrencode's symbol out (core/share/qr_encoder.h qrSymbol, as the desktop makes it).
#include "core/share/qr_symbol.h"

#include <emscripten.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>

// Returns a malloc'd block that the caller frees: the version (1 to 40) and the modules a side, then
// the modules (1 dark, row-major); or 0 and the length of the error's text, then the text.
// 0 when there is no memory for it.
extern "C" EMSCRIPTEN_KEEPALIVE unsigned char* lab_qr_encode(const char* text, int size) {
    std::string error;
    std::optional<lab::QrCode> code = lab::qrSymbol(std::string_view(text, size > 0 ? static_cast<std::size_t>(size) : 0), error);
    const std::int32_t words[2] = {code ? code->version : 0, static_cast<std::int32_t>(code ? code->size : error.size())};
    const std::size_t bytes = code ? code->modules.size() : error.size();
    auto* out = static_cast<unsigned char*>(std::malloc(sizeof words + bytes));
    if (out) {
        std::memcpy(out, words, sizeof words);
        std::memcpy(out + sizeof words, code ? static_cast<const void*>(code->modules.data()) : error.data(), bytes);
    }
    return out;
}
