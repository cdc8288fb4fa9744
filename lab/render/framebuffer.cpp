// framebuffer.cpp — framebuffer.h: binding and clearing, Framebuffer (a colour and depth
// renderbuffer pair, read back as RGB) and ViewportTarget (the viewport cache's texture-backed copy of a view).
#include "render/framebuffer.h"


#include "render/gl.h"

namespace lab {

void bindFramebuffer(unsigned id) { glBindFramebuffer(GL_FRAMEBUFFER, id); }

void clearFramebuffer(const glm::vec3& color, int width, int height) {
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(color.r, color.g, color.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

//----------------------------------------------------------------------------------------
// Framebuffer
//----------------------------------------------------------------------------------------

Framebuffer::Framebuffer(int width, int height) : width_(width), height_(height) {
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glGenRenderbuffers(1, &color_);
    glBindRenderbuffer(GL_RENDERBUFFER, color_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    complete_ = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

Framebuffer::~Framebuffer() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &color_);
    glDeleteRenderbuffers(1, &depth_);
}

void Framebuffer::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, fbo_); }

Image Framebuffer::readRgb() const {
    bind();
    std::vector<std::uint8_t> rgba(std::size_t(width_) * std::size_t(height_) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    Image image{width_, height_, std::vector<std::uint8_t>(std::size_t(width_) * std::size_t(height_) * 3)};
    // GL's first row is the bottom one.
    for (int y = 0; y < height_; ++y) {
        const std::uint8_t* src = rgba.data() + std::size_t(height_ - 1 - y) * std::size_t(width_) * 4;
        std::uint8_t* dst = image.rgb.data() + std::size_t(y) * std::size_t(width_) * 3;
        for (int x = 0; x < width_; ++x) {
            dst[3 * x + 0] = src[4 * x + 0];
            dst[3 * x + 1] = src[4 * x + 1];
            dst[3 * x + 2] = src[4 * x + 2];
        }
    }
    return image;
}

//----------------------------------------------------------------------------------------
// ViewportTarget
//----------------------------------------------------------------------------------------

namespace {

GLuint renderbuffer(GLenum format, int width, int height, int samples) {
    GLuint id = 0;
    glGenRenderbuffers(1, &id);
    glBindRenderbuffer(GL_RENDERBUFFER, id);
    if (samples > 0) {
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
        glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
    return id;
}

} // namespace

int supportedSamples(int wanted) {
    GLint most = 0;
    glGetInternalformativ(GL_RENDERBUFFER, GL_RGBA8, GL_SAMPLES, 1, &most); // the largest comes first
    return std::max(0, std::min(wanted, static_cast<int>(most)));
}

ViewportTarget::ViewportTarget(int width, int height, int samples) : width_(width), height_(height), samples_(samples) {
    glGenFramebuffers(1, &drawFbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, drawFbo_);
    drawColor_ = renderbuffer(GL_RGBA8, width, height, samples);
    depth_ = renderbuffer(GL_DEPTH_COMPONENT24, width, height, samples);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, drawColor_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    complete_ = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (samples > 0) {
        glGenFramebuffers(1, &readFbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, readFbo_);
        readColor_ = renderbuffer(GL_RGBA8, width, height, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, readColor_);
        complete_ = complete_ && glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
}

ViewportTarget::~ViewportTarget() {
    glDeleteFramebuffers(1, &drawFbo_);
    glDeleteRenderbuffers(1, &drawColor_);
    glDeleteRenderbuffers(1, &depth_);
    if (readFbo_) {
        glDeleteFramebuffers(1, &readFbo_);
        glDeleteRenderbuffers(1, &readColor_);
    }
}

void ViewportTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, drawFbo_); }

void ViewportTarget::resolve(int usedWidth, int usedHeight) const {
    if (readFbo_) {
        glDisable(GL_SCISSOR_TEST); // a blit obeys the scissor
        glBindFramebuffer(GL_READ_FRAMEBUFFER, drawFbo_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, readFbo_);
        glBlitFramebuffer(0, 0, usedWidth, usedHeight, 0, 0, usedWidth, usedHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
}

void ViewportTarget::present(unsigned target, const Viewport& dest, int usedWidth, int usedHeight) const {
    glDisable(GL_SCISSOR_TEST); // a blit obeys the scissor
    glBindFramebuffer(GL_READ_FRAMEBUFFER, readFbo_ ? readFbo_ : drawFbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    bool same = dest.width == usedWidth && dest.height == usedHeight;
    glBlitFramebuffer(0, 0, usedWidth, usedHeight, dest.x, dest.y, dest.x + dest.width, dest.y + dest.height,
                      GL_COLOR_BUFFER_BIT, same ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
}

} // namespace lab
