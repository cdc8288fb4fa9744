// draco_fetched.cpp — the page's Draco decoder, fetched on demand (draco_decoder.h).
//
// The decoder is a WebAssembly module of its own (lab/platform/web_draco_module.cpp: draco.js and
// draco.wasm beside lab.js), not part of the page's first load. The platform asks for it when a
// model that names KHR_draco_mesh_compression is opened (lab/platform/web_window.cpp holds the file
// meanwhile); once it is here, a decode copies the compressed bytes into the module's memory, calls
// it, and copies its answer (draco_wire.cpp) back: two copies of a mesh, a few milliseconds even for
// large ones.
#include "core/gltf/draco_decoder.h"

#include <emscripten.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace lab {

namespace {

FetchedModule gDecoder("draco.js", "LabDraco", "labDraco", "lab_draco_loaded");

// One decode in the module: the bytes and the query's words copied in, its answer (a 32-bit length,
// then the packed result) copied into this module's memory, which the caller frees. 0 when the
// module failed (the caller drops it: it is loaded again for the next model).
EM_JS(unsigned char*, labJsDracoDecode, (const unsigned char* data, int size, const double* words, double maxBytes), {
    const d = Module.labDraco;
    if (!d) return 0;
    try {
        const input = d._malloc(Math.max(size, 1));
        const w = d._malloc(64);
        d.HEAPU8.set(HEAPU8.subarray(data, data + size), input);
        d.HEAPF64.set(HEAPF64.subarray(words >> 3, (words >> 3) + 8), w >> 3);
        const out = d._lab_draco_decode(input, size, w, maxBytes);
        d._free(input);
        d._free(w);
        if (!out) return 0;
        const length = d.HEAPU32[out >> 2];
        const copy = _malloc(length + 4);
        if (copy) HEAPU8.set(d.HEAPU8.subarray(out, out + 4 + length), copy);
        d._free(out);
        return copy;
    } catch (e) {
        return 0;
    }
});

gltf_detail::DracoResult failure(std::string message) { return gltf_detail::DracoFailure{"", std::move(message)}; }

} // namespace

ModuleState dracoDecoderState() { return gDecoder.state(); }
std::string dracoDecoderProblem() { return gDecoder.problem(); }
void loadDracoDecoder() { gDecoder.load(); }
void dracoDecoderLoaded(bool ok, const std::string& problem) { gDecoder.loaded(ok, problem); }

bool mentionsDraco(const std::filesystem::path& file) {
    // Read in pieces, each searched with the end of the one before (a model may be hundreds of MB).
    static constexpr std::string_view kName = "KHR_draco_mesh_compression";
    std::FILE* f = std::fopen(file.c_str(), "rb");
    if (!f) {
        return false;
    }
    std::string window;
    char chunk[65536];
    bool found = false;
    for (std::size_t n; !found && (n = std::fread(chunk, 1, sizeof chunk, f)) > 0;) {
        window.append(chunk, n);
        found = window.find(kName) != std::string::npos;
        window.erase(0, window.size() - std::min(window.size(), kName.size() - 1));
    }
    std::fclose(f);
    return found;
}

gltf_detail::DracoResult runDracoDecoder(const unsigned char* data, std::size_t size, const gltf_detail::DracoQuery& query) {
    switch (gDecoder.state()) {
    case ModuleState::Ready: break;
    case ModuleState::Failed: return failure("the Draco decoder could not be loaded: " + gDecoder.problem());
    case ModuleState::Loading: return failure("the Draco decoder is still loading: open the model again in a moment");
    case ModuleState::NotLoaded: return failure("the Draco decoder is not loaded: open the model itself (.glb, .gltf) to load it");
    }
    const gltf_detail::DracoQueryWords words = gltf_detail::queryWords(query);
    unsigned char* answer = labJsDracoDecode(data, static_cast<int>(size), words.words, static_cast<double>(query.maxBytes));
    if (!answer) {
        gDecoder.failed("it stopped while decoding");
        return failure("the Draco decoder stopped while decoding this model (it is loaded again for the next one)");
    }
    std::uint32_t length = 0;
    std::memcpy(&length, answer, 4);
    std::optional<gltf_detail::DracoResult> result = gltf_detail::unpackDracoResult(answer + 4, length);
    std::free(answer);
    return result ? std::move(*result) : failure("the Draco decoder answered with data the lab cannot read");
}

} // namespace lab
