// view_mode_test.cpp — the views' names, where each applies (issue 26), the automatic range's
// rule, a preset's check.views and the legend band. No GL.
#include "core/plots/legend.h"
#include "core/scene/preset.h"
#include "core/scene/view_mode.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

TEST(ViewMode, EveryNameReadsBackAndAMisspeltOneDoesNot) {
    for (ViewMode m : kViewModes) {
        EXPECT_EQ(viewFromName(viewName(m)), m) << viewName(m);
        EXPECT_NE(std::string(toString(m)), "");
    }
    EXPECT_FALSE(viewFromName("dd"));
    EXPECT_FALSE(viewFromName("D")); // names are lower case, as typed on the command line
    EXPECT_EQ(viewNameList().size(), kViewModes.size());
}

TEST(ViewMode, AFactorAppliesOnlyWhereTheEquationHasIt) {
    Preset p; // Phong, one point light
    EXPECT_EQ(notApplicable(ViewMode::RdotV, p, 0), "");
    EXPECT_EQ(notApplicable(ViewMode::D, p, 0), "d is a Cook-Torrance factor; this preset's BRDF is phong");
    EXPECT_NE(notApplicable(ViewMode::NdotH, p, 0), "");
    p.brdf = BrdfModel::BlinnPhong;
    EXPECT_EQ(notApplicable(ViewMode::NdotH, p, 0), "");
    EXPECT_EQ(notApplicable(ViewMode::RdotV, p, 0), "R.V is the Phong BRDF's factor; this preset's BRDF is blinn-phong");
    p.brdf = BrdfModel::CookTorrance;
    for (ViewMode m : {ViewMode::D, ViewMode::F, ViewMode::G, ViewMode::Denominator, ViewMode::NdotH, ViewMode::NdotV}) {
        EXPECT_EQ(notApplicable(m, p, 0), "") << viewName(m);
    }
    EXPECT_EQ(notApplicable(ViewMode::D, p, 1), "there is no light 2 (the preset has 1 light)");
    p.lights[0].type = LightType::Directional;
    EXPECT_EQ(notApplicable(ViewMode::Distance, p, 0), "light 1 is directional: it has no distance");
    EXPECT_EQ(notApplicable(ViewMode::Attenuation, p, 0), ""); // 1 for a directional light
    p.lights[0].enabled = false;
    EXPECT_EQ(notApplicable(ViewMode::NdotL, p, 0), "light 1 is switched off");
    // The term views, normals and the Gouraud error need no light.
    p.lights.clear();
    for (ViewMode m : {ViewMode::Lit, ViewMode::Specular, ViewMode::Normals, ViewMode::GouraudError}) {
        EXPECT_EQ(notApplicable(m, p, 0), "") << viewName(m);
    }
}

// A range autoRange found (nearly) constant: [lo, hi] with the value and its half span.
ValueRange constantRange(float lo, float hi, float v, float spread) {
    ValueRange r{lo, hi};
    r.constant = v;
    r.spread = spread;
    return r;
}

TEST(ViewMode, ASpotFactorAppliesToASpotLightOnly) {
    Preset p;
    EXPECT_NE(notApplicable(ViewMode::Spot, p, 0).find("point light"), std::string::npos) << notApplicable(ViewMode::Spot, p, 0);
    p.lights[0].type = LightType::Spot;
    EXPECT_EQ(notApplicable(ViewMode::Spot, p, 0), "");
}

TEST(ViewMode, TheAutomaticRangeIsTheValuesOrAConstantAsWhatItIs) {
    EXPECT_EQ(autoRange(0.2f, 3.5f), (ValueRange{0.2f, 3.5f}));
    EXPECT_EQ(autoRange(1.0f, 1.0f), constantRange(0.0f, 1.0f, 1.0f, 0.0f)); // 1 everywhere is the palette's top
    EXPECT_EQ(autoRange(0.0f, 0.0f), constantRange(0.0f, 1.0f, 0.0f, 0.0f)); // 0 everywhere its bottom
    EXPECT_EQ(autoRange(5.0f, 5.0f), constantRange(0.0f, 5.0f, 5.0f, 0.0f));
    EXPECT_EQ(autoRange(-2.0f, -2.0f), constantRange(-2.0f, 1.0f, -2.0f, 0.0f));
    // Preset 13's F: 0.04 to 0.04001 is not a gradient to spread over the palette (issue 50).
    const ValueRange f = autoRange(0.04f, 0.04001f);
    ASSERT_TRUE(f.constant);
    EXPECT_NEAR(*f.constant, 0.040005f, 1e-7f);
    EXPECT_NEAR(f.spread, 0.000005f, 1e-7f);
    EXPECT_EQ(f.lo, 0.0f);
    EXPECT_EQ(f.hi, 1.0f);
    EXPECT_FALSE(autoRange(0.04f, 0.0405f).constant); // 1.2%: a span to show
    EXPECT_TRUE(autoRange(2.0f, 2.019f).constant);    // 0.9%
    EXPECT_FLOAT_EQ(rangePosition(0.5f, {0.0f, 2.0f}), 0.25f);
    EXPECT_FLOAT_EQ(rangePosition(9.0f, {0.0f, 2.0f}), 1.0f);
    EXPECT_FLOAT_EQ(rangePosition(-9.0f, {0.0f, 2.0f}), 0.0f);
}

const std::string kHead = R"({"format": "lighting-lab-preset", "version": 1, )";

TEST(CheckViews, ReadWriteAndRefuseWithTheirJsonPath) {
    Diagnostics d;
    std::optional<Preset> p =
        parsePreset(kHead + R"("check": {"views": ["d", {"view": "spot", "light": 2}]}})", "v.json", std::nullopt, d);
    ASSERT_TRUE(p) << toString(d);
    ASSERT_EQ(p->check.views.size(), 2u);
    EXPECT_EQ(p->check.views[0], (CheckView{"d", 1}));
    EXPECT_EQ(p->check.views[1], (CheckView{"spot", 2}));
    std::optional<Preset> back = parsePreset(presetToJson(*p), "v.json", std::nullopt, d);
    ASSERT_TRUE(back) << toString(d);
    EXPECT_EQ(back->check, p->check);
    const std::pair<const char*, const char*> bad[] = {
        {R"("check": {"views": ["dd"]}})", "check.views[0]: no view \"dd\" (did you mean \"d\"?)"},
        {R"("check": {"views": "d"}})", "check.views: expected an array"},
        {R"("check": {"views": [3]}})", "check.views[0]: expected a view name or an object"},
        {R"("check": {"views": [{"view": "d", "light": 0}]}})", "check.views[0].light"},
        {R"("check": {"views": [{"view": "d", "lamp": 1}]}})", "check.views[0].lamp: unknown key"},
        // One view twice would be one golden checked twice (and written twice by --update).
        {R"("check": {"views": ["d", {"view": "d", "light": 1}]}})", "check.views[1].view: \"d\" is listed twice"},
        {R"("check": {"views": [{"view": "d", "light": 2}, {"view": "d", "light": 2}]}})",
         "check.views[1].view: \"d\" of light 2 is listed twice"},
    };
    for (const auto& [text, message] : bad) {
        Diagnostics e;
        EXPECT_FALSE(parsePreset(kHead + text, "v.json", std::nullopt, e)) << text;
        EXPECT_NE(toString(e).find(message), std::string::npos) << toString(e);
    }
}

TEST(Legend, TheBandGoesUnderTheRenderWhichStaysAsItWas) {
    Image render{200, 100, std::vector<std::uint8_t>(200 * 100 * 3, 77)};
    Image out = withLegend(render, {"D: microfacet distribution, light 1", {0.0f, 3.5f}, ValuePalette::Viridis});
    ASSERT_EQ(out.width, 200);
    ASSERT_EQ(out.height, 100 + legendHeight(200));
    EXPECT_TRUE(std::equal(render.rgb.begin(), render.rgb.end(), out.rgb.begin()));
    // The bar runs from viridis's first colour (68, 1, 84) to its last (253, 231, 37).
    int barRow = -1;
    for (int y = 100; y < out.height && barRow < 0; ++y) {
        const std::uint8_t* px = &out.rgb[(std::size_t(y) * 200 + 190) * 3];
        barRow = px[0] > 200 && px[1] > 200 && px[2] < 80 ? y : -1; // the bar's yellow end
    }
    ASSERT_GE(barRow, 0) << "no palette bar in the band";
    EXPECT_EQ(legendNumber(3.5359235f), "3.54");
    EXPECT_EQ(legendNumber(0.000694f), "0.000694");
    EXPECT_EQ(legendNumber(-0.0f), "0");
    EXPECT_EQ(legendDigits({0.0f, 3.5f}), 3);
    EXPECT_EQ(legendDigits({0.04f, 0.04004f}), 4); // a narrow F: "0.04" and "0.04004", not "0.04" twice
    EXPECT_EQ(legendNumber(0.04004f, legendDigits({0.04f, 0.04004f})), "0.04004");
}

} // namespace
} // namespace lab
