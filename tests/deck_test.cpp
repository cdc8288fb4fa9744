// deck_test.cpp — decks (core/scene/deck.h) and the lecture's parts of a preset (core/scene/preset.h
// `display`, `notes`, `compare`): read, checked with their paths, written back, and the shipped deck.
#include "core/exercise/preset_fields.h"
#include "core/scene/deck.h"
#include "core/scene/view_mode.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <string>

namespace lab {
namespace {

namespace fs = std::filesystem;

const fs::path kPresets = fs::path(LAB_SOURCE_DIR) / "presets";

std::optional<Preset> parse(const std::string& keys, Diagnostics& d) {
    return parsePreset(R"({"format": "lighting-lab-preset", "version": 1, )" + keys + "}", "p.json", std::nullopt, d);
}

TEST(PresetLecture, DisplayNotesAndCompareAreReadAndWrittenBack) {
    Diagnostics d;
    std::optional<Preset> p = parse(R"("shading": "gouraud", "display": {"view": "n-dot-l", "light": 1, "wipe": true, "plots": "energy"},
        "notes": "Say this.", "compare": {"shading": "phong", "material": {"shininess": 64}})", d);
    ASSERT_TRUE(p) << toString(d);
    EXPECT_EQ(p->display.view, "n-dot-l");
    EXPECT_TRUE(p->display.wipe);
    EXPECT_FALSE(p->display.compare);
    EXPECT_EQ(p->display.plots, "energy");
    EXPECT_EQ(p->notes, "Say this.");
    std::optional<Preset> b = comparedPreset(*p, std::nullopt, d);
    ASSERT_TRUE(b) << toString(d);
    EXPECT_EQ(b->shading, Shading::Phong);
    EXPECT_EQ(b->material.shininess, 64.0f);
    EXPECT_EQ(b->material.diffuse, p->material.diffuse); // the rest is A's
    EXPECT_TRUE(b->compare.empty() && b->notes.empty() && b->display.empty());
    std::optional<Preset> again = parsePreset(presetToJson(*p), "again.json", std::nullopt, d);
    ASSERT_TRUE(again) << toString(d);
    EXPECT_EQ(*again, *p);
    // A preset without them is written as before they existed.
    EXPECT_EQ(presetToJson(Preset{}).find("display"), std::string::npos);
    EXPECT_EQ(presetToJson(Preset{}).find("compare"), std::string::npos);
}

TEST(PresetLecture, AnUnknownPlotsTabIsNamedWithTheTabsThereAre) {
    Diagnostics d;
    EXPECT_FALSE(parse(R"("display": {"plots": "energie"})", d));
    EXPECT_NE(toString(d).find("no plots tab \"energie\" (did you mean \"energy\"?); the tabs are plane, lobe3d, energy and slice"),
              std::string::npos)
        << toString(d);
}

TEST(PresetLecture, ACompareIsCheckedAsTheFileIsWithItsPath) {
    for (auto [keys, path] : {std::pair{R"("compare": {"shading": "gouroud"})", "compare.shading"},
                              std::pair{R"("compare": {"material": {"shininess": -1}})", "compare.material.shininess"},
                              std::pair{R"("compare": {"shinyness": 3})", "compare.shinyness"},
                              std::pair{R"("compare": {"format": "lighting-lab-preset"})", "compare.format"},
                              std::pair{R"("compare": {"compare": {}})", "compare.compare"},
                              std::pair{R"("compare": {"lights": [{"attenuation": [0, 0, 0]}]})", "compare.lights[0]"},
                              std::pair{R"("compare": 3)", "compare"},
                              std::pair{R"("display": {"view": "n-dot-q"})", "display.view"},
                              std::pair{R"("display": {"light": 9})", "display.light"},
                              std::pair{R"("display": {"colour": 1})", "display.colour"},
                              std::pair{R"("display": {"plots": "energie"})", "display.plots"}}) {
        Diagnostics d;
        EXPECT_FALSE(parse(keys, d)) << keys;
        EXPECT_NE(toString(d).find(path), std::string::npos) << keys << "\n" << toString(d);
    }
}

TEST(PresetLecture, ACompareMergesLightsElementByElementAndKeepsTheModel) {
    Diagnostics d;
    std::optional<Preset> p = parse(R"("model": {"builtin": "sphere", "subdivisions": [12, 6]},
        "lights": [{"position": [1, 2, 3]}, {"type": "directional"}],
        "compare": {"lights": [{}, {"enabled": false}, {"type": "spot"}], "model": {"scale": [2, 1, 1]}})", d);
    ASSERT_TRUE(p) << toString(d);
    std::optional<Preset> b = comparedPreset(*p, std::nullopt, d);
    ASSERT_TRUE(b) << toString(d);
    ASSERT_EQ(b->lights.size(), 3u);
    EXPECT_EQ(b->lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_EQ(b->lights[1].type, LightType::Directional);
    EXPECT_FALSE(b->lights[1].enabled);
    EXPECT_EQ(b->lights[2].type, LightType::Spot);
    EXPECT_EQ(b->model.subdivisions, glm::ivec2(12, 6)); // not the sphere's default
    EXPECT_EQ(b->model.scale, glm::vec3(2, 1, 1));
}

TEST(PresetLecture, DifferenceLabelsNameTheFieldsThatDiffer) {
    Preset a, b;
    a.normalMatrix = NormalMatrixMode::ModelView;
    b.camera.eye = {1, 2, 3}; // not a difference: B follows A's camera
    b.name = "other";
    DifferenceLabels labels = differenceLabels(a, b);
    EXPECT_EQ(labels.a, "normal matrix: model-view (wrong)");
    EXPECT_EQ(labels.b, "normal matrix: inverse-transpose (correct)");
    b = a;
    EXPECT_TRUE(differenceLabels(a, b).a.empty());
    b.material.shininess = 10;
    b.shading = Shading::Gouraud;
    b.lights.push_back(LightDesc{});
    b.lights[1].type = LightType::Spot;
    labels = differenceLabels(a, b, 2);
    EXPECT_EQ(labels.b, "shading: Gouraud; shininess: 10 (+1 more)") << labels.b;
}

TEST(Deck, ReadsSlidesByPathAndInlineWithTheirNotesAndDisplay) {
    TempFolder dir;
    fs::create_directories(dir.path() / "decks");
    writeText(dir.path() / "a.json", R"({"format": "lighting-lab-preset", "version": 1, "name": "A", "notes": "A's own"})");
    writeText(dir.path() / "decks" / "d.json", R"({"format": "lighting-lab-deck", "version": 1, "title": "T", "slides": [
        {"preset": "../a.json"},
        {"preset": "../a.json", "title": "A again", "notes": ["one", "two"], "display": {"view": "n-dot-l"},
         "compare": {"shading": "flat"}},
        {"preset": {"name": "Inline", "brdf": "blinn-phong"}}]})");
    Diagnostics d;
    std::optional<Deck> deck = loadDeck(dir.path() / "decks" / "d.json", d);
    ASSERT_TRUE(deck) << toString(d);
    EXPECT_EQ(deck->title, "T");
    ASSERT_EQ(deck->slides.size(), 3u);
    EXPECT_EQ(slideTitle(deck->slides[0]), "A");
    EXPECT_EQ(deck->slides[0].notes, "A's own");
    EXPECT_EQ(slideTitle(deck->slides[1]), "A again");
    EXPECT_EQ(deck->slides[1].notes, "one\ntwo");
    EXPECT_EQ(deck->slides[1].display.view, "n-dot-l");
    EXPECT_FALSE(deck->slides[1].compare.empty());
    EXPECT_TRUE(deck->slides[1].preset.preset.compare.empty()); // the file's preset as it is
    EXPECT_TRUE(deck->slides[2].preset.file.empty());
    EXPECT_EQ(deck->slides[2].preset.preset.brdf, BrdfModel::BlinnPhong);
    EXPECT_EQ(deck->slides[2].folder, dir.path() / "decks");
}

TEST(Deck, EveryBrokenSlideIsNamedAndTheDeckRefusedWhole) {
    TempFolder dir;
    fs::create_directories(dir.path() / "course" / "decks");
    writeText(dir.path() / "secret.json", R"({"format": "lighting-lab-preset", "version": 1})");
    writeText(dir.path() / "course" / "bad.json", R"({"format": "lighting-lab-preset", "version": 1, "shading": 3})");
    const std::string head = R"({"format": "lighting-lab-deck", "version": 1, "slides": [)";
    for (auto [slides, said] : {std::pair{R"({"preset": "../../secret.json"})", "slides[0].preset"},
                                std::pair{R"({"preset": "/etc/passwd"})", "absolute path"},
                                std::pair{R"({"preset": "../bad.json"})", "shading"},
                                std::pair{R"({"preset": "../none.json"})", "none.json"},
                                std::pair{R"({"preset": "../bad.txt"})", ".json"},
                                std::pair{R"({"preset": {"shininess": 3}})", "slides[0].preset.shininess"},
                                std::pair{R"({"preset": {}, "notes": 3})", "slides[0].notes"},
                                std::pair{R"({"preset": {}, "display": {"view": "x"}})", "slides[0].display.view"},
                                std::pair{R"({"preset": {}, "compare": {"brdf": "x"}})", "slides[0].compare.brdf"},
                                std::pair{R"({"preset": {}, "talk": 1})", "slides[0].talk"},
                                std::pair{R"({"title": "no preset"})", "slides[0].preset"},
                                std::pair{R"(3)", "slides[0]"}}) {
        writeText(dir.path() / "course" / "decks" / "d.json", head + slides + "]}");
        Diagnostics d;
        EXPECT_FALSE(loadDeck(dir.path() / "course" / "decks" / "d.json", d)) << slides;
        EXPECT_NE(toString(d).find(said), std::string::npos) << slides << "\n" << toString(d);
    }
    for (auto [text, said] : {std::pair{R"({"format": "lighting-lab-deck", "version": 1, "slides": []})", "slides"},
                              std::pair{R"({"format": "lighting-lab-preset", "version": 1})", "this is a preset"},
                              std::pair{R"({"format": "lighting-lab-deck", "version": 2, "slides": []})", "newer"},
                              std::pair{R"({"format": "lighting-lab-deck", "version": 1, "slides": [{"preset": {}}],)", "invalid JSON"}}) {
        Diagnostics d;
        EXPECT_FALSE(parseDeck(text, "d.json", dir.path(), d)) << text;
        EXPECT_NE(toString(d).find(said), std::string::npos) << text << "\n" << toString(d);
    }
    EXPECT_TRUE(isDeckText(R"({"format": "lighting-lab-deck"})"));
    EXPECT_FALSE(isDeckText(R"({"format": "lighting-lab-preset"})"));
    EXPECT_FALSE(isDeckText("[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[["));
}

// The lecture that ships: every slide loads, and every view it opens with applies to its preset.
TEST(Deck, TheShippedLectureLoadsAndItsViewsApply) {
    Diagnostics d;
    std::optional<Deck> deck = loadDeck(kPresets / "decks" / "lecture.json", d);
    ASSERT_TRUE(deck) << toString(d);
    EXPECT_GE(deck->slides.size(), 25u);
    int comparisons = 0;
    for (const Slide& slide : deck->slides) {
        EXPECT_FALSE(slide.notes.empty()) << slideTitle(slide);
        if (!slide.display.view.empty()) {
            std::optional<ViewMode> mode = viewFromName(slide.display.view);
            ASSERT_TRUE(mode) << slideTitle(slide);
            EXPECT_EQ(notApplicable(*mode, slide.preset.preset, slide.display.light - 1), "") << slideTitle(slide);
        }
        if (!slide.compare.empty()) {
            Preset a = slide.preset.preset;
            a.compare = slide.compare;
            std::optional<Preset> b = comparedPreset(a, slide.folder, d);
            ASSERT_TRUE(b) << toString(d);
            EXPECT_FALSE(differenceLabels(a, *b).a.empty()) << slideTitle(slide);
            ++comparisons;
        }
    }
    EXPECT_EQ(comparisons, 3); // the normal matrix, Gouraud against Phong, Phong against Blinn-Phong
}

} // namespace
} // namespace lab
