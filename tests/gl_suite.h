// gl_suite.h — a test suite's headless GL context and renderer, made once for all its tests.
// The renderer is the lab's Renderer, or the OffscreenRenderer that `lab render` uses (presets to
// images: GlSuite<testing::Test, OffscreenRenderer>).
#pragma once

#include "platform/headless_gl.h"
#include "render/renderer.h"

#include <gtest/gtest.h>

namespace lab {

template <typename Base = testing::Test, typename RendererType = Renderer>
class GlSuite : public Base {
protected:
    static void SetUpTestSuite() {
        gl_ = new HeadlessGl;
        std::string error;
        ASSERT_TRUE(gl_->create(error)) << error;
        renderer_ = new RendererType;
        Diagnostics d;
        ASSERT_TRUE(renderer_->init(d)) << toString(d);
    }
    static void TearDownTestSuite() {
        delete renderer_;
        delete gl_;
        renderer_ = nullptr;
        gl_ = nullptr;
    }
    static inline HeadlessGl* gl_ = nullptr;
    static inline RendererType* renderer_ = nullptr;
};

} // namespace lab
