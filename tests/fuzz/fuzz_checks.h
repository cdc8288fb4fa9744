// fuzz_checks.h — what "the lab behaved" means for each untrusted input path.
//
// Each check runs one input through the lab and returns "" when the outcome is acceptable —
// a result that satisfies the invariants below, or a refusal with at least one message — and a
// description of the failure otherwise. The libFuzzer targets (fuzz_*.cpp) abort on a failure;
// tests/fuzz_regression_test.cpp runs the same checks over the seeds and every crash found.
// (A crash, hang or sanitizer report is a failure by itself.)
#pragma once

#include "cli/command_line.h"
#include "cli/commands.h"
#include "core/scene/transforms.h"
#include "core/exercise/exercise.h"
#include "core/gltf/reader.h"
#include "core/io/file_io.h"
#include "core/io/image.h"
#include "core/io/safe_text.h"
#include "core/lighting/lighting.h"
#include "core/plots/fit.h"
#include "core/plots/plot_data.h"
#include "core/scene/field_edit.h"
#include "core/scene/field_table.h"
#include "core/scene/view_mode.h"
#include "core/scene/preset.h"
#include "core/share/share_link.h"
#include "platform/headless_gl.h"
#include "render/offscreen.h" // kMaxRenderSide

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace lab::fuzz {

inline std::string refusedWithoutMessage(const Diagnostics& d) {
    if (d.empty()) {
        return "refused without a diagnostic";
    }
    for (const Diagnostic& x : d) {
        if (x.message.empty()) {
            return "a diagnostic without a message";
        }
    }
    return "";
}

// Preset text: parse → validate → save → parse → save gives the same bytes, or a clean error.
inline std::string checkPreset(std::string_view text) {
    Diagnostics d;
    std::optional<Preset> first = parsePreset(text, "fuzz.json", std::nullopt, d);
    if (!first) {
        return refusedWithoutMessage(d);
    }
    std::string saved = presetToJson(*first);
    Diagnostics again;
    std::optional<Preset> second = parsePreset(saved, "saved.json", std::nullopt, again);
    if (!second) {
        return "a preset that loaded does not load after saving: " + toString(again);
    }
    if (!(*second == *first)) {
        return "load(save(x)) != x";
    }
    if (presetToJson(*second) != saved) {
        return "saving twice gives different bytes";
    }
    return "";
}

// An exercise's link opens the same exercise as the link carries it (linkedExercise), or the link
// is refused for its length.
inline std::string checkExerciseLinks(const Exercise& e) {
    const std::string link = exerciseLink(e, std::nullopt);
    if (link.size() > kMaxLinkChars) {
        return "";
    }
    Diagnostics d;
    std::optional<Linked> back = parseLink(link, ".", d);
    const Exercise* linked = back ? std::get_if<Exercise>(&*back) : nullptr;
    if (!linked) {
        return "an exercise's own link does not open: " + toString(d);
    }
    return *linked == linkedExercise(e) ? "" : "an exercise's link opens another exercise";
}

// Exercise text: parse → validate → save → parse → save gives the same bytes, and its link the same
// exercise; or a clean error.
inline std::string checkExercise(std::string_view text) {
    Diagnostics d;
    std::optional<Exercise> first = parseExercise(text, "fuzz.json", std::nullopt, d);
    if (!first) {
        return refusedWithoutMessage(d);
    }
    std::string saved = exerciseToJson(*first);
    Diagnostics again;
    std::optional<Exercise> second = parseExercise(saved, "saved.json", std::nullopt, again);
    if (!second) {
        return "an exercise that loaded does not load after saving: " + toString(again);
    }
    if (!(*second == *first)) {
        return "load(save(x)) != x";
    }
    if (exerciseToJson(*second) != saved) {
        return "saving twice gives different bytes";
    }
    return checkExerciseLinks(*first);
}

// A link fragment (the page's address or saved state): refused with a message, or what it opens
// links back to itself — a preset to the same preset, an exercise as checkExerciseLinks says, a name
// that is no path. (A message may quote the link's bytes: printable() escapes them on the way out.)
inline std::string checkLink(std::string_view fragment) {
    Diagnostics d;
    std::optional<Linked> linked = parseLink(fragment, ".", d);
    if (!linked) {
        return refusedWithoutMessage(d);
    }
    if (const Preset* p = std::get_if<Preset>(&*linked)) {
        const std::string again = presetLink(*p, std::nullopt);
        if (again.size() > kMaxLinkChars) {
            return "";
        }
        Diagnostics d2;
        std::optional<Linked> back = parseLink(again, ".", d2);
        const Preset* q = back ? std::get_if<Preset>(&*back) : nullptr;
        return q && *q == *p ? "" : "a preset's own link does not open the same preset: " + toString(d2);
    }
    if (const Exercise* e = std::get_if<Exercise>(&*linked)) {
        return checkExerciseLinks(*e);
    }
    const std::string* name = std::get_if<LinkedPresetName>(&*linked) ? &std::get<LinkedPresetName>(*linked).name
                                                                       : &std::get<LinkedExerciseName>(*linked).name;
    if (name->empty() || name->find_first_of("/\\") != std::string::npos || name->find("..") != std::string::npos) {
        return "a linked name that is a path: " + printable(*name);
    }
    return "";
}

// The headless GL context and renderer, made once per process; nullptr where there is no GL
// (the rendering checks are then skipped).
inline OffscreenRenderer* sharedRenderer() {
    static HeadlessGl gl;
    static OffscreenRenderer renderer;
    static int state = 0; // 0 not tried, 1 ready, -1 failed
    if (state == 0) {
        std::string error;
        Diagnostics d;
        state = gl.create(error) && renderer.init(d) ? 1 : -1;
    }
    return state == 1 ? &renderer : nullptr;
}

// A preset that validates keeps the lighting model finite (core/scene/limits.h): its colour at a few
// points and normals, and `lab plot`'s samples, are finite numbers; and it renders (at 8 x 8).
inline std::string checkPresetRenders(std::string_view text) {
    Diagnostics d;
    std::optional<Preset> preset = parsePreset(text, "fuzz.json", std::nullopt, d);
    if (!preset) {
        return "";
    }
    const Transforms t = computeTransforms(*preset, 1.0f);
    const ShadingInputs in = packShading(*preset, t.view);
    for (const glm::vec3& p : {glm::vec3(0.0f, 0.0f, -3.0f), glm::vec3(0.5f, -0.4f, -1.0f), glm::vec3(t.modelView[3])}) {
        for (const glm::vec3& n : {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(1, 1, 1)), glm::vec3(0, 1, 0)}) {
            glm::vec3 c = shade(in, p, n);
            if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
                return "a preset that validates shades to a non-finite colour";
            }
        }
    }
    for (float incident : {-90.0f, 0.0f, 45.0f, 90.0f}) {
        for (const PlotSample& s : reflectedIntensity(*preset, incident)) {
            if (!std::isfinite(s.total) || !std::isfinite(s.diffuse) || !std::isfinite(s.specular)) {
                return "a preset that validates has a non-finite plot sample";
            }
        }
    }
    OffscreenRenderer* renderer = sharedRenderer();
    if (!renderer) {
        return "";
    }
    std::optional<Image> image = renderer->render(LoadedPreset{*preset, {}}, 8, 8, d);
    if (!image) {
        return d.empty() ? "a valid preset did not render, without a diagnostic" : "";
    }
    return image->width == 8 && image->height == 8 ? "" : "a render of the wrong size";
}

// The page's field edit (what lab_page_field carries out: core/scene/field_edit.h), as "PATH\nTEXT"
// (no line feed: the whole input is the text for the shininess), on three scenes (the defaults; a
// Cook-Torrance spot light; a torus lit by a directional light). Taken: the preset still validates,
// as it would be saved and read back. Refused: a one-line message, terminal-safe, bounded whatever
// the input's size (values and paths quoted at 120 bytes), and the preset exactly as it was.
inline std::string checkFieldEdit(std::string_view input) {
    const std::size_t newline = input.find('\n');
    const std::string_view path = newline == std::string_view::npos ? "material.shininess" : input.substr(0, newline);
    const std::string_view text = newline == std::string_view::npos ? input : input.substr(newline + 1);
    Preset scenes[3];
    scenes[1].brdf = BrdfModel::CookTorrance;
    scenes[1].lights[0].type = LightType::Spot;
    scenes[2].model.builtin = Builtin::Torus;
    scenes[2].model.subdivisions = defaultSubdivisions(Builtin::Torus);
    scenes[2].lights.push_back(LightDesc{LightType::Directional});
    for (Preset& p : scenes) {
        const Preset before = p;
        const std::string problem = setFieldFromText(p, path, text);
        if (problem.empty()) {
            Diagnostics d;
            if (!parsePreset(presetToJson(p), "edited.json", std::nullopt, d)) {
                return "a field edit that was taken leaves a preset that does not validate: " + toString(d);
            }
            continue;
        }
        if (!(p == before)) {
            return "a refused field edit changed the preset: " + problem;
        }
        if (printable(problem, true) != problem) {
            return "a refusal that is not one terminal-safe line: " + printable(problem, true);
        }
        if (problem.size() > 600) {
            return "a refusal of " + std::to_string(problem.size()) + " bytes (values and paths are quoted at 120)";
        }
    }
    return "";
}

// `lab fit` of a preset that validates (core/plots/fit.h), to the model the input's size picks (one
// a run: a fit takes tens of milliseconds). A refusal says why in one line; a fit has an error in
// [0, 1] that the written preset reproduces, finite parameters, a preset that validates, and only
// `check` views its model has.
inline std::string checkFit(std::string_view text) {
    Diagnostics d;
    std::optional<Preset> target = parsePreset(text, "fuzz.json", std::nullopt, d);
    if (!target) {
        return "";
    }
    const FitRequest requests[] = {{BrdfModel::Phong}, {BrdfModel::BlinnPhong}, {BrdfModel::CookTorrance, Distribution::Ggx}};
    const FitRequest& request = requests[text.size() % 3];
    std::string error;
    std::optional<FitResult> fit = fitSpecular(*target, request, error);
    if (!fit) {
        return error.empty() || printable(error, true) != error ? "a fit refused without a one-line reason" : "";
    }
    if (!std::isfinite(fit->error) || fit->error < 0.0 || fit->error > 1.0 + 1e-6) {
        return "a fit's error outside [0, 1]: " + std::to_string(fit->error);
    }
    for (const FitParameter& p : fit->parameters) {
        if (!std::isfinite(p.value)) {
            return "a fitted parameter that is not finite: " + p.name;
        }
    }
    if (std::abs(fitError(*target, fit->fitted) - fit->error) > 1e-4) {
        return "the fitted preset's error is not the fit's";
    }
    Diagnostics again;
    if (!parsePreset(presetToJson(fit->fitted), "fit.json", std::nullopt, again)) {
        return "a fitted preset that does not validate: " + toString(again);
    }
    for (const CheckView& v : fit->fitted.check.views) {
        std::optional<ViewMode> mode = viewFromName(v.view);
        if (!mode || !notApplicable(*mode, fit->fitted, v.light - 1).empty()) {
            return "the fit keeps a check view its model does not have: " + v.view;
        }
    }
    return "";
}

// A .gltf or .glb (decided by its first bytes), as a real file in `folder`.
inline std::string checkGltf(std::string_view bytes, const std::filesystem::path& folder) {
    std::filesystem::path file = folder / "model.gltf";
    std::string error;
    if (!writeFileAtomic(file, bytes, error)) {
        return ""; // the scratch folder is not the subject
    }
    GltfLimits limits;
    limits.maxFileBytes = 16u << 20;
    limits.maxTriangles = 2'000'000;
    limits.maxVertices = 2'000'000;
    Diagnostics d;
    std::optional<GltfResult> r = loadGltf(file, "fuzz.gltf", d, limits);
    if (!r) {
        return refusedWithoutMessage(d);
    }
    const Mesh& m = r->mesh;
    if (m.indices.empty() || m.indices.size() % 3 != 0) {
        return "a loaded mesh without whole triangles";
    }
    if (m.normals.size() != m.positions.size()) {
        return "normals and positions differ in count";
    }
    if (m.triangleCount() > limits.maxTriangles || m.positions.size() > limits.maxVertices) {
        return "a loaded mesh beyond the limits";
    }
    for (std::uint32_t i : m.indices) {
        if (i >= m.positions.size()) {
            return "an index beyond the vertices survived loading";
        }
    }
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            if (!std::isfinite(m.positions[i][k]) || !std::isfinite(m.normals[i][k])) {
                return "a non-finite vertex survived loading";
            }
        }
    }
    return "";
}

// Where the command-line check runs commands: a scratch folder with a valid preset (a.json), a
// broken one (b.json), an exercise (e.json), a golden for a.json (golden/a.png, black: a comparison that fails) and a
// file where a folder is wanted. writeCommandFixtures() puts them back before each command, so a
// command that overwrote one (`--out a.json`) does not change what the next input meets.
inline const std::filesystem::path& commandScratch() {
    // Removed when the process ends.
    struct Scratch {
        std::filesystem::path path;
        ~Scratch() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const Scratch scratch{std::filesystem::temp_directory_path() / ("lab-fuzz-cli-" + std::to_string(::getpid()))};
    return scratch.path;
}

inline void writeCommandFixtures() {
    const std::filesystem::path& f = commandScratch();
    std::error_code ec;
    std::filesystem::remove_all(f, ec);
    std::filesystem::create_directories(f / "golden", ec);
    std::string error;
    writeFileAtomic(f / "a.json", R"({"format": "lighting-lab-preset", "version": 1, "name": "a"})", error);
    writeFileAtomic(f / "b.json", "{\"format\": \"lighting-lab-preset\", \"version\": 1, \"\x1b[2J\": 1}", error);
    writeFileAtomic(f / "file", "not a folder", error);
    writeFileAtomic(f / "e.json", R"({"format": "lighting-lab-exercise", "version": 1, "title": "e", "instructions": "",
                                      "start": {}, "target": {"material": {"shininess": 80}},
                                      "open": ["material.shininess"]})",
                    error);
    Image black{16, 16, std::vector<std::uint8_t>(16 * 16 * 3, 0)};
    writePng(black, f / "golden" / "a.png", error);
}

// Standard output and error into a temporary file (outside the scratch folder, which commands
// write to) for as long as it lives; restored whatever happens.
class CapturedOutput {
public:
    CapturedOutput() : file_(std::tmpfile()) {
        std::fflush(stdout);
        std::fflush(stderr);
        if (file_) {
            savedOut_ = ::dup(1);
            savedErr_ = ::dup(2);
            ::dup2(::fileno(file_), 1);
            ::dup2(::fileno(file_), 2);
        }
    }
    ~CapturedOutput() {
        std::fflush(stdout);
        std::fflush(stderr);
        for (auto [saved, fd] : {std::pair{savedOut_, 1}, std::pair{savedErr_, 2}}) {
            if (saved >= 0) {
                ::dup2(saved, fd);
                ::close(saved);
            }
        }
        if (file_) {
            std::fclose(file_);
        }
    }
    CapturedOutput(const CapturedOutput&) = delete;
    CapturedOutput& operator=(const CapturedOutput&) = delete;
    bool ok() const { return file_ != nullptr; }
    std::string text() {
        std::fflush(stdout);
        std::fflush(stderr);
        std::string out;
        std::rewind(file_);
        char buf[4096];
        for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, file_)) > 0;) {
            out.append(buf, n);
        }
        return out;
    }

private:
    std::FILE* file_;
    int savedOut_ = -1, savedErr_ = -1;
};

// A path the fuzzed command may use: relative, inside the scratch folder (no "..", no root).
inline std::optional<std::filesystem::path> inScratch(const std::filesystem::path& p) {
    if (p.empty() || p.is_absolute() || p.has_root_name()) {
        return std::nullopt;
    }
    for (const auto& part : p) {
        if (part == "..") {
            return std::nullopt;
        }
    }
    return commandScratch() / p;
}

// Runs a parsed render, plot or check with its paths moved into the scratch folder and its
// sizes at most 16 x 16, its output captured: the exit status is 0, 1 or 2, and what it printed
// is terminal-safe (printable() of it is itself). Commands that name a path outside are not run.
inline std::string runParsedCommand(CommandLine line) {
    std::vector<std::filesystem::path*> paths{&line.out,      &line.check.golden, &line.check.report,
                                              &line.exercise, &line.attempt,      &line.shared};
    for (std::filesystem::path& p : line.presets) {
        paths.push_back(&p);
    }
    for (std::optional<std::filesystem::path>* p : {&line.check.junit, &line.check.html, &line.diffOut, &line.qrOut}) {
        if (*p) {
            paths.push_back(&**p);
        }
    }
    for (std::filesystem::path* p : paths) {
        if (p->empty()) {
            continue; // not used by this command (an empty --out is refused by the parser)
        }
        std::optional<std::filesystem::path> moved = inScratch(*p);
        if (!moved) {
            return "";
        }
        *p = *moved;
    }
    for (Size* s : {&line.size, &line.check.size, &line.check.sweepSize}) {
        s->width = std::min(s->width, 16);
        s->height = std::min(s->height, 16);
    }
    writeCommandFixtures();
    int status = kExitOk;
    std::string text;
    {
        CapturedOutput output;
        if (!output.ok()) {
            return "";
        }
        switch (line.command) {
        case CommandLine::Command::Render: status = runRender(line.presets, line.out, line.size); break;
        case CommandLine::Command::Plot: status = runPlot(line.presets.front(), line.out, line.incidentDeg); break;
        case CommandLine::Command::Check: status = runCheck(line.presets, line.check); break;
        case CommandLine::Command::ExerciseCheck: status = runExerciseCheck(line.exercise, line.attempt, line.diffOut); break;
        case CommandLine::Command::Share: status = runShare(line.shared, line.base, line.qrOut, {}); break;
        case CommandLine::Command::Fit: status = runFit(line.presets.front(), line.fit, line.out); break;
        case CommandLine::Command::Lab: break;
        }
        text = output.text();
    }
    if (status != kExitOk && status != kExitFailure && status != kExitBadInput) {
        return "an exit status other than 0, 1 or 2";
    }
    if (printable(text) != text) {
        return "output that is not terminal-safe: " + printable(text);
    }
    return "";
}

// Command-line arguments, one per line (at most 64): parsed, and render, plot and check run on
// the scratch folder's files (runParsedCommand).
inline std::string checkCommandLine(std::string_view text) {
    std::vector<std::string> args{"lab"};
    std::size_t start = 0;
    while (start <= text.size() && args.size() < 65) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) {
            end = text.size();
        }
        args.emplace_back(text.substr(start, end - start));
        start = end + 1;
    }
    std::vector<const char*> argv;
    for (const std::string& a : args) {
        argv.push_back(a.c_str());
    }
    std::variant<CommandLine, int> parsed = parseCommandLine(static_cast<int>(argv.size()), argv.data());
    if (const int* status = std::get_if<int>(&parsed)) {
        return *status == kExitOk || *status == kExitBadInput ? "" : "an exit status other than 0 or 2";
    }
    const CommandLine& line = std::get<CommandLine>(parsed);
    using C = CommandLine::Command;
    if ((line.command == C::Render || line.command == C::Plot || line.command == C::Check) && line.presets.empty()) {
        return "a command without its preset";
    }
    if ((line.command == C::ExerciseCheck && (line.exercise.empty() || line.attempt.empty())) ||
        (line.command == C::Share && (line.shared.empty() || line.base.empty()))) {
        return "a command without its files";
    }
    for (const Size& s : {line.size, line.check.size}) {
        if (s.width < 1 || s.height < 1 || s.width > kMaxRenderSide || s.height > kMaxRenderSide) {
            return "a size outside the limits was accepted";
        }
    }
    if (line.incidentDeg && !(*line.incidentDeg >= -90.0f && *line.incidentDeg <= 90.0f)) {
        return "an incident angle outside [-90, 90] was accepted";
    }
    return line.command == CommandLine::Command::Lab ? "" : runParsedCommand(line);
}

} // namespace lab::fuzz
