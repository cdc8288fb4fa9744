// renderer.cpp — programs, uniforms, mesh buffers and the draw.
#include "render/renderer.h"

#include "core/scene/transforms.h"
#include "core/io/image.h"
#include "render/wireframe.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace lab {

namespace {

// The locations of one struct's fields (ShaderStruct's rows) under `uniform`, and their upload.
struct StructUniform {
    const ShaderStruct* shape = nullptr;
    std::vector<GLint> locations; // one per row

    StructUniform(GLuint program, const ShaderStruct& s, const std::string& uniform) : shape(&s) {
        for (const ShaderField& f : s.fields) {
            locations.push_back(glGetUniformLocation(program, (uniform + "." + f.name).c_str()));
        }
    }

    void upload(const void* data) const {
        const char* base = static_cast<const char*>(data);
        for (std::size_t i = 0; i < locations.size(); ++i) {
            const ShaderField& f = shape->fields[i];
            const char* at = base + f.offset;
            switch (f.type) {
            case FieldType::Int: glUniform1i(locations[i], *reinterpret_cast<const int*>(at)); break;
            case FieldType::Bool: glUniform1i(locations[i], *reinterpret_cast<const bool*>(at) ? 1 : 0); break;
            case FieldType::Float: glUniform1f(locations[i], *reinterpret_cast<const float*>(at)); break;
            case FieldType::Vec3: glUniform3fv(locations[i], 1, reinterpret_cast<const float*>(at)); break;
            }
        }
    }
};

// Uniform locations of one program, looked up once after linking.
struct Uniforms {
    GLint modelView = -1, projection = -1, normalMatrix = -1;
    GLint ambientLight = -1, lightCount = -1;
    GLint view = -1, factor = -1, factorLight = -1, palette = -1, range = -1, valueBits = -1;
    StructUniform material, brdf, terms;
    std::vector<StructUniform> lights;

    explicit Uniforms(GLuint p)
        : material(p, kMaterialUniform, kMaterialUniform.uniform), brdf(p, kBrdfUniform, kBrdfUniform.uniform),
          terms(p, kTermsUniform, kTermsUniform.uniform) {
        auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
        modelView = at("u_modelView");
        projection = at("u_projection");
        normalMatrix = at("u_normalMatrix");
        ambientLight = at("u_ambientLight");
        lightCount = at("u_lightCount");
        view = at("u_view");
        factor = at("u_factor");
        factorLight = at("u_factorLight");
        palette = at("u_palette");
        range = at("u_range");
        valueBits = at("u_valueBits");
        for (int i = 0; i < glsl::MAX_LIGHTS; ++i) {
            lights.emplace_back(p, kLightUniform, "u_lights[" + std::to_string(i) + "]");
        }
    }

    // Uploads exactly what the CPU face evaluates with (packShading).
    void upload(const Transforms& t, const ShadingInputs& in) const {
        glUniformMatrix4fv(modelView, 1, GL_FALSE, &t.modelView[0][0]);
        glUniformMatrix4fv(projection, 1, GL_FALSE, &t.projection[0][0]);
        glUniformMatrix3fv(normalMatrix, 1, GL_FALSE, &t.normalMatrix[0][0]);
        material.upload(&in.material);
        brdf.upload(&in.brdf);
        terms.upload(&in.terms);
        glUniform3fv(ambientLight, 1, &in.ambientLight[0]);
        glUniform1i(lightCount, in.lightCount);
        for (int i = 0; i < in.lightCount; ++i) {
            lights[static_cast<std::size_t>(i)].upload(&in.lights[i]);
        }
    }

    // What the view writes (view.glsl); `packedLight` is the factor's light among in.lights.
    void uploadView(const DrawOptions& o, int packedLight, bool bits) const {
        glUniform1i(view, viewKind(o.view));
        glUniform1i(factor, factorIndex(o.view));
        glUniform1i(factorLight, std::max(0, packedLight));
        glUniform1i(palette, paletteIndex(o.palette));
        glUniform2f(range, o.range.lo, o.range.hi);
        glUniform1i(valueBits, bits ? 1 : 0);
    }
};

struct Program {
    GLuint id = 0;
    std::unique_ptr<Uniforms> uniforms;
    void reset(GLuint p) {
        if (id) {
            glDeleteProgram(id);
        }
        id = p;
        uniforms = p ? std::make_unique<Uniforms>(p) : nullptr;
    }
};

// Attribute 2 (the point the lighting is evaluated at) is the vertex itself for smooth
// shading and the triangle's centroid for flat shading.
void bindFlatLayout() {
    const auto stride = static_cast<GLsizei>(sizeof(FlatVertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(FlatVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(FlatVertex, faceNormal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(FlatVertex, centroid)));
}

// A new vertex array, bound, with a new array buffer holding `bytes` bytes of `data`.
void newVertexArray(GLuint& vao, GLuint& vbo, const void* data, std::size_t bytes) {
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
}

// A vertex array over a new buffer of FlatVertex; returns the vertex count.
GLsizei uploadFlat(GLuint& vao, GLuint& vbo, const std::vector<FlatVertex>& vertices) {
    newVertexArray(vao, vbo, vertices.data(), vertices.size() * sizeof(FlatVertex));
    bindFlatLayout();
    glBindVertexArray(0);
    return static_cast<GLsizei>(vertices.size());
}

} // namespace

struct Renderer::Impl {
    StageSources sources;
    unsigned generation = 0;
    Program perVertex, perPixel, gouraudError;

    bool build(const StageSources& s, Diagnostics& diagnostics) {
        std::optional<GLuint> v = buildProgram(s, {"LAB_PER_VERTEX 1"}, diagnostics);
        if (!v) {
            return false;
        }
        std::optional<GLuint> p = buildProgram(s, {"LAB_PER_PIXEL 1"}, diagnostics);
        if (!p) {
            glDeleteProgram(*v);
            return false;
        }
        std::optional<GLuint> e = buildProgram(s, {"LAB_GOURAUD_ERROR 1"}, diagnostics);
        if (!e) {
            glDeleteProgram(*v);
            glDeleteProgram(*p);
            return false;
        }
        perVertex.reset(*v);
        perPixel.reset(*p);
        gouraudError.reset(*e);
        sources = s;
        ++generation;
        return true;
    }

    // gouraud-error compares the two evaluation sites on the smooth mesh, whatever the shading.
    const Program& programFor(Shading shading, ViewMode view = ViewMode::Lit) const {
        if (view == ViewMode::GouraudError) {
            return gouraudError;
        }
        return shading == Shading::Phong ? perPixel : perVertex;
    }

    void drawView(const Preset& preset, GpuMesh& mesh, const Viewport& viewport, const DrawOptions& options, bool bits);

    // GPU copies of the meshes being drawn. A copy whose mesh nobody else holds any more (the
    // cache evicted it, the caller dropped it) is released on the next lookup.
    std::vector<std::unique_ptr<GpuMesh>> uploads;

    GpuMesh& upload(const std::shared_ptr<const Mesh>& mesh) {
        std::erase_if(uploads, [](const std::unique_ptr<GpuMesh>& g) { return g->cpu().use_count() == 1; });
        for (const std::unique_ptr<GpuMesh>& g : uploads) {
            if (g->cpu() == mesh) {
                return *g;
            }
        }
        uploads.push_back(std::make_unique<GpuMesh>(mesh));
        return *uploads.back();
    }
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}

Renderer::~Renderer() {
    impl_->uploads.clear();
    impl_->perVertex.reset(0);
    impl_->perPixel.reset(0);
    impl_->gouraudError.reset(0);
}

bool Renderer::init(Diagnostics& diagnostics) {
    overlay_ = WireframeProgram::build(diagnostics);
    return overlay_ && impl_->build(builtinStageSources(), diagnostics);
}

bool Renderer::setStageSources(const StageSources& sources, Diagnostics& diagnostics) {
    return impl_->build(sources, diagnostics);
}

const StageSources& Renderer::stageSources() const { return impl_->sources; }

unsigned Renderer::generation() const { return impl_->generation; }

void Renderer::Impl::drawView(const Preset& shown, GpuMesh& mesh, const Viewport& viewport, const DrawOptions& asked,
                              bool bits) {
    DrawOptions options = asked;
    if (!notApplicable(options.view, shown, options.light).empty()) {
        options.view = ViewMode::Lit;
    }
    const Preset preset = viewed(shown, options.view);
    viewportPart(viewport, options.fromX, options.toX);
    glm::vec3 background = showsValue(options.view) ? glm::vec3(0.0f) : preset.background;
    if (bits) {
        glClearColor(1.0f, 1.0f, 1.0f, 1.0f); // all bits set: a NaN, which no model pixel counts as
    } else {
        glClearColor(background.r, background.g, background.b, 1.0f);
    }
    glClearDepthf(1.0f);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE); // no two-sided lighting, as in the classic pipeline; a plane seen from behind stays visible
    const Program& program = programFor(preset.shading, options.view);
    glUseProgram(program.id);
    Transforms t = computeTransforms(preset, static_cast<float>(viewport.width) / static_cast<float>(viewport.height));
    program.uniforms->upload(t, packShading(preset, t.view));
    program.uniforms->uploadView(options, packedLightIndex(preset, options.light), bits);
    if (preset.shading == Shading::Flat && options.view != ViewMode::GouraudError) {
        mesh.drawFlat();
    } else {
        mesh.drawSmooth();
    }
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
}

void Renderer::draw(const Preset& preset, GpuMesh& mesh, const Viewport& viewport, const DrawOptions& options) {
    impl_->drawView(preset, mesh, viewport, options, false);
}

namespace {

// The float whose bits are these four bytes, least significant first (memcpy: Emscripten 3.1.6's
// library has no std::bit_cast).
float floatOfBytes(const std::uint8_t* b) {
    std::uint32_t bits = std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
    float v = 0.0f;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

} // namespace

std::optional<float> Renderer::valueAt(const Preset& preset, const std::shared_ptr<const Mesh>& mesh, int width,
                                       int height, int x, int y, const DrawOptions& options) {
    if (!showsValue(options.view) || !notApplicable(options.view, preset, options.light).empty() || x < 0 || y < 0 ||
        x >= width || y >= height) {
        return std::nullopt;
    }
    GLint bound = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
    std::uint8_t bytes[4] = {255, 255, 255, 255};
    {
        Framebuffer target(1, 1);
        target.bind();
        DrawOptions whole = options;
        whole.fromX = 0.0f;
        whole.toX = 1.0f;
        impl_->drawView(preset, impl_->upload(mesh), Viewport{-x, -y, width, height}, whole, true); // (x, y) at (0, 0)
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(bound));
    float v = floatOfBytes(bytes);
    return std::isfinite(v) ? std::optional<float>(v) : std::nullopt;
}

std::optional<ValueRange> Renderer::autoValueRange(const Preset& preset, const std::shared_ptr<const Mesh>& mesh,
                                                   int width, int height, const DrawOptions& options) {
    if (!showsValue(options.view) || !notApplicable(options.view, preset, options.light).empty() || width < 1 ||
        height < 1) {
        return std::nullopt;
    }
    float shrink = std::min(1.0f, static_cast<float>(kRangeRenderSize) / static_cast<float>(std::max(width, height)));
    int w = std::max(1, static_cast<int>(std::lround(width * shrink)));
    int h = std::max(1, static_cast<int>(std::lround(height * shrink)));
    GLint bound = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
    std::vector<std::uint8_t> bytes(std::size_t(w) * std::size_t(h) * 4);
    {
        Framebuffer target(w, h);
        target.bind();
        DrawOptions whole = options;
        whole.fromX = 0.0f;
        whole.toX = 1.0f;
        impl_->drawView(preset, impl_->upload(mesh), Viewport{0, 0, w, h}, whole, true);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    }
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(bound));
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < bytes.size(); i += 4) {
        float v = floatOfBytes(&bytes[i]);
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    if (!(lo <= hi)) {
        return std::nullopt;
    }
    return autoRange(lo, hi);
}

void Renderer::draw(const Preset& preset, const std::shared_ptr<const Mesh>& mesh, const Viewport& viewport,
                    const DrawOptions& options) {
    draw(preset, impl_->upload(mesh), viewport, options);
}

void Renderer::drawOverlay(const Preset& preset, const std::shared_ptr<const Mesh>& mesh, const Viewport& viewport,
                           const WireframeOptions& options) {
    if (overlay_) { // none before init()
        overlay_->draw(preset, impl_->upload(mesh), viewport, options);
    }
}

void Renderer::drawPoints(const Preset& shown, const std::vector<FlatVertex>& vertices, int width, int height,
                          const DrawOptions& options, bool valueBits) {
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    const Preset preset = viewed(shown, options.view);
    const Program& program = impl_->programFor(preset.shading, options.view);
    glUseProgram(program.id);
    Transforms t = computeTransforms(preset, static_cast<float>(width) / static_cast<float>(height));
    program.uniforms->upload(t, packShading(preset, t.view));
    program.uniforms->uploadView(options, packedLightIndex(preset, options.light), valueBits);
    GLuint vao = 0, vbo = 0;
    GLsizei count = uploadFlat(vao, vbo, vertices);
    glBindVertexArray(vao);
    glDrawArrays(GL_POINTS, 0, count);
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    glDeleteBuffers(1, &vbo);
    glUseProgram(0);
}

ViewportDraw viewDraw(const DisplaySettings& view) {
    ViewportDraw d;
    d.options.view = view.mode;
    d.options.light = view.light;
    d.options.palette = view.palette;
    d.automatic = showsValue(view.mode) && !view.range;
    d.options.range = view.range.value_or(ValueRange{});
    d.wipe = view.wipe && view.mode != ViewMode::Lit;
    if (d.wipe) {
        d.options.fromX = std::clamp(view.wipeAt, 0.0f, 1.0f);
    }
    d.wireframe = view.wireframe;
    d.vertexNormals = view.vertexNormals;
    return d;
}

std::optional<ValueRange> drawView(Renderer& renderer, const Preset& preset, const std::shared_ptr<const Mesh>& mesh,
                                   const Viewport& viewport, const ViewportDraw& draw) {
    DrawOptions options = draw.options;
    std::optional<ValueRange> range;
    bool valueView = showsValue(options.view) && notApplicable(options.view, preset, options.light).empty();
    if (valueView) {
        range = draw.automatic ? renderer.autoValueRange(preset, mesh, viewport.width, viewport.height, options)
                               : std::optional<ValueRange>(options.range);
        options.range = range.value_or(ValueRange{});
    }
    if (draw.wipe) {
        DrawOptions lit;
        lit.toX = options.fromX;
        renderer.draw(preset, mesh, viewport, lit);
    }
    renderer.draw(preset, mesh, viewport, options);
    drawViewOverlays(renderer, preset, mesh, viewport, draw, valueView);
    return range;
}

void viewportPart(const Viewport& viewport, float fromX, float toX) {
    int x0 = viewport.x + static_cast<int>(std::lround(std::clamp(fromX, 0.0f, 1.0f) * viewport.width));
    int x1 = viewport.x + static_cast<int>(std::lround(std::clamp(toX, 0.0f, 1.0f) * viewport.width));
    glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
    glScissor(x0, viewport.y, std::max(0, x1 - x0), viewport.height);
    glEnable(GL_SCISSOR_TEST);
    glDisable(GL_DITHER);
    glDisable(GL_BLEND);
}


//----------------------------------------------------------------------------------------
// GpuMesh
//----------------------------------------------------------------------------------------

GpuMesh::GpuMesh(std::shared_ptr<const Mesh> mesh) : mesh_(std::move(mesh)) {
    // Interleaved position + normal; attribute 2 (the shading point) aliases the position.
    std::vector<float> interleaved;
    interleaved.reserve(mesh_->positions.size() * 6);
    for (std::size_t i = 0; i < mesh_->positions.size(); ++i) {
        const glm::vec3& p = mesh_->positions[i];
        const glm::vec3& n = mesh_->normals[i];
        interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
    }
    newVertexArray(vao_, vbo_, interleaved.data(), interleaved.size() * sizeof(float));
    const GLsizei stride = 6 * sizeof(float);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(3 * sizeof(float)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glGenBuffers(1, &ebo_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh_->indices.size() * sizeof(std::uint32_t)),
                 mesh_->indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
}

GpuMesh::~GpuMesh() {
    glDeleteVertexArrays(1, &vao_);
    glDeleteBuffers(1, &vbo_);
    glDeleteBuffers(1, &ebo_);
    if (flatVao_) {
        glDeleteVertexArrays(1, &flatVao_);
        glDeleteBuffers(1, &flatVbo_);
    }
}

void GpuMesh::drawSmooth() const {
    glBindVertexArray(vao_);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh_->indices.size()), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

void GpuMesh::drawFlat() {
    if (!flatVao_) {
        flatCount_ = uploadFlat(flatVao_, flatVbo_, expandFlat(*mesh_));
    }
    glBindVertexArray(flatVao_);
    glDrawArrays(GL_TRIANGLES, 0, flatCount_);
    glBindVertexArray(0);
}

} // namespace lab
