// fuzz_preset.cpp — libFuzzer target for preset parsing (parse, validate, save, parse, save), and
// for what a valid preset does: a finite model and plot, and a render at 8 x 8.
// The checks are in fuzz_checks.h; tools/dev fuzz runs this target (see README "Hardening").
#include "fuzz_checks.h"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view input(reinterpret_cast<const char*>(data), size);
    std::string problem = lab::fuzz::checkPreset(input);
    if (problem.empty()) {
        problem = lab::fuzz::checkPresetRenders(input);
    }
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_preset: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
