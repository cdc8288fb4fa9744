// fuzz_link.cpp — libFuzzer target for link fragments as the page's address and saved
// state hand them to the lab (#z=, #x=, #p=, #preset=, #exercise=).
// The checks are in fuzz_checks.h; tools/dev fuzz runs this target (see README "Hardening").
#include "fuzz_checks.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view input(reinterpret_cast<const char*>(data), size);
    std::string problem = lab::fuzz::checkLink(input);
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_link: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
