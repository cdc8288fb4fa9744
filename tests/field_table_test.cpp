// field_table_test.cpp — the field table (core/scene/field_table.h) and the path grammar
// (core/scene/field_path.h): every row is read, written and ranged as it says, the lookups, the
// one parser's rules, and the format check presets and exercises share (file_header.h).
#include "core/scene/field_path.h"
#include "core/scene/field_table.h"
#include "core/scene/file_header.h"
#include "core/scene/preset.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>

namespace lab {
namespace {

using Json = nlohmann::ordered_json;

// A preset where every row can apply: a spot light with an orbit, Cook-Torrance.
Preset everyRowPreset() {
    Preset p;
    p.lights = {LightDesc{}, LightDesc{}};
    p.lights[1].type = LightType::Spot;
    p.lights[1].orbit.on = true;
    return p;
}

// `row`'s value in `p` changed to another value the reader accepts.
void changeValue(const FieldRow& row, Preset& p, LightDesc* light) {
    switch (row.kind) {
    case FieldKind::Number: {
        float& v = fieldValue<float>(row, p, light);
        v = v == row.range->sliderMax ? row.range->sliderMin : row.range->sliderMax;
        break;
    }
    case FieldKind::Vec3:
    case FieldKind::Color:
    case FieldKind::Direction: {
        glm::vec3& v = fieldValue<glm::vec3>(row, p, light);
        v.x = v.x == 0.5f ? 0.25f : 0.5f; // within every triplet's range; keeps a direction long enough
        break;
    }
    case FieldKind::Int2: fieldValue<glm::ivec2>(row, p, light) = {7, 5}; break;
    case FieldKind::Switch: fieldValue<bool>(row, p, light) = !fieldValue<bool>(row, p, light); break;
    case FieldKind::Text: fieldValue<std::string>(row, p, light) += " changed"; break;
    case FieldKind::Choice: {
        int now = choiceValue(row, p, light);
        setChoice(row, p, light, row.choices[row.choices.back().value == now ? 0 : row.choices.size() - 1].value);
        break;
    }
    }
}

TEST(FieldTable, EveryRowIsWrittenAndReadBackWhereItSays) {
    for (const FieldRow& row : fieldRows()) {
        if (row.path == "model.gltf") {
            continue; // needs a file to resolve against: gltf_test's round trips
        }
        Preset p = everyRowPreset();
        LightDesc* light = isLightRow(row) ? &p.lights[1] : nullptr;
        changeValue(row, p, light);
        ASSERT_NE(p, everyRowPreset()) << row.path << ": changing its value changed nothing in the preset";
        Diagnostics d;
        std::optional<Preset> back = parsePreset(presetToJson(p), "t.json", std::nullopt, d);
        ASSERT_TRUE(back) << row.path << ": " << toString(d);
        EXPECT_EQ(*back, p) << row.path << " did not survive a round trip:\n" << presetToJson(p);
    }
}

TEST(FieldTable, TheWriterWritesTheKeysInTheTablesOrder) {
    const Preset p = everyRowPreset();
    Json j = Json::parse(presetToJson(p));
    std::vector<std::string> written;
    for (const auto& [key, value] : j.items()) {
        written.push_back(key);
    }
    std::vector<std::string> expected = {"format", "version"};
    for (const FieldRow& row : fieldRows()) {
        std::string top(row.path.substr(0, row.path.find_first_of(".[")));
        if (row.written && !row.written(p, &p.lights[1])) {
            continue;
        }
        if (std::find(expected.begin(), expected.end(), top) == expected.end()) {
            expected.push_back(top);
        }
    }
    EXPECT_EQ(written, expected);
    std::vector<std::string> lightKeys;
    for (const auto& [key, value] : j["lights"][1].items()) {
        lightKeys.push_back(key);
    }
    EXPECT_EQ(lightKeys, (std::vector<std::string>{"type", "position", "direction", "ambient", "diffuse", "specular",
                                                   "attenuation", "cutoff_deg", "exponent", "enabled", "orbit"}));
}

TEST(FieldTable, EveryRangedRowRefusesAValueOutsideItsRangeWithTheRangesWords) {
    for (const FieldRow& row : fieldRows()) {
        if (!row.range || row.range->max == limits::kUnbounded) {
            continue;
        }
        std::string path = fieldPath(row, 1); // the spot light, which moves: every light row is written
        Json j = Json::parse(presetToJson(everyRowPreset()));
        Json* at = &j;
        std::optional<std::vector<PathStep>> steps = parseFieldPath(path);
        for (const PathStep& s : *steps) {
            at = s.isIndex() ? &(*at)[s.index] : &(*at)[s.name];
        }
        bool triplet = at->is_array();
        (triplet ? (*at)[0] : *at) = double(row.range->max) * 2.0 + 1.0;
        Diagnostics d;
        EXPECT_FALSE(parsePreset(j.dump(), "t.json", std::nullopt, d)) << path;
        ASSERT_FALSE(d.empty()) << path;
        EXPECT_EQ(d.front().where, triplet ? path + "[0]" : path);
        EXPECT_NE(d.front().message.find(row.range->text), std::string::npos) << path << ": " << d.front().message;
    }
}

TEST(FieldTable, RowsAreWhole) {
    std::set<std::string_view> paths;
    for (const FieldRow& row : fieldRows()) {
        EXPECT_TRUE(paths.insert(row.path).second) << row.path << " is described twice";
        EXPECT_NE(row.at, nullptr) << row.path;
        EXPECT_FALSE(row.label.empty()) << row.path;
        EXPECT_FALSE(row.help.empty()) << row.path;
        bool ranged = row.kind == FieldKind::Number || row.kind == FieldKind::Vec3 || row.kind == FieldKind::Color ||
                      row.kind == FieldKind::Direction;
        EXPECT_EQ(row.range != nullptr, ranged) << row.path;
        EXPECT_EQ(row.intRange != nullptr, row.kind == FieldKind::Int2) << row.path;
        EXPECT_EQ(!row.choices.empty(), row.kind == FieldKind::Choice) << row.path;
        for (std::size_t i = 0; i < row.choices.size(); ++i) { // in the order of the values: label() indexes them
            EXPECT_EQ(row.choices[i].value, static_cast<int>(i)) << row.path;
        }
        EXPECT_EQ(fieldRow(fieldPath(row, 3)), &row) << row.path;
    }
}

TEST(FieldTable, PathsNameRowsObjectsAndElements) {
    EXPECT_EQ(fieldRow("material.shininess")->range, &limits::kShininess);
    EXPECT_EQ(fieldRow("lights[7].cutoff_deg")->path, "lights[].cutoff_deg");
    EXPECT_EQ(fieldRow("lights[07].cutoff_deg")->path, "lights[].cutoff_deg");
    EXPECT_EQ(fieldRow("material.diffuse[1]")->path, "material.diffuse");
    EXPECT_EQ(fieldRow("lights[8].cutoff_deg"), nullptr); // at most limits::kMaxLights
    EXPECT_EQ(fieldRow("material"), nullptr);             // an object is no row
    EXPECT_EQ(fieldRow("material.shininess[0]"), nullptr);
    for (std::string_view known : {"material", "lights", "lights[0]", "lights[7].orbit", "lights[0].attenuation[2]",
                                   "model.subdivisions[1]", "model.gltf", "camera", "plot.incident_deg"}) {
        EXPECT_TRUE(isFieldPath(known)) << known;
    }
    for (std::string_view unknown : {"materials", "material.diffuse_x", "material.diffuse[3]", "lights[8]", "lights[0][1]",
                                     "check", "sweep", "format", "Material", "", "material.", "lights[]"}) {
        EXPECT_FALSE(isFieldPath(unknown)) << unknown;
    }
    EXPECT_EQ(fieldPath(*fieldRow("lights[].exponent"), 2), "lights[2].exponent");
    EXPECT_EQ(fieldLabel(*fieldRow("lights[].cutoff_deg")), "cut-off (deg)");
}

TEST(FieldPath, OneGrammarLeadingZerosAllowed) {
    EXPECT_EQ(canonicalPath("lights[00].attenuation[2]"), "lights[0].attenuation[2]");
    EXPECT_EQ(canonicalPath("lights[007]"), "lights[7]");
    EXPECT_EQ(parseFieldPath("lights[1].attenuation")->size(), 3u);
    for (std::string_view bad : {"", ".a", "a.", "a..b", "a[", "a[]", "a[1234]", "a[x]", "A", "a b", "[0]", "a.[0]"}) {
        EXPECT_FALSE(parseFieldPath(bad)) << bad;
    }
    EXPECT_TRUE(covers("lights[0]", "lights[0].attenuation"));
    EXPECT_TRUE(covers("material", "material"));
    EXPECT_FALSE(covers("material.diffuse", "material.diffuse_x"));
    EXPECT_TRUE(overlaps("material.diffuse", "material"));
}

TEST(FileHeader, OneCheckForPresetsAndExercisesWithTheOthersHint) {
    Json preset = {{"format", "lighting-lab-preset"}, {"version", 1}};
    Json exercise = {{"format", "lighting-lab-exercise"}, {"version", 1}};
    EXPECT_FALSE(fileHeaderProblem(preset, kPresetFile));
    EXPECT_FALSE(fileHeaderProblem(exercise, kExerciseFile));
    EXPECT_EQ(fileHeaderProblem(exercise, kPresetFile)->message,
              R"(expected "lighting-lab-preset", got "lighting-lab-exercise" (this is an exercise, not a preset))");
    EXPECT_EQ(fileHeaderProblem(preset, kExerciseFile)->message,
              R"(expected "lighting-lab-exercise", got "lighting-lab-preset" (this is a preset, not an exercise))");
    Json newer = {{"format", "lighting-lab-preset"}, {"version", 2}};
    EXPECT_EQ(fileHeaderProblem(newer, kPresetFile)->key, "version");
    EXPECT_NE(fileHeaderProblem(newer, kPresetFile)->message.find("newer than this program reads"), std::string::npos);
    Json none = Json::object();
    EXPECT_EQ(fileHeaderProblem(none, kExerciseFile)->message, R"(missing; expected "lighting-lab-exercise")");
    Json longFormat = {{"format", std::string(500, 'x')}, {"version", 1}};
    EXPECT_LT(fileHeaderProblem(longFormat, kPresetFile)->message.size(), 200u); // shortened
}

} // namespace
} // namespace lab
