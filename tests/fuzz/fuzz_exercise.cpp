// fuzz_exercise.cpp — libFuzzer target for exercise files (parse, validate, save, parse,
// save; the exercise's link).
// The checks are in fuzz_checks.h; tools/dev fuzz runs this target (see README "Hardening").
#include "fuzz_checks.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view input(reinterpret_cast<const char*>(data), size);
    std::string problem = lab::fuzz::checkExercise(input);
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_exercise: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
