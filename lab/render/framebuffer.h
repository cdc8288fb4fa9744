// framebuffer.h — framebuffers: the window's, and offscreen ones read back or kept between frames.
//
// Framebuffer is a colour and depth pair read back as an RGB image (`lab render`, screenshots, the
// tests); ViewportTarget keeps a viewport's render between frames (the viewport cache, multisampled
// when the GL offers it). GL only. It does not draw anything into them (renderer.h).
#pragma once

#include "core/io/image.h"
#include "render/gl.h"

#include <glm/vec3.hpp>

namespace lab {

// A rectangle of the bound framebuffer, in GL's convention (origin at the bottom left).
struct Viewport {
    int x = 0, y = 0, width = 0, height = 0;
};

// Binds framebuffer `id` (0: the window's own), e.g. after offscreen work.
void bindFramebuffer(unsigned id);

// Clears the whole bound framebuffer (size width × height) to `color`.
void clearFramebuffer(const glm::vec3& color, int width, int height);

// An offscreen RGBA8 + 24-bit depth framebuffer, read back as a top-row-first RGB image.
class Framebuffer {
public:
    Framebuffer(int width, int height);
    ~Framebuffer();
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;

    bool complete() const { return complete_; }
    void bind() const;
    unsigned id() const { return fbo_; }
    Image readRgb() const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    GLuint fbo_ = 0, color_ = 0, depth_ = 0;
    bool complete_ = false;
};

// A viewport's render kept offscreen between frames (the interactive lab draws the model only when what it
// shows changes): colour and depth at width × height with `samples` (0: none) for drawing into,
// resolved into a single-sample copy that present() scales onto the bound draw framebuffer. A
// smaller view (drawn while dragging) uses the bottom-left `used` part, so nothing is allocated
// per frame.
class ViewportTarget {
public:
    ViewportTarget(int width, int height, int samples);
    ~ViewportTarget();
    ViewportTarget(const ViewportTarget&) = delete;
    ViewportTarget& operator=(const ViewportTarget&) = delete;

    bool complete() const { return complete_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }
    void bind() const; // for drawing: into Viewport{0, 0, used width, used height}
    // After drawing: the samples of the used part into the single-sample copy.
    void resolve(int usedWidth, int usedHeight) const;
    // Copies the used part into `dest` of framebuffer `target` (left bound), filtered linearly
    // when the sizes differ, pixel for pixel when they match.
    void present(unsigned target, const Viewport& dest, int usedWidth, int usedHeight) const;

private:
    int width_, height_, samples_;
    GLuint drawFbo_ = 0, drawColor_ = 0, depth_ = 0; // multisampled when samples_ > 0
    GLuint readFbo_ = 0, readColor_ = 0;             // the resolved copy (drawFbo_ itself without samples)
    bool complete_ = false;
};

// The largest sample count the GL offers for an RGBA8 view, at most `wanted`.
int supportedSamples(int wanted);

} // namespace lab
