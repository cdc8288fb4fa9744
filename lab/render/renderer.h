// renderer.h — draws a Preset with the lab's shaders. GL only: no windows, no ImGui.
//
// The renderer owns the GL programs (one per evaluation site: per vertex for flat and Gouraud,
// per pixel for Phong) and the GPU copies of the meshes it draws: one per mesh, kept exactly as
// long as someone else (core/gltf/mesh_cache.h, a caller) still holds that mesh. draw() reads the Preset and
// writes into whatever framebuffer is bound; it never changes the Preset.
// It does not create GL contexts (lab/platform) or load files (lab/core).
#pragma once

#include "core/io/image.h"
#include "core/lighting/lighting.h"
#include "core/scene/mesh.h"
#include "core/scene/preset.h"
#include "render/framebuffer.h"
#include "render/gl.h"
#include "render/shader.h"

#include <memory>
#include <optional>

namespace lab {

class WireframeLines;   // render/wireframe.h
class WireframeProgram; // render/wireframe.h

// A mesh on the GPU: the indexed buffers for smooth shading, and the de-indexed copy for flat
// shading, built the first time flat shading draws it. Shares the CPU mesh (the flat copy needs it).
class GpuMesh {
public:
    explicit GpuMesh(std::shared_ptr<const Mesh> mesh);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    const std::shared_ptr<const Mesh>& cpu() const { return mesh_; }
    void drawSmooth() const;
    void drawFlat();
    // The wireframe's and the normals' lines, made on first use (defined in overlay.cpp).
    WireframeLines& wireframe();

private:
    std::shared_ptr<const Mesh> mesh_;
    GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
    GLuint flatVao_ = 0, flatVbo_ = 0;
    GLsizei flatCount_ = 0;
    std::unique_ptr<WireframeLines> overlay_; // after mesh_: it refers to the mesh
};

// What a draw shows (core/scene/view_mode.h). The renderer applies the view itself: a term view
// switches the other terms off, a value view (a factor for `light`, or gouraud-error) is drawn
// through `palette` over `range` on a black background. A view that does not apply to the preset
// (notApplicable) draws the lit model. `fromX`..`toX` is the part of the viewport's width that is
// cleared and drawn (the wipe draws its two sides so).
struct DrawOptions {
    ViewMode view = ViewMode::Lit;
    int light = 0; // an index into preset.lights
    ValuePalette palette = ValuePalette::Viridis;
    ValueRange range;
    float fromX = 0.0f, toX = 1.0f;
    bool operator==(const DrawOptions&) const = default;
};

// The shading-rate views over the model (render/wireframe.h): the triangles' edges, each vertex's
// normal as a short line. `background` is what the wireframe's colour contrasts with;
// `fromX`..`toX` the part of the viewport's width drawn over, as in DrawOptions.
struct WireframeOptions {
    bool wireframe = false, vertexNormals = false;
    glm::vec3 background{0.0f};
    float fromX = 0.0f, toX = 1.0f;
    bool operator==(const WireframeOptions&) const = default;
};

// The side of the automatic range's render: its longer side has at most this many pixels.
inline constexpr int kRangeRenderSize = 256;

// How a viewport is drawn: the view (options; its range is the fixed one, replaced by the one
// found when `automatic`), and with the wipe, the lit model left of options.fromX. The GUI, the
// page and `lab render` all draw through drawView() below.
struct ViewportDraw {
    DrawOptions options;
    bool automatic = false; // a value view with an automatic range (Renderer::autoValueRange)
    bool wipe = false;
    bool wireframe = false, vertexNormals = false; // over the model, both sides of a wipe (drawOverlay)
    bool operator==(const ViewportDraw&) const = default;
};
ViewportDraw viewDraw(const DisplaySettings& view);

// Owns the GL programs and the GPU copies of meshes (not copyable: impl_ is unique).
class Renderer {
public:
    Renderer();
    ~Renderer();

    // Compiles the built-in shaders. Needs a current GL ES 3.0 context.
    bool init(Diagnostics& diagnostics);

    // Replaces the shader stage bodies and lighting.glsl (checked for non-ASCII text first); on
    // failure keeps the previous programs running and stageSources() unchanged.
    bool setStageSources(const StageSources& sources, Diagnostics& diagnostics);
    const StageSources& stageSources() const;
    // Counts the programs built: changes whenever setStageSources succeeds (a cached view drawn
    // with the old programs is stale).
    unsigned generation() const;

    // Clears the viewport to the background and draws the mesh with the preset's shading,
    // transforms and lights into the bound framebuffer. Aspect = viewport width / height.
    void draw(const Preset& preset, GpuMesh& mesh, const Viewport& viewport, const DrawOptions& options = {});
    // The same with the renderer's own GPU copy of `mesh`, uploaded on first use.
    void draw(const Preset& preset, const std::shared_ptr<const Mesh>& mesh, const Viewport& viewport,
              const DrawOptions& options = {});

    // The automatic range of options.view (view_mode.h autoRange) from the smallest and largest
    // value on the model's pixels in a render of `width` × `height` scaled down so that its longer
    // side is at most kRangeRenderSize: one extra draw that writes each value's float bits, read
    // back (at most 256 KB). None when the view shows no value or no pixel of the model is seen.
    // Leaves the framebuffer that was bound bound.
    std::optional<ValueRange> autoValueRange(const Preset& preset, const std::shared_ptr<const Mesh>& mesh, int width,
                                             int height, const DrawOptions& options);

    // Draws the overlays `options` asks for (render/wireframe.h) over what draw() left in the bound
    // framebuffer, its depth kept (so lines on the far side stay hidden); nothing when both are off.
    void drawOverlay(const Preset& preset, const std::shared_ptr<const Mesh>& mesh, const Viewport& viewport,
                     const WireframeOptions& options);

    // The value `options.view` has at pixel (x, y) (GL's convention: from the bottom left) of a
    // width × height view: that one pixel drawn as the value's float bits and read back, so it is
    // what the view shows there. None off the model, or for a view that shows no value.
    std::optional<float> valueAt(const Preset& preset, const std::shared_ptr<const Mesh>& mesh, int width, int height,
                                 int x, int y, const DrawOptions& options);

    // Draws `vertices` as single-pixel points with the preset's shading, transforms and
    // lights (no clear), as `options` shows them; with `valueBits`, a value view writes each
    // value's float as the four bytes of its pixel (little-endian R, G, B, A). The CPU–GPU parity
    // tests place probes with it.
    void drawPoints(const Preset& preset, const std::vector<FlatVertex>& vertices, int width, int height,
                    const DrawOptions& options = {}, bool valueBits = false);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::unique_ptr<WireframeProgram> overlay_; // built by init()
};

// Draws a viewport as `draw` says into the bound framebuffer; the value view's range, when it
// shows one.
std::optional<ValueRange> drawView(Renderer& renderer, const Preset& preset, const std::shared_ptr<const Mesh>& mesh,
                                   const Viewport& viewport, const ViewportDraw& draw);

// glViewport(viewport) with the scissor on its width's part fromX..toX (shares of the width, as
// DrawOptions has them), no dithering, no blending: how the model and its overlays are drawn.
void viewportPart(const Viewport& viewport, float fromX, float toX);

} // namespace lab
