// qr_fetched.cpp — the page's QR encoder, fetched on demand (qr_encoder.h).
//
// libqrencode is a WebAssembly module of its own (lab/platform/web_qr_module.cpp: qr.js and qr.wasm
// beside lab.js), not part of the page's first load. The QR code window asks for it
// (app/share_code.cpp) and shows the link meanwhile; once it is here, an encode copies the text into
// the module's memory, calls it, and copies its answer back: a few KB, once per link.
#include "core/share/qr_encoder.h"

#include <emscripten.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace lab {

namespace {

FetchedModule gEncoder("qr.js", "LabQr", "labQr", "lab_qr_loaded");

// clang-format off
// One encode in the module: the text copied in, its answer (two 32-bit words, then the modules or
// the error's text: web_qr_module.cpp) copied into this module's memory, which the caller frees.
// 0 when the module failed (the caller drops it: it is loaded again for the next code).
EM_JS(unsigned char*, labJsQrEncode, (const char* text, int size), {
    const q = Module.labQr;
    if (!q) return 0;
    try {
        const input = q._malloc(Math.max(size, 1));
        q.HEAPU8.set(HEAPU8.subarray(text, text + size), input);
        const out = q._lab_qr_encode(input, size);
        q._free(input);
        if (!out) return 0;
        const version = q.HEAP32[out >> 2], n = q.HEAP32[(out >> 2) + 1];
        const length = 8 + (version > 0 ? n * n : n);
        const copy = _malloc(length);
        if (copy) HEAPU8.set(q.HEAPU8.subarray(out, out + length), copy);
        q._free(out);
        return copy;
    } catch (e) {
        return 0;
    }
});
// clang-format on

} // namespace

ModuleState qrEncoderState() { return gEncoder.state(); }
std::string qrEncoderProblem() { return gEncoder.problem(); }
void loadQrEncoder() { gEncoder.load(); }
void qrEncoderLoaded(bool ok, const std::string& problem) { gEncoder.loaded(ok, problem); }

std::optional<QrCode> runQrEncoder(std::string_view text, std::string& error) {
    switch (gEncoder.state()) {
    case ModuleState::Ready: break;
    case ModuleState::Failed: error = "the QR encoder could not be loaded: " + gEncoder.problem(); return std::nullopt;
    case ModuleState::Loading: error = "the QR encoder is still loading"; return std::nullopt;
    case ModuleState::NotLoaded: error = "the QR encoder is not loaded"; return std::nullopt;
    }
    unsigned char* answer = labJsQrEncode(text.data(), static_cast<int>(text.size()));
    if (!answer) {
        gEncoder.failed("it stopped while encoding");
        error = "the QR encoder stopped while encoding (it is loaded again for the next code)";
        return std::nullopt;
    }
    std::int32_t words[2];
    std::memcpy(words, answer, sizeof words);
    const unsigned char* payload = answer + sizeof words;
    std::optional<QrCode> code;
    if (words[0] > 0) {
        code.emplace();
        code->version = words[0];
        code->size = words[1];
        code->modules.assign(payload, payload + std::size_t(words[1]) * std::size_t(words[1]));
    } else {
        error.assign(reinterpret_cast<const char*>(payload), static_cast<std::size_t>(words[1]));
    }
    std::free(answer);
    return code;
}

} // namespace lab
