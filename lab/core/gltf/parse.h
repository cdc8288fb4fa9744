// parse.h — a glTF file parsed by tinygltf behind the lab's guards, for the reader (reader.cpp).
//
// tinygltf reads only regular files inside the model's folder (FileGuard). Before it parses, the
// lab checks a GLB's chunks, the JSON's depth and counts against GltfLimits, every buffer and
// image URI, the glTF version and the required extensions; it resolves every buffer itself (a
// GLB's BIN chunk in place, data: URIs decoded, files beside the model mapped) and decodes
// compressed geometry (compression.h). tinygltf then parses only the JSON, with placeholders
// for the buffers. Images are skipped and counted.
#pragma once

#include "core/gltf/compression.h"
#include "core/gltf/data_uri.h"
#include "core/gltf/reader.h"
#include "core/io/file_io.h"

#include <tiny_gltf.h>

#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab::gltf_detail {

// What tinygltf may read: regular files in `folder` of at most maxBytes.
struct FileGuard {
    std::filesystem::path folder; // canonical
    std::size_t maxBytes = 0;
    std::string refusal; // why the first refused file was refused, for the diagnostic

    // tinygltf tries the model's folder first, then the process's working folder; the first
    // answer is the one that explains the failure.
    bool refuse(const char* why) {
        if (refusal.empty()) {
            refusal = why;
        }
        return false;
    }
};

// What tinygltf parsed, and where each buffer's bytes are.
struct ParsedModel {
    tinygltf::Model model;
    std::optional<std::string_view> bin;            // the GLB's BIN chunk, in the mapped file
    DataUriBuffers dataUris;                        // buffers decoded from base64 data: URIs (data_uri.h)
    std::deque<MappedFile> external;                // .bin files the loader read itself
    ModelBuffers buffers;                           // per buffer index: its bytes (then decoded ones appended)
    std::vector<char> tinygltfReads;                // per buffer index: left to tinygltf (a data: URI our pass did not follow)
    std::vector<std::string> notes;
};

// The file's bytes parsed behind `guard`; images skipped and counted in `skippedImages`. Nullopt
// after a diagnostic naming `displayName`.
std::optional<ParsedModel> parseModel(std::string_view bytes, FileGuard& guard, int& skippedImages,
                                      const GltfLimits& limits, const std::string& displayName,
                                      Diagnostics& diagnostics);

} // namespace lab::gltf_detail
