// gen_gltf_variants.cpp — writes the glTF variants of tools/gltf_variants.h into a folder.
//
//   lab_gen_gltf_variants OUT_FOLDER [MAJOR MINOR]
//
// MAJOR × MINOR: the torus's segments (24 × 12 by default; the fuzzer's seeds use 6 × 3).
// The tests make the same files at test time; this is for looking at them, for trying them in
// other viewers, and for the glTF fuzzer's seeds (tests/fuzz/seeds/gltf/variant-*.glb).
#include "gltf_variants.h"

#include <cstdio>
#include <cstdlib>
#include <exception>

int main(int argc, char** argv) {
    if (argc != 2 && argc != 4) {
        std::fprintf(stderr, "usage: lab_gen_gltf_variants OUT_FOLDER [MAJOR MINOR]\n");
        return 2;
    }
    const int major = argc == 4 ? std::atoi(argv[2]) : 24, minor = argc == 4 ? std::atoi(argv[3]) : 12;
    if (major < 3 || minor < 3 || major > 1024 || minor > 1024) {
        std::fprintf(stderr, "lab_gen_gltf_variants: MAJOR and MINOR must be in [3, 1024]\n");
        return 2;
    }
    try {
        for (const lab::tools::GltfVariant& v : lab::tools::writeGltfVariants(argv[1], major, minor)) {
            std::printf("%-40s %s\n", v.file.filename().string().c_str(), v.name.c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lab_gen_gltf_variants: %s\n", e.what());
        return 1;
    }
    return 0;
}
