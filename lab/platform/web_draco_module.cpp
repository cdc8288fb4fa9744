// web_draco_module.cpp — the page's Draco decoder, a WebAssembly module of its own (draco.js,
// draco.wasm). The page fetches it the first time a model needs it (core/gltf/draco_fetched.cpp)
// instead of carrying it in every first load. Its one function: the compressed bytes and the query
// in (core/gltf/draco_mesh.h), the packed result out.
#include "core/gltf/draco_mesh.h"

#include <emscripten.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>

// `words`: the query's 8 doubles (queryWords). Returns a malloc'd block: a 32-bit length, then the
// packed result (draco_wire.cpp); the caller frees it. 0 when there is no memory for it.
extern "C" EMSCRIPTEN_KEEPALIVE unsigned char* lab_draco_decode(const unsigned char* data, int size, const double* words,
                                                                double maxBytes) {
    using namespace lab::gltf_detail;
    const std::vector<unsigned char> packed =
        packDracoResult(decodeDracoMesh(data, size > 0 ? static_cast<std::size_t>(size) : 0, queryFromWords(words, maxBytes)));
    auto* out = static_cast<unsigned char*>(std::malloc(packed.size() + 4));
    if (out) {
        const auto length = static_cast<std::uint32_t>(packed.size());
        std::memcpy(out, &length, 4);
        std::memcpy(out + 4, packed.data(), packed.size());
    }
    return out;
}
