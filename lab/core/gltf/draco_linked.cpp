// draco_linked.cpp — the Draco decoder linked in (draco_decoder.h): the desktop and the command line.
#include "core/gltf/draco_decoder.h"

namespace lab {

ModuleState dracoDecoderState() { return ModuleState::Ready; }
std::string dracoDecoderProblem() { return {}; }
void loadDracoDecoder() {}

gltf_detail::DracoResult runDracoDecoder(const unsigned char* data, std::size_t size, const gltf_detail::DracoQuery& query) {
    return gltf_detail::decodeDracoMesh(data, size, query);
}

} // namespace lab
