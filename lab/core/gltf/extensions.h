// extensions.h — what a glTF file says it needs, read before anything else of it.
//
// Internal to gltf*.cpp. A file names its glTF version in `asset` and the extensions a reader
// must understand in `extensionsRequired`. Both are checked here, first, so that a file the lab
// cannot show correctly is refused with the reason (a glTF 1.0 file; an extension the lab does
// not know) instead of being half-read or failing later in words about its insides.
//
// The lab decodes: KHR_mesh_quantization, EXT_mesh_gpu_instancing, and (when this build has
// the decoders, gltf_compression.h) KHR_draco_mesh_compression and EXT_meshopt_compression.
// Extensions that only change materials, textures, lights or other data the lab does not draw
// (it shades with the preset's material) are ignored with a note, even when required.
#pragma once

#include "core/io/diagnostics.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace lab::gltf_detail {

// How the lab treats an extension a file requires.
enum class ExtensionSupport { Decoded, Ignored, NotInThisBuild, Unknown };
ExtensionSupport extensionSupport(std::string_view name);

// `doc` is the file's JSON (an object). False after a diagnostic: a glTF version other than 2.x
// (or a minVersion above 2.0), or a required extension the lab cannot honour. `notes` gets one
// line naming the required extensions that are ignored.
bool checkVersionAndExtensions(const nlohmann::json& doc, const std::string& displayName, Diagnostics& diagnostics,
                               std::vector<std::string>& notes);

} // namespace lab::gltf_detail
