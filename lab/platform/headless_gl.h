// headless_gl.h — an OpenGL ES 3.0 context with no window and no display server.
//
// EGL on Mesa's surfaceless platform (EGL_MESA_platform_surfaceless), falling back to the
// first EGL device (EGL_EXT_platform_device). With no GPU, Mesa renders with llvmpipe. The
// context draws only into framebuffer objects (render/renderer.h's Framebuffer).
// This is the platform for `lab render`, `lab check` and the GPU tests; the windowed platforms
// live beside it.
#pragma once

#include <memory>
#include <string>

namespace lab {

// Owns the EGL display and context (not copyable: impl_ is unique).
class HeadlessGl {
public:
    HeadlessGl();
    ~HeadlessGl();

    // Creates the context and makes it current on this thread; false with `error` if impossible.
    bool create(std::string& error);
    std::string renderer() const; // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace lab
