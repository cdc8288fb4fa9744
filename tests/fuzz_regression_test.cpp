// fuzz_regression_test.cpp — the fuzzers' checks (tests/fuzz/fuzz_checks.h) over their seeds and
// over every input a fuzzer has ever made fail (tests/fuzz/regressions/<target>/), in the normal
// test run, so a fixed crash stays fixed.
#include "fuzz/fuzz_checks.h"

#include "test_files.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> filesIn(std::initializer_list<const char*> folders) {
    std::vector<fs::path> files;
    for (const char* folder : folders) {
        fs::path dir = fs::path(LAB_SOURCE_DIR) / folder;
        if (fs::is_directory(dir)) {
            for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
                if (e.is_regular_file()) {
                    files.push_back(e.path());
                }
            }
        }
    }
    return files;
}

TEST(FuzzRegression, PresetInputs) {
    auto files = filesIn({"presets", "tests/data", "tests/fuzz/regressions/preset"});
    ASSERT_GT(files.size(), 20u);
    for (const fs::path& f : files) {
        EXPECT_EQ(fuzz::checkPreset(readText(f)), "") << f;
        EXPECT_EQ(fuzz::checkPresetRenders(readText(f)), "") << f;
    }
}

TEST(FuzzRegression, GltfInputs) {
    TempFolder scratch;
    auto files = filesIn({"tests/fuzz/seeds/gltf", "presets/models", "tests/fuzz/regressions/gltf"});
    ASSERT_GE(files.size(), 6u);
    for (const fs::path& f : files) {
        EXPECT_EQ(fuzz::checkGltf(readText(f), scratch.path()), "") << f;
    }
}

// fuzz_gltf's first find: vertices near the float range made the computed normals infinite.
TEST(FuzzRegression, HugeCoordinatesGetFiniteComputedNormals) {
    TempFolder scratch;
    fs::path f = fs::path(LAB_SOURCE_DIR) / "tests/fuzz/regressions/gltf/huge-coordinates-computed-normals.glb";
    writeText(scratch.path() / "m.glb", readText(f));
    Diagnostics d;
    std::optional<GltfResult> r = loadGltf(scratch.path() / "m.glb", "m.glb", d);
    ASSERT_TRUE(r) << toString(d);
    for (const glm::vec3& n : r->mesh.normals) {
        ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    }
}

TEST(FuzzRegression, CommandLineInputs) {
    auto files = filesIn({"tests/fuzz/seeds/cli", "tests/fuzz/regressions/cli"});
    ASSERT_GE(files.size(), 10u);
    for (const fs::path& f : files) {
        testing::internal::CaptureStdout();
        testing::internal::CaptureStderr();
        std::string problem = fuzz::checkCommandLine(readText(f));
        testing::internal::GetCapturedStdout();
        testing::internal::GetCapturedStderr();
        EXPECT_EQ(problem, "") << f;
    }
    // The commands are run, not only parsed: each leaves its file (the check a report, since a.json
    // differs from its black golden).
    const std::pair<const char*, const char*> runs[] = {{"render\na.json\n--out\nx.png", "x.png"},
                                                        {"plot\na.json\n--out\np.csv", "p.csv"},
                                                        {"check\na.json\n--golden\ngolden", "lab-check/report.txt"}};
    for (const auto& [args, file] : runs) {
        EXPECT_EQ(fuzz::checkCommandLine(args), "") << args;
        EXPECT_TRUE(fs::exists(fuzz::commandScratch() / file)) << args;
    }
}

} // namespace
} // namespace lab
