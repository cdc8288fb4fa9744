// check.cpp — `lab check`: each preset's render, sweep cells and plot against their goldens,
// and the report (report.txt, index.html, JUnit XML: check_report.h).
//
// Golden names, in the golden folder: <name>.png (the render), <name>.sweep.png (the grid of the
// preset's `sweep`), <name>.plot.csv (the lobe CSV of `lab plot --out`); <name>.<view>.png is
// kept free for other views (tests/check_goldens.cmake knows all of them).
#include "cli/commands.h"

#include "cli/check_plan.h"
#include "cli/check_report.h"
#include "cli/command_kit.h"
#include "cli/csv_compare.h"
#include "cli/output.h"
#include "core/io/file_io.h"
#include "core/io/safe_text.h"
#include "core/plots/plot_data.h"
#include "core/plots/sweep_grid.h"
#include "core/scene/preset.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace lab {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxGoldenCsvBytes = 16u << 20;

std::string shortNumber(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The tolerances for one preset: the command line's, with each one its `check` block gives
// replaced, and how the report names them.
struct Tolerances {
    Tolerance image;
    double plot = 0.0;
    std::string imageText, plotText;
};

Tolerances tolerancesFor(const Preset& preset, const CheckOptions& options) {
    const CheckSettings& own = preset.check;
    auto from = [](bool fromPreset) { return fromPreset ? " [preset]" : " [command line]"; };
    Tolerances t;
    t.image = options.tolerance;
    t.image.pixelTolerance = own.pixelTolerance.value_or(t.image.pixelTolerance);
    t.image.maxFailingShare = own.maxFailing ? double(*own.maxFailing) : t.image.maxFailingShare;
    t.image.maxMeanDifference = own.maxMean ? double(*own.maxMean) : t.image.maxMeanDifference;
    t.plot = own.plotTolerance ? double(*own.plotTolerance) : options.plotTolerance;
    t.imageText = "pixel_tolerance " + std::to_string(t.image.pixelTolerance) + from(own.pixelTolerance.has_value()) +
                  ", max_failing " + shortNumber(t.image.maxFailingShare) + from(own.maxFailing.has_value()) +
                  ", max_mean " + shortNumber(t.image.maxMeanDifference) + from(own.maxMean.has_value());
    t.plotText = "plot_tolerance " + shortNumber(t.plot) + from(own.plotTolerance.has_value());
    return t;
}

// "max M  mean X  over tolerance P%", or both sizes when they differ.
std::string imageFigures(const Comparison& cmp, const Image& actual, const Image& golden) {
    if (cmp.sameSize) {
        return "max " + std::to_string(cmp.maxDifference) + "  mean " + fixedDecimals(cmp.meanDifference, 3) +
               "  over tolerance " + fixedDecimals(cmp.failingShare * 100.0, 3) + "%";
    }
    return "size " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + " vs golden " +
           std::to_string(golden.width) + "x" + std::to_string(golden.height);
}

Image crop(const Image& image, int x, int y, int width, int height) {
    Image out{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 3)};
    for (int row = 0; row < height; ++row) {
        const std::uint8_t* from =
            image.rgb.data() + (std::size_t(y + row) * std::size_t(image.width) + std::size_t(x)) * 3;
        std::copy(from, from + std::size_t(width) * 3, out.rgb.data() + std::size_t(row) * std::size_t(width) * 3);
    }
    return out;
}

// `folder` as seen from `from` (both folders), each part URL-encoded, with a trailing '/'; "" when
// they are the same. Lexical, as a browser resolves a relative link from the path the page was
// opened by (a folder reached through a symbolic link included).
std::string linkPrefix(const fs::path& from, const fs::path& folder) {
    fs::path a = absolutePath(from).value_or(from), b = absolutePath(folder).value_or(folder);
    fs::path relative = b.lexically_relative(a);
    if (relative.empty() || relative == ".") {
        return relative.empty() && a != b ? b.generic_string() + "/" : "";
    }
    std::string out;
    for (const fs::path& part : relative) {
        out += urlEncoded(part.string()) + "/";
    }
    return out;
}

//----------------------------------------------------------------------------------------
// The cases of one run
//----------------------------------------------------------------------------------------

class Checker {
  public:
    Checker(Gpu& gpu, const CheckOptions& options) : gpu_(gpu), options_(options) {}

    std::vector<CheckCase> cases;
    bool badInput = false;
    bool writeFailed = false; // a golden or a report file that could not be written (exit status 2)

    void preset(const PresetPlan& plan) {
        if (!plan.loaded) {
            CheckCase c = start(CheckCase::Kind::Render, plan.cases.front().name, plan.file);
            c.verdict = CheckCase::Verdict::Error;
            c.message = "the preset does not load (see above)";
            badInput = true;
            finish(c, std::chrono::steady_clock::now());
            return;
        }
        const LoadedPreset& loaded = *plan.loaded;
        Tolerances tolerances = tolerancesFor(loaded.preset, options_);
        for (const PlannedCase& c : plan.cases) {
            if (c.kind == CheckCase::Kind::SweepCell) {
                sweep(loaded, c, tolerances);
            } else if (c.kind == CheckCase::Kind::Plot) {
                plot(loaded, c, tolerances);
            } else if (c.view >= 0) {
                checkView(loaded, c, tolerances);
            } else {
                render(loaded, c, tolerances);
            }
        }
    }

  private:
    CheckCase start(CheckCase::Kind kind, const std::string& name, const fs::path& file) {
        CheckCase c;
        c.kind = kind;
        c.name = name;
        c.presetFile = file.string();
        return c;
    }

    // A case that cannot be compared for its input (a golden that does not read, a sweep the preset
    // refuses): an error line, the message on stderr too, and exit status 2.
    void badInputCase(CheckCase& c, std::string message) {
        c.verdict = CheckCase::Verdict::Error;
        c.message = std::move(message);
        print(stderr, "lab check: " + c.presetFile + ": " + c.message + "\n");
        badInput = true;
    }

    void finish(CheckCase& c, std::chrono::steady_clock::time_point began) {
        c.seconds = secondsSince(began);
        print(stdout, checkLine(c, options_.report.string()) + "\n");
        cases.push_back(std::move(c));
    }

    // A file in the report folder; its name relative to the folder, or "" when it could not be
    // written (the case's message then says why).
    std::string reportFile(const std::string& name, std::string_view bytes, CheckCase& c) {
        std::string error;
        if (writeFileAtomic(options_.report / name, bytes, error, WriteSafety::Renewable)) {
            return name;
        }
        c.message += (c.message.empty() ? "" : "; ") + std::string("could not write the report's files: ") + error;
        writeFailed = true;
        return "";
    }
    std::string reportImage(const std::string& name, const Image& image, CheckCase& c) {
        return reportFile(name, encodePng(image), c);
    }

    // A golden image, judged by its header before it is decoded: one the size of the render is
    // decoded (no larger, then, than the render itself), one of another size is not (a 780 KB
    // file can claim 16384 x 16384), one larger than the lab renders is unreadable.
    struct Golden {
        fs::path file;
        std::optional<ImageSize> size; // what its header says; nullopt when missing or unreadable
        std::optional<Image> image;    // decoded when its size is the render's
    };

    // False after making `c` an error case (bad input) for a golden that does not read, except
    // with --update, which replaces it.
    bool readGolden(const fs::path& file, const Image& actual, Golden& golden, CheckCase& c) {
        golden.file = file;
        std::error_code ec;
        if (!fs::exists(file, ec)) {
            return true;
        }
        std::string error;
        golden.size = readPngSize(file, error);
        if (golden.size && (golden.size->width > kMaxRenderSide || golden.size->height > kMaxRenderSide)) {
            error = "its header claims " + std::to_string(golden.size->width) + "x" + std::to_string(golden.size->height) +
                    ", larger than the lab renders (" + std::to_string(kMaxRenderSide) + " a side)";
            golden.size.reset();
        }
        if (golden.size && *golden.size == ImageSize{actual.width, actual.height} &&
            !(golden.image = readPng(file, error, std::max(actual.width, actual.height)))) {
            golden.size.reset();
        }
        if (!golden.size && !options_.update) {
            badInputCase(c, "golden " + file.string() + ": " + error);
            return false;
        }
        return true;
    }

    // A golden of another size than the render: a failure at once, its file and the render in the
    // report folder (the golden as it is, not decoded).
    void sizeDiffers(CheckCase& c, const Image& actual, const Golden& golden, const std::string& files) {
        c.verdict = CheckCase::Verdict::Fail;
        c.figures = "size " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + " vs golden " +
                    std::to_string(golden.size->width) + "x" + std::to_string(golden.size->height);
        std::string error;
        if (std::optional<std::string> bytes = readFile(golden.file, kMaxPngBytes, error)) {
            c.golden = reportFile(files + ".golden.png", *bytes, c);
        }
        c.actual = reportImage(files + ".actual.png", actual, c);
    }

    // Compares `actual` with the golden, or says it is missing or of another size.
    void judge(CheckCase& c, const Image& actual, const Golden& golden, const Tolerance& tolerance, const std::string& files) {
        if (options_.update) {
            update(c, actual, golden);
        } else if (!golden.size) {
            missing(c, golden.file, &actual, files);
        } else if (!golden.image) {
            sizeDiffers(c, actual, golden, files);
        } else {
            compare(c, actual, *golden.image, tolerance, files);
        }
    }

    // --update's verdict for one golden (image or CSV): SAME when `same`, else `write(error)` writes
    // it: UPDATED or CREATED, or an error.
    template <typename Write> void updateGolden(CheckCase& c, bool same, bool hadGolden, Write write) {
        std::string error;
        if (same) {
            c.verdict = CheckCase::Verdict::Same;
        } else if (!write(error)) {
            c.verdict = CheckCase::Verdict::Error;
            c.message = "the golden was not written: " + error;
            writeFailed = true;
        } else {
            c.verdict = hadGolden ? CheckCase::Verdict::Updated : CheckCase::Verdict::Created;
        }
    }

    // --update: writes `actual` as the golden unless it is the same image.
    void update(CheckCase& c, const Image& actual, const Golden& golden) {
        std::optional<Comparison> cmp;
        if (golden.image) {
            cmp = compareImages(actual, *golden.image, Tolerance{});
            c.figures = imageFigures(*cmp, actual, *golden.image);
        } else if (golden.size) {
            c.figures = "size " + std::to_string(golden.size->width) + "x" + std::to_string(golden.size->height) + " before";
        }
        updateGolden(c, cmp && cmp->sameSize && cmp->maxDifference == 0, golden.size.has_value(),
                     [&](std::string& error) { return writePng(actual, golden.file, error); });
    }

    // Compares `actual` with `golden`; on a failure the three images go to the report folder
    // under `files` (<files>.golden.png, .actual.png, .diff.png).
    void compare(CheckCase& c, const Image& actual, const Image& golden, const Tolerance& tolerance,
                 const std::string& files) {
        Comparison cmp = compareImages(actual, golden, tolerance);
        c.figures = imageFigures(cmp, actual, golden);
        if (cmp.passes(tolerance)) {
            c.verdict = CheckCase::Verdict::Pass;
            return;
        }
        c.verdict = CheckCase::Verdict::Fail;
        c.golden = reportImage(files + ".golden.png", golden, c);
        c.actual = reportImage(files + ".actual.png", actual, c);
        if (cmp.sameSize) {
            c.diff = reportImage(files + ".diff.png", cmp.diff, c);
        }
    }

    void missing(CheckCase& c, const fs::path& goldenFile, const Image* actual, const std::string& files) {
        c.verdict = CheckCase::Verdict::Missing;
        c.message = "no golden " + goldenFile.string() + " (create it with --update)";
        if (actual) {
            c.actual = reportImage(files + ".actual.png", *actual, c);
        }
    }

    // The preset's check.views[i] (drawn with viridis over its automatic range) against
    // <stem>.<view>.png (<stem>.<view>.light<N>.png for a light other than the first).
    void checkView(const LoadedPreset& preset, const PlannedCase& planned, const Tolerances& tolerances) {
        const CheckView& v = preset.preset.check.views[std::size_t(planned.view)];
        DisplaySettings settings; // viridis over the automatic range
        settings.mode = *viewFromName(v.view); // checked when the preset was read
        settings.light = v.light - 1;
        const ViewportDraw draw = viewDraw(settings);
        std::string why = notApplicable(draw.options.view, preset.preset, draw.options.light);
        if (!why.empty()) {
            auto began = std::chrono::steady_clock::now();
            CheckCase c = start(CheckCase::Kind::Render, planned.name, preset.file);
            badInputCase(c, "check.views[" + std::to_string(planned.view) + "]: " + why);
            finish(c, began);
            return;
        }
        render(preset, planned, tolerances, draw);
    }

    void render(const LoadedPreset& preset, const PlannedCase& planned, const Tolerances& tolerances,
                const ViewportDraw& view = {}) {
        auto began = std::chrono::steady_clock::now();
        const std::string& stem = planned.name;
        CheckCase c = start(CheckCase::Kind::Render, stem, preset.file);
        c.tolerance = tolerances.imageText;
        Diagnostics diagnostics;
        std::optional<Rendered> rendered =
            gpu_.renderer.renderView(preset, options_.size.width, options_.size.height, view, diagnostics);
        std::optional<Image> actual;
        if (rendered) {
            actual = std::move(rendered->image);
        }
        Golden golden;
        if (!actual) {
            printDiagnostics(diagnostics);
            c.verdict = CheckCase::Verdict::Error;
            c.message = "render failed";
        } else if (readGolden(planned.golden, *actual, golden, c)) { // (else c says why)
            judge(c, *actual, golden, tolerances.image, stem);
        }
        finish(c, began);
    }

    // The preset's sweep as one grid, compared cell by cell (one case a cell).
    void sweep(const LoadedPreset& base, const PlannedCase& planned, const Tolerances& tolerances) {
        auto began = std::chrono::steady_clock::now();
        const std::string& whole = planned.name;
        CheckCase c = start(CheckCase::Kind::SweepCell, whole, base.file);
        c.tolerance = tolerances.imageText;
        std::vector<SweepAxis> axes;
        std::string error;
        for (const std::string& text : base.preset.sweep) {
            axes.push_back(*parseSweepAxis(text, error)); // checked when the preset was read
        }
        LoadedPreset preset = base;
        Diagnostics diagnostics;
        bool renderFailed = false;
        std::optional<Image> grid;
        if (frameForCells(preset, diagnostics)) {
            grid = renderSweepGrid(gpu_, preset, axes, options_.sweepSize, error, renderFailed);
        } else {
            error = diagnostics.empty() ? "the model does not load" : diagnostics.front().str();
        }
        Golden golden;
        if (!grid && renderFailed) {
            c.verdict = CheckCase::Verdict::Error;
            c.message = "sweep: " + error;
        } else if (!grid) { // a key or value the preset refuses (the JSON path "sweep")
            badInputCase(c, "sweep: " + error);
        }
        if (!grid) {
            finish(c, began);
            return;
        }
        if (!readGolden(planned.golden, *grid, golden, c)) { // (c says why)
            finish(c, began);
            return;
        }
        if (options_.update || !golden.image) {
            judge(c, *grid, golden, tolerances.image, whole); // updated, missing or of another size
            finish(c, began);
            return;
        }
        // Cell by cell: each compared on its own, named by its values.
        SweepGridLayout layout = sweepGridLayout(axes, options_.sweepSize.width, options_.sweepSize.height);
        double shared = secondsSince(began) / double(layout.columns * layout.rows);
        for (int row = 0; row < layout.rows; ++row) {
            for (int column = 0; column < layout.columns; ++column) {
                auto cellBegan = std::chrono::steady_clock::now();
                std::string values = axes[0].key + "=" + axes[0].values[std::size_t(column)];
                if (axes.size() > 1) {
                    values += ", " + axes[1].key + "=" + axes[1].values[std::size_t(row)];
                }
                CheckCase cell = start(CheckCase::Kind::SweepCell, whole + "[" + values + "]", base.file);
                cell.tolerance = tolerances.imageText;
                int x = layout.cellX(column), y = layout.cellY(row);
                compare(cell, crop(*grid, x, y, layout.cellWidth, layout.cellHeight),
                        crop(*golden.image, x, y, layout.cellWidth, layout.cellHeight), tolerances.image,
                        sweepCellFiles(whole, row, column));
                finish(cell, cellBegan);
                cases.back().seconds += shared;
            }
        }
    }

    // The lobe CSV `lab plot --out` writes, against <name>.plot.csv within the plot tolerance.
    void plot(const LoadedPreset& preset, const PlannedCase& planned, const Tolerances& tolerances) {
        auto began = std::chrono::steady_clock::now();
        CheckCase c = start(CheckCase::Kind::Plot, planned.name, preset.file);
        c.tolerance = tolerances.plotText;
        const std::string text = plotCsv(reflectedIntensity(preset.preset, preset.preset.plotIncidentDeg));
        const fs::path& goldenFile = planned.golden;
        std::string error;
        std::error_code ec;
        std::optional<std::string> goldenText;
        if (fs::exists(goldenFile, ec)) {
            goldenText = readFile(goldenFile, kMaxGoldenCsvBytes, error);
            if (!goldenText && !options_.update) {
                badInputCase(c, "golden " + goldenFile.string() + ": " + error);
                finish(c, began);
                return;
            }
        }
        std::optional<NumberCsv> golden; // parsed only for a comparison
        if (options_.update) {
            updateGolden(c, goldenText && *goldenText == text, goldenText.has_value(),
                         [&](std::string& why) { return writeFileAtomic(goldenFile, text, why); });
        } else if (!goldenText) {
            c.verdict = CheckCase::Verdict::Missing;
            c.message = "no golden " + goldenFile.string() + " (create it with --update --plots)";
            c.actual = reportFile(planned.name + ".actual.csv", text, c);
        } else if (golden = parseNumberCsv(*goldenText, error); !golden) {
            badInputCase(c, "golden " + goldenFile.string() + " is not a CSV of numbers: " + error);
        } else {
            std::string parseError;
            CsvComparison cmp = compareCsv(*parseNumberCsv(text, parseError), *golden, tolerances.plot);
            c.figures = cmp.figures;
            if (cmp.passes) {
                c.verdict = CheckCase::Verdict::Pass;
            } else {
                c.verdict = CheckCase::Verdict::Fail;
                c.message = cmp.firstDifference;
                c.golden = reportFile(planned.name + ".golden.csv", *goldenText, c);
                c.actual = reportFile(planned.name + ".actual.csv", text, c);
            }
        }
        finish(c, began);
    }

    Gpu& gpu_;
    const CheckOptions& options_;
};

} // namespace

int runCheck(const std::vector<fs::path>& presets, const CheckOptions& options) {
    auto began = std::chrono::steady_clock::now();
    auto loaded = loadAll(presets);
    const std::vector<PresetPlan> plans = planCheck(presets, loaded, options);
    if (!checkRunIsSafe(plans, options) || !makeCheckFolders(options)) {
        return kExitBadInput;
    }
    Gpu gpu;
    if (!gpu.start()) {
        return kExitFailure;
    }
    Checker checker(gpu, options);
    for (const PresetPlan& plan : plans) {
        checker.preset(plan);
    }
    const std::vector<CheckCase>& cases = checker.cases;
    const auto failed = std::count_if(cases.begin(), cases.end(), [](const CheckCase& c) { return c.failed(); });
    std::string summary =
        std::to_string(cases.size() - std::size_t(failed)) + " passed, " + std::to_string(failed) + " failed";
    print(stdout, summary + "\n");

    // The report: written whole or not at all (each file atomically).
    CheckRun run{
        options.golden.string(), std::to_string(options.size.width) + "x" + std::to_string(options.size.height),
        std::to_string(options.sweepSize.width) + "x" + std::to_string(options.sweepSize.height), options.update};
    bool written = true;
    auto write = [&](const char* flag, const fs::path& file, const std::string& text) {
        std::string error;
        if (!writeFileAtomic(file, text, error)) {
            print(stderr, "lab check: %s %s\n", flag, error.c_str());
            written = false;
        }
    };
    if (!options.update) {
        std::string text;
        for (const CheckCase& c : cases) {
            text += checkLine(c, options.report.string()) + "\n";
        }
        // The lines as the terminal showed them: escaped as every message is (a preset named with an
        // escape sequence would otherwise recolour the terminal of whoever reads report.txt).
        write("--report", options.report / "report.txt", printable(text + summary + "\n"));
        write("--report", options.report / "index.html", checkHtml(cases, run, ""));
    }
    if (options.html) {
        fs::path parent = options.html->parent_path().empty() ? fs::path(".") : options.html->parent_path();
        write("--html", *options.html, checkHtml(cases, run, linkPrefix(parent, options.report)));
    }
    if (options.junit) {
        write("--junit", *options.junit, checkJunit(cases, secondsSince(began)));
    }
    if (checker.badInput || checker.writeFailed || !written) {
        return kExitBadInput;
    }
    return failed > 0 ? kExitFailure : kExitOk;
}

} // namespace lab
