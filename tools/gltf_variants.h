// gltf_variants.h — the same small model written in every way a downloaded glTF may store it.
//
// For the loader's tests (tests/gltf_variants_test.cpp) and the glTF fuzzer's seeds
// (lab_gen_gltf_variants). Each variant that the lab should show has a "twin": a plain file
// (float positions and normals, 32-bit indices, no extension) holding exactly the geometry the
// variant encodes, so a test can load or render both and compare. The compressed variants are
// made with the libraries' own encoders (Debian's libdraco and libmeshoptimizer), here, at
// test time: no binary test file is stored that nobody can regenerate.
//
// Not part of the lab: the lab only reads glTF.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lab::tools {

struct GltfVariant {
    std::string name;                 // e.g. "draco"
    std::filesystem::path file;       // the variant's main file (.glb, or .gltf beside its .bin)
    std::filesystem::path twin;       // its plain twin; empty for a file the lab must refuse
    bool exact = true;                // the twin's geometry is bit-for-bit what the loader makes of the variant
                                      // (false for lossy encodings: Draco's quantization, octahedral normals)
    std::string refusal;              // for a refused file: a part of the one-line reason
    std::string note;                 // a part of a note the loader must give, if any

    GltfVariant(std::string name_, std::filesystem::path file_, std::filesystem::path twin_, bool exact_ = true,
                std::string refusal_ = {})
        : name(std::move(name_)), file(std::move(file_)), twin(std::move(twin_)), exact(exact_), refusal(std::move(refusal_)) {}
};

// Writes every variant (and its twin) into `folder` (created), returns them in a fixed order.
// The torus has `major` × `minor` segments (small ones make small fuzzer seeds).
std::vector<GltfVariant> writeGltfVariants(const std::filesystem::path& folder, int major = 24, int minor = 12);

} // namespace lab::tools
