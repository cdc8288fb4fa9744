// model_fit_test.cpp — "Fit Blinn-Phong" in the real lab (app/workspace_fit.cpp): the button in the BRDF
// section puts the fit of A's specular lobe into B, compare mode opens, B's label gives the fit and the
// message says what was found; in an exercise the buttons are not there.
#include "gui_harness.h"

#include <cstdlib>

namespace lab::test {
namespace {

TEST(GuiModelFit, FitBlinnPhongPutsTheFitIntoBBesideA) {
    START_LAB(lab, "--preset", preset("06-shininess-20")); // Phong, n = 20
    ASSERT_TRUE(lab.has("brdf.fit-blinn-phong")) << "the BRDF section offers the fit";
    EXPECT_FALSE(lab.has("view.label-b")) << "no compare mode yet";
    const Rect button = scrolledTo(lab, "brdf.fit-blinn-phong");
    lab.click(button.cx(), button.cy());
    ASSERT_TRUE(lab.has("view.label-b")) << "compare mode: the fit is B";
    // B's label is the fit ("B: Blinn-Phong fitted to A, error 23.5%: shininess 67.9, …"), longer than
    // A's "A: shading Phong | BRDF Phong" and cut to its strip.
    EXPECT_GT(lab.widget("view.label-b").w, lab.widget("view.label-a").w);
    EXPECT_TRUE(lab.has("view.toast")) << "the message with the fitted values";
    // B's half is drawn differently from A's: Blinn-Phong's lobe at 3.4× Phong's exponent is not Phong's.
    const Image a = lab.capture(lab.widget("view.a")), b = lab.capture(lab.widget("view.b"));
    EXPECT_GT(changedShare(a, b), 0.001);
    if (const char* shot = std::getenv("LAB_GUI_SHOT")) {
        int w = 0, h = 0;
        lab.x().screenSize(w, h);
        std::string error;
        writePng(lab.x().capture(0, 0, w, h), shot, error);
    }
}

TEST(GuiModelFit, AnExerciseDoesNotOfferTheFit) {
    START_LAB(lab, "--preset", preset("exercises/09-blinn-phong-for-beckmann"));
    EXPECT_FALSE(lab.has("brdf.fit-blinn-phong")) << "in an exercise B is the target";
}

} // namespace
} // namespace lab::test
