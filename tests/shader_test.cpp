// shader_test.cpp — the shader editor's half in the renderer: edited lighting.glsl and stage
// bodies compiled on the headless GL context, compile errors and non-ASCII text named by file and
// line, the previous programs kept on failure, and the built-in ones restored by a revert.
#include "core/gltf/mesh_cache.h"
#include "core/scene/preset.h"
#include "gl_suite.h"
#include "platform/headless_gl.h"
#include "render/gl.h"
#include "render/renderer.h"
#include "render/shader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace lab {
namespace {

constexpr int kSize = 96;

// The 1-based line of `text` that holds byte `at`.
int lineOf(const std::string& text, std::size_t at) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

// Replaces the first `what` after `after` in `text`; the line it was on, 0 if absent.
int replaceAfter(std::string& text, std::string_view after, std::string_view what, std::string_view with) {
    std::size_t from = text.find(after);
    std::size_t at = from == std::string::npos ? from : text.find(what, from);
    if (at == std::string::npos) {
        return 0;
    }
    text.replace(at, what.size(), with);
    return lineOf(text, at);
}

bool anyNames(const Diagnostics& d, const std::string& place, std::string_view also = {}) {
    return std::any_of(d.begin(), d.end(), [&](const Diagnostic& x) {
        return x.message.find(place) != std::string::npos && x.message.find(also) != std::string::npos;
    });
}

class ShaderEditing : public GlSuite<> {
protected:
    void SetUp() override {
        ASSERT_NE(renderer_, nullptr);
        Diagnostics d;
        ASSERT_TRUE(renderer_->setStageSources(builtinStageSources(), d)) << toString(d);
    }

    // A shipped preset, drawn at kSize x kSize with the renderer's current programs, with its
    // own shading or `shading`.
    static Image render(const char* name, std::optional<Shading> shading = std::nullopt) {
        Diagnostics d;
        std::optional<LoadedPreset> preset = loadPreset(std::string(LAB_SOURCE_DIR) + "/presets/" + name + ".json", d);
        EXPECT_TRUE(preset) << toString(d);
        if (!preset) {
            return {};
        }
        if (shading) {
            preset->preset.shading = *shading;
        }
        std::shared_ptr<const Mesh> mesh = meshes_.get(preset->preset.model, preset->folder(), d);
        EXPECT_TRUE(mesh) << toString(d);
        Framebuffer target(kSize, kSize);
        EXPECT_TRUE(target.complete());
        target.bind();
        renderer_->draw(preset->preset, mesh, Viewport{0, 0, kSize, kSize});
        Image image = target.readRgb();
        bindFramebuffer(0);
        return image;
    }

    // Built-in lighting.glsl with specularFactor always 0: no highlights anywhere.
    static std::string noSpecular() {
        std::string lighting = builtinStageSources().lighting;
        EXPECT_GT(replaceAfter(lighting, "float specularFactor(", "if (dot(N, L) <= 0.0f) {", "if (true) {"), 0)
            << "lighting.glsl changed: this test edits specularFactor's first line";
        return lighting;
    }

    static MeshCache meshes_;
};

MeshCache ShaderEditing::meshes_;

// How many channel values differ, and whether any of `b` is brighter than `a`.
struct Change {
    int differing = 0;
    bool brighter = false;
};

Change compare(const Image& a, const Image& b) {
    Change c;
    EXPECT_EQ(a.rgb.size(), b.rgb.size());
    for (std::size_t i = 0; i < std::min(a.rgb.size(), b.rgb.size()); ++i) {
        c.differing += a.rgb[i] != b.rgb[i];
        c.brighter |= b.rgb[i] > a.rgb[i] + 1;
    }
    return c;
}

// The lighting model's structs as rows (core/lighting/lighting.h's ShaderStruct) and the linked
// programs agree: every active uniform of a struct is a row, every row is an active uniform, in
// every program (per vertex, per pixel, and the Gouraud error's). A field added to lighting_api.glsl without its row,
// or a row whose field was renamed, fails here.
TEST(ShaderRows, TheProgramsActiveUniformsAreTheRowsOfTheShadingStructs) {
    HeadlessGl gl;
    std::string error;
    ASSERT_TRUE(gl.create(error)) << error;
    const std::vector<std::pair<std::string, const ShaderStruct*>> structs = {
        {"u_material", &kMaterialUniform}, {"u_brdf", &kBrdfUniform}, {"u_terms", &kTermsUniform}};
    const std::set<std::string> others = {"u_modelView", "u_projection", "u_normalMatrix",
                                          "u_ambientLight", "u_lightCount", "u_view", "u_factor",
                                          "u_factorLight", "u_palette", "u_range", "u_valueBits"};
    for (const char* define : {"LAB_PER_VERTEX 1", "LAB_PER_PIXEL 1", "LAB_GOURAUD_ERROR 1"}) {
        SCOPED_TRACE(define);
        Diagnostics d;
        std::optional<GLuint> program = buildProgram(builtinStageSources(), {define}, d);
        ASSERT_TRUE(program) << toString(d);
        std::set<std::string> active;
        GLint count = 0;
        glGetProgramiv(*program, GL_ACTIVE_UNIFORMS, &count);
        for (GLint i = 0; i < count; ++i) {
            char name[256];
            GLint size = 0;
            GLenum type = 0;
            glGetActiveUniform(*program, static_cast<GLuint>(i), sizeof name, nullptr, &size, &type, name);
            active.insert(name);
        }
        std::set<std::string> rows(others);
        if (std::string(define) == "LAB_GOURAUD_ERROR 1") { // it compares the lit colours: no factor
            rows.erase("u_factor");
            rows.erase("u_factorLight");
        }
        for (const auto& [uniform, shape] : structs) {
            for (const ShaderField& f : shape->fields) {
                rows.insert(uniform + "." + f.name);
            }
        }
        for (int light = 0; light < glsl::MAX_LIGHTS; ++light) {
            for (const ShaderField& f : kLightUniform.fields) {
                rows.insert("u_lights[" + std::to_string(light) + "]." + f.name);
            }
        }
        for (const std::string& name : active) {
            EXPECT_TRUE(rows.contains(name)) << name << " is an active uniform without a row in core/lighting/lighting.cpp";
        }
        for (const std::string& name : rows) {
            EXPECT_TRUE(active.contains(name)) << name << " is a row but not an active uniform of the program";
        }
        glDeleteProgram(*program);
    }
}

TEST_F(ShaderEditing, EditedLightingChangesTheRenderAndRevertRestoresIt) {
    // Lit per pixel (Phong shading) and per vertex (Gouraud): both programs take the edit.
    for (Shading shading : {Shading::Phong, Shading::Gouraud}) {
        const char* preset = "05-full-phong";
        SCOPED_TRACE(std::string(toString(shading)));
        auto render = [&](const char* name) { return ShaderEditing::render(name, shading); };
        Image builtin = render(preset);

        StageSources edited = builtinStageSources();
        edited.lighting = noSpecular();
        Diagnostics d;
        ASSERT_TRUE(renderer_->setStageSources(edited, d)) << toString(d);
        EXPECT_EQ(renderer_->stageSources().lighting, edited.lighting);
        Image flat = render(preset);
        Change change = compare(builtin, flat);
        EXPECT_GT(change.differing, 100) << "without its specular term the highlight must go";
        EXPECT_FALSE(change.brighter) << "dropping a term can only darken";

        // A broken lighting.glsl is refused, named by its own line, and the edited programs stay.
        StageSources broken = edited;
        int line = replaceAfter(broken.lighting, "float fresnelF0(", "return ", "return undefinedThing + ");
        ASSERT_GT(line, 0);
        EXPECT_FALSE(renderer_->setStageSources(broken, d));
        EXPECT_TRUE(anyNames(d, "lighting.glsl:" + std::to_string(line), "undefinedThing")) << toString(d);
        for (std::size_t i = 0; i < d.size(); ++i) {
            for (std::size_t j = i + 1; j < d.size(); ++j) {
                EXPECT_NE(d[i].message, d[j].message) << "both stages include lighting.glsl: report it once";
            }
        }
        EXPECT_EQ(renderer_->stageSources().lighting, edited.lighting);
        EXPECT_EQ(compare(flat, render(preset)).differing, 0) << "the previous programs keep rendering";

        // Revert: the built-in sources, the built-in image, byte for byte.
        d.clear();
        ASSERT_TRUE(renderer_->setStageSources(builtinStageSources(), d)) << toString(d);
        EXPECT_EQ(compare(builtin, render(preset)).differing, 0);
    }
}

TEST_F(ShaderEditing, BuiltinLightingIsTheEmbeddedFile) {
    EXPECT_EQ(builtinStageSources().lighting, shaderSource("lighting.glsl"));
    EXPECT_FALSE(builtinStageSources().lighting.empty());
    EXPECT_EQ(renderer_->stageSources().lighting, shaderSource("lighting.glsl"));
}

TEST_F(ShaderEditing, ErrorsInEachStageBodyNameItsFileAndLine) {
    StageSources broken = builtinStageSources();
    int line = replaceAfter(broken.vertex, "void main()", "{", "{\n    float x = missingInVertex;");
    ASSERT_GT(line, 0);
    Diagnostics d;
    EXPECT_FALSE(renderer_->setStageSources(broken, d));
    EXPECT_TRUE(anyNames(d, "lit.vert:" + std::to_string(line + 1), "missingInVertex")) << toString(d);
    EXPECT_EQ(renderer_->stageSources().vertex, builtinStageSources().vertex);
}

TEST_F(ShaderEditing, LightingThatBreaksThePrototypesIsRefused) {
    // lighting_api.glsl stays fixed: a definition that no longer matches its prototype fails.
    StageSources broken = builtinStageSources();
    ASSERT_GT(replaceAfter(broken.lighting, "float fresnelF0(", "float ior", "int ior"), 0);
    Diagnostics d;
    EXPECT_FALSE(renderer_->setStageSources(broken, d));
    EXPECT_FALSE(d.empty());
    EXPECT_EQ(renderer_->stageSources().lighting, builtinStageSources().lighting);
}

TEST_F(ShaderEditing, NonAsciiIsRefusedWithFileAndLineBeforeCompiling) {
    Image before = render("05-full-phong");
    StageSources typed = builtinStageSources();
    int lightingLine = replaceAfter(typed.lighting, "float fresnelF0(", "{", "{ // n\xC2\xB2");
    int fragmentLine = replaceAfter(typed.fragment, "void main()", "{", "{\n    // caf\xC3\xA9");
    ASSERT_GT(lightingLine, 0);
    ASSERT_GT(fragmentLine, 0);
    Diagnostics d;
    EXPECT_FALSE(renderer_->setStageSources(typed, d));
    EXPECT_TRUE(anyNames(d, "lighting.glsl:" + std::to_string(lightingLine) + ":", "U+00B2")) << toString(d);
    EXPECT_TRUE(anyNames(d, "lit.frag:" + std::to_string(fragmentLine + 1) + ": column 11", "U+00E9")) << toString(d);
    EXPECT_TRUE(anyNames(d, "lit.frag:", "only ASCII")) << toString(d);
    EXPECT_EQ(d.size(), 2u) << "nothing was compiled: no driver messages\n" << toString(d);
    EXPECT_EQ(renderer_->stageSources().fragment, builtinStageSources().fragment);
    EXPECT_EQ(compare(before, render("05-full-phong")).differing, 0);
}

TEST(CheckAscii, OneDiagnosticPerLineWithColumnAndCodePoint) {
    StageSources s;
    s.vertex = "ok\nx = 1; // \xE2\x86\x92 and \xE2\x86\x92\n\xFF\n";
    s.fragment = "plain\n";
    s.lighting = "";
    Diagnostics d;
    EXPECT_FALSE(checkAscii(s, d));
    ASSERT_EQ(d.size(), 2u) << toString(d);
    EXPECT_EQ(d[0].message.rfind("lit.vert:2: column 11: non-ASCII character U+2192", 0), 0u) << d[0].message;
    EXPECT_EQ(d[1].message.rfind("lit.vert:3: column 1: byte 0xFF", 0), 0u) << d[1].message;

    Diagnostics none;
    EXPECT_TRUE(checkAscii(builtinStageSources(), none)) << toString(none);
    EXPECT_TRUE(none.empty());

    std::string many(50, '\n');
    for (int i = 0; i < 50; ++i) {
        many.insert(many.begin() + i * 3, {'\xC3', '\xA9'});
    }
    Diagnostics bounded;
    EXPECT_FALSE(checkAscii({many, "", ""}, bounded, 8));
    EXPECT_EQ(bounded.size(), 8u);
}

TEST(ReadableLog, DriverPlacesBecomeFileAndLine) {
    Diagnostics d;
    readableLog("0:12(5): error: `x' undeclared\n"
                "ERROR: 0:3: 'y' : undeclared identifier\r\n"
                "0(7) : error C1008: undefined variable \"z\"\n"
                "\n"
                "10:12 is not a place\n",
                "lit.frag", d);
    ASSERT_EQ(d.size(), 4u) << toString(d);
    EXPECT_EQ(d[0].message, "lit.frag:12(5): error: `x' undeclared");
    EXPECT_EQ(d[1].message, "ERROR: lit.frag:3: 'y' : undeclared identifier");
    EXPECT_EQ(d[2].message, "lit.frag:7 : error C1008: undefined variable \"z\"");
    EXPECT_EQ(d[3].message, "10:12 is not a place");
}

// Issue 49: a 1 MB shader's compile log reached the page (and the editor) whole: a driver quotes
// the source it refuses. Each line is cut at 1000 bytes, and the log at kMaxLogLines lines.
TEST(ReadableLog, AQuotedSourceIsCutAndALongLogBounded) {
    Diagnostics d;
    readableLog("ERROR: 0:1: '" + std::string(1 << 20, 'x') + "' : syntax error\n", "lit.frag", d);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_LT(d[0].message.size(), 1100u);
    EXPECT_TRUE(d[0].message.starts_with("ERROR: lit.frag:1: 'xxx")) << d[0].message.substr(0, 80);
    EXPECT_TRUE(d[0].message.ends_with("(1048605 bytes)")) << d[0].message.substr(d[0].message.size() - 40);
    std::string many;
    for (int i = 1; i <= 500; ++i) {
        many += "0:" + std::to_string(i) + ": error: undeclared\n";
    }
    d.clear();
    readableLog(many, "lit.frag", d);
    ASSERT_EQ(d.size(), kMaxLogLines + 1) << toString(d);
    EXPECT_EQ(d[kMaxLogLines - 1].message, "lit.frag:50: error: undeclared");
    EXPECT_EQ(d.back().message, "(and 450 more lines of the driver's log)");
}

} // namespace
} // namespace lab
