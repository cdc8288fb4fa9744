// light_orbit_test.cpp — the moving light (issue 16): positions over time follow the orbit, and
// the preset's `orbit` setting reads, validates and round-trips.
#include "core/scene/light_orbit.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace lab {
namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

LightDesc orbiting(glm::vec3 position, glm::vec3 axis, float degreesPerSecond) {
    LightDesc l;
    l.position = position;
    l.orbit = {true, axis, degreesPerSecond};
    return l;
}

// The signed angle from `a` to `b` about `axis`, in degrees in [0, 360), both projected onto the
// plane normal to the axis (derived here from atan2, not from the code's rotation).
double angleAbout(glm::dvec3 axis, glm::dvec3 a, glm::dvec3 b) {
    axis = glm::normalize(axis);
    a -= axis * glm::dot(axis, a);
    b -= axis * glm::dot(axis, b);
    double deg = std::atan2(glm::dot(axis, glm::cross(a, b)), glm::dot(a, b)) * 180.0 / kPi;
    return deg < 0.0 ? deg + 360.0 : deg;
}

TEST(LightOrbit, PositionsOverTimeFollowTheOrbit) {
    const glm::vec3 centre(0.5f, -1.0f, 2.0f);
    for (glm::vec3 axis : {glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::vec3(0.3f, 2.0f, -0.7f)}) {
        for (float speed : {30.0f, -45.0f, 90.0f}) {
            LightDesc light = orbiting(centre + glm::vec3(3, 2, 4), axis, speed);
            glm::dvec3 k = glm::normalize(glm::dvec3(axis));
            glm::dvec3 start = glm::dvec3(light.position - centre);
            for (double t : {0.25, 1.0, 2.5, 7.0, 11.9}) {
                glm::dvec3 now = glm::dvec3(orbitedLight(light, centre, t).position - centre);
                SCOPED_TRACE(testing::Message() << "axis " << axis.x << "," << axis.y << "," << axis.z << " speed "
                                                << speed << " t " << t);
                // The distance to the centre and the height along the axis stay; the angle is speed·t.
                EXPECT_NEAR(glm::length(now), glm::length(start), 1e-5);
                EXPECT_NEAR(glm::dot(now, k), glm::dot(start, k), 1e-5);
                double expected = std::fmod(speed * t, 360.0);
                expected = expected < 0.0 ? expected + 360.0 : expected;
                double got = angleAbout(k, start, now);
                double diff = std::fmod(std::abs(got - expected), 360.0);
                EXPECT_NEAR(std::min(diff, 360.0 - diff), 0.0, 1e-3);
            }
            // After one period (360 / |speed| seconds) the light is back where it started.
            double period = 360.0 / std::abs(speed);
            glm::vec3 back = orbitedLight(light, centre, period).position;
            EXPECT_NEAR(glm::length(back - light.position), 0.0f, 1e-4f);
        }
    }
}

TEST(LightOrbit, TimeZeroIsThePresetsPositionExactly) {
    LightDesc light = orbiting({0.1f, 0.7f, -3.3f}, {1, 1, 0}, 37.0f);
    light.type = LightType::Spot;
    light.direction = {0.2f, -1.0f, 0.4f};
    LightDesc at0 = orbitedLight(light, {0.3f, 0.2f, 0.1f}, 0.0);
    EXPECT_EQ(at0, light); // bit for bit, not "near"
    // A whole number of turns is the angle 0 too, bit for bit: 30°/s for 12 s and for 36 s (products
    // that are exact in double, so fmod gives 0 and not 359.99…).
    LightDesc turning = light;
    turning.orbit.degreesPerSecond = 30.0f;
    EXPECT_EQ(orbitedLight(turning, {0.3f, 0.2f, 0.1f}, 12.0), turning);
    EXPECT_EQ(orbitedLight(turning, {0.3f, 0.2f, 0.1f}, 36.0), turning);
    EXPECT_NE(orbitedLight(turning, {0.3f, 0.2f, 0.1f}, 6.0), turning) << "half a turn moves it";
}

TEST(LightOrbit, OffOrStoppedLightsStay) {
    LightDesc light = orbiting({1, 2, 3}, {0, 1, 0}, 30.0f);
    light.orbit.on = false;
    EXPECT_EQ(orbitedLight(light, {}, 5.0), light);
    light.orbit.on = true;
    light.orbit.degreesPerSecond = 0.0f;
    EXPECT_EQ(orbitedLight(light, {}, 5.0), light);
}

TEST(LightOrbit, ALightOnTheAxisStaysWhereItIs) {
    // The offset from the centre parallel to the axis: a light straight above the model.
    const glm::vec3 centre(1, 0, 0);
    LightDesc light = orbiting(centre + glm::vec3(0, 4, 0), {0, 2, 0}, 45.0f);
    for (double t : {0.5, 1.0, 3.3}) {
        glm::vec3 p = orbitedLight(light, centre, t).position;
        EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        EXPECT_NEAR(glm::length(p - light.position), 0.0f, 1e-5f) << t;
    }
    // A light at the centre itself stays too.
    LightDesc atCentre = orbiting(centre, {0, 1, 0}, 45.0f);
    EXPECT_NEAR(glm::length(orbitedLight(atCentre, centre, 2.0).position - centre), 0.0f, 1e-6f);
}

TEST(LightOrbit, DirectionsTurnWithTheLight) {
    // A directional light from +x turned a quarter about +y (counter-clockwise from above) comes from -z.
    LightDesc sun = orbiting({0, 0, 0}, {0, 1, 0}, 90.0f);
    sun.type = LightType::Directional;
    sun.direction = {-1, 0, 0}; // shining towards -x
    glm::vec3 d = orbitedLight(sun, {}, 1.0).direction;
    EXPECT_NEAR(d.x, 0.0f, 1e-6f);
    EXPECT_NEAR(d.y, 0.0f, 1e-6f);
    EXPECT_NEAR(d.z, 1.0f, 1e-6f);
    // And the inverse rotation undoes it (a dragged marker while paused).
    glm::vec3 undone = orbitUnrotate(sun.orbit, 1.0, d);
    EXPECT_NEAR(glm::length(undone - sun.direction), 0.0f, 1e-6f);
}

TEST(LightOrbit, TheAngleStaysPreciseAfterHours) {
    LightOrbit o{true, {0, 1, 0}, 30.0f};
    EXPECT_NEAR(orbitAngleDeg(o, 3.0 * 3600.0 + 1.0), 30.0, 1e-9);
    o.degreesPerSecond = -30.0f;
    EXPECT_NEAR(orbitAngleDeg(o, 1.0), 330.0, 1e-9);
}

TEST(LightOrbit, PositionsStayInTheCoordinateRange) {
    LightDesc far = orbiting({1.0e4f, 1.0e4f, 0.0f}, {0, 0, 1}, 45.0f);
    glm::vec3 p = orbitedLight(far, {}, 1.0).position;
    for (int i = 0; i < 3; ++i) {
        EXPECT_LE(std::abs(p[i]), limits::kCoordinate.max);
    }
}

TEST(LightOrbit, OrbitedSceneMovesOnlyOrbitingLights) {
    Preset p;
    p.lights = {orbiting({2, 0, 0}, {0, 1, 0}, 90.0f), LightDesc{}};
    EXPECT_TRUE(anyOrbit(p));
    Preset shown = orbitedScene(p, {}, 1.0);
    EXPECT_NEAR(glm::length(shown.lights[0].position - glm::vec3(0, 0, -2)), 0.0f, 1e-5f);
    EXPECT_EQ(shown.lights[1], p.lights[1]);
    // Each light on its own clock: the second, switched on later, starts from its own position.
    p.lights[1].orbit.on = true;
    Preset clocked = orbitedScene(p, LightMotion{{}, {1.0}});
    EXPECT_NEAR(glm::length(clocked.lights[0].position - glm::vec3(0, 0, -2)), 0.0f, 1e-5f);
    EXPECT_EQ(clocked.lights[1], p.lights[1]);
    p.lights[0].orbit.on = false;
    p.lights[1].orbit.on = false;
    EXPECT_FALSE(anyOrbit(p));
}

//----------------------------------------------------------------------------------------
// The preset's `orbit`
//----------------------------------------------------------------------------------------

const std::string kHead = R"({"format": "lighting-lab-preset", "version": 1, )";

std::optional<Preset> parse(const std::string& body, Diagnostics& d) {
    return parsePreset(kHead + body + "}", "lecture.json", std::nullopt, d);
}

TEST(LightOrbitPreset, ReadsTheSettingAndDefaultsWhenAbsent) {
    Diagnostics d;
    std::optional<Preset> p = parse(R"("lights": [{"orbit": {"on": true, "axis": [1, 0, 0], "degrees_per_second": -20}},
                                                  {"orbit": {"on": true}}, {}])", d);
    ASSERT_TRUE(p) << toString(d);
    EXPECT_EQ(p->lights[0].orbit, (LightOrbit{true, {1, 0, 0}, -20.0f}));
    EXPECT_EQ(p->lights[1].orbit, (LightOrbit{true, {0, 1, 0}, 30.0f}));
    EXPECT_EQ(p->lights[2].orbit, LightOrbit{});
    EXPECT_FALSE(LightOrbit{}.on);
}

TEST(LightOrbitPreset, RoundTripsExactly) {
    Preset p;
    p.lights = {orbiting({3, 1, 2}, {0.1f, 0.9f, -0.3f}, 12.345f), LightDesc{}, LightDesc{}};
    p.lights[2].orbit.degreesPerSecond = 45.0f; // off, but not the default: kept too
    std::string text = presetToJson(p);
    Diagnostics d;
    std::optional<Preset> back = parsePreset(text, "saved.json", std::nullopt, d);
    ASSERT_TRUE(back) << toString(d) << text;
    EXPECT_EQ(*back, p) << text;
    EXPECT_EQ(presetToJson(*back), text);
    EXPECT_NE(text.find(R"("orbit": {)"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("degrees_per_second": 12.345)"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("on": false)"), std::string::npos) << text;
}

TEST(LightOrbitPreset, PresetsWithoutMotionAreWrittenAsBefore) {
    // Only lights whose orbit is not the default get the key: older presets save byte for byte as they did.
    EXPECT_EQ(presetToJson(Preset{}).find("orbit"), std::string::npos);
    for (const fs::directory_entry& e : fs::directory_iterator(fs::path(LAB_SOURCE_DIR) / "presets")) {
        if (e.path().extension() != ".json") {
            continue;
        }
        Diagnostics d;
        std::optional<LoadedPreset> p = loadPreset(e.path(), d);
        ASSERT_TRUE(p) << toString(d);
        bool orbits = anyOrbit(p->preset);
        EXPECT_EQ(presetToJson(p->preset).find("\"orbit\"") != std::string::npos, orbits) << e.path();
    }
}

struct BadOrbit {
    const char* body;
    const char* where;
    const char* message;
};

void PrintTo(const BadOrbit& c, std::ostream* os) { *os << c.body; }

class LightOrbitErrors : public testing::TestWithParam<BadOrbit> {};

TEST_P(LightOrbitErrors, AreReportedWithTheirJsonPath) {
    const BadOrbit& c = GetParam();
    Diagnostics d;
    EXPECT_FALSE(parse(c.body, d)) << c.body;
    bool found = false;
    for (const Diagnostic& x : d) {
        found |= x.file == "lecture.json" && x.where == c.where && x.message.find(c.message) != std::string::npos;
    }
    EXPECT_TRUE(found) << "expected \"" << c.where << ": ..." << c.message << "...\"\ngot:\n" << toString(d);
}

INSTANTIATE_TEST_SUITE_P(
    Validation, LightOrbitErrors,
    testing::Values(
        BadOrbit{R"("lights": [{"orbit": true}])", "lights[0].orbit", "expected an object"},
        BadOrbit{R"("lights": [{}, {"orbit": {"on": 1}}])", "lights[1].orbit.on", "true or false"},
        BadOrbit{R"("lights": [{"orbit": {"axis": [0, 0, 0]}}])", "lights[0].orbit.axis", "at least 0.001 long"},
        BadOrbit{R"("lights": [{"orbit": {"axis": [0, 1]}}])", "lights[0].orbit.axis", "expected an array of 3 numbers"},
        BadOrbit{R"("lights": [{"orbit": {"axis": [0, 1e5, 0]}}])", "lights[0].orbit.axis[1]", "in [-10000, 10000]"},
        BadOrbit{R"("lights": [{"orbit": {"degrees_per_second": 4000}}])", "lights[0].orbit.degrees_per_second",
                 "in [-3600, 3600]"},
        BadOrbit{R"("lights": [{"orbit": {"degrees_per_second": "fast"}}])", "lights[0].orbit.degrees_per_second",
                 "expected a number"},
        BadOrbit{R"("lights": [{"orbit": {"speed": 30}}])", "lights[0].orbit.speed", "unknown key"},
        BadOrbit{R"("lights": [{"orbit": {"degrees_per_secnd": 30}}])", "lights[0].orbit.degrees_per_secnd",
                 "did you mean \"degrees_per_second\""}));

} // namespace
} // namespace lab
