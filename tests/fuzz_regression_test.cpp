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

TEST(FuzzRegression, ExerciseInputs) {
    auto files = filesIn({"presets/exercises", "tests/fuzz/regressions/exercise"});
    ASSERT_GE(files.size(), 8u);
    for (const fs::path& f : files) {
        EXPECT_EQ(fuzz::checkExercise(readText(f)), "") << f;
    }
    // The check can fail: a tolerance infinite as a float was accepted, and its link aborted.
    std::string bundled = readText(fs::path(LAB_SOURCE_DIR) / "presets/exercises/02-shininess.json");
    std::string hostile = bundled.substr(0, bundled.rfind('}')) + R"(, "tolerance": {"fields": {"material.shininess": 1e308}}})";
    EXPECT_EQ(fuzz::checkExercise(hostile), "");
    Diagnostics d;
    EXPECT_FALSE(parseExercise(hostile, "x.json", std::nullopt, d)) << "refused when read";
}

TEST(FuzzRegression, LinkInputs) {
    auto files = filesIn({"tests/fuzz/seeds/link", "tests/fuzz/regressions/link"});
    ASSERT_GE(files.size(), 40u);
    int opened = 0;
    for (const fs::path& f : files) {
        EXPECT_EQ(fuzz::checkLink(readText(f)), "") << f;
        Diagnostics d;
        opened += parseLink(readText(f), ".", d).has_value() ? 1 : 0;
    }
    EXPECT_GE(opened, 30) << "the seeds are mostly links that open (the bundled scenes)";
    EXPECT_LE(opened, static_cast<int>(files.size()) - 5) << "and some that do not";
}

// The page's field edits: every path of the field table, and the hostile texts of issue 49.
TEST(FuzzRegression, FieldInputs) {
    auto files = filesIn({"tests/fuzz/seeds/field", "tests/fuzz/regressions/field"});
    ASSERT_GE(files.size(), 100u);
    for (const fs::path& f : files) {
        EXPECT_EQ(fuzz::checkFieldEdit(readText(f)), "") << f;
    }
    // The check can fail: strtof took a hex float and the text before a NUL (issue 49), which the
    // check's own reading of what a preset file holds does not.
    Preset p;
    EXPECT_NE(setFieldFromText(p, "material.shininess", "0x10"), "");
    EXPECT_EQ(fuzz::checkFieldEdit("material.shininess\n" + std::string(1 << 20, '7')), "");
}

// `lab fit` over the shipped presets, each to the model its size picks (fuzz_fit's check).
TEST(FuzzRegression, FitInputs) {
    auto files = filesIn({"presets", "tests/fuzz/regressions/fit"});
    ASSERT_GE(files.size(), 20u);
    for (const fs::path& f : files) {
        EXPECT_EQ(fuzz::checkFit(readText(f)), "") << f;
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
                                                        {"check\na.json\n--golden\ngolden", "lab-check/report.txt"},
                                                        {"exercise\ncheck\ne.json\na.json\n--diff\nd.png", "d.png"},
                                                        {"share\na.json\n--base\nhttps://x.org/\n--qr\nq.png", "q.png"}};
    for (const auto& [args, file] : runs) {
        EXPECT_EQ(fuzz::checkCommandLine(args), "") << args;
        EXPECT_TRUE(fs::exists(fuzz::commandScratch() / file)) << args;
    }
}

} // namespace
} // namespace lab
