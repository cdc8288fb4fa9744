// preset_test.cpp — defaults, every validation error with its path, round trips, shipped presets.
#include "core/scene/preset.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <fstream>
#include <csignal>
#include <sys/resource.h>
#include <sys/stat.h>

namespace lab {
namespace {

namespace fs = std::filesystem;

const std::string kHead = R"("format": "lighting-lab-preset", "version": 1)";

std::optional<Preset> parse(const std::string& body, Diagnostics& d) {
    return parsePreset("{" + kHead + (body.empty() ? "" : ", " + body) + "}", "red.json", std::nullopt, d);
}

TEST(Preset, MinimalFileGivesTheDocumentedDefaults) {
    Diagnostics d;
    std::optional<Preset> p = parse("", d);
    ASSERT_TRUE(p) << toString(d);
    EXPECT_EQ(*p, Preset{});
    // Spot-check the documented values, so a changed default in the struct is noticed.
    EXPECT_EQ(p->name, "Untitled");
    EXPECT_EQ(p->model.builtin, Builtin::Sphere);
    EXPECT_EQ(p->model.subdivisions, glm::ivec2(64, 32));
    EXPECT_EQ(p->camera.eye, glm::vec3(0, 0, 4));
    EXPECT_EQ(p->camera.fovyDeg, 45.0f);
    EXPECT_EQ(p->shading, Shading::Phong);
    EXPECT_EQ(p->brdf, BrdfModel::Phong);
    EXPECT_EQ(p->cookTorrance.roughness, 0.3f);
    EXPECT_EQ(p->cookTorrance.ior, 1.5f);
    EXPECT_EQ(p->material.ambient, glm::vec3(0.2f));
    EXPECT_EQ(p->material.diffuse, glm::vec3(0.8f));
    EXPECT_EQ(p->material.shininess, 32.0f);
    EXPECT_EQ(p->ambientLight, glm::vec3(0.1f));
    ASSERT_EQ(p->lights.size(), 1u);
    EXPECT_EQ(p->lights[0].position, glm::vec3(2, 2, 2));
    EXPECT_EQ(p->lights[0].attenuation, glm::vec3(1, 0, 0));
    EXPECT_EQ(p->lights[0].cutoffDeg, 30.0f);
    EXPECT_EQ(p->lights[0].exponent, 8.0f);
    EXPECT_EQ(p->background, glm::vec3(0.05f, 0.05f, 0.08f));
    EXPECT_EQ(p->plotIncidentDeg, 45.0f);
}

TEST(Preset, EmptyLightsMeansNoLights) {
    Diagnostics d;
    std::optional<Preset> p = parse(R"("lights": [])", d);
    ASSERT_TRUE(p) << toString(d);
    EXPECT_TRUE(p->lights.empty());
}

TEST(Preset, LightDefaultsApplyPerLight) {
    Diagnostics d;
    std::optional<Preset> p = parse(R"("lights": [{"type": "spot"}, {"diffuse": [0.5, 0.5, 0.5]}])", d);
    ASSERT_TRUE(p) << toString(d);
    ASSERT_EQ(p->lights.size(), 2u);
    EXPECT_EQ(p->lights[0].type, LightType::Spot);
    EXPECT_EQ(p->lights[0].position, glm::vec3(2, 2, 2));
    EXPECT_EQ(p->lights[1].diffuse, glm::vec3(0.5f));
    EXPECT_EQ(p->lights[1].specular, glm::vec3(1.0f));
}

TEST(Preset, BuiltinsGetTheirOwnDefaultSubdivisions) {
    Diagnostics d;
    std::optional<Preset> p = parse(R"("model": {"builtin": "plane"})", d);
    ASSERT_TRUE(p) << toString(d);
    EXPECT_EQ(p->model.subdivisions, defaultSubdivisions(Builtin::Plane));
}

// One bad input, the place it must be reported at, and words the message must contain.
struct BadCase {
    const char* body;
    const char* where;
    const char* message;
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.body; }

class PresetErrors : public testing::TestWithParam<BadCase> {};

TEST_P(PresetErrors, AreReportedWithTheirJsonPath) {
    const BadCase& c = GetParam();
    Diagnostics d;
    EXPECT_FALSE(parse(c.body, d)) << c.body;
    ASSERT_FALSE(d.empty()) << c.body;
    bool found = false;
    for (const Diagnostic& x : d) {
        found |= x.file == "red.json" && x.where == c.where && x.message.find(c.message) != std::string::npos;
    }
    EXPECT_TRUE(found) << "expected \"" << c.where << ": ..." << c.message << "...\" for " << c.body << "\ngot:\n"
                       << toString(d);
}

INSTANTIATE_TEST_SUITE_P(
    Validation, PresetErrors,
    testing::Values(
        BadCase{R"("material": {"difuse": [1, 0, 0]})", "material.difuse", "unknown key (did you mean \"diffuse\"?)"},
        BadCase{R"("colour": 1)", "colour", "unknown key"},
        BadCase{R"("lights": [{"positon": [0, 0, 0]}])", "lights[0].positon", "did you mean \"position\""},
        BadCase{R"("material": {"diffuse": "red"})", "material.diffuse", "expected an array of 3 numbers"},
        BadCase{R"("material": {"diffuse": [1, 0]})", "material.diffuse", "expected an array of 3 numbers"},
        BadCase{R"("material": {"diffuse": [1, 0, true]})", "material.diffuse[2]", "expected a number"},
        BadCase{R"("material": {"diffuse": [1.5, 0, 0]})", "material.diffuse[0]", "must be in [0, 1]"},
        BadCase{R"("material": {"ambient": [0, -0.1, 0]})", "material.ambient[1]", "must be in [0, 1]"},
        BadCase{R"("material": {"emissive": [0, 0, 2]})", "material.emissive[2]", "must be in [0, 1]"},
        BadCase{R"("material": {"shininess": 0})", "material.shininess", "in [0.001, 1000000]"},
        BadCase{R"("material": {"shininess": -3})", "material.shininess", "in [0.001, 1000000]"},
        BadCase{R"("material": {"shininess": 1e300})", "material.shininess", "out of range"},
        BadCase{R"("material": 5)", "material", "expected an object"},
        BadCase{R"("lights": [{"diffuse": [-1, 0, 0]}])", "lights[0].diffuse[0]", "in [0, 10000]"},
        BadCase{R"("lights": [{"attenuation": [1, -0.5, 0]}])", "lights[0].attenuation[1]", "in [0, 1000000]"},
        BadCase{R"("lights": [{"attenuation": [0, 0, 0]}])", "lights[0].attenuation", "must not all be 0"},
        BadCase{R"("lights": [{"type": "area"}])", "lights[0].type", "expected one of \"point\", \"directional\", \"spot\""},
        BadCase{R"("lights": [{"cutoff_deg": 120}])", "lights[0].cutoff_deg", "in [0, 90]"},
        BadCase{R"("lights": [{"direction": [0, 0, 0]}])", "lights[0].direction", "at least 0.001 long"},
        BadCase{R"("lights": [{"enabled": 1}])", "lights[0].enabled", "true or false"},
        BadCase{R"("lights": [1])", "lights[0]", "expected an object"},
        BadCase{R"("lights": {})", "lights", "expected an array"},
        BadCase{R"("lights": [{},{},{},{},{},{},{},{},{}])", "lights", "at most 8 lights"},
        BadCase{R"("ambient_light": [0, -1, 0])", "ambient_light[1]", "in [0, 10000]"},
        BadCase{R"("cook_torrance": {"roughness": 0})", "cook_torrance.roughness", "in [0.001, 10]"},
        BadCase{R"("cook_torrance": {"ior": -1})", "cook_torrance.ior", "in [0.01, 100]"},
        BadCase{R"("cook_torrance": {"distribution": "beckman"})", "cook_torrance.distribution", "did you mean \"beckmann\""},
        BadCase{R"("cook_torrance": {"fresnel": "exact"})", "cook_torrance.fresnel", "expected one of"},
        BadCase{R"("brdf": "lambert")", "brdf", "expected one of \"phong\", \"blinn-phong\", \"cook-torrance\""},
        BadCase{R"("shading": "smooth")", "shading", "expected one of \"flat\", \"gouraud\", \"phong\""},
        BadCase{R"("normal_matrix": "inverse")", "normal_matrix", "expected one of"},
        BadCase{R"("terms": {"diffuse": "yes"})", "terms.diffuse", "true or false"},
        BadCase{R"("background": [0, 0, 1.5])", "background[2]", "in [0, 1]"},
        BadCase{R"("plot": {"incident_deg": 95})", "plot.incident_deg", "in [-90, 90]"},
        BadCase{R"("name": 7)", "name", "expected a string"},
        BadCase{R"("camera": {"fovy_deg": 0})", "camera.fovy_deg", "in [0.1, 179]"},
        BadCase{R"("camera": {"near": 5, "far": 1})", "camera.far", "greater than near"},
        BadCase{R"("camera": {"eye": [0, 0, 0]})", "camera.target", "at least 0.001 from eye"},
        BadCase{R"("camera": {"up": [0, 0, 1]})", "camera.up", "parallel"},
        BadCase{R"("model": {"builtin": "teapot"})", "model.builtin", "expected one of \"sphere\", \"cube\", \"plane\", \"torus\""},
        BadCase{R"("model": {"builtin": "sphere", "subdivisions": [2, 32]})", "model.subdivisions[0]", "from 3 to 1024"},
        BadCase{R"("model": {"builtin": "sphere", "subdivisions": [64.5, 32]})", "model.subdivisions[0]", "expected an integer"},
        BadCase{R"("model": {"builtin": "plane", "subdivisions": [100000, 1]})", "model.subdivisions[0]", "from 1 to 1024"},
        BadCase{R"("model": {"scale": [1, 0, 1]})", "model.scale", "at least 0.0001 in magnitude"},
        BadCase{R"("model": {"builtin": "cube", "gltf": "a.glb"})", "model.gltf", "not both"},
        BadCase{R"("model": {"gltf": "a.glb"})", "model.gltf", "needs the preset to be a file"},
        BadCase{R"("model": {"gltf": "a.obj"})", "model.gltf", "expected a .gltf or .glb file"},
        // lab check's own block and the preset's sweep (issue 23)
        BadCase{R"("check": {"pixel_tolerance": -1})", "check.pixel_tolerance", "from 0 to 255, got -1"},
        BadCase{R"("check": {"pixel_tolerance": 2.5})", "check.pixel_tolerance", "expected an integer"},
        BadCase{R"("check": {"max_failing": -0.01})", "check.max_failing", "in [0, 1]"},
        BadCase{R"("check": {"max_mean": 300})", "check.max_mean", "in [0, 255]"},
        BadCase{R"("check": {"plot_tolerance": -1e-5})", "check.plot_tolerance", "in [0, 1000000]"},
        BadCase{R"("check": {"max_men": 1})", "check.max_men", "did you mean \"max_mean\""},
        BadCase{R"("check": 3)", "check", "expected an object"},
        BadCase{R"("sweep": "material.shininess=1,2")", "sweep", "expected an array of 1 or 2 strings"},
        BadCase{R"("sweep": ["a=1", "b=2", "c=3"])", "sweep", "expected an array of 1 or 2 strings"},
        BadCase{R"("sweep": [5])", "sweep[0]", "expected a string KEY=V1,V2,..."},
        BadCase{R"("sweep": ["material.shininess"])", "sweep[0]", "expected KEY=V1,V2,..."},
        BadCase{R"("sweep": ["material.shininess=10,,20"])", "sweep[0]", "value 2 is empty"}));

TEST(Preset, EveryProblemOfAFileIsReported) {
    Diagnostics d;
    EXPECT_FALSE(parse(R"("material": {"difuse": [1, 0, 0], "shininess": -1}, "lights": [{"attenuation": [0, 0, 0]}],
                         "brdf": "lambert")",
                       d));
    EXPECT_EQ(d.size(), 4u) << toString(d);
}

TEST(Preset, FileLevelProblems) {
    struct Case {
        std::string text, where, message;
    };
    const Case cases[] = {
        {"", "line 1, column 1", "invalid JSON"},
        {"{\n  \"format\": \"lighting-lab-preset\",\n  \"version\": 1,,\n}", "line 3, column 16", "invalid JSON"},
        {"[1, 2]", "", "a preset is a JSON object"},
        {R"({"version": 1})", "format", "missing"},
        {R"({"format": "gltf", "version": 1})", "format", "expected \"lighting-lab-preset\""},
        {R"({"format": "lighting-lab-preset"})", "version", "missing"},
        {R"({"format": "lighting-lab-preset", "version": 2})", "version", "newer than this program reads (1)"},
        {R"({"format": "lighting-lab-preset", "version": 0})", "version", "expected 1"},
        {R"({"format": "lighting-lab-preset", "version": "1"})", "version", "expected an integer"},
        {std::string(100, '[') + std::string(100, ']'), "", "nested deeper"},
        {"{\"format\": \"lighting-lab-preset\", \"version\": 1,\n \"material\": {\"shininess\": 1e999}}", "line 2, column 28",
         "number out of range: 1e999"},
        // Issue 49: the message kept only what followed the last ": ", which the excerpt holds too ("N'").
        {"{\"format\": \"lighting-lab-preset\", \"version\": 1,\n \"material\": {\"shininess\": NaN}}", "line 2, column 28",
         "invalid JSON: syntax error while parsing value - invalid literal; last read: '\"shininess\": N'"},
        // nlohmann's parser takes a NUL for the end of its input: what follows was never read.
        {std::string("{\"format\": \"lighting-lab-preset\", \"version\": 1}\n\0{\"brdf\": 7}", 60), "line 2, column 1",
         "a NUL byte, which JSON text never holds"},
        {"{\"format\": \"lighting-lab-preset\", \"version\": 1,\n \"material\": {\"shininess\": Infinity}}",
         "line 2, column 28", "invalid literal; last read: '\"shininess\": I'"},
    };
    for (const Case& c : cases) {
        Diagnostics d;
        EXPECT_FALSE(parsePreset(c.text, "red.json", std::nullopt, d)) << c.text;
        ASSERT_EQ(d.size(), 1u) << c.text << "\n" << toString(d);
        EXPECT_EQ(d[0].where, c.where) << c.text;
        EXPECT_NE(d[0].message.find(c.message), std::string::npos) << d[0].str();
    }
}

TEST(Preset, DiagnosticNamesFileAndPath) {
    Diagnostics d;
    parse(R"("material": {"difuse": [1, 0, 0]})", d);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].str(), "red.json: material.difuse: unknown key (did you mean \"diffuse\"?)");
}

Preset unusualPreset() {
    Preset p;
    p.name = "Round \"trip\" \u00e9";
    p.description = "line one\nline two";
    p.model.builtin = Builtin::Torus;
    p.model.subdivisions = {17, 9};
    p.model.scale = {1.5f, 0.25f, 3.0f};
    p.model.rotateDeg = {10.1f, -20.2f, 30.3f};
    p.model.translate = {0.1f, 0.2f, -0.3f};
    p.camera.eye = {1.0f / 3.0f, 2.0f, 7.0f};
    p.camera.fovyDeg = 33.3f;
    p.camera.near = 0.01f;
    p.camera.far = 1234.5f;
    p.shading = Shading::Gouraud;
    p.normalMatrix = NormalMatrixMode::ModelView;
    p.brdf = BrdfModel::CookTorrance;
    p.cookTorrance = {Distribution::Ggx, 0.123456f, FresnelMode::Full, 2.417f, false};
    p.material.diffuse = {0.1f, 0.7f, 0.3333333f};
    p.material.shininess = 0.5f;
    p.ambientLight = {0.0f, 1e-7f, 3.0f};
    LightDesc spot;
    spot.type = LightType::Spot;
    spot.direction = {0.3f, -1.0f, 0.2f};
    spot.attenuation = {0.0f, 0.0f, 0.0625f};
    spot.cutoffDeg = 12.5f;
    spot.exponent = 0.0f;
    spot.enabled = false;
    LightDesc sun;
    sun.type = LightType::Directional;
    sun.diffuse = {5.0f, 4.0f, 3.0f};
    p.lights = {spot, sun, LightDesc{}};
    p.terms = {false, true, false, true};
    p.background = {1.0f, 0.0f, 0.5f};
    p.plotIncidentDeg = -12.75f;
    p.check.pixelTolerance = 7;
    p.check.maxMean = 0.75f;
    p.sweep = {"material.shininess=10, 20,40", "lights[0].diffuse=[1,0,0],0.5"};
    return p;
}

TEST(Preset, SaveThenLoadGivesTheSamePreset) {
    for (const Preset& original : {Preset{}, unusualPreset()}) {
        std::string text = presetToJson(original);
        Diagnostics d;
        std::optional<Preset> back = parsePreset(text, "saved.json", std::nullopt, d);
        ASSERT_TRUE(back) << toString(d) << text;
        EXPECT_EQ(*back, original) << text;
        EXPECT_EQ(presetToJson(*back), text); // and the bytes are stable
    }
}

TEST(Preset, CheckAndSweepAreWrittenOnlyWhenGiven) {
    // A preset without them is written as before they existed (no version bump needed).
    std::string plain = presetToJson(Preset{});
    EXPECT_EQ(plain.find("\"check\""), std::string::npos);
    EXPECT_EQ(plain.find("\"sweep\""), std::string::npos);
    Preset p;
    p.check.plotTolerance = 1e-4f;
    std::string text = presetToJson(p);
    EXPECT_NE(text.find("\"check\": {\n    \"plot_tolerance\": 0.0001\n  }"), std::string::npos) << text;
    EXPECT_EQ(text.find("pixel_tolerance"), std::string::npos) << text; // only what was given
    Diagnostics d;
    std::optional<Preset> back = parsePreset(text, "saved.json", std::nullopt, d);
    ASSERT_TRUE(back) << toString(d);
    EXPECT_EQ(back->check.plotTolerance, 1e-4f);
    EXPECT_FALSE(back->check.pixelTolerance);
}

TEST(Preset, ASweepThatNoLongerFitsStillSavesAndLoads) {
    // A sweep naming the second light, then the light removed (as the panel does): the preset
    // round-trips as it is; lab check and the sweep window say what is wrong with the sweep.
    Diagnostics d;
    std::optional<Preset> p = parse(R"("lights": [{}, {}], "sweep": ["lights[1].diffuse=0.2,0.5"])", d);
    ASSERT_TRUE(p) << toString(d);
    p->lights.pop_back();
    std::optional<Preset> back = parsePreset(presetToJson(*p), "saved.json", std::nullopt, d);
    ASSERT_TRUE(back) << toString(d);
    EXPECT_EQ(*back, *p);
}

TEST(Preset, SweepValuesAreKeptAsTyped) {
    Diagnostics d;
    std::optional<Preset> p = parse(R"("sweep": ["material.shininess= 10,20 ", "brdf=phong,blinn-phong"])", d);
    ASSERT_TRUE(p) << toString(d);
    EXPECT_EQ(p->sweep, (std::vector<std::string>{"material.shininess= 10,20 ", "brdf=phong,blinn-phong"}));
}

TEST(Preset, SavedFileHasEveryKeyAndShortNumbers) {
    std::string text = presetToJson(Preset{});
    for (const char* key : {"\"format\"", "\"version\"", "\"name\"", "\"description\"", "\"model\"", "\"builtin\"",
                            "\"subdivisions\"", "\"scale\"", "\"rotate_deg\"", "\"translate\"", "\"camera\"",
                            "\"fovy_deg\"", "\"near\"", "\"far\"", "\"shading\"", "\"normal_matrix\"", "\"brdf\"",
                            "\"cook_torrance\"", "\"distribution\"", "\"roughness\"", "\"fresnel\"", "\"ior\"",
                            "\"geometry\"", "\"material\"", "\"emissive\"", "\"shininess\"", "\"ambient_light\"",
                            "\"lights\"", "\"attenuation\"", "\"cutoff_deg\"", "\"exponent\"", "\"enabled\"",
                            "\"terms\"", "\"background\"", "\"plot\"", "\"incident_deg\""}) {
        EXPECT_NE(text.find(key), std::string::npos) << key;
    }
    EXPECT_NE(text.find("\"diffuse\": [0.8, 0.8, 0.8]"), std::string::npos) << text;
    EXPECT_EQ(text.find("0.800000"), std::string::npos) << text;
}

TEST(Preset, NonFiniteValuesAreNeverWritten) {
    TempFolder dir;
    fs::path file = dir.path() / "p.json";
    Preset p;
    p.material.shininess = std::numeric_limits<float>::quiet_NaN();
    Diagnostics d;
    EXPECT_FALSE(savePreset(p, file, d));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("non-finite"), std::string::npos);
    EXPECT_FALSE(fs::exists(file));
}

TEST(Preset, SaveIsAtomicAndKeepsTheOldFileOnFailure) {
    TempFolder dir;
    fs::path file = dir.path() / "p.json";
    Diagnostics d;
    ASSERT_TRUE(savePreset(Preset{}, file, d)) << toString(d);
    std::string before = readText(file);
    if (::geteuid() == 0) {
        GTEST_SKIP() << "root ignores folder permissions; the write-failure half needs an ordinary user";
    }
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
    Preset changed;
    changed.name = "changed";
    EXPECT_FALSE(savePreset(changed, file, d));
    fs::permissions(dir.path(), fs::perms::owner_all);
    EXPECT_EQ(readText(file), before);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1); // no temporary left
}

TEST(Preset, FailedWriteKeepsTheOldFileEvenForRoot) {
    // A file-size limit makes the write fail with EFBIG for any user, root included: the disk
    // "fills up" halfway through the temporary file.
    TempFolder dir;
    fs::path file = dir.path() / "p.json";
    Diagnostics d;
    ASSERT_TRUE(savePreset(Preset{}, file, d)) << toString(d);
    std::string before = readText(file);
    Preset bigger;
    bigger.description = std::string(4 * before.size(), 'x');
    struct rlimit old {};
    ::getrlimit(RLIMIT_FSIZE, &old);
    struct rlimit small = old;
    small.rlim_cur = before.size() + 100;
    auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    ::setrlimit(RLIMIT_FSIZE, &small);
    bool saved = savePreset(bigger, file, d);
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);
    EXPECT_FALSE(saved);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].str().find("p.json"), std::string::npos) << d[0].str();
    EXPECT_EQ(readText(file), before);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1); // no temporary left
}

TEST(Preset, SaveToAMissingFolderFailsCleanly) {
    TempFolder dir;
    Diagnostics d;
    EXPECT_FALSE(savePreset(Preset{}, dir.path() / "no" / "such" / "p.json", d));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].str().find("p.json"), std::string::npos);
}

TEST(Preset, LoadReportsMissingFilesAndFolders) {
    TempFolder dir;
    Diagnostics d;
    EXPECT_FALSE(loadPreset(dir.path() / "missing.json", d));
    EXPECT_FALSE(loadPreset(dir.path(), d));
    ASSERT_EQ(d.size(), 2u);
    EXPECT_NE(d[0].message.find("no such file"), std::string::npos);
    EXPECT_NE(d[1].message.find("folder"), std::string::npos);
}

TEST(Preset, OversizedFileIsRefusedBeforeReading) {
    TempFolder dir;
    fs::path file = dir.path() / "big.json";
    writeText(file, std::string(kMaxPresetBytes + 1, ' '));
    Diagnostics d;
    EXPECT_FALSE(loadPreset(file, d));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("more than the limit"), std::string::npos);
}

// Issue 49: `lab fit` of a preset just under the limit wrote a fit over it (every key written, and
// " (Phong fit)" in the name), which `lab plot --compare` then refused. No preset is saved that no
// reader would open; the old file stays.
TEST(Preset, APresetOverTheLimitIsNotSaved) {
    TempFolder dir;
    const fs::path file = dir.path() / "fit.json";
    writeText(file, "old");
    Preset p;
    p.description = std::string(kMaxPresetBytes, 'x');
    Diagnostics d;
    EXPECT_FALSE(savePreset(p, file, d));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("more than the 1048576 a preset may have"), std::string::npos) << d[0].str();
    EXPECT_NE(d[0].message.find("shorten its description"), std::string::npos) << d[0].str();
    EXPECT_EQ(readText(file), "old");
    p.description = std::string(kMaxPresetBytes - 4096, 'x'); // under the limit with every key: saved, and it loads
    d.clear();
    ASSERT_TRUE(savePreset(p, file, d)) << toString(d);
    EXPECT_TRUE(loadPreset(file, d).has_value()) << toString(d);
}

TEST(Preset, GltfModelPathsStayInsideThePresetFolder) {
    TempFolder dir;
    fs::create_directories(dir.path() / "presets" / "models");
    writeText(dir.path() / "presets" / "models" / "m.glb", "x");
    writeText(dir.path() / "outside.glb", "x");
    fs::create_directories(dir.path() / "presets" / "folder.glb");
    fs::create_symlink(dir.path() / "outside.glb", dir.path() / "presets" / "link.glb");
    struct Case {
        std::string path;
        bool ok;
        std::string message;
    };
    const Case cases[] = {
        {"models/m.glb", true, ""},
        {"./models/../models/m.glb", true, ""},
        {"../outside.glb", false, "leaves the preset's folder"},
        {(dir.path() / "outside.glb").string(), false, "absolute path"},
        {"link.glb", false, "leaves the preset's folder"},
        {"models/none.glb", false, "not found"},
        {"folder.glb", false, "not a regular file"},
    };
    for (const Case& c : cases) {
        fs::path preset = dir.path() / "presets" / "p.json";
        writeText(preset, "{" + kHead + R"(, "model": {"gltf": ")" + c.path + "\"}}");
        Diagnostics d;
        std::optional<LoadedPreset> p = loadPreset(preset, d);
        EXPECT_EQ(p.has_value(), c.ok) << c.path << "\n" << toString(d);
        if (!c.ok) {
            ASSERT_EQ(d.size(), 1u) << toString(d);
            EXPECT_EQ(d[0].where, "model.gltf");
            EXPECT_NE(d[0].message.find(c.message), std::string::npos) << c.path << ": " << d[0].str();
        }
    }
}

TEST(Preset, EveryShippedPresetLoads) {
    int count = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(fs::path(LAB_SOURCE_DIR) / "presets")) {
        if (e.path().extension() != ".json") {
            continue;
        }
        ++count;
        Diagnostics d;
        std::optional<LoadedPreset> p = loadPreset(e.path(), d);
        EXPECT_TRUE(p) << toString(d);
        if (p) {
            EXPECT_NE(p->preset.name, "Untitled") << e.path() << " should have a name";
            EXPECT_FALSE(p->preset.description.empty()) << e.path() << " should say what it shows";
        }
    }
    EXPECT_GE(count, 15);
}

} // namespace
} // namespace lab
