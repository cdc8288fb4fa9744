// box_gltf.h — a real glTF file for tests: an axis-aligned box, written at test time.
#pragma once

#include "test_files.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

namespace lab {

// An axis-aligned box from `lo` to `hi` as `name`.gltf with its buffer in `name`.bin: positions
// and indices, no normals (the lab computes them), counter-clockwise faces seen from outside.
inline void writeBoxGltf(const std::filesystem::path& folder, const std::string& name, glm::vec3 lo, glm::vec3 hi) {
    std::array<glm::vec3, 8> corners;
    for (int i = 0; i < 8; ++i) { // bit 0: +x, bit 1: +y, bit 2: +z
        corners[static_cast<std::size_t>(i)] = {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
    }
    const std::array<std::uint16_t, 36> indices = {0, 2, 1, 1, 2, 3,  4, 5, 6, 5, 7, 6,  0, 4, 2, 2, 4, 6,
                                                   1, 3, 5, 3, 7, 5,  0, 1, 4, 1, 5, 4,  2, 6, 3, 3, 6, 7};
    std::string bin(sizeof corners + sizeof indices, '\0');
    std::memcpy(bin.data(), corners.data(), sizeof corners);
    std::memcpy(bin.data() + sizeof corners, indices.data(), sizeof indices);
    writeText(folder / (name + ".bin"), bin);
    auto vec = [](glm::vec3 v) {
        return "[" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + "]";
    };
    writeText(folder / (name + ".gltf"),
              R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"uri": ")" + name + R"(.bin", "byteLength": )" + std::to_string(bin.size()) + R"(}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 72}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3", "min": )" +
                  vec(lo) + R"(, "max": )" + vec(hi) + R"(},
                {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}]})");
}

} // namespace lab
