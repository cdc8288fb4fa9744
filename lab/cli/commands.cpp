// commands.cpp — render, plot and the preview fallback (check: check.cpp), and command_kit.h.
#include "cli/commands.h"

#include "cli/command_kit.h"
#include "cli/output.h"
#include "core/exercise/exercise.h"
#include "core/exercise/preset_fields.h"
#include "core/gltf/model_loader.h"
#include "core/io/file_io.h"
#include "core/io/safe_text.h"
#include "core/io/number_format.h"
#include "core/plots/compare_image.h"
#include "core/plots/energy.h"
#include "core/plots/legend.h"
#include "core/plots/plot_data.h"
#include "core/plots/sweep_grid.h"
#include "core/scene/limits.h"
#include "core/scene/preset.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace lab {

namespace fs = std::filesystem;

namespace {

void printNotes(const fs::path& preset, const std::vector<std::string>& notes) {
    for (const std::string& n : notes) {
        print(stderr, preset.string() + ": note: " + n + "\n");
    }
}

} // namespace

void printDiagnostics(const Diagnostics& diagnostics) {
    print(stderr, toString(diagnostics));
}

std::vector<std::optional<LoadedPreset>> loadAll(const std::vector<fs::path>& files, bool* anyBad) {
    std::vector<std::optional<LoadedPreset>> loaded;
    for (const fs::path& f : files) {
        Diagnostics diagnostics;
        loaded.push_back(loadPreset(f, diagnostics));
        if (!loaded.back()) {
            printDiagnostics(diagnostics);
            if (anyBad) {
                *anyBad = true;
            }
        }
    }
    return loaded;
}

void addPresetInputs(RunFiles& files, const LoadedPreset& preset, const std::string& what) {
    files.input(preset.file, what + " " + preset.file.string());
    addModelInput(files, preset.preset, preset.folder(), preset.file);
}

void addModelInput(RunFiles& files, const Preset& scene, const fs::path& folder, const fs::path& owner) {
    if (!scene.model.gltf.empty()) {
        fs::path model = folder / scene.model.gltf;
        files.input(model, "the model " + model.string() + " of " + owner.string());
    }
}

bool filesUsable(const RunFiles& files, const char* command) {
    std::string problem = files.problem();
    if (!problem.empty()) {
        print(stderr, std::string(command) + ": " + problem + " (nothing was written)\n");
    }
    return problem.empty();
}

bool frameForCells(LoadedPreset& preset, Diagnostics& diagnostics) {
    if (preset.omitted == OmittedKeys{}) {
        return true;
    }
    std::optional<Mesh> mesh = loadModel(preset.preset.model, preset.folder(), diagnostics);
    if (!mesh) {
        return false;
    }
    frameOmitted(preset, *mesh);
    return true;
}

bool Gpu::start() {
    std::string error;
    if (!gl.create(error)) {
        print(stderr, "lab: " + error + "\n");
        return false;
    }
    Diagnostics diagnostics;
    if (!renderer.init(diagnostics)) {
        print(stderr, "lab: the built-in shaders do not compile on %s:\n", gl.renderer().c_str());
        printDiagnostics(diagnostics);
        return false;
    }
    return true;
}

std::optional<Image> renderSweepGrid(Gpu& gpu, const LoadedPreset& base, const std::vector<SweepAxis>& axes, Size cell,
                                     std::string& error, bool& renderFailed, const ViewportDraw& view) {
    renderFailed = false;
    auto renderCell = [&](const LoadedPreset& one, int width, int height, std::string& why) -> std::optional<Image> {
        Diagnostics problems;
        std::vector<std::string> notes;
        std::optional<Rendered> r = gpu.renderer.renderView(one, width, height, view, problems, &notes);
        if (!r) {
            renderFailed = true;
            why = problems.empty() ? "render failed" : problems.front().str();
            return std::nullopt;
        }
        return std::move(r->image);
    };
    return renderSweep(base, axes, cell.width, cell.height, renderCell, error);
}

std::optional<Size> parseSize(const std::string& text, std::string& error) {
    Size s;
    std::size_t x = text.find_first_of("xX");
    auto number = [](std::string_view t, int& v) {
        auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        return ec == std::errc{} && p == t.data() + t.size();
    };
    if (x == std::string::npos || !number(std::string_view(text).substr(0, x), s.width) ||
        !number(std::string_view(text).substr(x + 1), s.height)) {
        error = "--size: expected WIDTHxHEIGHT such as 512x512, got " + inQuotes(text);
        return std::nullopt;
    }
    if (s.width < 1 || s.height < 1 || s.width > kMaxRenderSide || s.height > kMaxRenderSide) {
        error = "--size: each side must be from 1 to " + std::to_string(kMaxRenderSide) + ", got " + inQuotes(text);
        return std::nullopt;
    }
    return s;
}

//----------------------------------------------------------------------------------------
// lab render
//----------------------------------------------------------------------------------------

namespace {

// The command line's view as the GUI's view settings would draw it (render/renderer.h viewDraw).
ViewportDraw viewDrawOf(const RenderView& v) {
    DisplaySettings settings;
    settings.mode = v.mode;
    settings.light = v.light;
    settings.palette = v.palette;
    settings.range = v.range;
    return viewDraw(settings);
}

// False, with the message, when `view` cannot show `preset` ("d is a Cook-Torrance factor; ...").
bool viewApplies(const RenderView& view, const LoadedPreset& preset, const std::string& where) {
    std::string why = notApplicable(view.mode, preset.preset, view.light);
    if (!why.empty()) {
        print(stderr, "lab render: %s: --view %s: %s\n", where.c_str(), viewName(view.mode), why.c_str());
    }
    return why.empty();
}

// The render as it is written: with the legend band when asked, and the automatic range said.
Image finished(Rendered rendered, const RenderView& view, const fs::path& target) {
    if (rendered.range && !view.range) {
        print(stdout, "%s: %s: automatic range %s,%s\n", target.string().c_str(), legendTitle(view.mode, view.light).c_str(),
              shortestFloat(rendered.range->lo).c_str(), shortestFloat(rendered.range->hi).c_str());
    }
    if (view.legend && rendered.range) {
        return withLegend(rendered.image, {legendTitle(view.mode, view.light), *rendered.range, view.palette});
    }
    return std::move(rendered.image);
}

// One render of `preset` as `lab render` writes it: a prepared comparison (preset.h `compare`) as
// compare mode shows it (core/plots/compare_image.h), each half width/2 wide under its label.
std::optional<Image> picture(Gpu& gpu, const LoadedPreset& preset, Size size, const RenderView& view, const fs::path& target) {
    Diagnostics diagnostics;
    std::vector<std::string> notes;
    std::optional<LoadedPreset> b;
    int width = size.width, height = size.height;
    if (!preset.preset.compare.empty()) {
        std::optional<Preset> compared = comparedPreset(preset.preset, preset.folder(), diagnostics);
        if (!compared) {
            printDiagnostics(diagnostics);
            return std::nullopt;
        }
        b = LoadedPreset{*compared, preset.file, preset.omitted};
        width = std::max(1, (size.width - 2) / 2);
        height = std::max(1, size.height - compareLabelHeight(size.height));
    }
    std::optional<Rendered> rendered = gpu.renderer.renderView(preset, width, height, viewDrawOf(view), diagnostics, &notes);
    std::optional<Rendered> second = b && rendered ? gpu.renderer.renderView(*b, width, height, viewDrawOf(view), diagnostics, &notes)
                                                   : std::nullopt;
    printNotes(preset.file, notes);
    if (!rendered || (b && !second)) {
        printDiagnostics(diagnostics);
        return std::nullopt;
    }
    Image image = finished(std::move(*rendered), view, target);
    if (b) {
        const DifferenceLabels labels = differenceLabels(preset.preset, b->preset);
        image = composeComparison(image, finished(std::move(*second), view, target),
                                  labels.a.empty() ? "A" : "A: " + labels.a, labels.b.empty() ? "B" : "B: " + labels.b);
    }
    return image;
}

} // namespace

int runRender(const std::vector<fs::path>& presets, const fs::path& out, Size size, const RenderView& view) {
    bool anyBad = false;
    auto loaded = loadAll(presets, &anyBad);
    const bool toFolder = presets.size() > 1;
    std::error_code ec;
    if (toFolder && fs::exists(out, ec) && !fs::is_directory(out, ec)) {
        print(stderr, "lab render: --out %s: with several presets --out must be a folder (it is a file)\n",
              out.string().c_str());
        return kExitBadInput;
    }
    // Every PNG's path, checked against the presets and their models before any is written; two
    // presets with one file name would write one PNG (a preset named twice is rendered twice).
    RunFiles files;
    std::map<std::string, fs::path> names;
    for (std::size_t i = 0; i < presets.size(); ++i) {
        const fs::path& p = presets[i];
        if (loaded[i]) {
            addPresetInputs(files, *loaded[i]);
        } else {
            files.input(p, "the preset " + p.string());
        }
        auto [it, fresh] = names.emplace(p.stem().string(), p);
        if (fresh) {
            files.output(toFolder ? out / (p.stem().string() + ".png") : out, "--out", toFolder);
        } else if (!sameFile(it->second, p)) {
            print(stderr, "lab render: %s and %s would both write %s.png\n", it->second.string().c_str(), p.string().c_str(),
                  p.stem().string().c_str());
            return kExitBadInput;
        }
    }
    if (!filesUsable(files, "lab render")) {
        return kExitBadInput;
    }
    if (std::none_of(loaded.begin(), loaded.end(), [](const auto& p) { return p.has_value(); })) {
        return kExitBadInput;
    }
    if (toFolder) {
        std::error_code made;
        fs::create_directories(out, made);
        if (!fs::is_directory(out, ec)) {
            print(stderr, "lab render: --out %s: cannot make the folder: %s\n", out.string().c_str(), made.message().c_str());
            return kExitBadInput;
        }
    }
    Gpu gpu;
    if (!gpu.start()) {
        return kExitFailure;
    }
    for (const auto& preset : loaded) {
        if (!preset) {
            continue;
        }
        if (!viewApplies(view, *preset, preset->file.string())) {
            anyBad = true;
            continue;
        }
        fs::path target = toFolder ? out / (preset->file.stem().string() + ".png") : out;
        std::optional<Image> image = picture(gpu, *preset, size, view, target);
        if (!image) {
            anyBad = true;
            continue;
        }
        std::string error;
        // Renewable: renamed into place without an fsync (about 10 ms a run here, sometimes 50,
        // while the file system commits its journal); a render is made again by running it again.
        if (!writePng(*image, target, error, WriteSafety::Renewable)) {
            print(stderr, "lab render: " + error + "\n");
            anyBad = true;
            continue;
        }
        print(stdout, target.string() + "\n");
    }
    return anyBad ? kExitBadInput : kExitOk;
}

namespace {

// How a sweep's cells are drawn: a value view with one range for all (the fixed one, or the union of
// the cells' automatic ranges, printed). Nullopt, with the message, when the view does not apply to
// a cell.
std::optional<ViewportDraw> sweepViewDraw(Gpu& gpu, const LoadedPreset& base, const std::vector<SweepAxis>& sweeps,
                                      Size size, const RenderView& view, const fs::path& out) {
    ViewportDraw draw = viewDrawOf(view);
    if (!showsValue(view.mode)) {
        return draw;
    }
    std::string error;
    std::optional<SweepCells> cells = sweepCells(base, sweeps, error); // checked by the caller already
    std::optional<ValueRange> all;
    for (const LoadedPreset& cell : cells ? cells->presets : std::vector<LoadedPreset>{}) {
        if (!viewApplies(view, cell, base.file.string() + " (cell " + cell.preset.name + ")")) {
            return std::nullopt;
        }
        Diagnostics ignored; // a model that does not load is reported when the cell is rendered
        std::optional<ValueRange> r = draw.automatic ? gpu.renderer.autoRange(cell, size.width, size.height, draw, ignored)
                                                     : std::nullopt;
        if (r) {
            all = all ? ValueRange{std::min(all->lo, r->lo), std::max(all->hi, r->hi)} : *r;
        }
    }
    if (draw.automatic) {
        draw.options.range = all.value_or(ValueRange{});
        draw.automatic = false;
        print(stdout, "%s: %s: automatic range %s,%s (all cells)\n", out.string().c_str(),
              legendTitle(view.mode, view.light).c_str(), shortestFloat(draw.options.range.lo).c_str(),
              shortestFloat(draw.options.range.hi).c_str());
    }
    return draw;
}

} // namespace

int runSweep(const std::vector<fs::path>& presets, const std::vector<SweepAxis>& sweeps, const fs::path& out, Size size,
             const RenderView& view) {
    if (presets.size() != 1) {
        // `--sweep a=1 b=2` gives b=2 to the presets: say what it looks like.
        std::string hint;
        for (const fs::path& p : presets) {
            std::error_code ec;
            if (hint.empty() && p.string().find('=') != std::string::npos && !fs::exists(p, ec)) {
                hint = " (" + inQuotes(p.string(), 80) + " looks like KEY=V1,V2,...: give each its own --sweep)";
            }
        }
        print(stderr, "lab render: --sweep renders one preset, got %zu%s\n", presets.size(), hint.c_str());
        return kExitBadInput;
    }
    Diagnostics diagnostics;
    std::optional<LoadedPreset> preset = loadPreset(presets.front(), diagnostics);
    if (!preset) {
        printDiagnostics(diagnostics);
        return kExitBadInput;
    }
    // A glTF model without a camera (or lights) in the file is framed first, as `lab render` frames
    // it: a swept camera or light key then changes the framed one.
    if (!frameForCells(*preset, diagnostics)) {
        printDiagnostics(diagnostics);
        return kExitBadInput;
    }
    RunFiles files;
    addPresetInputs(files, *preset);
    files.output(out, "--out");
    if (!filesUsable(files, "lab render")) {
        return kExitBadInput;
    }
    std::string error;
    if (!sweepCells(*preset, sweeps, error)) { // before starting the GPU: a bad value is a usage error
        print(stderr, "lab render: --sweep " + error + "\n");
        return kExitBadInput;
    }
    Gpu gpu;
    if (!gpu.start()) {
        return kExitFailure;
    }
    std::optional<ViewportDraw> draw = sweepViewDraw(gpu, *preset, sweeps, size, view, out);
    if (!draw) {
        return kExitBadInput;
    }
    bool renderFailed = false;
    std::optional<Image> grid = renderSweepGrid(gpu, *preset, sweeps, size, error, renderFailed, *draw);
    if (!grid) {
        print(stderr, "lab render: " + std::string(renderFailed ? "" : "--sweep ") + error + "\n");
        return renderFailed ? kExitFailure : kExitBadInput;
    }
    if (view.legend && showsValue(view.mode)) {
        grid = withLegend(*grid, {legendTitle(view.mode, view.light), draw->options.range, view.palette});
    }
    // Renewable, as a single render: made again by running the command again.
    if (!writePng(*grid, out, error, WriteSafety::Renewable)) {
        print(stderr, "lab render: " + error + "\n");
        return kExitBadInput;
    }
    print(stdout, out.string() + "\n");
    return kExitOk;
}

//----------------------------------------------------------------------------------------
// lab plot
//----------------------------------------------------------------------------------------

int runPlot(const fs::path& presetFile, const fs::path& out, std::optional<float> incidentDeg,
            const std::optional<fs::path>& albedoOut, const FigureOutputs& figure) {
    Diagnostics diagnostics;
    std::optional<LoadedPreset> preset = loadPreset(presetFile, diagnostics);
    if (!preset) {
        printDiagnostics(diagnostics);
        return kExitBadInput;
    }
    // Every file at most once (two outputs on one path would leave only the last), none the preset.
    RunFiles files;
    addPresetInputs(files, *preset);
    std::optional<LoadedPreset> compare;
    if (figure.compare) {
        if (!(compare = loadPreset(*figure.compare, diagnostics))) {
            printDiagnostics(diagnostics);
            return kExitBadInput;
        }
        addPresetInputs(files, *compare, "the --compare preset");
    }
    for (auto [flag, file] : {std::pair{"--out", std::optional<fs::path>(out.empty() ? std::nullopt : std::optional(out))},
                              std::pair{"--albedo", albedoOut}, std::pair{"--svg", figure.files.svg},
                              std::pair{"--png", figure.files.png}, std::pair{"--csv", figure.files.csv}}) {
        if (file) {
            files.output(*file, flag);
        }
    }
    if (!filesUsable(files, "lab plot")) {
        return kExitBadInput;
    }
    float angle = incidentDeg.value_or(preset->preset.plotIncidentDeg);
    if (!limits::contains(limits::kPlotIncidentDeg, angle)) {
        print(stderr, "lab plot: --incident-deg must be %s, got %g\n", limits::kPlotIncidentDeg.text, double(angle));
        return kExitBadInput;
    }
    std::string error;
    if (!out.empty()) {
        if (!writeFileAtomic(out, plotCsv(reflectedIntensity(preset->preset, angle)), error)) {
            print(stderr, "lab plot: " + error + "\n");
            return kExitBadInput;
        }
        print(stdout, out.string() + "\n");
    }
    if (albedoOut) {
        if (!writeFileAtomic(*albedoOut, albedoCsv(albedoCurve(lobeInputs(preset->preset, angle))), error)) {
            print(stderr, "lab plot: " + error + "\n");
            return kExitBadInput;
        }
        print(stdout, albedoOut->string() + "\n");
    }
    if (figure.any()) {
        FigureRequest request = figure.request;
        request.incidentDeg = angle;
        std::optional<FigureResult> result = makeFigure(preset->preset, compare ? &compare->preset : nullptr, request, error);
        if (!result) {
            print(stderr, "lab plot: --figure %s: %s\n", std::string(toString(request.kind)).c_str(), error.c_str());
            return kExitBadInput;
        }
        if (!writeFigure(*result, figure.files, error)) {
            print(stderr, "lab plot: " + error + "\n");
            return kExitBadInput;
        }
        for (const auto& file : {figure.files.svg, figure.files.png, figure.files.csv}) {
            if (file) {
                print(stdout, file->string() + "\n");
            }
        }
    }
    return kExitOk;
}

//----------------------------------------------------------------------------------------
// lab (no GUI available)
//----------------------------------------------------------------------------------------

int runPreview(const std::optional<fs::path>& presetFile) {
    LoadedPreset preset{Preset{}, {}};
    preset.preset.name = "Default";
    RunFiles files;
    std::string what = inQuotes(preset.preset.name); // what the preview shows
    if (presetFile) {
        // An exercise opens at its start, as in the lab's window.
        Diagnostics diagnostics;
        std::string error;
        std::optional<std::string> text = readFile(*presetFile, kMaxExerciseBytes, error);
        std::optional<LoadedExercise> exercise;
        std::optional<LoadedPreset> loaded;
        if (text && isExerciseText(*text) && (exercise = loadExercise(*presetFile, diagnostics))) {
            loaded = LoadedPreset{exercise->exercise.start, exercise->file};
        } else if (!exercise && diagnostics.empty()) {
            loaded = loadPreset(*presetFile, diagnostics);
        }
        if (!loaded) {
            printDiagnostics(diagnostics);
            return kExitBadInput;
        }
        preset = std::move(*loaded);
        addPresetInputs(files, preset, exercise ? "the exercise" : "the preset");
        what = exercise ? "the start of the exercise " + inQuotes(exercise->exercise.title) : inQuotes(preset.preset.name);
    }
    std::error_code ec;
    fs::path folder = fs::temp_directory_path(ec) / "lighting-lab";
    fs::path out = folder / ((presetFile ? presetFile->stem().string() : std::string("default")) + ".png");
    files.output(out, "the preview", true);
    if (!filesUsable(files, "lab")) {
        return kExitBadInput;
    }
    fs::create_directories(folder, ec);
    Gpu gpu;
    if (!gpu.start()) {
        return kExitFailure;
    }
    Diagnostics diagnostics;
    std::optional<Image> image = gpu.renderer.render(preset, 512, 512, diagnostics);
    if (!image) {
        printDiagnostics(diagnostics);
        return kExitBadInput;
    }
    std::string error;
    if (!writePng(*image, out, error, WriteSafety::Renewable)) { // a preview, made again on the next run
        print(stderr, "lab: the preview was not written: " + error + "\n");
        return kExitBadInput;
    }
    print(stdout, "No window available: rendered " + what + " to " + out.string() + "\n");
    return kExitOk;
}

} // namespace lab
