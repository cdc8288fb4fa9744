// view_fit_test.cpp — every shipped preset's model is whole in the model's viewport of every
// classroom screen: the desktop at 1024x768, 1280x800, 1600x900 and 1920x1080, normal and in
// presenter mode (caption on, control panel hidden below 1600), compare mode's halves, and the
// compact layout of a phone (390x844) and a tablet (768x1024).
//
// The layout is the lab's own (computeLayout, then placeText with the text's room at the UI's
// font size); each preset is rendered with the OffscreenRenderer at the shape of each model
// viewport (scaled down: the shape decides what is whole, fovy spanning the narrower side) and
// must not touch the image's border. The GUI tests (tests/gui/classroom_test.cpp) check the
// same on the real window for some presets, with the real font's text.
#include "core/gltf/mesh_cache.h"
#include "core/scene/preset.h"
#include "gl_suite.h"
#include "render/offscreen.h"
#include "ui/layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace lab {
namespace {

namespace fs = std::filesystem;

struct Screen {
    float w, h;
};

// The shapes (width / height, to 1%) of the model's viewports the classroom's screens give, and
// where each comes from.
std::map<int, std::string> viewportShapes() {
    std::map<int, std::string> shapes;
    const Screen screens[] = {{1024, 768}, {1280, 800}, {1600, 900}, {1920, 1080}, {1280, 720}, {390, 844}, {768, 1024}};
    for (const Screen& s : screens) {
        for (bool presenter : {false, true}) {
            float scale = presenter ? 1.75f : 1.0f, font = 15.0f * scale; // DejaVu Sans at 15 · scale
            bool panel = !presenter || s.w >= 1600.0f;
            ui::Layout l = ui::computeLayout({s.w, s.h, scale, panel, true});
            for (bool compare : {false, true}) {
                ui::TextRoom room;
                room.header = font + 0.8f * font; // one line (ui/viewport/viewport.cpp headerText)
                room.footer = 2.0f * font + 0.8f * font; // a message on two lines
                room.label = compare ? font + 0.8f * font : 0.0f;
                if (presenter) { // a caption of about 180 characters: a title and two lines
                    room.captionHeight = [font](float width) { return font * (1.35f + 1.3f * std::ceil(180.0f * 0.55f * font / width)) + 0.8f * font; };
                    room.captionWidth = 36.0f * font;
                    room.sideWidth = 18.0f * font;
                }
                ui::Layout placed = l;
                ui::placeText(placed, room);
                const ui::Rect& r = compare ? placed.halves[0] : placed.viewport;
                int shape = static_cast<int>(std::lround(100.0f * r.w / r.h));
                shapes.emplace(shape, std::to_string(int(s.w)) + "x" + std::to_string(int(s.h)) + (presenter ? " presenter" : "") +
                                          (compare ? " compare" : ""));
            }
        }
    }
    return shapes;
}

struct Border {
    bool touched = false;
    int pixels = 0; // of the model
};

Border border(const Image& image, glm::vec3 background) {
    Border b;
    const glm::ivec3 bg = glm::ivec3(glm::round(background * 255.0f));
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.rgb[3 * static_cast<std::size_t>(y * image.width + x)];
            glm::ivec3 d = glm::abs(glm::ivec3(p[0], p[1], p[2]) - bg);
            if (std::max({d.x, d.y, d.z}) > 2) {
                ++b.pixels;
                b.touched = b.touched || x == 0 || y == 0 || x == image.width - 1 || y == image.height - 1;
            }
        }
    }
    return b;
}

class ViewFit : public GlSuite<testing::Test, OffscreenRenderer> {};

TEST_F(ViewFit, EveryShippedPresetIsWholeInEveryClassroomViewport) {
    ASSERT_NE(renderer_, nullptr);
    std::map<int, std::string> shapes = viewportShapes();
    ASSERT_GE(shapes.size(), 4u);
    EXPECT_TRUE(shapes.begin()->first < 100 && shapes.rbegin()->first > 100) << "tall and wide viewports both";
    std::set<fs::path> presets;
    for (const fs::directory_entry& e : fs::directory_iterator(fs::path(LAB_SOURCE_DIR) / "presets")) {
        if (e.path().extension() == ".json") {
            presets.insert(e.path());
        }
    }
    ASSERT_GE(presets.size(), 20u);
    for (const fs::path& file : presets) {
        Diagnostics d;
        std::optional<LoadedPreset> preset = loadPreset(file, d);
        ASSERT_TRUE(preset) << toString(d);
        for (const auto& [shape, where] : shapes) {
            int w = shape >= 100 ? 160 : std::max(8, 160 * shape / 100), h = shape >= 100 ? std::max(8, 16000 / shape) : 160;
            std::optional<Image> image = renderer_->render(*preset, w, h, d);
            ASSERT_TRUE(image) << toString(d);
            Border b = border(*image, preset->preset.background);
            EXPECT_FALSE(b.touched) << file.filename() << " is cut at the border of the model's viewport on " << where << " ("
                                    << w << "x" << h << ")";
            EXPECT_GT(b.pixels, 0) << file.filename() << " shows no model on " << where;
        }
    }
}

} // namespace
} // namespace lab
