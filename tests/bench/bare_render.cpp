// bare_render.cpp — the floor for `lab render`: a bare EGL program that initialises, draws the
// default preset's mesh once with the lab's shader, reads back and writes the same 512x512 PNG.
// No argument parsing beyond the output path, no preset file, no validation: just the work.
//
//   bare_render OUT.png
#include "core/scene/transforms.h"
#include "core/lighting/lighting.h"
#include "core/scene/mesh.h"
#include "render/gl.h"
#include "render/shader.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stb_image_write.h>

#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: bare_render OUT.png\n");
        return 2;
    }
    const int w = 512, h = 512;
    auto getDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    EGLDisplay display = getDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    eglInitialize(display, nullptr, nullptr);
    eglBindAPI(EGL_OPENGL_ES_API);
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);

    GLuint fbo, color, depth;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);

    lab::Diagnostics d;
    GLuint program = *lab::buildProgram(lab::builtinStageSources(), {"LAB_PER_PIXEL 1"}, d);
    lab::Preset preset; // the defaults: a 64x32 sphere, one point light
    lab::Mesh mesh = lab::makeSphere(64, 32);
    std::vector<float> v;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        v.insert(v.end(), {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z, mesh.normals[i].x,
                           mesh.normals[i].y, mesh.normals[i].z});
    }
    GLuint vao, vbo, ebo;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * 4), v.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, reinterpret_cast<void*>(12));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 24, nullptr);
    glGenBuffers(1, &ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * 4), mesh.indices.data(), GL_STATIC_DRAW);

    glUseProgram(program);
    lab::Transforms t = lab::computeTransforms(preset, 1.0f);
    lab::ShadingInputs in = lab::packShading(preset, t.view);
    auto at = [&](const char* n) { return glGetUniformLocation(program, n); };
    glUniformMatrix4fv(at("u_modelView"), 1, GL_FALSE, &t.modelView[0][0]);
    glUniformMatrix4fv(at("u_projection"), 1, GL_FALSE, &t.projection[0][0]);
    glUniformMatrix3fv(at("u_normalMatrix"), 1, GL_FALSE, &t.normalMatrix[0][0]);
    glUniform3fv(at("u_material.ambient"), 1, &in.material.ambient[0]);
    glUniform3fv(at("u_material.diffuse"), 1, &in.material.diffuse[0]);
    glUniform3fv(at("u_material.specular"), 1, &in.material.specular[0]);
    glUniform1f(at("u_material.shininess"), in.material.shininess);
    glUniform1i(at("u_terms.emissive"), 1);
    glUniform1i(at("u_terms.ambient"), 1);
    glUniform1i(at("u_terms.diffuse"), 1);
    glUniform1i(at("u_terms.specular"), 1);
    glUniform3fv(at("u_ambientLight"), 1, &in.ambientLight[0]);
    glUniform1i(at("u_lightCount"), 1);
    glUniform3fv(at("u_lights[0].position"), 1, &in.lights[0].position[0]);
    glUniform3fv(at("u_lights[0].diffuse"), 1, &in.lights[0].diffuse[0]);
    glUniform3fv(at("u_lights[0].specular"), 1, &in.lights[0].specular[0]);
    glUniform3fv(at("u_lights[0].attenuation"), 1, &in.lights[0].attenuation[0]);

    glViewport(0, 0, w, h);
    glEnable(GL_DEPTH_TEST);
    glClearColor(preset.background.r, preset.background.g, preset.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT, nullptr);
    std::vector<unsigned char> rgba(std::size_t(w) * h * 4), rgb(std::size_t(w) * h * 3);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (int k = 0; k < 3; ++k) {
                rgb[(std::size_t(y) * w + x) * 3 + k] = rgba[(std::size_t(h - 1 - y) * w + x) * 4 + k];
            }
        }
    }
    int ok = stbi_write_png(argv[1], w, h, 3, rgb.data(), w * 3);
    eglTerminate(display);
    return ok ? 0 : 1;
}
