// wireframe.cpp — the wireframe's and the normals' line buffers, and their draw.
#include "render/wireframe.h"

#include "core/scene/transforms.h"
#include "core/lighting/lighting.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lab {

glm::vec3 wireframeColor(const glm::vec3& background) {
    float luminance = glm::dot(background, glm::vec3(0.2126f, 0.7152f, 0.0722f)); // Rec. 709 weights
    return luminance > 0.5f ? kWireDark : kWireLight;
}

std::vector<std::uint32_t> edgeIndices(std::span<const std::uint32_t> triangles) {
    // Each edge as one 64-bit key, the smaller index in the high half; sorting puts the copies
    // that neighbouring triangles make side by side (and the result in an order the GPU's
    // vertex cache likes better than the triangles' own).
    std::vector<std::uint64_t> keys;
    keys.reserve(triangles.size());
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        for (std::size_t k = 0; k < 3; ++k) {
            std::uint32_t a = triangles[t + k], b = triangles[t + (k + 1) % 3];
            if (a != b) { // a degenerate triangle's collapsed edge is no line
                keys.push_back(std::uint64_t(std::min(a, b)) << 32 | std::max(a, b));
            }
        }
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::vector<std::uint32_t> pairs;
    pairs.reserve(keys.size() * 2);
    for (std::uint64_t key : keys) {
        pairs.push_back(static_cast<std::uint32_t>(key >> 32));
        pairs.push_back(static_cast<std::uint32_t>(key));
    }
    return pairs;
}

std::size_t normalLineStep(std::size_t vertexCount) {
    return std::max<std::size_t>(1, (vertexCount + kMaxNormalLines - 1) / kMaxNormalLines);
}

//----------------------------------------------------------------------------------------
// WireframeLines
//----------------------------------------------------------------------------------------

namespace {

constexpr GLsizei kStride = 6 * sizeof(float); // position, normal: GpuMesh's layout

// Attributes 0 (position) and 1 (normal) of the bound vertex array from `buffer`, advancing
// once a vertex (divisor 0) or once an instance (divisor 1).
void bindPositionNormal(GLuint buffer, GLuint divisor) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, kStride, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, kStride, reinterpret_cast<void*>(3 * sizeof(float)));
    glVertexAttribDivisor(0, divisor);
    glVertexAttribDivisor(1, divisor);
}

} // namespace

WireframeLines::WireframeLines(const Mesh& mesh, GLuint vertices) : mesh_(mesh), vertices_(vertices) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    diagonal_ = mesh.positions.empty() ? glm::vec3(0.0f) : hi - lo;
}

WireframeLines::~WireframeLines() {
    glDeleteVertexArrays(1, &edgeVao_); // zero names are ignored
    glDeleteBuffers(1, &edgeEbo_);
    glDeleteVertexArrays(1, &normalVao_);
    glDeleteBuffers(1, &normalVbo_);
    glDeleteBuffers(1, &tipVbo_);
}

void WireframeLines::drawEdges() {
    if (!edgeVao_) {
        std::vector<std::uint32_t> pairs = edgeIndices(mesh_.indices);
        glGenVertexArrays(1, &edgeVao_);
        glBindVertexArray(edgeVao_);
        bindPositionNormal(vertices_, 0);
        glGenBuffers(1, &edgeEbo_);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, edgeEbo_);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(pairs.size() * sizeof(std::uint32_t)),
                     pairs.data(), GL_STATIC_DRAW);
        edgeCount_ = static_cast<GLsizei>(pairs.size());
    }
    glBindVertexArray(edgeVao_);
    glDrawElements(GL_LINES, edgeCount_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

// One instance a line, its two vertices told apart by a_tip (wireframe.vert), so the mesh's own
// buffer serves unless only every k-th vertex is drawn: a compact copy of those then (a stride
// of k vertices would do without one, but WebGL2 allows strides up to 255 bytes). a_tip comes
// from a buffer that advances per vertex, not from gl_VertexID: the first WebGL 2.0 spec (and
// browsers that kept to it) refuses an instanced draw in which every attribute advances per
// instance.
void WireframeLines::drawNormals() {
    if (!normalVao_) {
        std::size_t step = normalLineStep(mesh_.positions.size());
        GLuint source = vertices_;
        if (step > 1) {
            std::vector<float> every;
            every.reserve((mesh_.positions.size() / step + 1) * 6);
            for (std::size_t i = 0; i < mesh_.positions.size(); i += step) {
                const glm::vec3 &p = mesh_.positions[i], &n = mesh_.normals[i];
                every.insert(every.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
            }
            glGenBuffers(1, &normalVbo_);
            glBindBuffer(GL_ARRAY_BUFFER, normalVbo_);
            glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(every.size() * sizeof(float)), every.data(),
                         GL_STATIC_DRAW);
            source = normalVbo_;
        }
        glGenVertexArrays(1, &normalVao_);
        glBindVertexArray(normalVao_);
        bindPositionNormal(source, 1);
        const float tips[] = {0.0f, 1.0f};
        glGenBuffers(1, &tipVbo_);
        glBindBuffer(GL_ARRAY_BUFFER, tipVbo_);
        glBufferData(GL_ARRAY_BUFFER, sizeof tips, tips, GL_STATIC_DRAW);
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
        normalCount_ = static_cast<GLsizei>((mesh_.positions.size() + step - 1) / step);
    }
    glBindVertexArray(normalVao_);
    glDrawArraysInstanced(GL_LINES, 0, 2, normalCount_);
    glBindVertexArray(0);
}

WireframeLines& GpuMesh::wireframe() {
    if (!overlay_) {
        overlay_ = std::make_unique<WireframeLines>(*mesh_, vbo_);
    }
    return *overlay_;
}

//----------------------------------------------------------------------------------------
// WireframeProgram
//----------------------------------------------------------------------------------------

std::unique_ptr<WireframeProgram> WireframeProgram::build(Diagnostics& diagnostics) {
    std::optional<GLuint> id = buildPlainProgram("wireframe.vert", "wireframe.frag", diagnostics);
    return id ? std::unique_ptr<WireframeProgram>(new WireframeProgram(*id)) : nullptr;
}

WireframeProgram::WireframeProgram(GLuint id)
    : id_(id), modelView_(glGetUniformLocation(id, "u_modelView")),
      projection_(glGetUniformLocation(id, "u_projection")), normalMatrix_(glGetUniformLocation(id, "u_normalMatrix")),
      normalLength_(glGetUniformLocation(id, "u_normalLength")), depthBias_(glGetUniformLocation(id, "u_depthBias")),
      color_(glGetUniformLocation(id, "u_color")) {}

WireframeProgram::~WireframeProgram() { glDeleteProgram(id_); }

void WireframeProgram::draw(const Preset& preset, GpuMesh& mesh, const Viewport& viewport,
                          const WireframeOptions& options) const {
    if ((!options.wireframe && !options.vertexNormals) || viewport.width < 1 || viewport.height < 1) {
        return;
    }
    WireframeLines& lines = mesh.wireframe();
    viewportPart(viewport, options.fromX, options.toX);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE); // the lines test against the model, not against each other
    glUseProgram(id_);
    float aspect = static_cast<float>(viewport.width) / static_cast<float>(viewport.height);
    Transforms t = computeTransforms(preset, aspect);
    glUniformMatrix4fv(modelView_, 1, GL_FALSE, &t.modelView[0][0]);
    glUniformMatrix4fv(projection_, 1, GL_FALSE, &t.projection[0][0]);
    glUniformMatrix3fv(normalMatrix_, 1, GL_FALSE, &t.normalMatrix[0][0]);
    // A pixel's footprint as a share of the distance: the view's height spans 2 tan(fovy / 2) of it.
    float footprint =
        2.0f * std::tan(0.5f * verticalFovRadians(preset.camera, aspect)) / static_cast<float>(viewport.height);
    glUniform1f(depthBias_, kOverlayDepthBiasPixels * footprint);
    if (options.wireframe) {
        glm::vec3 color = wireframeColor(options.background);
        glUniform3fv(color_, 1, &color[0]);
        glUniform1f(normalLength_, 0.0f);
        lines.drawEdges();
    }
    if (options.vertexNormals) { // after the wireframe: on top where they cross
        // The view matrix is rigid, so this is the diagonal's length in the model as drawn.
        float length = kNormalLineShare * glm::length(glm::mat3(t.modelView) * lines.diagonal());
        glUniform3fv(color_, 1, &kNormalLineColor[0]);
        glUniform1f(normalLength_, length);
        lines.drawNormals();
    }
    glUseProgram(0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
}

//----------------------------------------------------------------------------------------
// In a view (drawView)
//----------------------------------------------------------------------------------------

void drawViewOverlays(Renderer& renderer, const Preset& preset, const std::shared_ptr<const Mesh>& mesh,
                      const Viewport& viewport, const ViewportDraw& draw, bool valueView) {
    WireframeOptions overlay{.wireframe = draw.wireframe, .vertexNormals = draw.vertexNormals};
    overlay.background = valueView ? glm::vec3(0.0f) : preset.background;
    if (draw.wipe && wireframeColor(overlay.background) != wireframeColor(preset.background)) {
        WireframeOptions lit = overlay; // the lit side's background: a colour of its own there
        lit.background = preset.background;
        lit.toX = overlay.fromX = draw.options.fromX;
        renderer.drawOverlay(preset, mesh, viewport, lit);
    }
    renderer.drawOverlay(preset, mesh, viewport, overlay);
}

} // namespace lab
