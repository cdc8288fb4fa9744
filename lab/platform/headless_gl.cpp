// headless_gl.cpp — EGL surfaceless context creation.
#include "platform/headless_gl.h"

#include "render/gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

namespace lab {

struct HeadlessGl::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

HeadlessGl::HeadlessGl() : impl_(std::make_unique<Impl>()) {}

HeadlessGl::~HeadlessGl() {
    if (impl_->display != EGL_NO_DISPLAY) {
        eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (impl_->context != EGL_NO_CONTEXT) {
            eglDestroyContext(impl_->display, impl_->context);
        }
        eglTerminate(impl_->display);
    }
}

namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list) {
        return false;
    }
    std::size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += n) {
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) {
            return true;
        }
    }
    return false;
}

EGLDisplay openDisplay() {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) {
        return EGL_NO_DISPLAY;
    }
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
            return d;
        }
    }
    if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (queryDevices && queryDevices(8, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
                    return d;
                }
            }
        }
    }
    return EGL_NO_DISPLAY;
}

} // namespace

bool HeadlessGl::create(std::string& error) {
    Impl& m = *impl_;
    m.display = openDisplay();
    if (m.display == EGL_NO_DISPLAY) {
        error = "no EGL display for headless rendering (is Mesa's libegl-mesa0 installed?)";
        return false;
    }
    if (!eglBindAPI(EGL_OPENGL_ES_API)) {
        error = "EGL cannot bind the OpenGL ES API";
        return false;
    }
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    // Surfaceless needs no config at all where EGL_KHR_no_config_context exists.
    const char* displayExtensions = eglQueryString(m.display, EGL_EXTENSIONS);
    if (!hasExtension(displayExtensions, "EGL_KHR_no_config_context")) {
        if (!eglChooseConfig(m.display, configAttributes, &config, 1, &count) || count == 0) {
            error = "no EGL config for OpenGL ES 3";
            return false;
        }
    }
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    m.context = eglCreateContext(m.display, config, EGL_NO_CONTEXT, contextAttributes);
    if (m.context == EGL_NO_CONTEXT) {
        error = "cannot create an OpenGL ES 3.0 context (EGL error 0x" + std::to_string(eglGetError()) + ")";
        return false;
    }
    if (!eglMakeCurrent(m.display, EGL_NO_SURFACE, EGL_NO_SURFACE, m.context)) {
        error = "cannot make the headless context current";
        return false;
    }
    return true;
}

std::string HeadlessGl::renderer() const {
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return s ? s : "";
}

} // namespace lab
