// fuzz_gltf.cpp — libFuzzer target for glTF/GLB loading with the lab's validation.
// The checks are in fuzz_checks.h; tools/dev fuzz runs this target (see README "Hardening").
#include "fuzz_checks.h"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view input(reinterpret_cast<const char*>(data), size);
    // One scratch folder for the run: the input is written there as a real file each time.
    static const std::filesystem::path folder = [] {
        char tmpl[] = "/tmp/lab-fuzz-gltf-XXXXXX";
        return std::filesystem::path(::mkdtemp(tmpl));
    }();
    std::string problem = lab::fuzz::checkGltf(input, folder);
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_gltf: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
