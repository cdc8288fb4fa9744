// page_model_test.cpp — the page's parallel DOM as data (app/page_model.h), a field set from the
// page's text (core/scene/field_edit.h) and the pictures in words (core/plots/describe.h). Headless:
// no window, no ImGui, no GL, no browser (web/tests/access.test.mjs drives the real page).
#include "app/page_model.h"

#include "core/io/safe_text.h"
#include "core/plots/describe.h"
#include "core/scene/field_edit.h"
#include "core/scene/field_table.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>

namespace lab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kPresets = fs::path(LAB_SOURCE_DIR) / "presets";

TEST(FieldEdit, SetsAFieldOfEachKindFromText) {
    Preset p;
    p.lights.push_back(LightDesc{});
    EXPECT_EQ(setFieldFromText(p, "material.shininess", "64"), "");
    EXPECT_EQ(p.material.shininess, 64.0f);
    EXPECT_EQ(setFieldFromText(p, "material.diffuse[2]", "0.25"), "");
    EXPECT_EQ(p.material.diffuse, glm::vec3(0.8f, 0.8f, 0.25f));
    EXPECT_EQ(setFieldFromText(p, "lights[1].type", "spot"), "");
    EXPECT_EQ(p.lights[1].type, LightType::Spot);
    EXPECT_EQ(setFieldFromText(p, "lights[01].enabled", "false"), "");
    EXPECT_FALSE(p.lights[1].enabled);
    EXPECT_EQ(setFieldFromText(p, "brdf", "cook-torrance"), "");
    EXPECT_EQ(p.brdf, BrdfModel::CookTorrance);
    EXPECT_EQ(setFieldFromText(p, "model.builtin", "torus"), "");
    EXPECT_EQ(p.model.subdivisions, defaultSubdivisions(Builtin::Torus)) << "a new built-in gets its own subdivisions";
}

TEST(FieldEdit, RefusesWhatAPresetFileWouldAndLeavesThePresetAsItWas) {
    Preset p;
    const Preset before = p;
    const std::map<std::pair<std::string, std::string>, std::string> refused = {
        {{"material.shininess", "-1"}, "material.shininess: must be"},
        {{"material.shininess", "lots"}, "material.shininess: expected a number"},
        {{"material.shininess", "nan"}, "expected a number"},
        {{"material.diffuse", "0.5"}, "one element at a time"},
        {{"material.diffuse[3]", "0.5"}, "has no element 3"},
        {{"lights[4].type", "spot"}, "there is no light 4"},
        {{"lights[0].type", "laser"}, "not one of its choices"},
        {{"lights[0].enabled", "yes"}, "expected true or false"},
        {{"lights[0].attenuation[0]", "0"}, "lights[0].attenuation[0]: "}, // c0, c1, c2 all 0 (the table's rule)
        {{"camera.up[1]", "0"}, "not a field the page can set"},           // hidden rows
        {{"material.colour", "1"}, "not a field the page can set"},
        {{"model.gltf", "x.glb"}, "not a field the page can set"},
        {{"model.subdivisions[0]", "2"}, "a sphere or a torus needs at least 3"},
        // The camera's rule sits on its row "far"; an edit of the eye keeps it too (fuzz_field's find).
        {{"camera.eye[2]", "0"}, "camera.eye[2]: camera.target must be at least 0.001 from eye"},
    };
    for (const auto& [edit, message] : refused) {
        std::string problem = setFieldFromText(p, edit.first, edit.second);
        EXPECT_NE(problem.find(message), std::string::npos) << edit.first << " = " << edit.second << ": " << problem;
        EXPECT_EQ(p, before) << edit.first << " = " << edit.second;
    }
}

// Issue 49: a refusal showed an in-range number ("got 1e+06" for 1000001, "got 10" for 10.00001),
// and 1e39 was "expected a number": the value is said as it was typed, as the command line says it.
TEST(FieldEdit, ARefusedNumberIsSaidAsTyped) {
    Preset p;
    const Preset before = p;
    const std::pair<std::pair<const char*, const char*>, const char*> cases[] = {
        {{"material.shininess", "1000001"}, "material.shininess: must be in [0.001, 1000000], got 1000001"},
        {{"cook_torrance.roughness", "10.00001"}, "cook_torrance.roughness: must be in [0.001, 10], got 10.00001"},
        {{"material.shininess", "1e39"}, "material.shininess: number out of range: 1e39"},
        {{"material.shininess", "1e309"}, "material.shininess: number out of range: 1e309"},
        {{"material.diffuse[0]", "-0.5"}, "material.diffuse[0]: must be in [0, 1], got -0.5"},
    };
    p.brdf = BrdfModel::CookTorrance;
    for (const auto& [edit, message] : cases) {
        EXPECT_EQ(setFieldFromText(p, edit.first, edit.second), message) << edit.second;
    }
    p.brdf = before.brdf;
    EXPECT_EQ(p, before);
    p.lights[0].type = LightType::Spot;
    EXPECT_EQ(setFieldFromText(p, "lights[0].exponent", "1000000.5"), "lights[0].exponent: must be in [0, 1000000], got 1000000.5");
}

// Issue 49: the page's edits took what the preset reader refuses — hex floats ("0x10" set 16) and
// text after a NUL — through strtof. They are read by the reader's own JSON parser now.
TEST(FieldEdit, ANumberIsReadAsAPresetFileReadsIt) {
    Preset p;
    const Preset before = p;
    for (const std::string& text : std::initializer_list<std::string>{"0x10", "0X1p4", std::string("5\0junk", 6), "inf", "-", "e", "--5", "+5", "1e", "", " ",
                                   "5 6", "[5]", "true", "\"5\"", "1,5"}) {
        const std::string problem = setFieldFromText(p, "material.shininess", text);
        EXPECT_TRUE(problem.starts_with("material.shininess: expected a number such as 0.5, -2 or 1e-3, got \""))
            << printable(text) << ": " << problem;
        EXPECT_EQ(p, before) << printable(text);
    }
    EXPECT_NE(setFieldFromText(p, "material.shininess", std::string("5\0junk", 6)).find("\"5\\0junk\""), std::string::npos)
        << "a NUL is shown, not cut at";
    // What a preset file holds is taken, and .5 and 5. as the panel's own fields take them.
    for (const auto& [text, value] : {std::pair{"64", 64.0f}, {"6.4e1", 64.0f}, {" 12 ", 12.0f}, {".5", 0.5f}, {"5.", 5.0f},
                                      {"-.5e1", -5.0f}, {"1E2", 100.0f}}) {
        const char* path = value < 0.0f ? "model.translate[0]" : "material.shininess";
        EXPECT_EQ(setFieldFromText(p, path, text), "") << text;
        EXPECT_EQ(value < 0.0f ? p.model.translate.x : p.material.shininess, value) << text;
    }
    EXPECT_EQ(setFieldFromText(p, "model.subdivisions[0]", "0x20"),
              "model.subdivisions[0]: expected a whole number in [1, 1024], got \"0x20\"");
}

// Issue 49: a 1 MB value put a 1,048,634-character line in the page's log and stalled its canvas; a
// path likewise. Every value and path a refusal quotes is cut at 120 bytes with its size.
TEST(FieldEdit, ARefusalQuotesAtMost120BytesOfWhatWasTyped) {
    Preset p;
    const std::string huge(1 << 20, '7'), digits(10000, '9');
    for (const auto& [path, text] : {std::pair<std::string, std::string>{"material.shininess", huge + "x"},
                                     {"material.shininess", digits},
                                     {"lights[0].type", huge},
                                     {"lights[0].enabled", huge},
                                     {"model.subdivisions[0]", huge},
                                     {huge, "1"},
                                     {"material.shininess" + huge, "1"},
                                     {std::string("material.shininess\0x", 20), "1"}}) {
        const std::string problem = setFieldFromText(p, path, text);
        EXPECT_FALSE(problem.empty());
        EXPECT_LT(problem.size(), 400u) << problem.substr(0, 400);
        EXPECT_EQ(printable(problem, true), problem) << "escaped for the page and the terminal";
    }
    EXPECT_EQ(setFieldFromText(p, "material.shininess", "1" + digits + "x").find("material.shininess: expected a number"), 0u)
        << "not a number, though its digits alone would be too large";
    EXPECT_EQ(setFieldFromText(p, "material.shininess", digits),
              "material.shininess: number out of range: \"" + std::string(120, '9') + "\xe2\x80\xa6\" (10000 bytes)");
    EXPECT_EQ(setFieldFromText(p, std::string("material.shininess\0x", 20), "1"),
              "\"material.shininess\\0x\": not a field the page can set");
    EXPECT_EQ(setFieldFromText(p, "", "1"), "\"\": not a field the page can set");
    EXPECT_EQ(p, Preset{});
}

// Every field of the table that applies has its control, with the table's range and the preset's value.
void expectEveryRowHasItsControl(Workspace& ws, const json& page) {
    std::map<std::string, json> controls;
    for (const json& s : page["sections"]) {
        for (const json& c : s["controls"]) {
            EXPECT_TRUE(controls.emplace(c["path"].get<std::string>(), c).second) << "twice: " << c["path"];
        }
    }
    Preset& p = ws.edited();
    std::size_t expected = 0;
    for (const FieldRow& row : fieldRows()) {
        for (int i = 0; i < (isLightRow(row) ? static_cast<int>(p.lights.size()) : 1); ++i) {
            LightDesc* light = isLightRow(row) ? &p.lights[static_cast<std::size_t>(i)] : nullptr;
            if ((row.style & kStyleHidden) || (row.custom && row.kind == FieldKind::Text) || !applies(row, p, light)) {
                continue;
            }
            ++expected;
            const std::string path = fieldPath(row, i);
            ASSERT_TRUE(controls.count(path)) << "no control for " << path;
            const json& c = controls[path];
            EXPECT_EQ(c["label"], std::string(row.label)) << path;
            if (row.range) {
                EXPECT_EQ(static_cast<float>(c["min"].get<double>()), row.range->min) << path;
                EXPECT_EQ(static_cast<float>(c["max"].get<double>()), row.range->max) << path;
            }
            if (row.kind == FieldKind::Number) {
                EXPECT_EQ(static_cast<float>(c["value"].get<double>()), fieldValue<float>(row, p, light)) << path;
            }
        }
    }
    EXPECT_EQ(controls.size(), expected);
}

TEST(PageModel, EveryFieldThatAppliesHasItsControlWithTheTablesRange) {
    Workspace ws{WorkspaceOptions{{kPresets}, {}, true, {}}};
    ws.start(kPresets);
    PageModel model;
    expectEveryRowHasItsControl(ws, json::parse(model.json(ws, {})));
    // Another BRDF and light types: other rows apply.
    ws.edited().brdf = BrdfModel::CookTorrance;
    ws.edited().lights.push_back(LightDesc{LightType::Spot});
    ws.edited().lights.push_back(LightDesc{LightType::Directional});
    json page = json::parse(model.json(ws, {}));
    expectEveryRowHasItsControl(ws, page);
    EXPECT_NE(page["pictures"]["description"].get<std::string>().find("Cook-Torrance"), std::string::npos)
        << page["pictures"]["description"];
    EXPECT_EQ(page["pictures"]["slice"].get<std::string>(), describeSlice(ws.a())) << "the Slice tab in words";
}

TEST(PageModel, EditsAndCommandsFromThePageTakeThePanelsWay) {
    Workspace ws{WorkspaceOptions{{kPresets}, {}, true, {}}};
    ws.start(kPresets);
    std::vector<Request> requests;
    std::vector<PageRefusal> refused = applyPageEdits(ws, {{"material.shininess", "12"}, {"material.shininess", "-5"},
                                                           {"", "", static_cast<int>(Command::OrbitLeft), -1},
                                                           {"", "", static_cast<int>(Command::OpenPresetAt), 2},
                                                           {"", "", 100000, -1}, {"lights[00].type", "laser"}},
                                                      PageFacts{}, requests);
    EXPECT_EQ(ws.edited().material.shininess, 12.0f);
    ASSERT_EQ(refused.size(), 2u);
    EXPECT_EQ(refused[0].path, "material.shininess");
    EXPECT_EQ(refused[0].message, "material.shininess: must be in [0.001, 1000000], got -5");
    EXPECT_EQ(refused[1].path, "lights[00].type") << "the path as the page sent it: its control's";
    EXPECT_EQ(refused[1].message.rfind("lights[0].type: not one of its choices: \"laser\"", 0), 0u) << refused[1].message;
    ASSERT_EQ(requests.size(), 2u) << "a command number the table does not have is dropped";
    EXPECT_EQ(requests[0].command, Command::OrbitLeft);
    EXPECT_EQ(requests[1].command, Command::OpenPresetAt);
    EXPECT_EQ(requests[1].index, 2);
    const glm::vec3 eye = ws.a().camera.eye;
    ws.run(requests[0]);
    EXPECT_NE(ws.a().camera.eye, eye) << "Orbit left moves the camera";
    EXPECT_NEAR(glm::length(ws.a().camera.eye - ws.a().camera.target), glm::length(eye - ws.a().camera.target), 1e-4f);
    ws.endFrame(false);
    EXPECT_TRUE(ws.document().canUndo());
}

// Issue 49: an edit without a path was dropped without a word; every refusal reaches the page's
// description, each with the path of the control that sent it, as well as the message log.
TEST(PageModel, RefusedEditsAreSaidAndNamedForTheirControls) {
    Workspace ws{WorkspaceOptions{{kPresets}, {}, true, {}}};
    ws.start(kPresets);
    std::vector<Request> requests;
    PageNews news;
    ui::PanelState panel;
    takePageInput(ws, {{"", "5"}, {"material.shininess", "--5"}, {"material.shininess", "7"}}, std::nullopt, PageFacts{},
                  panel, news);
    const std::vector<PageRefusal>& refused = news.refused;
    ASSERT_EQ(refused.size(), 2u);
    EXPECT_EQ(refused[0].message, "\"\": not a field the page can set");
    EXPECT_EQ(refused[1].message, "material.shininess: expected a number such as 0.5, -2 or 1e-3, got \"--5\"");
    EXPECT_EQ(ws.edited().material.shininess, 7.0f) << "the edit after a refused one is taken";
    PageFacts facts;
    facts.news = news;
    const json page = json::parse(PageModel().json(ws, facts));
    ASSERT_EQ(page["messages"]["refused"].size(), 2u);
    EXPECT_EQ(page["messages"]["refused"][1]["path"], "material.shininess");
    EXPECT_EQ(page["messages"]["refused"][1]["message"], refused[1].message);
    const std::vector<std::string> notes = ws.takeNotes();
    ASSERT_FALSE(notes.empty());
    EXPECT_NE(notes.back().find("got \"--5\""), std::string::npos) << notes.back();
}

// The speaker's notes the canvas shows are in the page's description too (web/access.js renders
// them as a region); none while the strip is closed.
TEST(PageModel, TheSpeakersNotesAreDescribedWhileShown) {
    Workspace ws{WorkspaceOptions{{kPresets}, {}, true, {}}};
    ws.start(kPresets);
    PageModel model;
    PageFacts facts;
    EXPECT_FALSE(json::parse(model.json(ws, facts)).contains("notes"));
    const ui::NotesModel notes{"Slide 2 of 3: Diffuse", "Say \"Lambert\".", "Specular", "10:15"};
    facts.notes = &notes;
    const json page = json::parse(model.json(ws, facts));
    ASSERT_TRUE(page.contains("notes"));
    EXPECT_EQ(page["notes"]["position"], "Slide 2 of 3: Diffuse");
    EXPECT_EQ(page["notes"]["text"], "Say \"Lambert\".");
    EXPECT_EQ(page["notes"]["next"], "Specular");
}

TEST(PageModel, AnExerciseShowsOnlyItsOpenFieldsAndRefusesTheOthers) {
    Workspace ws{WorkspaceOptions{{kPresets}, {}, true, {}}};
    ws.start(kPresets);
    ws.openLink("exercise=02-shininess");
    ASSERT_TRUE(ws.exercise());
    ui::ExercisePanelModel view;
    view.title = ws.exercise()->exercise.title;
    view.open = ws.exercise()->exercise.open;
    PageModel model;
    PageFacts facts;
    facts.exercise = &view;
    json page = json::parse(model.json(ws, facts));
    std::vector<std::string> paths;
    for (const json& s : page["sections"]) {
        for (const json& c : s["controls"]) {
            paths.push_back(c["path"]);
        }
    }
    EXPECT_NE(std::find(paths.begin(), paths.end(), "material.shininess"), paths.end());
    EXPECT_EQ(std::find(paths.begin(), paths.end(), "material.diffuse"), paths.end()) << "not open in 02-shininess";
    EXPECT_TRUE(page.contains("exercise"));
    std::vector<Request> requests;
    const glm::vec3 diffuse = ws.edited().material.diffuse;
    std::vector<PageRefusal> refused = applyPageEdits(ws, {{"material.diffuse[0]", "0.1"}}, PageFacts{}, requests);
    ASSERT_EQ(refused.size(), 1u);
    EXPECT_EQ(refused[0].message, "material.diffuse[0]: this exercise does not let you change it");
    EXPECT_EQ(ws.edited().material.diffuse, diffuse);
}

TEST(Describe, SaysWhereTheLightIsAndWhereTheHighlightFalls) {
    Preset p; // the camera on +z looking at the origin, up +y
    p.lights = {LightDesc{}};
    p.lights[0].position = {3.0f, 3.0f, 3.0f};
    std::string text = describeScene(p);
    EXPECT_NE(text.find("Light 1, point, on, white: upper right, in front"), std::string::npos) << text;
    EXPECT_NE(text.find("highlight of Light 1 falls on the upper right of the model"), std::string::npos) << text;
    p.lights[0].position = {-3.0f, 0.0f, -3.0f};
    text = describeScene(p);
    EXPECT_NE(text.find("left, behind"), std::string::npos) << text;
    p.lights[0].position = {0.0f, 0.0f, -3.0f};
    EXPECT_NE(describeScene(p).find("on the far side of the model"), std::string::npos) << describeScene(p);
    EXPECT_EQ(directionWords(p.camera, {0, 0, 1}), "straight ahead, in front");
    EXPECT_EQ(directionWords(p.camera, {0, -1, 0}), "below");
}

TEST(Describe, ThePlanePlotsTableHasItsNumbersEveryFiveDegrees) {
    Preset p;
    p.plotIncidentDeg = 30.0f;
    PlotWords words = describePlanePlot(p, 5);
    ASSERT_FALSE(words.rows.empty());
    EXPECT_EQ(words.rows[1].thetaOutDeg - words.rows[0].thetaOutDeg, 5.0f);
    std::vector<PlotSample> every = reflectedIntensity(p, 30.0f);
    EXPECT_EQ(words.rows.back().thetaOutDeg, every.back().thetaOutDeg);
    EXPECT_NE(words.summary.find("light at 30 degrees"), std::string::npos) << words.summary;
    EXPECT_NE(words.summary.find("peaks at 30 degrees"), std::string::npos) << "Phong's lobe peaks at the mirror direction: " << words.summary;
}

} // namespace
} // namespace lab
