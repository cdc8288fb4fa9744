// gen_gltf_variants.cpp — writes the glTF variants of tools/gltf_variants.h into a folder.
//
//   lab_gen_gltf_variants OUT_FOLDER
//
// The tests make the same files at test time; this is for looking at them, for trying them in
// other viewers, and for the glTF fuzzer's seeds (tests/fuzz/seeds/gltf/variant-*.glb).
#include "gltf_variants.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: lab_gen_gltf_variants OUT_FOLDER\n");
        return 2;
    }
    try {
        for (const lab::tools::GltfVariant& v : lab::tools::writeGltfVariants(argv[1])) {
            std::printf("%-40s %s\n", v.file.filename().string().c_str(), v.name.c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lab_gen_gltf_variants: %s\n", e.what());
        return 1;
    }
    return 0;
}
