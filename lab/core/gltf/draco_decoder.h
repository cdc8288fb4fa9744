// draco_decoder.h — the seam between the glTF loader and the Draco decoder, one implementation
// compiled: linked (draco_linked.cpp: the desktop, the command line, the tests) or fetched on demand
// (draco_fetched.cpp: the page, which leaves the decoder out of its first load — most students
// never open a Draco model — and loads lab/platform/web_draco_module.cpp's module once, the first
// time a model needs it).
#pragma once

#include "core/gltf/draco_mesh.h"
#include "core/io/fetched_module.h"

#include <filesystem>
#include <string>

namespace lab {

// Ready where it is linked; in the page, as fetched (core/io/fetched_module.h): the next model tries
// again after a failure, which dracoDecoderProblem() explains.
ModuleState dracoDecoderState();
std::string dracoDecoderProblem();

// Starts fetching the decoder where it is not here yet (the page); nothing where it is linked.
void loadDracoDecoder();

// The mesh, or why not; a failure that names the decoder when it is not Ready.
gltf_detail::DracoResult runDracoDecoder(const unsigned char* data, std::size_t size, const gltf_detail::DracoQuery& query);

#ifdef __EMSCRIPTEN__
// The page: the module's answer to loadDracoDecoder (lab_draco_loaded, lab/platform/web_window.cpp).
void dracoDecoderLoaded(bool ok, const std::string& problem);
// Whether a file names KHR_draco_mesh_compression anywhere: the page fetches the decoder before
// opening it (a false alarm only fetches it early).
bool mentionsDraco(const std::filesystem::path& file);
#endif

} // namespace lab
