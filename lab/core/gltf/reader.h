// reader.h — loading a glTF 2.0 model (.gltf or .glb) into one Mesh, safely.
//
// tinygltf 2.7.0 parses the file but does not check what it parsed: accessors past their
// buffers, out-of-range indices and node cycles all get through, and it opens any path a URI
// names. This loader is the guard. It:
//   * reads only regular files inside the model's own folder (its own file-system callbacks),
//   * refuses every index and byte range it cannot prove in bounds (with overflow checks),
//   * bounds vertex, index and triangle counts before allocating,
//   * skips images (the lab uses the preset's material, not glTF materials or textures).
// Every triangle primitive (triangles, strips, fans) of the default scene contributes, with
// the node transforms applied (and once per instance of EXT_mesh_gpu_instancing); normals that
// are missing, zero or not finite are computed (area-weighted). No rescaling: a preset without
// a camera frames the model instead (core/scene/camera.h).
//
// Besides core glTF 2.0 (sparse accessors too), it reads KHR_mesh_quantization,
// EXT_mesh_gpu_instancing, KHR_draco_mesh_compression and EXT_meshopt_compression
// (gltf_compression.h); extensionsRequired and the version are checked first (gltf_extensions.h).
#pragma once

#include "core/io/diagnostics.h"
#include "core/scene/mesh.h"

#include <filesystem>
#include <optional>
#include <string>

namespace lab {

struct GltfLimits {
    std::size_t maxFileBytes = std::size_t{512} << 20;  // the .gltf/.glb and each external buffer
    std::size_t maxTriangles = 20'000'000;
    std::size_t maxVertices = 20'000'000;
    int maxNodeDepth = 64;
    int maxJsonDepth = 128; // JSON nesting, bounded before tinygltf's recursive parse sees the text
    // How many of each object a file may declare, counted before tinygltf builds them: far above
    // any real model, low enough that every loader step stays fast.
    std::size_t maxNodes = 200'000;
    std::size_t maxMeshes = 100'000;
    std::size_t maxPrimitives = 200'000; // all meshes' together
    std::size_t maxAccessors = 1'000'000;
    std::size_t maxOtherObjects = 100'000; // bufferViews, buffers, materials, images, ..., each
    std::size_t maxInstances = 100'000;    // EXT_mesh_gpu_instancing instances, all nodes together
};

struct GltfResult {
    Mesh mesh;
    std::vector<std::string> notes; // things skipped that the user may want to know about
};

// `displayName` prefixes diagnostics. Returns nullopt after adding at least one diagnostic.
std::optional<GltfResult> loadGltf(const std::filesystem::path& file, const std::string& displayName,
                                   Diagnostics& diagnostics, const GltfLimits& limits = {});

} // namespace lab
