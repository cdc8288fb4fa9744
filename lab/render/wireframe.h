// wireframe.h — the shading-rate views drawn over the shaded model: the wireframe (every triangle
// edge once) and the vertex normals as short lines, so a class sees how many vertices the
// lighting is evaluated at and where (issue 26, "See the equation on the model").
//
// Drawn after the model into the same framebuffer, keeping its depth: a line on the surface is
// pulled a little toward the eye (wireframe.vert) and wins the depth test, a line on the far side
// stays hidden. The same for every shading: flat shading draws the same positions, so the same
// edges. GLES 3.0 / WebGL2 only — no glPolygonMode, no geometry shader — and lines one pixel wide
// (WebGL's only width). A mesh's line buffers are made the first time the wireframe or the normals draw it and
// freed with its GpuMesh.
// It does not clear or draw the model (Renderer::draw) and does not decide when they are
// shown (DisplaySettings, viewDraw).
#pragma once

#include "core/scene/mesh.h"
#include "render/gl.h"
#include "render/renderer.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace lab {

// A normal's line is this share of the model's bounding-box diagonal (as drawn: after the
// model's scale) long: long enough to read its direction, short enough not to cross the
// neighbours' on a fine mesh.
inline constexpr float kNormalLineShare = 0.06f;
// At most this many normals are drawn: above it, every k-th vertex's (normalLineStep), so a
// million-triangle model stays cheap and readable.
inline constexpr std::size_t kMaxNormalLines = 50'000;
// How far a line is pulled toward the eye (wireframe.vert), in pixels' footprints: how far apart
// two pixels are on a surface facing the eye at the line's distance. A line's pixel lies up to
// about half a pixel off the edge it draws, where the triangle's depth differs from the line's by
// that offset times the tangent of the angle the triangle is seen at: three footprints cover
// triangles seen up to about 80 degrees from head-on. The model's thickness (what hides the
// lines on its far side) is many footprints except a few pixels from its silhouette.
inline constexpr float kOverlayDepthBiasPixels = 3.0f;

// The colours, exact in 8 bits (tests compare pixels with them).
inline constexpr glm::vec3 kWireLight{224.0f / 255.0f, 224.0f / 255.0f, 224.0f / 255.0f};
inline constexpr glm::vec3 kWireDark{24.0f / 255.0f, 24.0f / 255.0f, 24.0f / 255.0f};
inline constexpr glm::vec3 kNormalLineColor{1.0f, 160.0f / 255.0f, 0.0f}; // orange: unlike any wireframe

// The wireframe's colour on `background`: light on a dark one, dark on a light one.
glm::vec3 wireframeColor(const glm::vec3& background);

// The triangles' edges (three indices a triangle) as GL_LINES index pairs, each edge once
// whichever way round its triangles name it, in ascending order. Edges are told apart by their
// vertex indices: split vertices (a seam, a cube's corners) give two edges in the same place.
std::vector<std::uint32_t> edgeIndices(std::span<const std::uint32_t> triangles);

// Every how-many-th vertex gets a normal's line: 1 up to kMaxNormalLines vertices, then the
// smallest step that keeps the count at most kMaxNormalLines.
std::size_t normalLineStep(std::size_t vertexCount);

// The lines of one GpuMesh on the GPU, each kind built the first time it is drawn.
class WireframeLines {
public:
    // `vertices`: the GpuMesh's interleaved position + normal buffer, shared (not owned).
    WireframeLines(const Mesh& mesh, GLuint vertices);
    ~WireframeLines();
    WireframeLines(const WireframeLines&) = delete;
    WireframeLines& operator=(const WireframeLines&) = delete;

    void drawEdges();
    void drawNormals();
    // The model-space bounding box's diagonal, as a vector from its low corner to its high one.
    const glm::vec3& diagonal() const { return diagonal_; }

private:
    const Mesh& mesh_;
    GLuint vertices_;
    glm::vec3 diagonal_{0.0f};
    GLuint edgeVao_ = 0, edgeEbo_ = 0;
    GLsizei edgeCount_ = 0; // indices, two an edge
    GLuint normalVao_ = 0, normalVbo_ = 0; // normalVbo_: every k-th vertex, only when k > 1
    GLuint tipVbo_ = 0; // {0, 1}: a line's base and tip
    GLsizei normalCount_ = 0; // lines
};

// The wireframe's program (wireframe.vert, wireframe.frag) and its draw.
class WireframeProgram {
public:
    // Compiles the built-in wireframe shaders; none, with the compiler's messages, if they fail.
    static std::unique_ptr<WireframeProgram> build(Diagnostics& diagnostics);
    ~WireframeProgram();
    WireframeProgram(const WireframeProgram&) = delete;
    WireframeProgram& operator=(const WireframeProgram&) = delete;

    // What Renderer::drawOverlay draws, with `mesh` on the GPU.
    void draw(const Preset& preset, GpuMesh& mesh, const Viewport& viewport, const WireframeOptions& options) const;

private:
    explicit WireframeProgram(GLuint id);
    GLuint id_;
    GLint modelView_, projection_, normalMatrix_, normalLength_, depthBias_, color_;
};

// drawView's part: the overlays `draw` asks for over the view it drew, `valueView` when that is a
// value view (on black). On a wipe, each side's wireframe contrasts with that side's background,
// in one draw when both sides take the same colour.
void drawViewOverlays(Renderer& renderer, const Preset& preset, const std::shared_ptr<const Mesh>& mesh,
                      const Viewport& viewport, const ViewportDraw& draw, bool valueView);

} // namespace lab
