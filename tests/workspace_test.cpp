// workspace_test.cpp — files, links, drops and undo of the editing state, headless: no window,
// no ImGui, no GL. What went wrong must leave the scene exactly as it was, with a problem that
// says why.
#include "app/figure_export.h"
#include "app/workspace.h"

#include "core/gltf/model_loader.h"
#include "core/scene/camera.h"
#include "core/share/share_link.h"
#include "box_gltf.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace lab {
namespace {

namespace fs = std::filesystem;

const fs::path kPresets = fs::path(LAB_SOURCE_DIR) / "presets";
const fs::path kModel = kPresets / "models" / "trefoil.glb";

// A workspace over a temporary folder with two presets in it.
struct Fixture {
    TempFolder dir;
    Workspace ws{WorkspaceOptions{{}, {}, false, {}}};
    fs::path red, blue;

    Fixture() {
        red = dir.path() / "red.json";
        blue = dir.path() / "blue.json";
        Preset p;
        p.name = "red";
        p.material.diffuse = {1, 0, 0};
        Diagnostics d;
        EXPECT_TRUE(savePreset(p, red, d));
        p.name = "blue";
        p.material.diffuse = {0, 0, 1};
        EXPECT_TRUE(savePreset(p, blue, d));
        ws = Workspace(WorkspaceOptions{{}, dir.path() / "shots", false, dir.path() / "user"});
        ws.start(dir.path(), red);
        EXPECT_TRUE(ws.takeProblems().empty());
    }
};

std::string titles(const std::vector<Problem>& problems) {
    std::string s;
    for (const Problem& p : problems) {
        s += p.title + "\n" + toString(p.diagnostics);
    }
    return s;
}

TEST(Workspace, OpensAPresetAndListsItsFolder) {
    Fixture f;
    EXPECT_EQ(f.ws.document().file(), f.red);
    EXPECT_EQ(f.ws.a().material.diffuse, glm::vec3(1, 0, 0));
    ASSERT_EQ(f.ws.presetFiles().size(), 2u);
    EXPECT_EQ(f.ws.presetFiles()[static_cast<std::size_t>(f.ws.currentPreset())], f.red);
    f.ws.run({Command::NextPreset}); // blue sorts first: red is last, and the next wraps around
    EXPECT_EQ(f.ws.document().file(), f.blue);
    f.ws.run({Command::PreviousPreset});
    EXPECT_EQ(f.ws.document().file(), f.red);
}

TEST(Workspace, ABrokenFileLeavesTheSceneAsItWasAndSaysWhere) {
    Fixture f;
    f.ws.a().material.shininess = 77.0f; // an unsaved edit
    Preset before = f.ws.a();
    fs::path broken = f.dir.path() / "broken.json";
    writeText(broken, R"({"format": "lighting-lab-preset", "version": 1, "material": {"shininess": -3}})");
    f.ws.open(broken);
    std::vector<Problem> problems = f.ws.takeProblems();
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].title.find("broken.json"), std::string::npos);
    EXPECT_NE(toString(problems[0].diagnostics).find("material.shininess"), std::string::npos) << titles(problems);
    EXPECT_EQ(f.ws.a(), before);
    EXPECT_EQ(f.ws.document().file(), f.red);
    EXPECT_FALSE(f.ws.question()); // nothing to confirm: nothing will happen
}

TEST(Workspace, UnsavedEditsAreNotDroppedWithoutAnAnswer) {
    Fixture f;
    f.ws.a().material.shininess = 5.0f;
    f.ws.open(f.blue);
    ASSERT_TRUE(f.ws.question());
    EXPECT_EQ(*f.ws.question(), "open blue.json");
    f.ws.answer(UnsavedAnswer::Cancel);
    EXPECT_EQ(f.ws.document().file(), f.red);
    EXPECT_EQ(f.ws.a().material.shininess, 5.0f);

    f.ws.open(f.blue);
    f.ws.answer(UnsavedAnswer::SaveFirst); // saves red.json, then opens blue
    EXPECT_EQ(f.ws.document().file(), f.blue);
    Diagnostics d;
    EXPECT_EQ(loadPreset(f.red, d)->preset.material.shininess, 5.0f);

    f.ws.a().material.shininess = 9.0f;
    f.ws.requestQuit();
    EXPECT_FALSE(f.ws.quit());
    f.ws.answer(UnsavedAnswer::Discard);
    EXPECT_TRUE(f.ws.quit());
}

TEST(Workspace, SaveAsWritesANewFileThatBecomesTheDocument) {
    Fixture f;
    f.ws.a().material.shininess = 12.0f;
    fs::path copy = f.dir.path() / "sub" / "copy.json";
    fs::create_directories(copy.parent_path());
    f.ws.run({Command::SaveAs, copy.string()});
    EXPECT_TRUE(f.ws.takeProblems().empty());
    EXPECT_EQ(f.ws.document().file(), copy);
    EXPECT_FALSE(f.ws.document().dirty());
    Diagnostics d;
    EXPECT_EQ(loadPreset(copy, d)->preset.material.shininess, 12.0f);
    EXPECT_NE(loadPreset(f.red, d)->preset.material.shininess, 12.0f); // the original is untouched

    f.ws.run({Command::SaveAs, ""});
    EXPECT_EQ(f.ws.takeProblems().size(), 1u); // no path typed
    f.ws.run({Command::SaveAs, (f.dir.path() / "no-such-folder" / "x.json").string()});
    EXPECT_EQ(f.ws.takeProblems().size(), 1u);
    EXPECT_EQ(f.ws.document().file(), copy);
}

TEST(Workspace, RevertReturnsToTheFileAndIsUndoable) {
    Fixture f;
    f.ws.a().material.shininess = 3.0f;
    f.ws.endFrame(false);
    f.ws.run({Command::Revert});
    EXPECT_FALSE(f.ws.document().dirty());
    f.ws.run({Command::Undo});
    EXPECT_EQ(f.ws.a().material.shininess, 3.0f);
}

TEST(Workspace, UndoWalksAcrossCompareEdits) {
    Fixture f;
    f.ws.run({Command::ToggleCompare});
    ASSERT_TRUE(f.ws.view.compare);
    EXPECT_EQ(f.ws.b().shading, Shading::Gouraud); // B starts as A with the other shading
    f.ws.endFrame(false);
    f.ws.view.editingB = true;
    f.ws.run({Command::NextBrdf}); // edits B
    f.ws.endFrame(false);
    EXPECT_EQ(f.ws.b().brdf, BrdfModel::BlinnPhong);
    EXPECT_EQ(f.ws.a().brdf, BrdfModel::Phong);
    f.ws.view.editingB = false;
    f.ws.run({Command::ShadingFlat}); // edits A
    f.ws.endFrame(false);
    f.ws.run({Command::Undo});
    EXPECT_EQ(f.ws.a().shading, Shading::Phong);
    EXPECT_EQ(f.ws.b().brdf, BrdfModel::BlinnPhong);
    f.ws.run({Command::Undo});
    EXPECT_EQ(f.ws.b().brdf, BrdfModel::Phong);
    EXPECT_FALSE(f.ws.document().dirty()); // B's edits never make the file dirty
}

TEST(Workspace, ALinkRoundTripsTheSceneAndABrokenLinkChangesNothing) {
    Fixture f;
    f.ws.a().material.shininess = 64.0f;
    f.ws.a().brdf = BrdfModel::CookTorrance;
    std::string link = f.ws.link();
    ASSERT_EQ(link.rfind("z=", 0), 0u);
    Preset shared = f.ws.a();

    Fixture g;
    g.ws.openLink(link);
    EXPECT_TRUE(g.ws.takeProblems().empty());
    Preset opened = g.ws.a();
    EXPECT_EQ(opened, shared);
    EXPECT_TRUE(g.ws.document().file().empty()); // a link is untitled

    g.ws.openLink("p=not-base64!");
    EXPECT_EQ(g.ws.takeProblems().size(), 1u);
    EXPECT_EQ(g.ws.a(), opened);
}

// A scene whose link would be longer than a link may be (a long description) cannot be copied as a
// link (a problem says how long it is), and is opened again from the page's saved state only.
TEST(Workspace, ASceneWhoseLinkIsTooLongIsKeptButNotShared) {
    Fixture f;
    std::string text;
    for (unsigned i = 0; text.size() < 2 * kMaxLinkChars; ++i) {
        text += std::to_string(i * 2654435761u) + " "; // digits that do not deflate away
    }
    f.ws.a().description = text;
    const std::string link = f.ws.link();
    ASSERT_GT(link.size(), kMaxLinkChars);
    EXPECT_FALSE(f.ws.linkShareable());
    std::string problems = titles(f.ws.takeProblems());
    EXPECT_NE(problems.find("Cannot copy the link"), std::string::npos) << problems;
    EXPECT_NE(problems.find("would be " + std::to_string(link.size()) + " characters, more than the 16384"), std::string::npos)
        << problems;

    Fixture g;
    g.ws.openLink(link); // as an address: refused, nothing changed
    EXPECT_NE(titles(g.ws.takeProblems()).find("longer than 16384 characters"), std::string::npos);
    EXPECT_NE(g.ws.a().description, text);
    g.ws.openLink(link, true); // as the page's saved state
    EXPECT_TRUE(g.ws.takeProblems().empty());
    EXPECT_EQ(g.ws.a().description, text);
    g.ws.a().description = "short";
    EXPECT_TRUE(g.ws.linkShareable());
    EXPECT_TRUE(g.ws.takeProblems().empty());
}

// An inline link's glTF preset without a camera is framed as a file's is: from three-quarters;
// one with a camera keeps it.
TEST(Workspace, ALinkedGltfPresetWithoutACameraIsFramed) {
    TempFolder user;
    Workspace ws{WorkspaceOptions{{kPresets}, {}, false, user.path()}}; // links resolve models in the bundled presets
    const std::string model = R"({"format": "lighting-lab-preset", "version": 1, "model": {"gltf": "models/trefoil.glb"})";
    ws.openLink("p=" + base64UrlEncode(model + "}"));
    ASSERT_TRUE(ws.takeProblems().empty());
    const Camera& framed = ws.a().camera;
    EXPECT_NE(framed.eye, Camera{}.eye);
    EXPECT_GT(glm::dot(glm::normalize(framed.eye - framed.target), threeQuarterDirection()), 0.9999f);
    ws.openLink("p=" + base64UrlEncode(model + R"(, "camera": {}})"));
    ASSERT_TRUE(ws.takeProblems().empty());
    EXPECT_EQ(ws.a().camera.eye, Camera{}.eye) << "a camera in the link is used as it is";
}

// A copy of presets/ as the shipped folder, so the test can see it stay byte for byte.
struct ShippedFixture {
    TempFolder dir;
    fs::path shipped = dir.path() / "presets", user = dir.path() / "user";
    Workspace ws{WorkspaceOptions{{shipped}, dir.path() / "shots", false, user}};

    ShippedFixture() {
        fs::copy(kPresets, shipped, fs::copy_options::recursive);
        ws.start(dir.path(), shipped / "05-full-phong.json");
    }
};

TEST(Workspace, SavingAShippedPresetWritesACopyInTheUserFolder) {
    ShippedFixture f;
    std::string before = readText(f.shipped / "05-full-phong.json");
    f.ws.a().material.shininess = 3.0f;
    f.ws.run({Command::Save});
    EXPECT_TRUE(f.ws.takeProblems().empty());
    EXPECT_EQ(readText(f.shipped / "05-full-phong.json"), before);
    EXPECT_EQ(f.ws.document().file(), f.user / "05-full-phong.json");
    Diagnostics d;
    EXPECT_EQ(loadPreset(f.user / "05-full-phong.json", d)->preset.material.shininess, 3.0f);
    ASSERT_FALSE(f.ws.takeNotes().empty());

    f.ws.saveTo(f.shipped / "05-full-phong.json"); // Save as over a shipped file
    EXPECT_EQ(f.ws.takeProblems().size(), 1u);
    EXPECT_EQ(readText(f.shipped / "05-full-phong.json"), before);
}

TEST(Workspace, SaveFirstOnAShippedPresetKeepsItToo) {
    ShippedFixture f;
    std::string before = readText(f.shipped / "05-full-phong.json");
    f.ws.a().material.diffuse = {0, 1, 0};
    f.ws.open(f.shipped / "06-shininess-10.json"); // by path: asked (stepping would keep the edits: slides_test.cpp)
    ASSERT_TRUE(f.ws.question());
    f.ws.answer(UnsavedAnswer::SaveFirst);
    EXPECT_EQ(readText(f.shipped / "05-full-phong.json"), before);
    EXPECT_TRUE(fs::exists(f.user / "05-full-phong.json"));
    EXPECT_EQ(f.ws.document().file().filename(), "06-shininess-10.json");
}

TEST(Workspace, LookingAroundIsNotAnUnsavedChangeButIsUndoable) {
    Fixture f;
    f.ws.a().camera.eye = {3, 1, 2}; // an orbit
    f.ws.endFrame(false);
    EXPECT_FALSE(f.ws.document().dirty());
    f.ws.run({Command::NextPreset});
    EXPECT_FALSE(f.ws.question()); // no prompt: the next preset opens
    EXPECT_EQ(f.ws.document().file(), f.blue);
    f.ws.open(f.red);
    f.ws.a().camera.eye = {3, 1, 2};
    f.ws.endFrame(false);
    f.ws.run({Command::Undo});
    EXPECT_EQ(f.ws.a().camera, Camera{});
}

TEST(Workspace, ABundledPresetIsLinkedByName) {
    Workspace ws(WorkspaceOptions{{kPresets}, {}, false, {}});
    ws.start(kPresets, kPresets / "05-full-phong.json");
    EXPECT_EQ(ws.link(), "preset=05-full-phong");
    ws.a().material.shininess += 1.0f;
    EXPECT_EQ(ws.link().rfind("z=", 0), 0u);
}

// The page moves a file a student opens into the shipped presets' folder (so its model paths
// resolve): it is not shipped, and linking it by name would open nothing on anyone else's page.
TEST(Workspace, AFileAddedToTheShippedFolderLaterIsNotLinkedByName) {
    TempFolder shipped;
    Preset p;
    p.name = "shipped";
    Diagnostics d;
    ASSERT_TRUE(savePreset(p, shipped.path() / "one.json", d));
    Workspace ws(WorkspaceOptions{{shipped.path()}, {}, true, {}});
    ws.start(shipped.path(), shipped.path() / "one.json");
    EXPECT_EQ(ws.link(), "preset=one");
    p.name = "uploaded";
    ASSERT_TRUE(savePreset(p, shipped.path() / "uploaded.json", d));
    ws.open(shipped.path() / "uploaded.json");
    ASSERT_EQ(ws.document().file(), shipped.path() / "uploaded.json");
    EXPECT_EQ(ws.link().rfind("z=", 0), 0u) << ws.link();
}

TEST(Workspace, ADroppedModelInsideTheFolderBecomesTheModelAndOneOutsideIsRefused) {
    Fixture f;
    fs::copy_file(kModel, f.dir.path() / "trefoil.glb");
    f.ws.drop({(f.dir.path() / "trefoil.glb").string()});
    EXPECT_TRUE(f.ws.takeProblems().empty());
    EXPECT_EQ(f.ws.a().model.gltf, "trefoil.glb");
    ASSERT_TRUE(f.ws.mesh(Side::A));
    EXPECT_GT(f.ws.mesh(Side::A)->indices.size(), 0u);

    TempFolder elsewhere;
    fs::copy_file(kModel, elsewhere.path() / "outside.glb");
    Preset before = f.ws.a();
    f.ws.drop({(elsewhere.path() / "outside.glb").string()});
    std::vector<Problem> problems = f.ws.takeProblems();
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(toString(problems[0].diagnostics).find("outside this preset's folder"), std::string::npos);
    EXPECT_EQ(f.ws.a(), before);

    f.ws.drop({(f.dir.path() / "notes.txt").string()});
    EXPECT_EQ(f.ws.takeProblems().size(), 1u);
}

// Framing (README: Presets, Framing): a dropped model is framed from three-quarters and its lights
// carried to it in the same undo step as the model change; F frames the current model along the
// current direction; a preset without a camera opens framed.

// How much of a square view's side `points` span as seen from `c` (projected with glm, as the
// renderer does), and the centre of their projection (0: centred).
struct Span {
    float larger = 0.0f;
    glm::vec2 center{0.0f};
};

Span span(const Camera& c, const std::vector<glm::vec3>& points) {
    glm::mat4 clip = glm::perspective(glm::radians(c.fovyDeg), 1.0f, c.near, c.far) * glm::lookAt(c.eye, c.target, c.up);
    glm::vec2 mn(INFINITY), mx(-INFINITY);
    for (const glm::vec3& point : points) {
        glm::vec4 p = clip * glm::vec4(point, 1.0f);
        mn = glm::min(mn, glm::vec2(p) / p.w);
        mx = glm::max(mx, glm::vec2(p) / p.w);
    }
    return {std::max(mx.x - mn.x, mx.y - mn.y) / 2.0f, (mx + mn) / 2.0f};
}

std::vector<glm::vec3> corners(glm::vec3 lo, glm::vec3 hi) {
    std::vector<glm::vec3> c;
    for (int i = 0; i < 8; ++i) {
        c.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    }
    return c;
}

// Issue 25: a model 150 units across dropped on the default scene is seen as a preset without a
// camera sees it, and the scene's lights are carried to it: they stand as far from it, in its
// radii, as they stood from the unit sphere (outside it), and their attenuation falls off over its
// size. One undo restores model, camera and lights.
TEST(Workspace, ADroppedModelIsFramedAndLitInOneUndoStepWithTheModel) {
    Fixture f;
    const glm::vec3 lo(-50.0f, -75.0f, 25.0f), hi(100.0f, 75.0f, 175.0f); // a cube 150 across
    const glm::vec3 center = (lo + hi) / 2.0f;
    const float radius = 75.0f * std::sqrt(3.0f); // every corner is farthest from the centre
    writeBoxGltf(f.dir.path(), "large", lo, hi);
    f.ws.a().camera.eye = {1.0f, 2.0f, 30.0f}; // looking from somewhere else, far away
    f.ws.a().lights[0].attenuation = {1.0f, 0.5f, 0.25f};
    LightDesc spot;
    spot.type = LightType::Spot;
    spot.position = {0.0f, 3.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.attenuation = {0.0f, 1.0f, 2.0f};
    LightDesc sun;
    sun.type = LightType::Directional;
    sun.direction = {1.0f, -1.0f, 0.0f};
    f.ws.a().lights.push_back(spot);
    f.ws.a().lights.push_back(sun);
    f.ws.endFrame(false);
    Preset before = f.ws.a();

    f.ws.drop({(f.dir.path() / "large.gltf").string()});
    f.ws.endFrame(false);
    ASSERT_TRUE(f.ws.takeProblems().empty());
    ASSERT_EQ(f.ws.a().model.gltf, "large.gltf");
    const Preset& after = f.ws.a();
    // The camera: from three-quarters (above the front, turned towards +x), the box spanning 85%.
    glm::vec3 d = glm::normalize(after.camera.eye - after.camera.target);
    EXPECT_NEAR(glm::dot(d, threeQuarterDirection()), 1.0f, 1e-5f);
    EXPECT_GT(d.y, 0.0f);
    EXPECT_GT(d.x, 0.0f);
    Span s = span(after.camera, corners(lo, hi));
    EXPECT_NEAR(s.larger, 0.85f, 0.005f);
    EXPECT_NEAR(s.center.x, 0.0f, 0.005f);
    EXPECT_NEAR(s.center.y, 0.0f, 0.005f);
    EXPECT_EQ(f.ws.b().camera, after.camera);
    // The lights: scaled about the centre by 150 · √3 / 2 over the unit sphere's 1.
    ASSERT_EQ(after.lights.size(), 3u);
    const float k = radius / 1.0f;
    for (std::size_t i : {0u, 1u}) {
        SCOPED_TRACE("light " + std::to_string(i));
        glm::vec3 offset = after.lights[i].position - center;
        EXPECT_GT(glm::length(offset), radius) << "outside the model";
        EXPECT_NEAR(glm::length(offset) / radius, glm::length(before.lights[i].position), 1e-4f) << "as far, in radii";
        EXPECT_NEAR(glm::dot(glm::normalize(offset), glm::normalize(before.lights[i].position)), 1.0f, 1e-5f);
        glm::vec3 a = before.lights[i].attenuation, b = after.lights[i].attenuation;
        EXPECT_EQ(b.x, a.x);
        EXPECT_NEAR(b.y, a.y / k, 1e-6f * a.y);
        EXPECT_NEAR(b.z, a.z / (k * k), 1e-6f * a.z);
        EXPECT_EQ(after.lights[i].direction, before.lights[i].direction);
        EXPECT_EQ(after.lights[i].orbit, before.lights[i].orbit);
    }
    EXPECT_EQ(after.lights[2], sun) << "a directional light keeps its direction";

    f.ws.run({Command::Undo});
    EXPECT_EQ(f.ws.a(), before) << "one undo restores the model, the camera and the lights together";
    f.ws.run({Command::Redo});
    EXPECT_EQ(f.ws.a().model.gltf, "large.gltf");
    EXPECT_NEAR(glm::length(f.ws.a().lights[0].position - center), glm::length(before.lights[0].position) * radius, 0.05f);
}

// A model dropped on a scene with a glTF model: the lights go from its bounds to the new one's.
TEST(Workspace, ADroppedModelCarriesTheLightsFromTheModelBefore) {
    Fixture f;
    writeBoxGltf(f.dir.path(), "small", glm::vec3(9.0f), glm::vec3(11.0f));   // radius √3, centre 10
    writeBoxGltf(f.dir.path(), "large", glm::vec3(-30.0f), glm::vec3(30.0f)); // radius 30 √3, centre 0
    f.ws.drop({(f.dir.path() / "small.gltf").string()});
    f.ws.endFrame(false);
    f.ws.a().lights[0].position = {10.0f, 10.0f, 13.0f}; // 3 above the small box's centre
    f.ws.endFrame(false);
    f.ws.drop({(f.dir.path() / "large.gltf").string()});
    f.ws.endFrame(false);
    ASSERT_TRUE(f.ws.takeProblems().empty());
    EXPECT_LT(glm::distance(f.ws.a().lights[0].position, glm::vec3(0.0f, 0.0f, 90.0f)), 1e-3f) << "3 · 30 above the centre";
}

// In compare mode B compares settings on the same model: a dropped model goes to both halves,
// B's lights carried like A's, and one undo takes both back.
TEST(Workspace, ADroppedModelInCompareModeGoesToBothHalves) {
    Fixture f;
    writeBoxGltf(f.dir.path(), "large", glm::vec3(-30.0f), glm::vec3(30.0f)); // radius 30 √3, centre 0
    f.ws.run({Command::ToggleCompare});
    f.ws.b().lights[0].position = {0.0f, 0.0f, 3.0f};
    f.ws.endFrame(false);
    Preset beforeB = f.ws.b();
    f.ws.drop({(f.dir.path() / "large.gltf").string()});
    f.ws.endFrame(false);
    ASSERT_TRUE(f.ws.takeProblems().empty());
    EXPECT_EQ(f.ws.b().model, f.ws.a().model);
    EXPECT_EQ(f.ws.b().shading, beforeB.shading) << "B keeps its own settings";
    EXPECT_LT(glm::distance(f.ws.b().lights[0].position, glm::vec3(0.0f, 0.0f, 90.0f * std::sqrt(3.0f))), 1e-2f)
        << "3 radii in front of the centre, as it was for the unit sphere";
    f.ws.run({Command::Undo});
    EXPECT_EQ(f.ws.b(), beforeB);
}

// W and N switch the overlays of the shading rate: how the scene is shown, not the scene.
TEST(Workspace, WAndNToggleTheWireframeAndTheVertexNormalsWithoutEditingThePreset) {
    EXPECT_EQ(commandForKey('W', kNoModifier, false), Command::ToggleWireframe);
    EXPECT_EQ(commandForKey('N', kNoModifier, false), Command::ToggleVertexNormals);
    Fixture f;
    f.ws.run({Command::ToggleWireframe});
    f.ws.run({Command::ToggleVertexNormals});
    f.ws.endFrame(false);
    EXPECT_TRUE(f.ws.view.wireframe);
    EXPECT_TRUE(f.ws.view.vertexNormals);
    EXPECT_FALSE(f.ws.document().dirty());
    f.ws.run({Command::ToggleWireframe});
    EXPECT_FALSE(f.ws.view.wireframe);
    EXPECT_TRUE(f.ws.view.vertexNormals);
}

TEST(Workspace, FFramesTheModelTightlyAlongTheViewDirectionAndIsUndoable) {
    EXPECT_EQ(commandForKey('F', kNoModifier, false), Command::FrameModel);
    Fixture f;
    f.ws.a().camera.eye = {30.0f, 10.0f, 50.0f};
    f.ws.a().camera.target = {1.0f, 0.0f, 0.0f};
    f.ws.endFrame(false);
    Camera before = f.ws.a().camera;
    f.ws.run({Command::FrameModel});
    f.ws.endFrame(false);
    const Camera& c = f.ws.a().camera;
    EXPECT_NEAR(glm::dot(glm::normalize(c.eye - c.target), glm::normalize(before.eye - before.target)), 1.0f, 1e-6f)
        << "the view direction is kept";
    // The default sphere's points span 85% of the view, centred.
    Span s = span(c, f.ws.mesh(Side::A)->positions);
    EXPECT_NEAR(s.larger, 0.85f, 0.005f);
    EXPECT_NEAR(s.center.x, 0.0f, 0.005f);
    EXPECT_NEAR(s.center.y, 0.0f, 0.005f);
    EXPECT_EQ(f.ws.a().lights, Preset{}.lights) << "F moves only the camera";
    EXPECT_FALSE(f.ws.document().dirty()) << "a camera move, like the gestures";
    f.ws.run({Command::Undo});
    EXPECT_EQ(f.ws.a().camera, before);
}

TEST(Workspace, APresetWithoutACameraOpensFramedAndKeepsThatCamera) {
    Fixture f;
    fs::copy_file(kModel, f.dir.path() / "trefoil.glb");
    fs::path bare = f.dir.path() / "bare.json";
    writeText(bare, R"({"format": "lighting-lab-preset", "version": 1, "model": {"gltf": "trefoil.glb", "scale": [100, 100, 100]}})");
    f.ws.open(bare);
    ASSERT_TRUE(f.ws.takeProblems().empty());
    ASSERT_EQ(f.ws.document().file(), bare);
    std::optional<Sphere> bounds = drawnBounds(*f.ws.mesh(Side::A), f.ws.a().model);
    std::optional<std::vector<glm::vec3>> drawn = drawnPositions(*f.ws.mesh(Side::A), f.ws.a().model);
    ASSERT_TRUE(bounds && drawn);
    Camera framed = framedCamera(Camera{}, *drawn, threeQuarterDirection());
    EXPECT_EQ(f.ws.a().camera, framed);
    EXPECT_FALSE(f.ws.document().dirty());
    EXPECT_EQ(f.ws.a().lights[0].position, bounds->center + glm::vec3(2.0f) * bounds->radius);
    f.ws.a().camera.eye.x += 5.0f; // look around, then R: back to the framed camera, the preset's own
    f.ws.endFrame(false);
    f.ws.run({Command::ResetCamera});
    EXPECT_EQ(f.ws.a().camera, framed);
    ASSERT_TRUE(f.ws.saveTo(f.dir.path() / "saved.json"));
    Diagnostics d;
    std::optional<LoadedPreset> saved = loadPreset(f.dir.path() / "saved.json", d);
    ASSERT_TRUE(saved) << toString(d);
    EXPECT_EQ(saved->preset.camera, framed) << "saved as an ordinary camera";
    EXPECT_EQ(saved->omitted, OmittedKeys{});
}

TEST(Workspace, SavingElsewhereRebasesTheModelPath) {
    Fixture f;
    fs::create_directories(f.dir.path() / "models");
    fs::copy_file(kModel, f.dir.path() / "models" / "trefoil.glb");
    f.ws.useModel(f.dir.path() / "models" / "trefoil.glb");
    ASSERT_EQ(f.ws.a().model.gltf, "models/trefoil.glb");
    fs::path inside = f.dir.path() / "models" / "next-to-model.json";
    ASSERT_TRUE(f.ws.saveTo(inside));
    EXPECT_EQ(f.ws.a().model.gltf, "trefoil.glb");
    Diagnostics d;
    EXPECT_TRUE(loadPreset(inside, d).has_value()) << toString(d);

    TempFolder elsewhere;
    EXPECT_FALSE(f.ws.saveTo(elsewhere.path() / "far.json")); // the model would be outside
    EXPECT_EQ(f.ws.takeProblems().size(), 1u);
    EXPECT_FALSE(fs::exists(elsewhere.path() / "far.json"));
}

TEST(Workspace, AModelEditThatCannotLoadGoesBackWithAProblem) {
    Fixture f;
    ASSERT_TRUE(f.ws.mesh(Side::A));
    Model good = f.ws.a().model;
    f.ws.a().model.gltf = "missing.glb";
    EXPECT_TRUE(f.ws.mesh(Side::A));
    EXPECT_EQ(f.ws.a().model, good);
    EXPECT_EQ(f.ws.takeProblems().size(), 1u);
}

TEST(Workspace, ScreenshotsAreNumberedFilesOrDownloads) {
    Fixture f;
    Image image{4, 3, std::vector<std::uint8_t>(4 * 3 * 3, 128)};
    f.ws.saveScreenshot(image);
    f.ws.saveScreenshot(image);
    EXPECT_TRUE(fs::exists(f.dir.path() / "shots" / "red-001.png"));
    EXPECT_TRUE(fs::exists(f.dir.path() / "shots" / "red-002.png"));

    Workspace browser(WorkspaceOptions{{}, "/nonexistent-screenshots", true, {}});
    browser.start(f.dir.path(), f.red);
    browser.saveScreenshot(image);
    browser.run({Command::Save});
    std::vector<Download> downloads = browser.takeDownloads();
    ASSERT_EQ(downloads.size(), 2u);
    EXPECT_EQ(downloads[0].name, "red-001.png");
    EXPECT_EQ(downloads[1].name, "red.json");
    Diagnostics d;
    EXPECT_TRUE(parsePreset(downloads[1].bytes, "red.json", std::nullopt, d).has_value()) << toString(d);
}

// Export figures: the five figures as SVG, PNG (at the chosen scale) and CSV, each export in a
// folder of its own beside the screenshots (never over an earlier one), or as downloads.
TEST(Workspace, ExportedFiguresGoToANewFolderEachTimeOrAreDownloads) {
    Fixture f;
    ui::PlotSettings settings;
    std::vector<Download> files = exportFigures(f.ws.a(), nullptr, settings, 1.0f, Theme::Light);
    ASSERT_EQ(files.size(), 15u) << "lobe, overlay, attenuation, albedo and slice, each as SVG, PNG and CSV";
    EXPECT_EQ(files[12].name, "slice.svg");
    std::string error;
    fs::create_directories(f.dir.path() / "shots" / "red-figures-001"); // taken: the next number is used
    f.ws.saveFiles(files, "Figures");
    f.ws.saveFiles(files, "Figures");
    EXPECT_TRUE(f.ws.takeProblems().empty());
    for (const char* folder : {"red-figures-002", "red-figures-003"}) {
        for (const char* name : {"lobe.svg", "overlay.png", "attenuation.csv", "albedo.png", "slice.csv"}) {
            EXPECT_TRUE(fs::exists(f.dir.path() / "shots" / folder / name)) << folder << "/" << name;
        }
    }
    std::optional<Image> png = readPng(f.dir.path() / "shots" / "red-figures-002" / "lobe.png", error);
    ASSERT_TRUE(png) << error;
    EXPECT_EQ(png->width, 720) << "scale 1";
    EXPECT_EQ(readPng(fs::path(f.dir.path() / "shots" / "red-figures-003" / "lobe.png"), error)->rgb, png->rgb);
    Preset dark = f.ws.a();
    dark.lights.clear();
    EXPECT_EQ(exportFigures(dark, nullptr, settings, 2.0f, Theme::Light).size(), 12u) << "no light, no attenuation figure";

    Workspace browser(WorkspaceOptions{{}, "/nonexistent-screenshots", true, {}});
    browser.start(f.dir.path(), f.red);
    browser.saveFiles(files, "Figures");
    std::vector<Download> downloads = browser.takeDownloads();
    ASSERT_EQ(downloads.size(), 15u);
    EXPECT_EQ(downloads[0].name, "red-" + files[0].name);
}

// The figures are exported in the lab's theme: its plots' background and its curves' colours.
TEST(Workspace, ExportedFiguresAreInTheLabsTheme) {
    Fixture f;
    ui::PlotSettings settings;
    for (Theme theme : kThemes) {
        std::vector<Download> files = exportFigures(f.ws.a(), nullptr, settings, 1.0f, theme);
        ASSERT_EQ(files[0].name, "lobe.svg");
        const std::string& svg = files[0].bytes;
        const Palette& plot = themeColors(theme).plot;
        auto hex = [](FigureColor c) {
            char text[8];
            std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
            return std::string(text);
        };
        EXPECT_NE(svg.find("fill=\"" + hex(colorOf(plot, Ink::Background)) + "\""), std::string::npos) << toString(theme);
        EXPECT_NE(svg.find("stroke=\"" + hex(colorOf(plot, Ink::Diffuse)) + "\""), std::string::npos) << toString(theme);
        std::string error;
        const fs::path file = f.dir.path() / (std::string(toString(theme)) + "-lobe.png");
        std::ofstream(file, std::ios::binary) << files[1].bytes;
        std::optional<Image> png = readPng(file, error);
        ASSERT_TRUE(png) << error;
        const FigureColor bg = colorOf(plot, Ink::Background);
        EXPECT_EQ(std::vector<std::uint8_t>(png->rgb.begin(), png->rgb.begin() + 3), (std::vector<std::uint8_t>{bg.r, bg.g, bg.b}))
            << toString(theme) << ": the PNG's corner is the plots' background";
    }
}

// Fit: B becomes the model fitted to A's specular lobe, beside A; its label holds while neither changes.
TEST(Workspace, FitPutsTheFittedModelIntoBInCompareMode) {
    Fixture f;
    f.ws.a().brdf = BrdfModel::Phong;
    f.ws.a().material.shininess = 20.0f;
    f.ws.endFrame(false);
    ASSERT_TRUE(f.ws.run({Command::FitBlinnPhong}));
    EXPECT_TRUE(f.ws.view.compare);
    EXPECT_FALSE(f.ws.view.editingB);
    EXPECT_EQ(f.ws.b().brdf, BrdfModel::BlinnPhong);
    EXPECT_NEAR(f.ws.b().material.shininess, 68.0f, 1.0f); // 3.4× Phong's 20 (tests/fit_test.cpp)
    EXPECT_EQ(f.ws.b().material.diffuse, f.ws.a().material.diffuse) << "everything else is A's";
    EXPECT_NE(f.ws.fitNote().find("Blinn-Phong fitted to A, error "), std::string::npos) << f.ws.fitNote();
    const std::vector<std::string> notes = f.ws.takeNotes();
    ASSERT_FALSE(notes.empty());
    EXPECT_NE(notes.back().find("shininess"), std::string::npos) << notes.back();
    f.ws.b().material.shininess = 30.0f; // B edited: no longer the fit
    EXPECT_TRUE(f.ws.fitNote().empty());

    ASSERT_TRUE(f.ws.run({Command::FitCookTorrance, {}, 2}));
    EXPECT_EQ(f.ws.b().brdf, BrdfModel::CookTorrance);
    EXPECT_EQ(f.ws.b().cookTorrance.distribution, Distribution::Ggx);
    f.ws.a().material.shininess = 10.0f; // A edited: the fit is of another lobe
    EXPECT_TRUE(f.ws.fitNote().empty());

    f.ws.a().terms.specular = false; // nothing to fit: B stays as it was, a note says why
    const Preset before = f.ws.b();
    ASSERT_TRUE(f.ws.run({Command::FitPhong}));
    EXPECT_EQ(f.ws.b(), before);
    EXPECT_NE(f.ws.takeNotes().back().find("nothing to fit"), std::string::npos);
}

} // namespace
} // namespace lab
