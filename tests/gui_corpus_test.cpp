// gui_corpus_test.cpp — every input the fuzzers know, dropped on the interactive lab.
//
// The lab runs on its headless platform (real App frames, ImGui and all, drawn offscreen). Each
// file of the committed seeds and regressions, the shipped presets and test inputs, and any
// corpus folders named in LAB_FUZZ_CORPUS (CI passes the corpora its fuzz run grew) is dropped on
// the lab like a file from the desktop (a link opened as the page opens its address, a field edit
// sent as the page's controls send it). The lab must keep running, and a file that does not load
// must leave the scene exactly as it was (its link, the whole preset, unchanged).
#include "app/app.h"
#include "core/exercise/exercise.h"
#include "core/gltf/reader.h"
#include "core/scene/preset.h"
#include "core/share/share_link.h"
#include "platform/headless_app.h"
#include "platform/headless_gl.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace lab {
namespace {

namespace fs = std::filesystem;

enum class Kind { Preset, Gltf, Exercise, Link, Field };

std::vector<std::pair<fs::path, Kind>> corpus() {
    std::vector<std::pair<fs::path, Kind>> files;
    auto add = [&](const fs::path& folder, Kind kind) {
        std::error_code ec;
        for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
            if (e.is_regular_file()) {
                files.emplace_back(e.path(), kind);
            }
        }
    };
    fs::path src(LAB_SOURCE_DIR);
    add(src / "presets", Kind::Preset);
    add(src / "tests/data", Kind::Preset);
    add(src / "tests/fuzz/regressions/preset", Kind::Preset);
    add(src / "presets/models", Kind::Gltf);
    add(src / "tests/fuzz/seeds/gltf", Kind::Gltf);
    add(src / "tests/fuzz/regressions/gltf", Kind::Gltf);
    add(src / "presets/exercises", Kind::Exercise);
    add(src / "tests/fuzz/regressions/exercise", Kind::Exercise);
    add(src / "tests/fuzz/seeds/link", Kind::Link);
    add(src / "tests/fuzz/regressions/link", Kind::Link);
    add(src / "tests/fuzz/seeds/field", Kind::Field);
    add(src / "tests/fuzz/regressions/field", Kind::Field);
    if (const char* extra = std::getenv("LAB_FUZZ_CORPUS")) {
        add(fs::path(extra) / "preset", Kind::Preset);
        add(fs::path(extra) / "gltf", Kind::Gltf);
        add(fs::path(extra) / "exercise", Kind::Exercise);
        add(fs::path(extra) / "link", Kind::Link);
        // (Not the field edits fuzz_field grew: about 2,000 inputs, two minutes of CI under ASan, for what
        // its own check already covers — the lab only adds the message's toast; the seeds come in above.)
    }
    return files;
}

TEST(GuiCorpus, EveryFuzzInputDroppedOnTheLabIsSurvived) {
    HeadlessGl gl;
    std::string error;
    ASSERT_TRUE(gl.create(error)) << error;
    TempFolder dir;
    AppOptions options;
    options.presetFolders = {fs::path(LAB_SOURCE_DIR) / "presets"};
    options.screenshotFolder = dir.path();
    App app(options);
    HeadlessApp lab;
    ASSERT_TRUE(lab.start(app, 640, 480, error)) << error;
    std::string link = lab.frame().link;

    auto files = corpus();
    ASSERT_GT(files.size(), 30u);
    int refused = 0;
    for (const auto& [file, kind] : files) {
        // A drop carries a file name with the extension the lab expects for its content; a link is
        // opened as the page opens its address.
        std::string bytes = readText(file);
        bool glb = bytes.rfind("glTF", 0) == 0;
        fs::path dropped = dir.path() / (kind == Kind::Gltf ? (glb ? "dropped.glb" : "dropped.gltf") : "dropped.json");
        writeText(dropped, bytes);
        Diagnostics d;
        bool loads = kind == Kind::Preset     ? loadPreset(dropped, d).has_value()
                     : kind == Kind::Exercise ? loadExercise(dropped, d).has_value()
                     : kind == Kind::Link     ? parseLink(bytes, options.presetFolders[0], d).has_value()
                     : kind == Kind::Field    ? true // taken or refused, the lab goes on
                                              : loadGltf(dropped, "m", d).has_value();

        // A field edit ("PATH\nTEXT", fuzz_checks.h checkFieldEdit) arrives as the page's controls send it.
        const std::size_t newline = bytes.find('\n');
        const std::string path = newline == std::string::npos ? "material.shininess" : bytes.substr(0, newline);
        const std::string text = newline == std::string::npos ? bytes : bytes.substr(newline + 1);

        FrameInput in;
        if (kind == Kind::Link) {
            in.openLink = bytes;
        } else if (kind == Kind::Field) {
            in.pageEdits = {{path, text}};
        } else {
            in.droppedFiles = {dropped.string()};
        }
        FrameOutput out = lab.frame(in);
        if (!loads && kind != Kind::Field) { // (a field edit changes the scene or is refused: both survive)
            ++refused;
            EXPECT_EQ(out.link, link) << file << " did not load, yet the scene changed";
        }
        link = out.link;
    }
    EXPECT_GE(refused, 5) << "the corpus should hold files the lab refuses";
    RecordProperty("files", static_cast<int>(files.size()));
}

} // namespace
} // namespace lab
