// fuzz_fit.cpp — libFuzzer target for `lab fit` of every preset that validates.
// The checks are in fuzz_checks.h; tools/dev fuzz runs this target (see README "Hardening").
#include "fuzz_checks.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view input(reinterpret_cast<const char*>(data), size);
    std::string problem = lab::fuzz::checkFit(input);
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_fit: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
