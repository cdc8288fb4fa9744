// sweep_test.cpp — sweeps (core/scene/sweep.h): the arguments, their validation as a preset's, the
// cells' presets, and the grid against single renders of the same values, pixel for pixel.
#include "cli/commands.h"
#include "core/plots/sweep_grid.h"
#include "core/scene/sweep.h"
#include "gl_suite.h"
#include "render/offscreen.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <cstring>

namespace lab {
namespace {

//----------------------------------------------------------------------------------------
// Arguments: syntax only
//----------------------------------------------------------------------------------------

struct AxisCase {
    const char* text;
    const char* key;                  // nullptr: refused
    std::vector<std::string> values;  // when accepted
    const char* error;                // part of the message when refused
};

const AxisCase kAxisCases[] = {
    {"material.shininess=10,20,30,50", "material.shininess", {"10", "20", "30", "50"}, ""},
    {" material.specular = 0.2 , 0.5,1 ", "material.specular", {"0.2", "0.5", "1"}, ""},
    {"material.diffuse=[1,0,0],[0, 1, 0],0.5", "material.diffuse", {"[1,0,0]", "[0, 1, 0]", "0.5"}, ""},
    {"brdf=phong,blinn-phong", "brdf", {"phong", "blinn-phong"}, ""},
    {"material.shininess=7", "material.shininess", {"7"}, ""},
    {"material.shininess", nullptr, {}, "expected KEY=V1,V2,..."},
    {"=1,2", nullptr, {}, "no key before '='"},
    {"material.shininess=", nullptr, {}, "value 1 is empty"},
    {"material.shininess=10,,20", nullptr, {}, "value 2 is empty"},
    {"material.shininess=10,20,", nullptr, {}, "value 3 is empty"},
    {"material.shininess=1,2,3,4,5,6,7,8,9,10,11", nullptr, {}, "at most 10 values, got 11"},
    // A bracket left open or closed unopened is refused, not cut off (the value "[0,0,0" was dropped).
    {"material.specular=[1,1,1],[0,0,0", nullptr, {}, "value 2 \"[0,0,0\" leaves a '[' open"},
    {"material.specular=[0,0,0", nullptr, {}, "value 1 \"[0,0,0\" leaves a '[' open"},
    {"material.specular=[[1,1,1]", nullptr, {}, "value 1 \"[[1,1,1]\" leaves a '[' open"},
    {"material.specular=1],2", nullptr, {}, "value 1 \"1]\" closes a ']' it did not open"},
    {"material.specular=[1,1,1]],2", nullptr, {}, "value 1 \"[1,1,1]]\" closes a ']' it did not open"},
};

TEST(SweepAxis, ParsesOrNamesTheProblem) {
    for (const AxisCase& c : kAxisCases) {
        SCOPED_TRACE(c.text);
        std::string error;
        std::optional<SweepAxis> axis = parseSweepAxis(c.text, error);
        if (c.key) {
            ASSERT_TRUE(axis) << error;
            EXPECT_EQ(axis->key, c.key);
            EXPECT_EQ(axis->values, c.values);
        } else {
            EXPECT_FALSE(axis);
            EXPECT_NE(error.find(c.error), std::string::npos) << error;
        }
    }
}

//----------------------------------------------------------------------------------------
// Validation against a preset: the preset reader's rules and wording
//----------------------------------------------------------------------------------------

struct CellsCase {
    std::vector<std::string> arguments;
    const char* error; // "" when accepted; else the whole message
};

const CellsCase kCellsCases[] = {
    {{"material.shininess=10,20,30,50", "material.specular=0.2,0.5,1"}, ""},
    {{"brdf=phong,blinn-phong,cook-torrance"}, ""},
    {{"lights[0].attenuation=[1,0,0],[1,0.5,0]", "lights[0].attenuation[2]=0,1"},
     "lights[0].attenuation and lights[0].attenuation[2] overlap"},
    {{"material.shininess=-1"}, "material.shininess=-1: must be in [0.001, 1000000], got -1"},
    {{"material.shininess=10,abc"}, "material.shininess=abc: expected a number, got a string"},
    {{"material.specular=0.5,2"}, "material.specular=2: material.specular[0]: must be in [0, 1], got 2"},
    {{"material.specular=[1,1]"}, "material.specular=[1,1]: expected an array of 3 numbers, got an array of 2"},
    {{"cook_torrance.roughness=0"}, "cook_torrance.roughness=0: must be in [0.001, 10], got 0"},
    {{"brdf=blinn"}, "brdf=blinn: expected one of \"phong\", \"blinn-phong\", \"cook-torrance\", got \"blinn\""},
    {{"brdf=blin-phong"}, "brdf=blin-phong: expected one of \"phong\", \"blinn-phong\", \"cook-torrance\", got \"blin-phong\" (did you mean \"blinn-phong\"?)"},
    {{"lights[0].attenuation=0"}, "lights[0].attenuation=0: c0, c1 and c2 must not all be 0"},
    {{"camera.near=200"}, "camera.near=200: camera.far: must be greater than near"},
    {{"material.shinyness=1"}, "material.shinyness: unknown key (did you mean \"material.shininess\"?)"},
    {{"lights[3].diffuse=1"}, "lights[3].diffuse: unknown key (the preset has 1)"},
    {{"material=1"}, "material: not a single value; name one of its keys"},
    {{"name=a,b"}, "name: not a key a sweep varies"},
    {{"model.scale=1,2"}, "model.scale: not a key a sweep varies"},
    {{"Material.Shininess=1"}, "Material.Shininess: not a preset key"},
    {{"material.shininess=1", "material.shininess=2"}, "material.shininess: the same key twice"},
    // Two spellings of one key are one key (the second would overwrite the first in every cell).
    {{"lights[0].attenuation=[1,0,0]", "lights[00].attenuation=[2,0,0]"},
     "lights[0].attenuation and lights[00].attenuation: the same key twice"},
    {{"lights[0].attenuation[2]=0,1", "lights[000].attenuation=[1,0,0]"},
     "lights[0].attenuation[2] and lights[000].attenuation overlap"},
    // Keys no render shows would make a grid of one picture.
    {{"plot.incident_deg=10,80"}, "plot.incident_deg: changes no render"},
    {{"lights[0].orbit.degrees_per_second=10,80"}, "lights[0].orbit.degrees_per_second: changes no render"},
    {{"material.shininess=1", "material.specular=1", "material.diffuse=1"}, "one or two keys"},
};

LoadedPreset basePreset() {
    Diagnostics d;
    std::optional<LoadedPreset> p = loadPreset(LAB_SOURCE_DIR "/presets/06-shininess-10.json", d);
    EXPECT_TRUE(p) << toString(d);
    return p ? *p : LoadedPreset{};
}

std::vector<SweepAxis> axesOf(const std::vector<std::string>& arguments) {
    std::vector<SweepAxis> axes;
    for (const std::string& a : arguments) {
        std::string error;
        std::optional<SweepAxis> axis = parseSweepAxis(a, error);
        EXPECT_TRUE(axis) << error;
        axes.push_back(axis.value_or(SweepAxis{}));
    }
    return axes;
}

TEST(SweepCells, EveryValueIsValidatedAsAPresetsWithItsMessage) {
    LoadedPreset base = basePreset();
    for (const CellsCase& c : kCellsCases) {
        SCOPED_TRACE(c.arguments.front());
        std::string error;
        std::optional<SweepCells> cells = sweepCells(base, axesOf(c.arguments), error);
        if (*c.error == '\0') {
            EXPECT_TRUE(cells) << error;
        } else {
            EXPECT_FALSE(cells);
            EXPECT_EQ(error.substr(0, std::strlen(c.error)), c.error);
        }
    }
}

TEST(SweepCells, TheFirstKeyRunsAlongTheColumnsTheSecondDownTheRows) {
    LoadedPreset base = basePreset();
    std::string error;
    std::optional<SweepCells> cells =
        sweepCells(base, axesOf({"material.shininess=10,20,30,50", "material.specular=0.2,0.5,1"}), error);
    ASSERT_TRUE(cells) << error;
    ASSERT_EQ(cells->columns, 4);
    ASSERT_EQ(cells->rows, 3);
    const float shininess[] = {10, 20, 30, 50}, specular[] = {0.2f, 0.5f, 1.0f};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 4; ++column) {
            Preset expected = base.preset;
            expected.material.shininess = shininess[column];
            expected.material.specular = glm::vec3(specular[row]);
            EXPECT_EQ(cells->presets[static_cast<std::size_t>(row * 4 + column)].preset, expected) << row << "," << column;
        }
    }
    // Triplets as [r,g,b], names, and one element of a triplet.
    cells = sweepCells(base, axesOf({"material.diffuse=[1,0,0.5]", "brdf=cook-torrance"}), error);
    ASSERT_TRUE(cells) << error;
    EXPECT_EQ(cells->presets[0].preset.material.diffuse, glm::vec3(1, 0, 0.5f));
    EXPECT_EQ(cells->presets[0].preset.brdf, BrdfModel::CookTorrance);
    cells = sweepCells(base, axesOf({"lights[0].attenuation[1]=0.25"}), error);
    ASSERT_TRUE(cells) << error;
    EXPECT_EQ(cells->presets[0].preset.lights[0].attenuation, glm::vec3(1, 0.25f, 0));
}

TEST(SweepCells, EverySuggestedKeyAndRangeIsAccepted) {
    for (BrdfModel brdf : {BrdfModel::Phong, BrdfModel::CookTorrance}) {
        LoadedPreset base = basePreset();
        base.preset.brdf = brdf;
        base.preset.lights.push_back(LightDesc{LightType::Spot});
        for (const SweepKeySuggestion& s : sweepKeySuggestions(base.preset)) {
            std::string error;
            EXPECT_TRUE(sweepCells(base, axesOf({s.key + "=" + s.values}), error)) << s.key << ": " << error;
        }
    }
}

// The suggestions follow the field table's rows that apply: the BRDF's own lobe first, the other
// BRDF's lobe parameter offered too (for a grid across BRDFs), nothing that cannot change the picture.
TEST(SweepCells, SuggestionsAreTheRowsThatApplyTheLobeFirst) {
    auto keysOf = [](const Preset& p) {
        std::vector<std::string> keys;
        for (const SweepKeySuggestion& s : sweepKeySuggestions(p)) {
            keys.push_back(s.key);
        }
        return keys;
    };
    auto has = [](const std::vector<std::string>& keys, const std::string& key) {
        return std::find(keys.begin(), keys.end(), key) != keys.end();
    };
    auto at = [](const std::vector<std::string>& keys, const std::string& key) {
        return std::find(keys.begin(), keys.end(), key) - keys.begin();
    };
    Preset phong;
    std::vector<std::string> keys = keysOf(phong);
    ASSERT_FALSE(keys.empty());
    EXPECT_EQ(keys.front(), "material.shininess");
    EXPECT_TRUE(has(keys, "cook_torrance.roughness")); // the other BRDF's lobe
    EXPECT_FALSE(has(keys, "cook_torrance.ior"));      // changes nothing under Phong
    EXPECT_FALSE(has(keys, "lights[0].cutoff_deg"));   // a point light has no cone
    EXPECT_TRUE(has(keys, "lights[0].attenuation[1]"));
    EXPECT_EQ(at(keys, "cook_torrance.roughness"), at(keys, "material.specular") + 1); // after the colours
    EXPECT_LT(at(keys, "cook_torrance.roughness"), at(keys, "brdf"));
    EXPECT_EQ(keys.back(), "camera.fovy_deg");
    Preset ct;
    ct.brdf = BrdfModel::CookTorrance;
    ct.lights[0].type = LightType::Spot;
    keys = keysOf(ct);
    EXPECT_EQ(std::vector<std::string>(keys.begin(), keys.begin() + 2),
              (std::vector<std::string>{"cook_torrance.roughness", "cook_torrance.ior"}));
    EXPECT_TRUE(has(keys, "lights[0].cutoff_deg"));
    EXPECT_EQ(at(keys, "material.shininess"), at(keys, "material.specular") + 1);
}

//----------------------------------------------------------------------------------------
// The grid: each cell is the single render of its preset, pixel for pixel
//----------------------------------------------------------------------------------------

class SweepGrid : public GlSuite<testing::Test, OffscreenRenderer> {};

TEST_F(SweepGrid, CellsEqualSingleRendersOfTheSameValues) {
    LoadedPreset base = basePreset();
    // Not square, so cells put in each other's places (or transposed) cannot match.
    constexpr int kWidth = 56, kHeight = 44;
    std::vector<SweepAxis> axes = axesOf({"material.shininess=10,20,30,50", "material.specular=0.2,0.5,1"});
    std::string error;
    auto renderCell = [](const LoadedPreset& cell, int w, int h, std::string& why) {
        Diagnostics d;
        std::optional<Image> image = renderer_->render(cell, w, h, d);
        why = toString(d);
        return image;
    };
    std::optional<Image> grid = renderSweep(base, axes, kWidth, kHeight, renderCell, error);
    ASSERT_TRUE(grid) << error;
    SweepGridLayout layout = sweepGridLayout(axes, kWidth, kHeight);
    ASSERT_EQ(grid->width, layout.width);
    ASSERT_EQ(grid->height, layout.height);
    const float shininess[] = {10, 20, 30, 50}, specular[] = {0.2f, 0.5f, 1.0f};
    std::vector<Image> singles;
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 4; ++column) {
            // The single render: the preset's struct set by hand, not through the sweep.
            LoadedPreset single = base;
            single.preset.material.shininess = shininess[column];
            single.preset.material.specular = glm::vec3(specular[row]);
            Diagnostics d;
            std::optional<Image> expected = renderer_->render(single, kWidth, kHeight, d);
            ASSERT_TRUE(expected) << toString(d);
            int differing = 0;
            for (int y = 0; y < kHeight; ++y) {
                const std::uint8_t* got =
                    grid->rgb.data() + (static_cast<std::size_t>(layout.cellY(row) + y) * grid->width + layout.cellX(column)) * 3;
                const std::uint8_t* want = expected->rgb.data() + static_cast<std::size_t>(y) * kWidth * 3;
                differing += std::memcmp(got, want, kWidth * 3) != 0;
            }
            EXPECT_EQ(differing, 0) << "cell row " << row << " column " << column << ": rows of pixels differ";
            singles.push_back(std::move(*expected));
        }
    }
    // The values change the picture (else the comparison above would prove nothing).
    EXPECT_NE(singles[0].rgb, singles[3].rgb);
    EXPECT_NE(singles[0].rgb, singles[8].rgb);
    // The page around the cells carries labels: some ink above the first row and left of the cells.
    auto inkIn = [&](int x0, int y0, int x1, int y1) {
        int ink = 0;
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                ink += grid->rgb[(static_cast<std::size_t>(y) * grid->width + x) * 3] < 128;
            }
        }
        return ink;
    };
    EXPECT_GT(inkIn(layout.left, 0, layout.width, layout.top), 20);
    EXPECT_GT(inkIn(0, layout.top, layout.left, layout.height), 20);
}

// `lab render --sweep` frames a glTF preset without camera or lights first, as `lab render` does:
// sweeping its light's default specular gives the plain render (the light placed for the model),
// and another value changes it. (Before, a swept light was left at the unit sphere's (2, 2, 2),
// inside a large model's framing.)
TEST(SweepCommand, AFramedModelsSweptLightIsTheFramedLight) {
    namespace fs = std::filesystem;
    TempFolder dir;
    fs::copy_file(LAB_SOURCE_DIR "/presets/models/trefoil.glb", dir.path() / "trefoil.glb");
    // Scaled up, so the unframed default light (2, 2, 2) would sit inside the knot's framing.
    writeText(dir.path() / "knot.json", R"({"format": "lighting-lab-preset", "version": 1,
        "model": {"gltf": "trefoil.glb", "scale": [40, 40, 40]}})");
    const Size size{40, 32};
    ASSERT_EQ(runRender({dir.path() / "knot.json"}, dir.path() / "single.png", size), 0);
    std::vector<SweepAxis> axes = axesOf({"lights[0].specular=1,0"});
    ASSERT_EQ(runSweep({dir.path() / "knot.json"}, axes, dir.path() / "grid.png", size), 0);
    std::string error;
    std::optional<Image> single = readPng(dir.path() / "single.png", error), grid = readPng(dir.path() / "grid.png", error);
    ASSERT_TRUE(single && grid) << error;
    SweepGridLayout layout = sweepGridLayout(axes, size.width, size.height);
    auto cell = [&](int column) {
        Image c{size.width, size.height, {}};
        for (int y = 0; y < size.height; ++y) {
            const std::uint8_t* row = grid->rgb.data() + (static_cast<std::size_t>(layout.cellY(0) + y) * grid->width + layout.cellX(column)) * 3;
            c.rgb.insert(c.rgb.end(), row, row + size.width * 3);
        }
        return c;
    };
    EXPECT_EQ(cell(0).rgb, single->rgb) << "specular 1 (the default) is the plain render";
    EXPECT_NE(cell(1).rgb, single->rgb) << "specular 0 changes it";
}

} // namespace
} // namespace lab
