// fuzz_cli.cpp — libFuzzer target for the command line: the argument parser, then render, plot and
// check run on a scratch folder's files (fuzz_checks.h, runParsedCommand).
// The checks are in fuzz_checks.h; tools/dev fuzz runs this target (see README "Hardening").
#include "fuzz_checks.h"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view input(reinterpret_cast<const char*>(data), size);
    std::string problem = lab::fuzz::checkCommandLine(input);
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_cli: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
