// shader_editor_test.cpp — the shader editor's pure helpers: which file and line a compile log
// line names, and which lines of each tab to mark.
#include "ui/tools/shader_editor.h"

#include <gtest/gtest.h>

namespace lab::ui {
namespace {

TEST(LogPlace, ReadsTheFileAndLineOfEachDriversFormat) {
    EXPECT_EQ(logPlace("lighting.glsl:12(5): error: `x' undeclared"), (LogPlace{"lighting.glsl", 12}));
    EXPECT_EQ(logPlace("ERROR: lit.frag:3: 'y' : undeclared identifier"), (LogPlace{"lit.frag", 3}));
    EXPECT_EQ(logPlace("lit.vert:7 : error C1008: undefined variable"), (LogPlace{"lit.vert", 7}));
    EXPECT_EQ(logPlace("lit.frag:2: column 5: non-ASCII character U+00E9"), (LogPlace{"lit.frag", 2}));
    EXPECT_EQ(logPlace("lighting_api.glsl:40(1): error: conflicting types"), (LogPlace{"lighting_api.glsl", 40}));
    // The first place in the line wins.
    EXPECT_EQ(logPlace("lit.frag:9: called from lighting.glsl:4"), (LogPlace{"lit.frag", 9}));
    EXPECT_EQ(logPlace("lighting.glsl:4: see lit.frag:9"), (LogPlace{"lighting.glsl", 4}));
}

TEST(LogPlace, NamesNothingWithoutAShaderFileAndANumber) {
    EXPECT_FALSE(logPlace("Compile failed; the previous shaders keep running:"));
    EXPECT_FALSE(logPlace("program: does not link: error: unresolved reference"));
    EXPECT_FALSE(logPlace("lit.frag: does not compile (the driver gave no log)"));
    EXPECT_FALSE(logPlace("lit.frag:x"));
    EXPECT_FALSE(logPlace("lit.frag:"));
    EXPECT_FALSE(logPlace("my_lit.frag:3: not ours"));
    EXPECT_FALSE(logPlace("0:12(5): error: unmapped"));
    EXPECT_FALSE(logPlace(""));
}

TEST(LinesNamed, SortedOncePerLineForOneFile) {
    std::vector<std::string> log = {"Compile failed; the previous shaders keep running:",
                                    "lighting.glsl:30(5): error: a",
                                    "lit.frag:4(1): error: b",
                                    "lighting.glsl:12(9): error: c",
                                    "lighting.glsl:30(7): error: d"};
    EXPECT_EQ(linesNamed(log, "lighting.glsl"), (std::vector<int>{12, 30}));
    EXPECT_EQ(linesNamed(log, "lit.frag"), (std::vector<int>{4}));
    EXPECT_TRUE(linesNamed(log, "lit.vert").empty());
}

} // namespace
} // namespace lab::ui
