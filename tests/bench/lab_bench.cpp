// lab_bench.cpp — the lab against the bare GL floor, side by side in one run (Google Benchmark).
//
//   build/tests/bench/lab_bench                 every comparison, then the table of ratios
//   build/tests/bench/lab_bench --benchmark_filter=Frame
//
// Comparisons (README "Performance" has the targets and the latest figures):
//   1. Frame (lab_ms vs bare_ms): the renderer's frame (256x128-segment sphere, 4 point lights,
//      1280x720, headless) against drawing the same vertex buffer with the same shader and
//      uniforms and nothing else, for each shading mode and BRDF;
//   1b. View (view_ms vs lit_ms): a factor view (its automatic range included) and the wipe against
//      the lit view, drawn as the GUI draws a viewport (drawView);
//   2. GuiFrame (gui_ms vs model_ms): a whole App frame (panel, plots, the model drawn again: its
//      light orbits) offscreen against the model drawn alone at the view's size;
//   3. Plots: the CPU cost of one frame of the plots panel (samples, geometry, ImGui draw lists),
//      alone and with a compare set, unchanged from the frame before (as while the mouse moves
//      or nothing happens) and with the shininess changing every frame (as during a slider drag:
//      nothing is found in the cache);
//   4. Process (lab_ms vs bare_ms): `lab render` as a process against a bare EGL program that
//      draws the same mesh once, reads back and writes the same PNG, alternately, as medians;
//   5. Gltf (load_ms vs read_ms): loading a generated 1-million-triangle .glb against reading
//      the file's bytes;
//   12. Fit: the README's fits of one model to another (core/plots/fit.h), each on its own.
// Wall-clock times; every GL benchmark ends its iteration with glFinish.
#include "../../tools/glb_writer.h"
#include "../test_files.h"
#include "app/app.h"
#include "core/scene/transforms.h"
#include "core/gltf/reader.h"
#include "core/io/file_io.h"
#include "core/lighting/lighting.h"
#include "core/plots/fit.h"
#include "core/scene/mesh.h"
#include "platform/headless_app.h"
#include "platform/headless_gl.h"
#include "render/renderer.h"
#include "render/shader.h"
#include "ui/plots/plots.h"
#include "ui/widgets.h"

#include <benchmark/benchmark.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace lab {
namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 1280, kHeight = 720;

HeadlessGl& context() {
    static HeadlessGl gl;
    static bool created = [] {
        std::string error;
        if (!gl.create(error)) {
            std::fprintf(stderr, "lab_bench: %s\n", error.c_str());
            std::exit(1);
        }
        return true;
    }();
    (void)created;
    return gl;
}

// The scene of comparisons 1 and 2: a 256 x 128 sphere lit by 4 point lights.
Preset benchPreset(Shading shading, BrdfModel brdf) {
    Preset p;
    p.model.subdivisions = {256, 128};
    p.shading = shading;
    p.brdf = brdf;
    p.lights.clear();
    const glm::vec3 positions[4] = {{2, 2, 2}, {-2, 1, 2}, {0, -2, 3}, {1, 3, -1}};
    for (const glm::vec3& pos : positions) {
        LightDesc l;
        l.position = pos;
        l.diffuse = glm::vec3(0.4f);
        l.specular = glm::vec3(0.5f);
        l.attenuation = {1.0f, 0.05f, 0.01f};
        p.lights.push_back(l);
    }
    return p;
}

//----------------------------------------------------------------------------------------
// 1. The renderer's frame against the bare draw
//----------------------------------------------------------------------------------------

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The bare program: the same buffers, program and uniform values as the lab's, set once; a
// frame is a clear and one draw call.
struct BareDraw {
    GLuint program = 0, vao = 0, vbo = 0, ebo = 0;
    GLsizei count = 0;
    bool flat = false;
    glm::vec3 background;

    explicit BareDraw(const Preset& preset) {
        Mesh mesh = makeBuiltin(preset.model.builtin, preset.model.subdivisions);
        Diagnostics d;
        program = *buildProgram(builtinStageSources(), {preset.shading == Shading::Phong ? "LAB_PER_PIXEL 1" : "LAB_PER_VERTEX 1"}, d);
        glGenVertexArrays(1, &vao);
        glBindVertexArray(vao);
        glGenBuffers(1, &vbo);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        flat = preset.shading == Shading::Flat;
        if (flat) {
            std::vector<FlatVertex> v = expandFlat(mesh);
            glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(FlatVertex)), v.data(), GL_STATIC_DRAW);
            for (GLuint a = 0; a < 3; ++a) {
                glEnableVertexAttribArray(a);
                glVertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, sizeof(FlatVertex), reinterpret_cast<void*>(a * sizeof(glm::vec3)));
            }
            count = static_cast<GLsizei>(v.size());
        } else {
            std::vector<float> v;
            for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
                v.insert(v.end(), {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z, mesh.normals[i].x,
                                   mesh.normals[i].y, mesh.normals[i].z});
            }
            glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, nullptr);
            glEnableVertexAttribArray(1);
            glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, reinterpret_cast<void*>(12));
            glEnableVertexAttribArray(2);
            glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 24, nullptr);
            glGenBuffers(1, &ebo);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * 4), mesh.indices.data(), GL_STATIC_DRAW);
            count = static_cast<GLsizei>(mesh.indices.size());
        }
        glBindVertexArray(0);
        glUseProgram(program);
        Transforms t = computeTransforms(preset, float(kWidth) / float(kHeight));
        ShadingInputs in = packShading(preset, t.view);
        auto at = [&](const std::string& n) { return glGetUniformLocation(program, n.c_str()); };
        glUniformMatrix4fv(at("u_modelView"), 1, GL_FALSE, &t.modelView[0][0]);
        glUniformMatrix4fv(at("u_projection"), 1, GL_FALSE, &t.projection[0][0]);
        glUniformMatrix3fv(at("u_normalMatrix"), 1, GL_FALSE, &t.normalMatrix[0][0]);
        glUniform3fv(at("u_material.emissive"), 1, &in.material.emissive[0]);
        glUniform3fv(at("u_material.ambient"), 1, &in.material.ambient[0]);
        glUniform3fv(at("u_material.diffuse"), 1, &in.material.diffuse[0]);
        glUniform3fv(at("u_material.specular"), 1, &in.material.specular[0]);
        glUniform1f(at("u_material.shininess"), in.material.shininess);
        glUniform1i(at("u_brdf.model"), in.brdf.model);
        glUniform1i(at("u_brdf.distribution"), in.brdf.distribution);
        glUniform1i(at("u_brdf.fresnel"), in.brdf.fresnel);
        glUniform1i(at("u_brdf.geometry"), in.brdf.geometry);
        glUniform1f(at("u_brdf.roughness"), in.brdf.roughness);
        glUniform1f(at("u_brdf.ior"), in.brdf.ior);
        for (const char* term : {"emissive", "ambient", "diffuse", "specular"}) {
            glUniform1i(at(std::string("u_terms.") + term), 1);
        }
        glUniform3fv(at("u_ambientLight"), 1, &in.ambientLight[0]);
        glUniform1i(at("u_lightCount"), in.lightCount);
        for (int i = 0; i < in.lightCount; ++i) {
            std::string l = "u_lights[" + std::to_string(i) + "].";
            glUniform1i(at(l + "type"), in.lights[i].type);
            glUniform3fv(at(l + "position"), 1, &in.lights[i].position[0]);
            glUniform3fv(at(l + "direction"), 1, &in.lights[i].direction[0]);
            glUniform3fv(at(l + "ambient"), 1, &in.lights[i].ambient[0]);
            glUniform3fv(at(l + "diffuse"), 1, &in.lights[i].diffuse[0]);
            glUniform3fv(at(l + "specular"), 1, &in.lights[i].specular[0]);
            glUniform3fv(at(l + "attenuation"), 1, &in.lights[i].attenuation[0]);
            glUniform1f(at(l + "cosCutoff"), in.lights[i].cosCutoff);
            glUniform1f(at(l + "exponent"), in.lights[i].exponent);
        }
        glUseProgram(0);
        background = preset.background;
    }

    ~BareDraw() {
        glDeleteProgram(program);
        glDeleteBuffers(1, &vbo);
        if (ebo) {
            glDeleteBuffers(1, &ebo);
        }
        glDeleteVertexArrays(1, &vao);
    }

    void frame() const {
        glViewport(0, 0, kWidth, kHeight);
        glEnable(GL_DEPTH_TEST);
        glClearColor(background.r, background.g, background.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glUseProgram(program);
        glBindVertexArray(vao);
        if (flat) {
            glDrawArrays(GL_TRIANGLES, 0, count);
        } else {
            glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
        }
        glFinish();
    }
};

// The lab's frame and the bare frame, alternately, each timed on its own (counters lab_ms and
// bare_ms): whatever the machine does meanwhile affects both alike.
void Frame(benchmark::State& state) {
    context();
    Preset preset = benchPreset(static_cast<Shading>(state.range(0)), static_cast<BrdfModel>(state.range(1)));
    Renderer renderer;
    Diagnostics d;
    renderer.init(d);
    GpuMesh mesh(std::make_shared<const Mesh>(makeBuiltin(preset.model.builtin, preset.model.subdivisions)));
    BareDraw bare(preset);
    Framebuffer target(kWidth, kHeight);
    target.bind();
    renderer.draw(preset, mesh, {0, 0, kWidth, kHeight}); // warm up (the flat copy is built here)
    bare.frame();
    double lab = 0, base = 0;
    for (auto _ : state) {
        Clock::time_point t0 = Clock::now();
        renderer.draw(preset, mesh, {0, 0, kWidth, kHeight});
        glFinish();
        lab += msSince(t0);
        Clock::time_point t1 = Clock::now();
        bare.frame();
        base += msSince(t1);
    }
    state.counters["lab_ms"] = lab / double(state.iterations());
    state.counters["bare_ms"] = base / double(state.iterations());
}

//----------------------------------------------------------------------------------------
// 1b. A factor view and the wipe against the lit view
//----------------------------------------------------------------------------------------

// drawView() as the GUI calls it, for the lit view and, alternately, a factor view (its automatic
// range found as the GUI finds it: one extra draw at 256 px, read back) or the wipe (the lit
// model left of the middle, the factor view right of it): counters view_ms and lit_ms. The
// scene is comparison 1's with Cook-Torrance and Phong shading; the view is range(0)'s ViewMode,
// wiped when range(1) is 1.
void View(benchmark::State& state) {
    context();
    Preset preset = benchPreset(Shading::Phong, BrdfModel::CookTorrance);
    Renderer renderer;
    Diagnostics d;
    renderer.init(d);
    auto mesh = std::make_shared<const Mesh>(makeBuiltin(preset.model.builtin, preset.model.subdivisions));
    Framebuffer target(kWidth, kHeight);
    target.bind();
    const Viewport viewport{0, 0, kWidth, kHeight};
    ViewportDraw lit;
    ViewportDraw view;
    view.options.view = static_cast<ViewMode>(state.range(0));
    view.automatic = true;
    if (state.range(1) != 0) {
        view.wipe = true;
        view.options.fromX = 0.5f;
    }
    drawView(renderer, preset, mesh, viewport, lit); // warm up: the programs, the mesh's upload
    drawView(renderer, preset, mesh, viewport, view);
    glFinish();
    double viewMs = 0, litMs = 0;
    for (auto _ : state) {
        Clock::time_point t0 = Clock::now();
        drawView(renderer, preset, mesh, viewport, view);
        glFinish();
        viewMs += msSince(t0);
        Clock::time_point t1 = Clock::now();
        drawView(renderer, preset, mesh, viewport, lit);
        glFinish();
        litMs += msSince(t1);
    }
    state.counters["view_ms"] = viewMs / double(state.iterations());
    state.counters["lit_ms"] = litMs / double(state.iterations());
}

//----------------------------------------------------------------------------------------
// 2. A whole GUI frame against the model alone
//----------------------------------------------------------------------------------------

// The scene of comparison 2: comparison 1's, its first light orbiting, so that every frame draws
// the model again (an unchanged view is not drawn again: its copy is put on screen).
fs::path benchPresetFile(const TempFolder& dir) {
    fs::path file = dir.path() / "bench.json";
    Diagnostics d;
    Preset p = benchPreset(Shading::Phong, BrdfModel::Phong);
    p.lights[0].orbit.on = true;
    savePreset(p, file, d);
    return file;
}

// A whole App frame (panel, plots, model drawn again at full resolution) and, alternately, the
// model alone drawn at the size the view has in that frame (counters gui_ms and model_ms): the
// difference is what the UI costs on top of the model.
void GuiFrame(benchmark::State& state) {
    context();
    TempFolder dir;
    AppOptions options;
    options.frameBudgetSeconds = 0.0f; // always full resolution, as the model alone is drawn
    options.preset = benchPresetFile(dir);
    options.presetFolders = {fs::path(LAB_SOURCE_DIR) / "presets"};
    App app(options);
    HeadlessApp headless;
    std::string error;
    if (!headless.start(app, kWidth, kHeight, error)) {
        state.SkipWithError(error.c_str());
        return;
    }
    for (int i = 0; i < 5; ++i) {
        headless.frame(); // settle: fonts, first layout, mesh upload
    }
    ui::Rect view{0, 0, float(kWidth), float(kHeight)};
    std::string map = ui::widgets().text();
    std::size_t at = map.find("\nview ");
    if (at != std::string::npos) {
        std::sscanf(map.c_str() + at + 6, "%f %f %f %f", &view.x, &view.y, &view.w, &view.h);
    }
    Preset preset = benchPreset(Shading::Phong, BrdfModel::Phong);
    Renderer renderer;
    Diagnostics d;
    renderer.init(d);
    GpuMesh mesh(std::make_shared<const Mesh>(makeBuiltin(preset.model.builtin, preset.model.subdivisions)));
    Framebuffer modelTarget(kWidth, kHeight);
    double gui = 0, model = 0;
    for (auto _ : state) {
        Clock::time_point t0 = Clock::now();
        headless.frame();
        gui += msSince(t0);
        Clock::time_point t1 = Clock::now();
        modelTarget.bind();
        clearFramebuffer(glm::vec3(0.1f), kWidth, kHeight);
        renderer.draw(preset, mesh, {0, 0, int(view.w), int(view.h)});
        glFinish();
        model += msSince(t1);
    }
    state.counters["gui_ms"] = gui / double(state.iterations());
    state.counters["model_ms"] = model / double(state.iterations());
    state.SetLabel(std::to_string(int(view.w)) + "x" + std::to_string(int(view.h)) + " view");
}

//----------------------------------------------------------------------------------------
// 3. The plots: one frame of the plots panel on the CPU
//----------------------------------------------------------------------------------------

// 12. One fit of the README's table (core/plots/fit.h): 0 Blinn-Phong to Phong n = 20, 1 Blinn-Phong to
// Beckmann m = 0.3, 2 Cook-Torrance (Beckmann) to Phong n = 20.
void Fit(benchmark::State& state) {
    Preset target;
    target.brdf = state.range(0) == 1 ? BrdfModel::CookTorrance : BrdfModel::Phong;
    target.material.shininess = 20.0f;
    target.cookTorrance.roughness = 0.3f;
    const FitRequest request{state.range(0) == 2 ? BrdfModel::CookTorrance : BrdfModel::BlinnPhong, Distribution::Beckmann};
    for (auto _ : state) {
        std::string error;
        benchmark::DoNotOptimize(fitSpecular(target, request, error));
    }
}

void Plots(benchmark::State& state) {
    ImGuiContext* previous = ImGui::GetCurrentContext();
    ImGuiContext* cpu = ImGui::CreateContext();
    ImGui::SetCurrentContext(cpu);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(380, 720);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels;
    int fw, fh;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &fw, &fh); // the font atlas, on the CPU only
    Preset a = benchPreset(Shading::Phong, BrdfModel::CookTorrance);
    Preset b = a;
    b.brdf = BrdfModel::BlinnPhong;
    ui::PlotSettings settings;
    settings.view = static_cast<ui::PlotTab>(state.range(2));
    // range(1): 0 unchanged, 1 editing (a new shininess every frame), 2 the frame after a change
    // ends (timed: a new value drawn untimed, then the same value again: what was lagging or coarse
    // is computed exactly).
    const bool compare = state.range(0) != 0;
    const int editing = static_cast<int>(state.range(1));
    int frame = 0;
    auto draw = [&] {
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(io.DisplaySize);
        ImGui::Begin("plots");
        ui::plotsPanel(a, compare ? &b : nullptr, settings, nullptr);
        ImGui::End();
        ImGui::Render();
        benchmark::DoNotOptimize(ImGui::GetDrawData()->TotalVtxCount);
    };
    for (auto _ : state) {
        if (editing != 0) {
            a.material.shininess = 20.0f + 0.01f * static_cast<float>(frame++ % 1000); // never one the cache holds
        }
        if (editing == 2) {
            state.PauseTiming();
            draw();
            state.ResumeTiming();
        }
        draw();
    }
    ImGui::DestroyContext(cpu);
    ImGui::SetCurrentContext(previous);
}

//----------------------------------------------------------------------------------------
// 4. `lab render` as a process against a bare EGL program
//----------------------------------------------------------------------------------------

void run(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const std::string& a : argv) {
        args.push_back(const_cast<char*>(a.c_str()));
    }
    args.push_back(nullptr);
    pid_t pid;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    if (posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ) == 0) {
        int status;
        waitpid(pid, &status, 0);
    }
    posix_spawn_file_actions_destroy(&actions);
}

double median(std::vector<double> values) {
    if (values.empty()) {
        return -1.0;
    }
    auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// How many pairs of processes the comparison runs: enough that two runs of the benchmark agree
// on the ratio within 0.05 on this project's 2-core machine (README Performance).
constexpr int kProcessPairs = 61;

// `lab render` on the default preset and the bare program, alternately, each pair in the other
// order than the last (so that neither is always the one that runs right after the other):
// the median wall time of each (counters lab_ms and bare_ms). Medians, not means: a process the
// machine holds up now and then would move a mean by itself.
void Process(benchmark::State& state) {
    TempFolder dir;
    fs::path preset = dir.path() / "default.json";
    writeText(preset, R"({"format": "lighting-lab-preset", "version": 1})");
    const std::vector<std::string> lab{LAB_EXE, "render", preset.string(), "--out", (dir.path() / "lab.png").string()};
    const std::vector<std::string> bare{BARE_RENDER_EXE, (dir.path() / "bare.png").string()};
    auto timed = [](const std::vector<std::string>& argv) {
        Clock::time_point t0 = Clock::now();
        run(argv);
        return msSince(t0);
    };
    timed(lab); // warm up: the programs and their libraries in the page cache
    timed(bare);
    std::vector<double> labMs, bareMs;
    for (auto _ : state) {
        if (labMs.size() % 2 == 0) {
            labMs.push_back(timed(lab));
            bareMs.push_back(timed(bare));
        } else {
            bareMs.push_back(timed(bare));
            labMs.push_back(timed(lab));
        }
    }
    state.counters["lab_ms"] = median(labMs);
    state.counters["bare_ms"] = median(bareMs);
    state.SetLabel("medians of " + std::to_string(labMs.size()) + " runs each");
}

//----------------------------------------------------------------------------------------
// 5. A 1-million-triangle glTF against reading its bytes
//----------------------------------------------------------------------------------------

const fs::path& bigGlb() {
    static TempFolder dir;
    static fs::path file = [] {
        Mesh sphere = makeSphere(1001, 500); // 1001 * 500 * 2 - 2 * 1001 = 998,998 triangles
        tools::GlbMesh m{"big sphere", sphere.positions, sphere.normals, sphere.indices};
        // Top up to exactly 1,000,000 triangles by repeating the first ones.
        for (std::size_t t = 0; m.indices.size() < 3'000'000; t += 3) {
            m.indices.insert(m.indices.end(), {sphere.indices[t], sphere.indices[t + 1], sphere.indices[t + 2]});
        }
        fs::path f = dir.path() / "big.glb";
        std::string error;
        writeFileAtomic(f, tools::writeGlb(m, nlohmann::ordered_json::array({{{"mesh", 0}}}), "lab_bench"), error);
        return f;
    }();
    return file;
}

// Loading and, alternately, reading the bytes (counters load_ms and read_ms), so both meet the
// same state of the heap.
void Gltf(benchmark::State& state) {
    const fs::path& file = bigGlb();
    double load = 0, read = 0;
    for (auto _ : state) {
        Clock::time_point t0 = Clock::now();
        {
            Diagnostics d;
            std::optional<GltfResult> r = loadGltf(file, "big.glb", d);
            if (!r || r->mesh.triangleCount() != 1'000'000) {
                state.SkipWithError("the big model did not load");
                break;
            }
            benchmark::DoNotOptimize(r->mesh.indices.data());
        }
        load += msSince(t0);
        Clock::time_point t1 = Clock::now();
        {
            std::string error;
            std::optional<std::string> bytes = readFile(file, std::size_t{1} << 30, error);
            benchmark::DoNotOptimize(bytes->data());
        }
        read += msSince(t1);
    }
    state.counters["load_ms"] = load / double(state.iterations());
    state.counters["read_ms"] = read / double(state.iterations());
    state.SetLabel(std::to_string(fs::file_size(file) >> 20) + " MiB");
}

//----------------------------------------------------------------------------------------
// Registration and the comparison table
//----------------------------------------------------------------------------------------

void registerAll() {
    // First, while the process's heap is fresh, as it is when a model is dropped on the lab.
    benchmark::RegisterBenchmark("Gltf", Gltf)->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(3.0);
    const char* shadings[] = {"flat", "gouraud", "phong"};
    const char* brdfs[] = {"phong", "blinn-phong", "cook-torrance"};
    for (int s = 0; s < 3; ++s) {
        for (int b = 0; b < 3; ++b) {
            std::string name = std::string("Frame/") + shadings[s] + "/" + brdfs[b];
            benchmark::RegisterBenchmark(name.c_str(), Frame)->Args({s, b})->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
        }
    }
    // 1b: a factor view of each kind (a dot product, D, the Gouraud error: the views' costliest)
    // and the wipe.
    const std::pair<const char*, ViewMode> factorViews[] = {
        {"NdotL", ViewMode::NdotL}, {"D", ViewMode::D}, {"GouraudError", ViewMode::GouraudError}};
    for (const auto& [name, mode] : factorViews) {
        benchmark::RegisterBenchmark((std::string("View/") + name).c_str(), View)
            ->Args({static_cast<int>(mode), 0})->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
    }
    benchmark::RegisterBenchmark("View/wipe-D", View)
        ->Args({static_cast<int>(ViewMode::D), 1})->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
    benchmark::RegisterBenchmark("GuiFrame", GuiFrame)->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(4.0);
    const char* views[] = {"", "lobe3d-", "energy-", "slice-"}; // ui::PlotTab's order: Plane, 3D lobe, Energy, Slice
    for (int v = 0; v < 4; ++v) {
        for (int edit = 0; edit < 3; ++edit) {
            for (int compare = 0; compare < 2; ++compare) {
                static const char* const suffix[3] = {"", "-editing", "-release"};
                std::string name = std::string("Plots/") + views[v] + (compare ? "compare" : "single") + suffix[edit];
                benchmark::RegisterBenchmark(name.c_str(), Plots)->Args({compare, edit, v})->Unit(benchmark::kMicrosecond);
            }
        }
    }
    benchmark::RegisterBenchmark("Fit/blinn-phong-to-phong-20", Fit)->Args({0})->UseRealTime()->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("Fit/blinn-phong-to-beckmann-0.3", Fit)->Args({1})->UseRealTime()->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("Fit/cook-torrance-to-phong-20", Fit)->Args({2})->UseRealTime()->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("Process", Process)->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(kProcessPairs);
}

// Collects each run's real time per iteration (in milliseconds) for the table.
class Collector : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> ms;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            if (!r.error_occurred) {
                for (const auto& [counter, value] : r.counters) {
                    ms[r.benchmark_name() + "#" + counter] = value;
                }
                ms[r.benchmark_name()] = r.GetAdjustedRealTime() * benchmark::GetTimeUnitMultiplier(benchmark::kMillisecond) /
                                         benchmark::GetTimeUnitMultiplier(r.time_unit);
            }
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

void table(const std::map<std::string, double>& ms) {
    auto get = [&](const std::string& prefix) {
        for (const auto& [name, value] : ms) {
            if (name.rfind(prefix, 0) == 0) {
                return value;
            }
        }
        return -1.0;
    };
    std::printf("\n%-44s %12s %12s %8s %10s\n", "comparison", "lab", "baseline", "ratio", "target");
    auto row = [](const std::string& what, double lab, double base, double ratio, const char* target, bool met) {
        std::printf("%-44s %10.3f ms %9.3f ms %8.3f %10s %s\n", what.c_str(), lab, base, ratio, target, met ? "met" : "MISSED");
    };
    auto counter = [&](const std::string& prefix, const std::string& name) {
        for (const auto& [key, value] : ms) {
            if (key.rfind(prefix, 0) == 0 && key.size() > name.size() && key.compare(key.size() - name.size(), name.size(), name) == 0) {
                return value;
            }
        }
        return -1.0;
    };
    for (const char* s : {"flat", "gouraud", "phong"}) {
        for (const char* b : {"phong", "blinn-phong", "cook-torrance"}) {
            std::string name = std::string("Frame/") + s + "/" + b + "/";
            double lab = counter(name, "#lab_ms"), bare = counter(name, "#bare_ms");
            if (lab > 0 && bare > 0) {
                row("1. frame " + std::string(s) + ", " + b, lab, bare, lab / bare, "<= 1.10", lab / bare <= 1.10);
            }
        }
    }
    for (const char* v : {"NdotL", "D"}) {
        std::string name = std::string("View/") + v + "/";
        double view = counter(name, "#view_ms"), lit = counter(name, "#lit_ms");
        if (view > 0 && lit > 0) {
            row("1b. factor view " + std::string(v) + " (auto range) vs lit", view, lit, view / lit, "<= 1.10", view / lit <= 1.10);
        }
    }
    // Not a factor: the difference of two lightings (per vertex and per pixel) at each pixel, so two
    // lightings' work, as the wipe's two halves are.
    double gouraud = counter("View/GouraudError/", "#view_ms"), gouraudLit = counter("View/GouraudError/", "#lit_ms");
    if (gouraud > 0 && gouraudLit > 0) {
        row("1c. Gouraud error (two lightings) vs lit", gouraud, gouraudLit, gouraud / gouraudLit, "<= 2.00", gouraud / gouraudLit <= 2.0);
    }
    double wipe = counter("View/wipe-D/", "#view_ms"), wipeLit = counter("View/wipe-D/", "#lit_ms");
    if (wipe > 0 && wipeLit > 0) {
        // One extra draw: the lit half and the view's half, each a draw of the whole mesh.
        row("1b. wipe, lit | D (auto range) vs lit", wipe, wipeLit, wipe / wipeLit, "<= 2.00", wipe / wipeLit <= 2.0);
    }
    double gui = counter("GuiFrame", "#gui_ms"), model = counter("GuiFrame", "#model_ms");
    if (gui > 0 && model > 0) {
        double share = (gui - model) / gui;
        std::printf("%-44s %10.3f ms %9.3f ms %7.1f%% %10s %s\n", "2. UI share of a 1280x720 frame (model drawn)", gui, model, share * 100,
                    "<= 15%", share <= 0.15 ? "met" : "MISSED");
    }
    // Every view of the plots, unchanged (target 50 us) and while a value changes every frame (100 us);
    // the frame after a change ends computes what lagged (no target: one frame, once).
    for (const char* view : {"", "lobe3d-", "energy-", "slice-"}) {
        for (const char* set : {"single", "compare"}) {
            const std::string name = std::string("Plots/") + view + set + "-release/";
            if (const double plots = get(name); plots > 0) {
                std::printf("%-44s %10.1f us\n", ("3b. " + name).c_str(), plots * 1000);
            }
        }
    }
    for (const char* view : {"", "lobe3d-", "energy-", "slice-"}) {
        for (const char* edit : {"", "-editing"}) {
            for (const char* set : {"single", "compare"}) {
                const std::string name = std::string("Plots/") + view + set + edit + "/";
                const double plots = get(name), target = *edit ? 100.0 : 50.0;
                if (plots > 0) {
                    std::printf("%-44s %10.1f us %12s %8s %7s us %s\n", ("3. " + name).c_str(), plots * 1000, "", "",
                                std::to_string(int(target)).insert(0, "<= ").c_str(), plots * 1000 <= target ? "met" : "MISSED");
                }
            }
        }
    }
    // The README's fits (core/plots/fit.h), each once per iteration: target 0.2 s natively.
    for (const char* fit : {"blinn-phong-to-phong-20", "blinn-phong-to-beckmann-0.3", "cook-torrance-to-phong-20"}) {
        const std::string name = std::string("Fit/") + fit;
        if (const double fitMs = get(name); fitMs > 0) {
            std::printf("%-44s %10.1f ms %12s %8s %10s %s\n", ("12. " + name).c_str(), fitMs, "", "", "<= 200 ms",
                        fitMs <= 200.0 ? "met" : "MISSED");
        }
    }
    double labRender = counter("Process", "#lab_ms"), bareRender = counter("Process", "#bare_ms");
    if (labRender > 0 && bareRender > 0) {
        row("4. lab render vs bare EGL program (medians)", labRender, bareRender, labRender / bareRender, "<= 1.05",
            labRender / bareRender <= 1.05);
    }
    double load = counter("Gltf", "#load_ms"), read = counter("Gltf", "#read_ms");
    if (load > 0 && read > 0) {
        row("5. 1M-triangle .glb: load vs read", load, read, load / read, "<= 2", load / read <= 2.0);
    }
}

} // namespace
} // namespace lab

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    lab::registerAll();
    lab::Collector collector;
    benchmark::RunSpecifiedBenchmarks(&collector);
    lab::table(collector.ms);
    benchmark::Shutdown();
    return 0;
}
