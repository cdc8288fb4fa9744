// sweep_view_test.cpp — the sweep window shows a preset's own sweep (issue 23), and keeps the
// user's edits until another preset's sweep comes.
#include "ui/tools/sweep_view.h"

#include <gtest/gtest.h>

namespace lab::ui {
namespace {

TEST(SweepView, APresetsOwnSweepBecomesTheWindowsChoices) {
    SweepViewState s;
    Preset plain;
    followPresetSweep(s, plain);
    EXPECT_EQ(s.key[0], "material.shininess"); // the window's own defaults stay
    EXPECT_EQ(s.values[0], "10,20,30,50");

    Preset grid;
    grid.sweep = {"material.shininess=5,20,80", "material.specular=0.25,0.5,1"};
    followPresetSweep(s, grid);
    EXPECT_EQ(sweepArguments(s), grid.sweep);

    s.values[0] = "1,2"; // the user's edit survives the next frames of the same preset
    followPresetSweep(s, grid);
    EXPECT_EQ(s.values[0], "1,2");

    Preset one;
    one.sweep = {"cook_torrance.roughness=0.1,0.4"};
    followPresetSweep(s, one);
    EXPECT_EQ(sweepArguments(s), one.sweep); // one axis: no rows key
    EXPECT_TRUE(s.key[1].empty());

    followPresetSweep(s, plain); // a preset without a sweep leaves the choices as they are
    EXPECT_EQ(sweepArguments(s), one.sweep);
}

} // namespace
} // namespace lab::ui
