// limits_test.cpp — the ranges' arithmetic, and that the validator refuses exactly what they exclude.
#include "core/scene/limits.h"

#include "core/io/number_format.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lab {
namespace {

using limits::Range;

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(Limits, NextUpIsNextafterTowardsInfinity) {
    for (float x : {0.0f, -0.0f, 1.0f, -1.0f, 90.0f, -90.0f, 1e-40f, -1e-40f, 3.0e38f, limits::kUnbounded}) {
        EXPECT_EQ(limits::nextUp(x), std::nextafter(x, kInf)) << x;
    }
    EXPECT_EQ(limits::nextUp(kInf), kInf);
    EXPECT_TRUE(std::isnan(limits::nextUp(std::nanf(""))));
}

TEST(Limits, ContainsAndClampAreConstexpr) {
    static_assert(limits::contains(limits::kCutoffDeg, 0.0f) && limits::contains(limits::kCutoffDeg, 90.0f));
    static_assert(!limits::contains(limits::kShininess, 0.0f) && limits::contains(limits::kShininess, 1e-3f));
    static_assert(!limits::contains(limits::kRoughness, 1e-30f) && !limits::contains(limits::kCoordinate, 2e4f));
    static_assert(limits::clamp(limits::kCutoffDeg, 120.0f) == 90.0f);
    static_assert(limits::clamp(limits::kSubdivisionsRound, 1) == 3);
    static_assert(limits::contains(limits::kSubdivisions, 1024) && !limits::contains(limits::kSubdivisions, 1025));
}

TEST(Limits, ClampGivesTheNearestAcceptedValue) {
    EXPECT_EQ(limits::clamp(limits::kShininess, 0.0f), 1e-3f);
    EXPECT_EQ(limits::clamp(limits::kShininess, -5.0f), 1e-3f);
    EXPECT_EQ(limits::clamp(limits::kRoughness, 1e-30f), 1e-3f) << "a square that underflows was NaN (issue 14)";
    EXPECT_EQ(limits::clamp(limits::kFovyDeg, 200.0f), 179.0f);
    EXPECT_EQ(limits::clamp(limits::kPlotIncidentDeg, -91.0f), -90.0f);
    EXPECT_EQ(limits::clamp(limits::kAttenuation, 3.5f), 3.5f);
    EXPECT_EQ(limits::clamp(limits::kAttenuation, kInf), 1e6f);
    EXPECT_EQ(limits::clamp(limits::kIor, std::nanf("")), 1e-2f);
    EXPECT_FALSE(limits::contains(limits::kMaterialColor, std::nanf("")));
}

TEST(Limits, FiniteIsEveryFiniteFloat) {
    static_assert(limits::contains(limits::kFinite, -limits::kUnbounded));
    static_assert(limits::contains(limits::kFinite, limits::kUnbounded));
    EXPECT_FALSE(limits::contains(limits::kFinite, kInf));
    EXPECT_FALSE(limits::contains(limits::kFinite, -kInf));
    EXPECT_EQ(limits::clamp(limits::kFinite, kInf), limits::kUnbounded);
}

// Every range a preset key is validated against, with a body that puts a value at that key.
struct Field {
    const char* where;  // the diagnostic's path
    const char* before; // the JSON before the value
    const char* after;  // and after it
    const Range* range;
};

void PrintTo(const Field& f, std::ostream* os) { *os << f.where; }

const Field kFields[] = {
    {"material.diffuse[0]", R"("material": {"diffuse": [)", ", 0, 0]}", &limits::kMaterialColor},
    {"material.shininess", R"("material": {"shininess": )", "}", &limits::kShininess},
    {"cook_torrance.roughness", R"("cook_torrance": {"roughness": )", "}", &limits::kRoughness},
    {"cook_torrance.ior", R"("cook_torrance": {"ior": )", "}", &limits::kIor},
    {"lights[0].specular[0]", R"("lights": [{"specular": [)", ", 0, 0]}]", &limits::kLightColor},
    {"lights[0].attenuation[0]", R"("lights": [{"attenuation": [)", ", 1, 0]}]", &limits::kAttenuation},
    {"lights[0].cutoff_deg", R"("lights": [{"cutoff_deg": )", "}]", &limits::kCutoffDeg},
    {"lights[0].exponent", R"("lights": [{"exponent": )", "}]", &limits::kSpotExponent},
    {"ambient_light[0]", R"("ambient_light": [)", ", 0, 0]", &limits::kAmbientLight},
    {"camera.fovy_deg", R"("camera": {"fovy_deg": )", "}", &limits::kFovyDeg},
    {"camera.near", R"("camera": {"far": 1e6, "near": )", "}", &limits::kNear},
    {"camera.eye[0]", R"("camera": {"eye": [)", ", 0, 3]}", &limits::kCoordinate},
    {"camera.target[1]", R"("camera": {"target": [0, )", ", 0]}", &limits::kCoordinate},
    {"lights[0].position[2]", R"("lights": [{"position": [1, 1, )", "]}]", &limits::kCoordinate},
    {"lights[0].direction[0]", R"("lights": [{"direction": [)", ", -1, 0]}]", &limits::kCoordinate},
    {"model.translate[0]", R"("model": {"translate": [)", ", 0, 0]}", &limits::kCoordinate},
    {"model.scale[1]", R"("model": {"scale": [1, )", ", 1]}", &limits::kCoordinate},
    {"model.rotate_deg[2]", R"("model": {"rotate_deg": [0, 0, )", "]}", &limits::kRotationDeg},
    {"camera.far", R"("camera": {"far": )", "}", &limits::kFar},
    {"background[2]", R"("background": [0, 0, )", "]", &limits::kBackground},
    {"plot.incident_deg", R"("plot": {"incident_deg": )", "}", &limits::kPlotIncidentDeg},
};

class LimitsOfKey : public testing::TestWithParam<Field> {
protected:
    // Whether the validator, given `value` at the key, says it is outside the range.
    bool refused(float value) {
        const Field& f = GetParam();
        std::string text = R"({"format": "lighting-lab-preset", "version": 1, )" + std::string(f.before) +
                           shortestFloat(value) + f.after + "}";
        Diagnostics d;
        parsePreset(text, "red.json", std::nullopt, d);
        std::string expected = std::string("must be ") + f.range->text + ", got ";
        for (const Diagnostic& x : d) {
            EXPECT_FALSE(x.message.starts_with("invalid JSON") || x.message.starts_with("number out of range"))
                << text << ": " << x.message;
        }
        for (const Diagnostic& x : d) {
            if (x.where == f.where && x.message.starts_with(expected)) {
                return true;
            }
        }
        return false;
    }
};

TEST_P(LimitsOfKey, TheValidatorRefusesExactlyWhatTheRangeExcludes) {
    const Range& r = *GetParam().range;
    EXPECT_FALSE(refused(limits::lowest(r)));
    EXPECT_FALSE(refused(r.max));
    EXPECT_FALSE(refused(r.sliderMin));
    EXPECT_FALSE(refused(r.sliderMax));
    EXPECT_TRUE(refused(r.minExclusive ? r.min : std::nextafter(r.min, -kInf)));
    if (r.max < limits::kUnbounded) {
        EXPECT_TRUE(refused(limits::nextUp(r.max)));
    }
}

TEST_P(LimitsOfKey, TheSliderSpansPartOfTheRange) {
    const Range& r = *GetParam().range;
    EXPECT_LT(r.sliderMin, r.sliderMax);
    EXPECT_TRUE(limits::contains(r, r.sliderMin));
    EXPECT_TRUE(limits::contains(r, r.sliderMax));
    EXPECT_NE(r.text, nullptr);
}

// "lights[0].cutoff_deg" -> "lights_0__cutoff_deg"
std::string fieldName(const testing::TestParamInfo<Field>& field) {
    std::string name;
    for (char c : std::string(field.param.where)) {
        name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return name;
}

INSTANTIATE_TEST_SUITE_P(Preset, LimitsOfKey, testing::ValuesIn(kFields), fieldName);

// Rules beyond one number's range: a direction and the camera's eye-to-target need a length to
// normalize, a scale factor a magnitude to invert (issue 14: a tiny direction validated and then
// normalized to garbage).
TEST(Limits, DirectionsAndScalesHaveAMinimumSize) {
    auto messages = [](const std::string& body) {
        Diagnostics d;
        parsePreset(R"({"format": "lighting-lab-preset", "version": 1, )" + body + "}", "red.json", std::nullopt, d);
        return toString(d);
    };
    EXPECT_NE(messages(R"("lights": [{"type": "directional", "direction": [1e-4, 0, 0]}])").find("lights[0].direction: must be at least 0.001 long"), std::string::npos);
    EXPECT_EQ(messages(R"("lights": [{"type": "directional", "direction": [1e-3, 0, 0]}])"), "");
    EXPECT_NE(messages(R"("camera": {"eye": [0, 0, 1e-4], "target": [0, 0, 0]})").find("camera.target: must be at least 0.001 from eye"), std::string::npos);
    EXPECT_NE(messages(R"("model": {"scale": [1, 1e-5, 1]})").find("model.scale: scale factors must be at least 0.0001"), std::string::npos);
    EXPECT_EQ(messages(R"("model": {"scale": [1, -1e-4, 1]})"), "");
}

TEST(Limits, SubdivisionsAreValidatedPerBuiltin) {
    auto refusedAt = [](const char* builtin, int n) {
        Diagnostics d;
        std::string text = R"({"format": "lighting-lab-preset", "version": 1, "model": {"builtin": ")" +
                           std::string(builtin) + R"(", "subdivisions": [)" + std::to_string(n) + ", 8]}}";
        return !parsePreset(text, "red.json", std::nullopt, d).has_value();
    };
    for (const char* round : {"sphere", "torus"}) {
        EXPECT_TRUE(refusedAt(round, limits::kSubdivisionsRound.min - 1)) << round;
        EXPECT_FALSE(refusedAt(round, limits::kSubdivisionsRound.min)) << round;
        EXPECT_FALSE(refusedAt(round, limits::kSubdivisionsRound.max)) << round;
        EXPECT_TRUE(refusedAt(round, limits::kSubdivisionsRound.max + 1)) << round;
    }
    for (const char* flat : {"cube", "plane"}) {
        EXPECT_TRUE(refusedAt(flat, limits::kSubdivisions.min - 1)) << flat;
        EXPECT_FALSE(refusedAt(flat, limits::kSubdivisions.min)) << flat;
        EXPECT_FALSE(refusedAt(flat, limits::kSubdivisions.max)) << flat;
        EXPECT_TRUE(refusedAt(flat, limits::kSubdivisions.max + 1)) << flat;
    }
}

} // namespace
} // namespace lab
