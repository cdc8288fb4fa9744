// exercise_test.cpp — exercises round-trip through their file, every problem of a file is refused with
// its JSON path, preset fields by path (changes, open paths, patches), locked fields, what is rendered to
// score an attempt (the score itself: exercise_score_test.cpp).
#include "core/exercise/exercise.h"
#include "core/exercise/preset_fields.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <functional>

namespace lab {
namespace {

namespace fs = std::filesystem;

// A small valid exercise: the shininess from 10 to 60, only the shininess open.
const char* const kValid = R"({
  "format": "lighting-lab-exercise", "version": 1,
  "title": "Find the shininess",
  "instructions": "Make the highlight match the target's.",
  "start": {"material": {"shininess": 10}},
  "target": {"material": {"shininess": 60}},
  "open": ["material.shininess"]
})";

PresetJson validJson() { return PresetJson::parse(kValid); }

// kValid changed by `change`, as text.
std::string with(const std::function<void(PresetJson&)>& change) {
    PresetJson j = validJson();
    change(j);
    return j.dump();
}

std::optional<Exercise> parse(const std::string& text, Diagnostics& d) {
    return parseExercise(text, "ex.json", std::nullopt, d);
}

// Key order does not matter to a preset: compare JSON values as unordered objects.
nlohmann::json unordered(const PresetJson& j) { return nlohmann::json::parse(j.dump()); }

// Every field set: two lights, a tolerance with every key and two field tolerances, hints.
Exercise fullExercise() {
    Exercise e;
    e.title = "Two lights, one highlight";
    e.instructions = "Match the highlight and the second light's fall-off.";
    e.start.name = "Start";
    e.start.description = "Where the student begins.";
    e.start.material.shininess = 10.0f;
    e.start.material.diffuse = {0.7f, 0.2f, 0.1f};
    e.start.background = {0.1f, 0.1f, 0.12f};
    e.start.lights.push_back(LightDesc{});
    e.start.lights[1].type = LightType::Spot;
    e.start.lights[1].position = {-2.0f, 1.0f, 3.0f};
    e.target = e.start;
    e.target.material.shininess = 60.0f;
    e.target.lights[1].attenuation = {1.0f, 0.25f, 0.05f};
    e.open = {"material.shininess", "lights[1].attenuation"};
    e.tolerance.pixelTolerance = 4;
    e.tolerance.maxFailing = 0.01f;
    e.tolerance.maxMean = 0.75f;
    e.tolerance.fields = {{"material.shininess", 5.0f}, {"lights[1].attenuation", 0.05f}};
    e.hints = {"n is the exponent of the highlight.", "c1 makes light fall off with distance."};
    return e;
}

//----------------------------------------------------------------------------------------
// The file: writing and reading back
//----------------------------------------------------------------------------------------

TEST(Exercise, AValidFileIsReadWithItsFieldsAndTheTargetMergedOverStart) {
    Diagnostics d;
    std::optional<Exercise> e = parse(kValid, d);
    ASSERT_TRUE(e) << toString(d);
    EXPECT_TRUE(d.empty());
    EXPECT_EQ(e->title, "Find the shininess");
    EXPECT_EQ(e->instructions, "Make the highlight match the target's.");
    EXPECT_EQ(e->start.material.shininess, 10.0f);
    EXPECT_EQ(e->target.material.shininess, 60.0f);
    Preset expected = e->start;
    expected.material.shininess = 60.0f;
    EXPECT_EQ(e->target, expected); // everything else is start's
    EXPECT_EQ(e->open, std::vector<std::string>{"material.shininess"});
    EXPECT_TRUE(e->tolerance.empty());
    EXPECT_TRUE(e->hints.empty());
    EXPECT_TRUE(isExerciseText(kValid));
}

TEST(Exercise, AnExerciseWithEveryFieldRoundTripsThroughItsJson) {
    const Exercise e = fullExercise();
    const std::string text = exerciseToJson(e);
    Diagnostics d;
    std::optional<Exercise> back = parse(text, d);
    ASSERT_TRUE(back) << toString(d) << text;
    EXPECT_EQ(*back, e);
    EXPECT_EQ(back->tolerance.fields, e.tolerance.fields); // in their order
    EXPECT_EQ(exerciseToJson(*back), text);                // and written the same again
}

// Found by fuzz_exercise: saving laid arrays of numbers on one line by a scan that did not skip
// strings, so "[a, b]" in the instructions lost its spaces.
TEST(Exercise, BracketsInTheTextsAreSavedAsTheyAre) {
    Exercise e = fullExercise();
    e.instructions = "Set the colour to [0.5, 0.5, 0.5] or to [ 1 , 0 ,0 ], then try [roughness -- ] and \"[a, b]\".";
    e.title = "[x, y]";
    e.hints = {"[1, 2, 3]", "a ] then a ["};
    Diagnostics d;
    std::optional<Exercise> back = parseExercise(exerciseToJson(e), "ex.json", std::nullopt, d);
    ASSERT_TRUE(back) << toString(d);
    EXPECT_EQ(back->instructions, e.instructions);
    EXPECT_EQ(back->title, e.title);
    EXPECT_EQ(back->hints, e.hints);
    EXPECT_NE(exerciseToJson(e).find("\"diffuse\": [0.7, 0.2, 0.1]"), std::string::npos) << "colours still on one line";
}

TEST(Exercise, TheWrittenTargetIsOnlyWhatDiffersFromStart) {
    const Exercise e = fullExercise();
    PresetJson j = PresetJson::parse(exerciseToJson(e));
    EXPECT_EQ(j["format"], "lighting-lab-exercise");
    EXPECT_EQ(j["version"], 1);
    // start has every key, target only the shininess and the second light's attenuation.
    EXPECT_TRUE(j["start"].contains("camera"));
    EXPECT_TRUE(j["start"].contains("background"));
    EXPECT_EQ(unordered(j["target"]),
              nlohmann::json::parse(R"({"material": {"shininess": 60}, "lights": [{}, {"attenuation": [1, 0.25, 0.05]}]})"))
        << j["target"].dump();
    for (const char* key : {"camera", "background", "name", "description", "model", "format"}) {
        EXPECT_FALSE(j["target"].contains(key)) << key;
    }
    // The tolerance: every key given, the field tolerances by path (numbers are floats: compared as such).
    EXPECT_EQ(j["tolerance"].size(), 4u);
    EXPECT_EQ(j["tolerance"]["fields"].size(), 2u);
    EXPECT_EQ(j["tolerance"]["pixel_tolerance"], 4);
    EXPECT_FLOAT_EQ(j["tolerance"]["max_failing"].get<float>(), 0.01f);
    EXPECT_FLOAT_EQ(j["tolerance"]["max_mean"].get<float>(), 0.75f);
    EXPECT_FLOAT_EQ(j["tolerance"]["fields"]["lights[1].attenuation"].get<float>(), 0.05f);
    EXPECT_FLOAT_EQ(j["tolerance"]["fields"]["material.shininess"].get<float>(), 5.0f);
    EXPECT_EQ(j["hints"], PresetJson(e.hints));
}

TEST(Exercise, AnExerciseWithoutToleranceOrHintsWritesNeither) {
    Diagnostics d;
    std::optional<Exercise> e = parse(kValid, d);
    ASSERT_TRUE(e) << toString(d);
    PresetJson j = PresetJson::parse(exerciseToJson(*e));
    EXPECT_FALSE(j.contains("tolerance"));
    EXPECT_FALSE(j.contains("hints"));
    EXPECT_EQ(unordered(j["target"]), nlohmann::json::parse(R"({"material": {"shininess": 60}})"));
    std::optional<Exercise> back = parse(j.dump(), d);
    ASSERT_TRUE(back) << toString(d);
    EXPECT_EQ(*back, *e);
}

TEST(Exercise, SaveThenLoadGivesTheSameExercise) {
    TempFolder dir;
    const fs::path file = dir.path() / "two-lights.json";
    const Exercise e = fullExercise();
    Diagnostics d;
    ASSERT_TRUE(saveExercise(e, file, d)) << toString(d);
    EXPECT_EQ(readText(file), exerciseToJson(e));
    std::optional<LoadedExercise> loaded = loadExercise(file, d);
    ASSERT_TRUE(loaded) << toString(d);
    EXPECT_EQ(loaded->exercise, e);
    EXPECT_EQ(loaded->file, file);
    EXPECT_EQ(loaded->folder(), dir.path());
    EXPECT_TRUE(d.empty()) << toString(d);
    // A missing file and a missing folder are refused with a diagnostic, not a crash.
    EXPECT_FALSE(loadExercise(dir.path() / "none.json", d));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].file, (dir.path() / "none.json").string());
    d.clear();
    EXPECT_FALSE(saveExercise(e, dir.path() / "no-folder" / "e.json", d));
    EXPECT_EQ(d.size(), 1u);
}

TEST(Exercise, AGltfStartResolvesRelativeToTheExerciseFile) {
    TempFolder dir;
    fs::create_directories(dir.path() / "models");
    fs::copy_file(fs::path(LAB_SOURCE_DIR) / "presets" / "models" / "trefoil.glb", dir.path() / "models" / "trefoil.glb");
    const std::string text = with([](PresetJson& j) { j["start"]["model"] = {{"gltf", "models/trefoil.glb"}}; });
    writeText(dir.path() / "trefoil.json", text);
    Diagnostics d;
    std::optional<LoadedExercise> loaded = loadExercise(dir.path() / "trefoil.json", d);
    ASSERT_TRUE(loaded) << toString(d);
    EXPECT_EQ(loaded->exercise.start.model.gltf, "models/trefoil.glb");
    EXPECT_EQ(loaded->exercise.target.model.gltf, "models/trefoil.glb");
    // Saved next to the model, it loads again as it was.
    ASSERT_TRUE(saveExercise(loaded->exercise, dir.path() / "again.json", d)) << toString(d);
    std::optional<LoadedExercise> again = loadExercise(dir.path() / "again.json", d);
    ASSERT_TRUE(again) << toString(d);
    EXPECT_EQ(again->exercise, loaded->exercise);

    // The same file in a folder without the model: refused at the model's path.
    TempFolder other;
    writeText(other.path() / "trefoil.json", text);
    d.clear();
    EXPECT_FALSE(loadExercise(other.path() / "trefoil.json", d));
    ASSERT_EQ(d.size(), 1u) << toString(d);
    EXPECT_EQ(d[0].where, "start.model.gltf");
    // From memory, with no folder to resolve it against: refused too.
    d.clear();
    EXPECT_FALSE(parse(text, d));
    ASSERT_EQ(d.size(), 1u) << toString(d);
    EXPECT_EQ(d[0].where, "start.model.gltf");
}

TEST(Exercise, ATargetGivenAsAWholePresetReplacesStart) {
    // start's name and camera are always free, so a whole target may leave them at the defaults.
    const std::string text = with([](PresetJson& j) {
        j["start"]["name"] = "Start";
        j["start"]["camera"] = {{"eye", {1, 2, 5}}};
        j["target"] = {{"format", "lighting-lab-preset"}, {"version", 1}, {"material", {{"shininess", 60}}}};
    });
    Diagnostics d;
    std::optional<Exercise> e = parse(text, d);
    ASSERT_TRUE(e) << toString(d);
    EXPECT_EQ(e->start.name, "Start");
    EXPECT_EQ(e->start.camera.eye, glm::vec3(1, 2, 5));
    Preset expected;
    expected.material.shininess = 60.0f;
    EXPECT_EQ(e->target, expected); // nothing of start's: its name and camera are the defaults
}

TEST(Exercise, ATargetPatchWithLightsMergesLightByLight) {
    const std::string text = with([](PresetJson& j) {
        j["start"]["lights"] = PresetJson::parse(R"([{"position": [1, 2, 3]}, {"position": [-1, 0, 2]}])");
        j["target"] = PresetJson::parse(R"({"lights": [{"attenuation": [1, 0.5, 0]}]})");
        j["open"] = PresetJson::array({"lights[0].attenuation"});
    });
    Diagnostics d;
    std::optional<Exercise> e = parse(text, d);
    ASSERT_TRUE(e) << toString(d);
    ASSERT_EQ(e->target.lights.size(), 2u);
    EXPECT_EQ(e->target.lights[0].attenuation, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_EQ(e->target.lights[0].position, glm::vec3(1, 2, 3)); // start's
    EXPECT_EQ(e->target.lights[1], e->start.lights[1]);         // untouched
}

//----------------------------------------------------------------------------------------
// The file: every problem, one line with its JSON path
//----------------------------------------------------------------------------------------

struct BadFile {
    std::string name;
    std::string text;
    std::string where;
    std::string message; // a part of it
};

std::string nested(int depth) {
    return R"({"format": "lighting-lab-exercise", "version": 1, "title": )" + std::string(depth, '[') +
           std::string(depth, ']') + "}";
}

std::vector<BadFile> badFiles() {
    auto set = [](const char* key, PresetJson value) {
        return with([&](PresetJson& j) { j[key] = value; });
    };
    auto drop = [](const char* key) { return with([&](PresetJson& j) { j.erase(key); }); };
    auto tolerance = [](const char* json) {
        return with([&](PresetJson& j) { j["tolerance"] = PresetJson::parse(json); });
    };
    std::vector<std::string> seventeen(17, "a hint");
    return {
        {"NotJson", "{\n  \"format\": oops\n}", "line 2, column", "invalid JSON"},
        {"NaNLiteral", "{\n  \"version\": NaN\n}", "line 2, column 14",
         "invalid JSON: syntax error while parsing value - invalid literal; last read: '\"version\": N'"},
        {"NotAnObject", "[1, 2]", "", "an exercise is a JSON object, got an array"},
        {"FormatMissing", drop("format"), "format", "missing; expected \"lighting-lab-exercise\""},
        {"FormatWrong", set("format", "lighting-lab-scene"), "format", "expected \"lighting-lab-exercise\", got \"lighting-lab-scene\""},
        {"VersionNewer", set("version", 2), "version", "newer than this program reads"},
        {"VersionMissing", drop("version"), "version", "missing"},
        {"TitleMissing", drop("title"), "title", "missing; expected a string"},
        {"TitleEmpty", set("title", ""), "title", "is empty"},
        {"InstructionsNotAString", set("instructions", 5), "instructions", "expected a string, got a number"},
        {"StartMissing", drop("start"), "start", "missing; expected a preset object"},
        {"StartNotAnObject", set("start", "05-full-phong"), "start", "expected a preset object, got a string"},
        {"StartInvalidInside", with([](PresetJson& j) { j["start"]["material"]["shininess"] = -1; }),
         "start.material.shininess", "-1"},
        {"TargetMissing", drop("target"), "target", "missing"},
        {"TargetNotAnObject", set("target", PresetJson::array()), "target", "got an array"},
        {"TargetInvalidInside", with([](PresetJson& j) { j["target"]["material"]["shininess"] = -1; }),
         "target.material.shininess", "-1"},
        {"OpenMissing", drop("open"), "open", "missing; expected the JSON paths"},
        {"OpenEmpty", set("open", PresetJson::array()), "open", "non-empty array of field paths, got []"},
        {"OpenNotAnArray", set("open", "material.shininess"), "open", "got a string"},
        {"OpenNotStrings", set("open", PresetJson::array({7})), "open[0]", "expected a field path, got a number"},
        {"OpenUnknownPath", set("open", PresetJson::array({"material.shinines"})), "open[0]",
         "no field \"material.shinines\" in a preset (did you mean \"material.shininess\"?)"},
        {"OpenListedTwice", set("open", PresetJson::array({"material.shininess", "material.shininess"})), "open[1]",
         "\"material.shininess\" is listed twice"},
        {"TargetDiffersInALockedField",
         with([](PresetJson& j) { j["target"]["material"]["diffuse"] = {1, 0, 0}; }), "target.material.diffuse",
         "differs from start, but the field is not open"},
        {"TargetEqualsStartInEveryOpenField",
         set("target", PresetJson::parse(R"({"camera": {"eye": [0, 1, 5]}, "name": "Target"})")), "target",
         "equals start in every open field"},
        {"ToleranceNotAnObject", set("tolerance", 6), "tolerance", "expected an object"},
        {"ToleranceUnknownKey", tolerance(R"({"pixel_tolerence": 6})"), "tolerance.pixel_tolerence",
         "unknown key (did you mean \"pixel_tolerance\"?)"},
        {"PixelToleranceTooLarge", tolerance(R"({"pixel_tolerance": 300})"), "tolerance.pixel_tolerance",
         "expected 0 to 255 levels, got 300"},
        {"PixelToleranceNotWhole", tolerance(R"({"pixel_tolerance": 2.5})"), "tolerance.pixel_tolerance",
         "expected a whole number of levels, got 2.5"},
        {"PixelToleranceNotANumber", tolerance(R"({"pixel_tolerance": "6"})"), "tolerance.pixel_tolerance",
         "expected a number"},
        {"MaxFailingOverOne", tolerance(R"({"max_failing": 2})"), "tolerance.max_failing",
         "expected a share from 0 to 1"},
        {"MaxMeanNegative", tolerance(R"({"max_mean": -1})"), "tolerance.max_mean", "expected 0 to 255 levels, got -1"},
        {"FieldToleranceOnALockedField", tolerance(R"({"fields": {"material.diffuse": 0.1}})"),
         "tolerance.fields.material.diffuse", "is not an open field"},
        {"FieldToleranceOnTheCamera", tolerance(R"({"fields": {"camera.eye": 0.1}})"), "tolerance.fields.camera.eye",
         "is not an open field"},
        {"FieldToleranceOnAnUnknownField", tolerance(R"({"fields": {"material.shinyness": 1}})"),
         "tolerance.fields.material.shinyness", "no such field"},
        {"FieldToleranceOnANonNumericField",
         with([](PresetJson& j) {
             j["open"] = PresetJson::array({"material.shininess", "brdf"});
             j["tolerance"] = PresetJson::parse(R"({"fields": {"brdf": 1}})");
         }),
         "tolerance.fields.brdf", "needs a number or numbers; this field is a string"},
        // One field spelt two ways (leading zeros are allowed in a path): listed twice.
        {"FieldToleranceTwiceSpeltTwoWays",
         with([](PresetJson& j) {
             j["open"] = PresetJson::array({"material.shininess", "lights[0]"});
             j["tolerance"] = PresetJson::parse(R"({"fields": {"lights[0].diffuse": 0.1, "lights[00].diffuse": 0.2}})");
         }),
         "tolerance.fields.lights[00].diffuse", "is listed twice (\"lights[0].diffuse\")"},
        {"FieldToleranceNegative", tolerance(R"({"fields": {"material.shininess": -1}})"),
         "tolerance.fields.material.shininess", "must be in [0, 1000000], got -1"},
        // Finite as a double, infinite as the float the lab keeps (and then written as "inf" into
        // links: `lab share` aborted on it).
        {"FieldToleranceBeyondFloat", tolerance(R"({"fields": {"material.shininess": 1e308}})"),
         "tolerance.fields.material.shininess", "must be in [0, 1000000], got 1e+308"},
        {"FieldToleranceJustBeyondFloat", tolerance(R"({"fields": {"material.shininess": 3.5e38}})"),
         "tolerance.fields.material.shininess", "must be in [0, 1000000], got 3.5e+38"},
        {"FieldToleranceNotANumber", tolerance(R"({"fields": {"material.shininess": "8"}})"),
         "tolerance.fields.material.shininess", "expected a number >= 0, got \"8\""},
        {"FieldsNotAnObject", tolerance(R"({"fields": ["material.shininess"]})"), "tolerance.fields",
         "expected an object of field paths and numbers"},
        {"HintsNotAnArray", set("hints", "A larger n."), "hints", "expected an array of strings, got a string"},
        {"HintEmpty", set("hints", PresetJson::array({"A larger n.", ""})), "hints[1]", "expected a non-empty string"},
        {"HintNotAString", set("hints", PresetJson::array({3})), "hints[0]", "got a number"},
        {"TooManyHints", set("hints", seventeen), "hints", "at most 16 hints, got 17"},
        {"UnknownTopLevelKey", set("hints_", PresetJson::array({"x"})), "hints_", "unknown key (did you mean \"hints\"?)"},
        {"NestedTooDeep", nested(100), "", "JSON nested deeper than 32 levels"},
    };
}

TEST(Exercise, EveryProblemOfAFileIsRefusedWithItsPath) {
    for (const BadFile& c : badFiles()) {
        SCOPED_TRACE(c.name);
        Diagnostics d;
        EXPECT_FALSE(parse(c.text, d)) << c.text;
        ASSERT_EQ(d.size(), 1u) << toString(d) << c.text;
        EXPECT_EQ(d[0].file, "ex.json");
        if (c.name == "NotJson") {
            EXPECT_EQ(d[0].where.rfind(c.where, 0), 0u) << d[0].str();
        } else {
            EXPECT_EQ(d[0].where, c.where) << d[0].str();
        }
        EXPECT_NE(d[0].message.find(c.message), std::string::npos) << d[0].str();
        EXPECT_EQ(d[0].str().find('\n'), std::string::npos) << d[0].str(); // one line
    }
}

TEST(Exercise, ATargetThatDiffersInALockedFieldIsRefusedWithItsPath) {
    Diagnostics d;
    EXPECT_FALSE(parse(with([](PresetJson& j) {
                           j["target"]["material"]["diffuse"] = {1, 0, 0};
                           j["target"]["background"] = {0, 0, 0};
                       }),
                       d));
    // Each locked field that differs, in the preset's order.
    ASSERT_EQ(d.size(), 2u) << toString(d);
    EXPECT_EQ(d[0].where, "target.material.diffuse");
    EXPECT_EQ(d[1].where, "target.background");
    // Opened, the same target is fine.
    d.clear();
    std::optional<Exercise> e = parse(with([](PresetJson& j) {
                                          j["target"]["material"]["diffuse"] = {1, 0, 0};
                                          j["target"]["background"] = {0, 0, 0};
                                          j["open"] = PresetJson::array({"material", "background"});
                                      }),
                                      d);
    ASSERT_TRUE(e) << toString(d);
    EXPECT_EQ(e->target.material.diffuse, glm::vec3(1, 0, 0));
}

TEST(Exercise, APresetFileIsNotAnExercise) {
    const std::string text = readText(fs::path(LAB_SOURCE_DIR) / "presets" / "05-full-phong.json");
    ASSERT_FALSE(text.empty());
    Diagnostics d;
    EXPECT_FALSE(parse(text, d));
    ASSERT_EQ(d.size(), 1u) << toString(d);
    EXPECT_EQ(d[0].where, "format");
    EXPECT_NE(d[0].message.find("(this is a preset, not an exercise)"), std::string::npos) << d[0].str();
    EXPECT_FALSE(isExerciseText(text));
    EXPECT_FALSE(isExerciseText("{\"format\": \"lighting-lab-exercise\""));
    EXPECT_FALSE(isExerciseText(nested(100)));
    EXPECT_FALSE(isExerciseText("[\"lighting-lab-exercise\"]"));
}

TEST(Exercise, EveryProblemOfAFileIsReportedAtOnce) {
    Diagnostics d;
    EXPECT_FALSE(parse(with([](PresetJson& j) {
                           j["title"] = "";
                           j["hints"] = "x";
                           j["tolerance"] = {{"max_mean", -1}};
                       }),
                       d));
    ASSERT_EQ(d.size(), 3u) << toString(d);
    EXPECT_EQ(d[0].where, "title");
    EXPECT_EQ(d[1].where, "tolerance.max_mean");
    EXPECT_EQ(d[2].where, "hints");
}

TEST(Exercise, TheImageToleranceIsTheGivenValuesOverTheDefaults) {
    ExerciseTolerance t;
    EXPECT_EQ(t.image().pixelTolerance, kExerciseTolerance.pixelTolerance);
    EXPECT_EQ(t.image().maxFailingShare, kExerciseTolerance.maxFailingShare);
    EXPECT_EQ(t.image().maxMeanDifference, kExerciseTolerance.maxMeanDifference);
    t.maxMean = 2.0f;
    EXPECT_EQ(t.image().maxMeanDifference, 2.0);
    EXPECT_EQ(t.image().pixelTolerance, kExerciseTolerance.pixelTolerance);
    t.pixelTolerance = 0;
    t.maxFailing = 0.0f;
    EXPECT_EQ(t.image().pixelTolerance, 0);
    EXPECT_EQ(t.image().maxFailingShare, 0.0);
}

//----------------------------------------------------------------------------------------
// Preset fields by JSON path
//----------------------------------------------------------------------------------------

TEST(PresetFields, ChangedFieldsNameEachLeafThatDiffers) {
    const Preset a;
    EXPECT_TRUE(changedFields(presetValue(a), presetValue(a)).empty());
    Preset b = a;
    b.material.diffuse = {0.8f, 0.1f, 0.1f};
    EXPECT_EQ(changedFields(presetValue(a), presetValue(b)), std::vector<std::string>{"material.diffuse"});
    b = a;
    b.lights.push_back(LightDesc{});
    EXPECT_EQ(changedFields(presetValue(a), presetValue(b)), std::vector<std::string>{"lights[1]"});
    EXPECT_EQ(changedFields(presetValue(b), presetValue(a)), std::vector<std::string>{"lights[1]"});
    b = a;
    b.lights[0].position = {0.0f, 3.0f, 0.0f};
    EXPECT_EQ(changedFields(presetValue(a), presetValue(b)), std::vector<std::string>{"lights[0].position"});
    // Several, in the order of the preset's keys; a light's orbit is one key only one of them has.
    b.camera.eye = {0.0f, 0.0f, 6.0f};
    b.background = {0.0f, 0.0f, 0.0f};
    b.lights[0].orbit.on = true;
    EXPECT_EQ(changedFields(presetValue(a), presetValue(b)),
              (std::vector<std::string>{"camera.eye", "lights[0].position", "lights[0].orbit", "background"}));
    // A glTF model against a built-in: the keys only one of them has.
    b = a;
    b.model.gltf = "m.glb";
    EXPECT_EQ(changedFields(presetValue(a), presetValue(b)),
              (std::vector<std::string>{"model.builtin", "model.subdivisions", "model.gltf"}));
}

TEST(PresetFields, CoversIsAPrefixThatEndsAtAFieldBoundary) {
    EXPECT_TRUE(covers("material", "material"));
    EXPECT_TRUE(covers("material", "material.diffuse"));
    EXPECT_TRUE(covers("material.diffuse", "material.diffuse"));
    EXPECT_FALSE(covers("material.diffuse", "material.diffuse_x"));
    EXPECT_FALSE(covers("material.diffuse", "material"));
    EXPECT_FALSE(covers("material", "materials"));
    EXPECT_TRUE(covers("lights", "lights[2].position"));
    EXPECT_TRUE(covers("lights[0]", "lights[0].attenuation"));
    EXPECT_FALSE(covers("lights[0]", "lights[01]"));
    EXPECT_FALSE(covers("lights[1]", "lights[10]"));
    EXPECT_FALSE(covers("lights[0].attenuation", "lights[0].position"));
}

TEST(PresetFields, LookingNamingAndDescribingAreAlwaysFree) {
    for (const char* free : {"camera", "camera.eye", "camera.fovy_deg", "name", "description", "plot.incident_deg",
                             "check", "check.pixel_tolerance", "sweep"}) {
        EXPECT_TRUE(alwaysFree(free)) << free;
    }
    for (const char* locked : {"material", "material.diffuse", "lights[0].position", "background", "model.gltf",
                               "cameras", "named", "brdf"}) {
        EXPECT_FALSE(alwaysFree(locked)) << locked;
    }
}

TEST(PresetFields, KnownFieldPathsAreThoseAPresetCanHave) {
    const std::string lastLight = "lights[" + std::to_string(kMaxLights - 1) + "]";
    const std::string pastTheLast = "lights[" + std::to_string(kMaxLights) + "]";
    for (const std::string& known :
         {std::string("material"), std::string("material.shininess"), std::string("lights"), std::string("lights[0]"),
          std::string("lights[3].cutoff_deg"), lastLight + ".attenuation", std::string("lights[5].orbit.axis"),
          std::string("model.gltf"), std::string("model.builtin"), std::string("camera.eye"),
          std::string("cook_torrance.roughness"), std::string("terms.specular"), std::string("plot.incident_deg")}) {
        EXPECT_TRUE(knownFieldPath(known, {})) << known;
    }
    for (const std::string& unknown :
         {pastTheLast, std::string("lights[99]"), std::string("lights[0].colour"), std::string("material."),
          std::string("material..x"), std::string("[0]"), std::string(".material"), std::string("material[0]"),
          std::string("lights[]"), std::string("lights[x]"), std::string("lights[0]x"), std::string(""),
          std::string("materials"), std::string("check.pixel_tolerance")}) {
        EXPECT_FALSE(knownFieldPath(unknown, {})) << unknown;
    }
    // An example's own keys are known too (a check block is not among the defaults).
    Preset withCheck;
    withCheck.check.pixelTolerance = 4;
    const PresetJson example = presetValue(withCheck);
    EXPECT_TRUE(knownFieldPath("check.pixel_tolerance", {&example}));
    EXPECT_FALSE(knownFieldPath("check.max_mean", {&example}));
}

TEST(PresetFields, FieldAtFindsTheValueAtAPath) {
    Preset p;
    p.material.shininess = 70.0f;
    p.lights.push_back(LightDesc{});
    p.lights[1].position = {-1.0f, 0.5f, 2.0f};
    const PresetJson v = presetValue(p);
    ASSERT_TRUE(fieldAt(v, "material.shininess"));
    EXPECT_EQ(*fieldAt(v, "material.shininess"), 70);
    ASSERT_TRUE(fieldAt(v, "lights[1].position"));
    EXPECT_EQ(*fieldAt(v, "lights[1].position"), PresetJson::parse("[-1, 0.5, 2]"));
    ASSERT_TRUE(fieldAt(v, "lights[1]"));
    EXPECT_TRUE(fieldAt(v, "lights[1]")->is_object());
    ASSERT_TRUE(fieldAt(v, "material"));
    EXPECT_EQ(fieldAt(v, "material"), &v["material"]); // into the value, not a copy
    EXPECT_EQ(fieldAt(v, "lights[2]"), nullptr);
    EXPECT_EQ(fieldAt(v, "material.nope"), nullptr);
    EXPECT_EQ(fieldAt(v, "material."), nullptr);
    EXPECT_EQ(fieldAt(v, "material[0]"), nullptr);
    EXPECT_EQ(fieldAt(v, "lights.0"), nullptr);
    EXPECT_EQ(fieldAt(v, "format"), nullptr); // presetValue leaves out format and version
}

// mergePreset(base, presetPatch(base, full)) reads as `full` (a light the base lacks is patched over the
// defaults, so the values may differ by the keys left out; the presets may not). A glTF model's path is
// resolved, so it needs a folder with the file.
void expectPatchRoundTrips(const Preset& base, const Preset& full, const char* what) {
    SCOPED_TRACE(what);
    TempFolder dir;
    fs::create_directories(dir.path() / "models");
    writeText(dir.path() / "models" / "trefoil.glb", "x");
    const PresetJson b = presetValue(base), f = presetValue(full);
    const PresetJson patch = presetPatch(b, f);
    const PresetJson merged = mergePreset(b, patch);
    Diagnostics d;
    std::optional<Preset> p = parseInlinePreset(merged.dump(), "merged", "", dir.path(), d);
    ASSERT_TRUE(p) << toString(d) << "patch: " << patch.dump();
    EXPECT_EQ(*p, full) << "patch: " << patch.dump();
}

TEST(PresetFields, APatchMergedOverItsBaseGivesTheFullPresetBack) {
    Preset base;
    base.material.shininess = 10.0f;
    base.lights.push_back(LightDesc{});
    base.lights[1].position = {-2.0f, 1.0f, 0.0f};
    expectPatchRoundTrips(base, base, "the same");
    EXPECT_EQ(presetPatch(presetValue(base), presetValue(base)), PresetJson::object());

    Preset full = base;
    full.material.shininess = 80.0f;
    expectPatchRoundTrips(base, full, "one number");
    EXPECT_EQ(unordered(presetPatch(presetValue(base), presetValue(full))),
              nlohmann::json::parse(R"({"material": {"shininess": 80}})"));

    full = base;
    full.lights.push_back(LightDesc{});
    full.lights[2].type = LightType::Directional;
    full.lights.push_back(LightDesc{});
    full.lights[3].orbit.on = true;
    expectPatchRoundTrips(base, full, "more lights");

    full = base;
    full.lights.pop_back();
    expectPatchRoundTrips(base, full, "fewer lights");
    EXPECT_TRUE(presetPatch(presetValue(base), presetValue(full)).contains("format")); // whole: a patch cannot remove

    full.lights.clear();
    expectPatchRoundTrips(base, full, "no lights");

    full = base;
    full.model.gltf = "models/trefoil.glb";
    full.model.scale = glm::vec3(2.0f);
    expectPatchRoundTrips(base, full, "a glTF model over a built-in");
    expectPatchRoundTrips(full, base, "a built-in over a glTF model");

    full = base;
    full.model.builtin = Builtin::Torus;
    full.model.subdivisions = defaultSubdivisions(Builtin::Torus);
    expectPatchRoundTrips(base, full, "another built-in");

    full = base;
    full.check.pixelTolerance = 2;
    full.sweep = {"material.shininess=10,20,50"};
    expectPatchRoundTrips(base, full, "a check block and a sweep added");
    expectPatchRoundTrips(full, base, "a check block and a sweep removed");
}

// A key missing below the top level (a light whose orbit was switched off is saved without "orbit",
// a check block lost a tolerance) is null in the patch, and the merge removes it. (Until 0b6c124 the
// patch was the whole preset below the top, and the light got "format" and "version" keys.)
TEST(PresetFields, APatchThatRemovesAKeyBelowTheTopRemovesIt) {
    Preset base;
    base.lights[0].orbit.on = true;
    expectPatchRoundTrips(base, Preset{}, "an orbit turned off");
    Preset checked;
    checked.check.pixelTolerance = 2;
    checked.check.maxMean = 1.0f;
    Preset fewer = checked;
    fewer.check.maxMean.reset();
    expectPatchRoundTrips(checked, fewer, "a check tolerance removed");
}

TEST(PresetFields, MergeAddsLightsAndSwapsTheKindOfModel) {
    const PresetJson base = presetValue(Preset{});
    PresetJson merged = mergePreset(base, PresetJson::parse(R"({"lights": [{}, {"type": "spot"}]})"));
    ASSERT_EQ(merged["lights"].size(), 2u);
    EXPECT_EQ(merged["lights"][0], base["lights"][0]);
    EXPECT_EQ(merged["lights"][1], PresetJson::parse(R"({"type": "spot"})")); // a light the base lacks is added
    merged = mergePreset(base, PresetJson::parse(R"({"model": {"gltf": "m.glb"}})"));
    EXPECT_FALSE(merged["model"].contains("builtin"));
    EXPECT_FALSE(merged["model"].contains("subdivisions"));
    EXPECT_EQ(merged["model"]["scale"], base["model"]["scale"]);
    merged = mergePreset(merged, PresetJson::parse(R"({"model": {"builtin": "cube"}})"));
    EXPECT_FALSE(merged["model"].contains("gltf"));
    EXPECT_EQ(merged["model"]["builtin"], "cube");
    // A patch with "format" is a whole preset: nothing of the base is kept.
    const PresetJson whole = PresetJson::parse(R"({"format": "lighting-lab-preset", "version": 1, "brdf": "blinn-phong"})");
    EXPECT_EQ(mergePreset(base, whole), whole);
}

//----------------------------------------------------------------------------------------
// Locked fields of an attempt
//----------------------------------------------------------------------------------------

Exercise shininessExercise() {
    Exercise e;
    e.title = "Find the shininess";
    e.start.material.shininess = 10.0f;
    e.target = e.start;
    e.target.material.shininess = 60.0f;
    e.open = {"material.shininess"};
    return e;
}

TEST(Exercise, OpenFieldsAreTheOpenPathsWhatIsBelowThemAndTheFreeOnes) {
    const Exercise e = shininessExercise();
    EXPECT_TRUE(fieldIsOpen(e, "material.shininess"));
    EXPECT_TRUE(fieldIsOpen(e, "camera.eye"));
    EXPECT_TRUE(fieldIsOpen(e, "name"));
    EXPECT_FALSE(fieldIsOpen(e, "material"));
    EXPECT_FALSE(fieldIsOpen(e, "material.diffuse"));
    EXPECT_FALSE(fieldIsOpen(e, "background"));
    Exercise lights = e;
    lights.open = {"lights[0]"};
    EXPECT_TRUE(fieldIsOpen(lights, "lights[0].attenuation"));
    EXPECT_FALSE(fieldIsOpen(lights, "lights[1].attenuation"));
    EXPECT_FALSE(fieldIsOpen(lights, "lights"));
}

TEST(Exercise, AnAttemptChangingOpenFieldsAndTheCameraChangesNothingLocked) {
    const Exercise e = shininessExercise();
    Preset attempt = e.start;
    attempt.material.shininess = 45.0f;
    attempt.camera.eye = {1.0f, 1.0f, 3.0f};
    attempt.name = "Mine";
    EXPECT_TRUE(lockedChanges(e, attempt).empty());
    EXPECT_EQ(withLockedFieldsOfStart(e, attempt), attempt);
    attempt.background = {1.0f, 1.0f, 1.0f};
    EXPECT_EQ(lockedChanges(e, attempt), std::vector<std::string>{"background"});
    attempt.material.diffuse = {0.1f, 0.2f, 0.3f};
    EXPECT_EQ(lockedChanges(e, attempt), (std::vector<std::string>{"material.diffuse", "background"}));
}

TEST(Exercise, LockedFieldsArePutBackAndTheOpenOnesKept) {
    const Exercise e = shininessExercise();
    Preset attempt = e.start;
    attempt.material.shininess = 45.0f;
    attempt.camera.eye = {1.0f, 1.0f, 3.0f};
    attempt.background = {1.0f, 1.0f, 1.0f};
    attempt.material.diffuse = {0.1f, 0.2f, 0.3f};
    const Preset kept = withLockedFieldsOfStart(e, attempt);
    EXPECT_EQ(kept.background, e.start.background);
    EXPECT_EQ(kept.material.diffuse, e.start.material.diffuse);
    EXPECT_EQ(kept.material.shininess, 45.0f);
    EXPECT_EQ(kept.camera.eye, glm::vec3(1.0f, 1.0f, 3.0f));
    EXPECT_TRUE(lockedChanges(e, kept).empty());
}

TEST(Exercise, AFieldOpenBelowALightLeavesTheRestOfTheLightLocked) {
    Exercise e = shininessExercise();
    e.target = e.start;
    e.target.lights[0].attenuation = {1.0f, 0.5f, 0.0f};
    e.open = {"lights[0].attenuation"};
    Preset attempt = e.start;
    attempt.lights[0].attenuation = {1.0f, 0.3f, 0.0f};
    EXPECT_TRUE(lockedChanges(e, attempt).empty());
    attempt.lights[0].position = {0.0f, 5.0f, 0.0f};
    EXPECT_EQ(lockedChanges(e, attempt), std::vector<std::string>{"lights[0].position"});
    const Preset kept = withLockedFieldsOfStart(e, attempt);
    EXPECT_EQ(kept.lights[0].position, e.start.lights[0].position);
    EXPECT_EQ(kept.lights[0].attenuation, glm::vec3(1.0f, 0.3f, 0.0f));
    // A light the start lacks is a change of "lights[1]": locked unless the lights are open.
    attempt = e.start;
    attempt.lights.push_back(LightDesc{});
    EXPECT_EQ(lockedChanges(e, attempt), std::vector<std::string>{"lights[1]"});
    EXPECT_EQ(withLockedFieldsOfStart(e, attempt).lights.size(), 1u);
}

TEST(Exercise, AnAddedLightIsKeptWhenTheLightsAreOpen) {
    Exercise e = shininessExercise();
    e.open = {"material.shininess", "lights"};
    Preset attempt = e.start;
    attempt.lights.push_back(LightDesc{});
    attempt.lights[1].position = {-3.0f, 0.0f, 1.0f};
    attempt.background = {1.0f, 0.0f, 0.0f};
    EXPECT_EQ(lockedChanges(e, attempt), std::vector<std::string>{"background"});
    const Preset kept = withLockedFieldsOfStart(e, attempt);
    ASSERT_EQ(kept.lights.size(), 2u);
    EXPECT_EQ(kept.lights[1], attempt.lights[1]);
    EXPECT_EQ(kept.background, e.start.background);
}

// With "lights" open and a locked field changed too, putting the locked field back keeps the
// attempt's removal of a light.
TEST(Exercise, ARemovedLightIsKeptRemovedWhenTheLightsAreOpen) {
    Exercise e = shininessExercise();
    e.start.lights.push_back(LightDesc{});
    e.target = e.start;
    e.target.material.shininess = 60.0f;
    e.open = {"material.shininess", "lights"};
    Preset attempt = e.start;
    attempt.lights.pop_back();
    attempt.background = {1.0f, 0.0f, 0.0f};
    EXPECT_EQ(lockedChanges(e, attempt), std::vector<std::string>{"background"});
    const Preset kept = withLockedFieldsOfStart(e, attempt);
    EXPECT_EQ(kept.lights.size(), 1u);
    EXPECT_EQ(kept.background, e.start.background);
}

TEST(Exercise, TheSameModelFileNamedFromAnotherFolderIsNotAChange) {
    TempFolder dir;
    fs::create_directories(dir.path() / "models");
    writeText(dir.path() / "models" / "m.glb", "x"); // only its name matters here
    Exercise e = shininessExercise();
    e.start.model.gltf = "models/m.glb";
    e.target.model.gltf = "models/m.glb";
    Preset attempt = e.start;
    attempt.model.gltf = "m.glb"; // saved in models/
    EXPECT_TRUE(lockedChanges(e, attempt, dir.path(), dir.path() / "models").empty());
    EXPECT_EQ(lockedChanges(e, attempt, dir.path(), dir.path()), std::vector<std::string>{"model.gltf"});
    attempt.model.gltf = "./models/../models/m.glb";
    EXPECT_TRUE(lockedChanges(e, attempt, dir.path(), dir.path()).empty());
}

// A glTF start: the attempt's open field is kept and the locked one put back, though no folder is
// there to read the model path against.
TEST(Exercise, LockedFieldsArePutBackAndTheOpenOnesKeptForAGltfModel) {
    Exercise e = shininessExercise();
    e.start.model.gltf = "models/m.glb";
    e.target.model.gltf = "models/m.glb";
    Preset attempt = e.start;
    attempt.material.shininess = 45.0f;
    attempt.background = {1.0f, 1.0f, 1.0f};
    const Preset kept = withLockedFieldsOfStart(e, attempt);
    EXPECT_EQ(kept.background, e.start.background);
    EXPECT_EQ(kept.material.shininess, 45.0f);
}

TEST(Exercise, AnAttemptIsScoredThroughTheTargetsCamera) {
    Exercise e = shininessExercise();
    e.target.camera.eye = {0.0f, 2.0f, 4.0f};
    Preset attempt = e.start;
    attempt.camera.eye = {5.0f, 0.0f, 0.0f};
    attempt.material.shininess = 30.0f;
    const Preset scored = attemptAsScored(e, attempt);
    EXPECT_EQ(scored.camera, e.target.camera);
    EXPECT_EQ(scored.material.shininess, 30.0f);
    EXPECT_EQ(targetAsScored(e), e.target);
    // The start, for d(start), is seen as an attempt is.
    const Preset start = startAsScored(e);
    EXPECT_EQ(start.camera, e.target.camera);
    EXPECT_EQ(start.material.shininess, e.start.material.shininess);
}

} // namespace
} // namespace lab
