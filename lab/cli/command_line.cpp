// command_line.cpp — the CLI11 definition of `lab`'s arguments.
#include "cli/command_line.h"

#include "cli/output.h"
#include "cli/settings.h"
#include "core/io/safe_text.h"
#include "core/io/suggest.h"
#include "core/scene/field_table.h"
#include "core/scene/limits.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>

#ifndef LAB_VERSION
#define LAB_VERSION "0.0.0"
#endif

namespace lab {

namespace {

// An empty path is no path: `--out ""` is refused naming the option, not later as "cannot replace :".
const CLI::Validator kNotEmpty(
    [](std::string& text) { return text.empty() ? std::string("must not be empty") : std::string(); }, "PATH");


// A number option must be finite before CLI::Range sees it: "nan" passes every range check (each
// comparison with NaN is false), and would reach a figure as "θi = nan°" or a tolerance as none.
const CLI::Validator kFinite(
    [](std::string& text) {
        double v = std::strtod(text.c_str(), nullptr); // CLI11 reports text that is no number itself
        return std::isfinite(v) ? std::string() : "must be a finite number, got " + text;
    },
    "");

// CLI11 validator for --size, so a bad size is reported like every other bad flag.
struct SizeValidator : CLI::Validator {
    SizeValidator() {
        name_ = "WxH";
        func_ = [](std::string& text) {
            std::string error;
            return parseSize(text, error) ? std::string{} : error;
        };
    }
};

std::vector<std::filesystem::path> toPaths(const std::vector<std::string>& v) { return {v.begin(), v.end()}; }

// `check`'s arguments as text, until they are parsed into the CommandLine.
struct CheckArguments {
    std::vector<std::string> presets;
    std::string golden, report = "lab-check", size = "512x512", sweepSize = "128x128", junit, html;
};

CLI::App* addCheckCommand(CLI::App& app, CommandLine& line, CheckArguments& a) {
    CLI::App* check = app.add_subcommand("check", "Render presets and compare them with golden images");
    check->add_option("presets", a.presets, "Preset files")->required();
    check->add_option("--golden", a.golden, "Folder of goldens: <name>.png, <name>.sweep.png, <name>.plot.csv")
        ->required()
        ->check(kNotEmpty);
    check->add_flag("--update", line.check.update, "Write goldens from the renders instead of comparing");
    check->add_option("--report", a.report,
                      "Folder for report.txt, index.html and the golden, actual and diff files of failures")
        ->capture_default_str()
        ->check(kNotEmpty);
    check->add_option("--junit", a.junit, "JUnit XML file to write (one test case per render, sweep cell and plot)")
        ->check(kNotEmpty);
    check->add_option("--html", a.html, "The HTML report again, at this path (its images stay in --report)")->check(kNotEmpty);
    check->add_flag("--plots", line.check.plots,
                    "Check every preset's plot CSV against <name>.plot.csv (else only where that golden exists)");
    check->add_option("--size", a.size, "Render size")->check(SizeValidator())->capture_default_str();
    check->add_option("--sweep-size", a.sweepSize, "Each cell of a preset's sweep")->check(SizeValidator())->capture_default_str();
    using limits::kMaxFailing, limits::kMaxMean, limits::kPixelTolerance, limits::kPlotTolerance;
    check->add_option("--pixel-tolerance", line.check.tolerance.pixelTolerance, "A pixel fails above this channel difference")
        ->check(CLI::Range(kPixelTolerance.min, kPixelTolerance.max))->capture_default_str();
    check->add_option("--max-failing", line.check.tolerance.maxFailingShare, "Largest share of failing pixels (0.001 = 0.1%)")
        ->check(kFinite)->check(CLI::Range(double(kMaxFailing.min), double(kMaxFailing.max)))->capture_default_str();
    check->add_option("--max-mean", line.check.tolerance.maxMeanDifference, "Largest mean channel difference, in levels")
        ->check(kFinite)->check(CLI::Range(double(kMaxMean.min), double(kMaxMean.max)))->capture_default_str();
    check->add_option("--plot-tolerance", line.check.plotTolerance, "Largest difference of a plot CSV value from its golden")
        ->check(kFinite)->check(CLI::Range(double(kPlotTolerance.min), double(kPlotTolerance.max)))->capture_default_str();
    return check;
}

// `plot`'s figure options as text, until they are checked into FigureOutputs.
// A theme's name (core/plots/theme.h), or why not.
const CLI::Validator kThemeName(
    [](std::string& text) {
        return themeFrom(text) ? std::string() : "unknown theme '" + text + "': the themes are " + themeNames();
    },
    "dark|light");

struct FigureArguments {
    std::string kind = "lobe", svg, png, csv, theme = "light", component = "specular", compare;
    float scale = 1.0f;
    int light = 1;
    bool log = false;
    std::vector<float> overlayDeg{60.0f, 25.0f, 10.0f};
    CLI::Option* kindOption = nullptr;
    CLI::Option* overlayOption = nullptr;
    CLI::Option* scaleOption = nullptr;
    CLI::Option* lightOption = nullptr;
    CLI::Option* themeOption = nullptr;
    CLI::Option* componentOption = nullptr;
};

void addFigureOptions(CLI::App* plot, FigureArguments& a) {
    std::vector<std::string> kinds;
    for (FigureKind k : kFigureKinds) {
        kinds.emplace_back(toString(k));
    }
    a.kindOption = plot->add_option("--figure", a.kind, "Which figure --svg, --png and --csv write: lobe, overlay (three incident "
                                                        "angles), attenuation (of --light), albedo or slice (the BRDF over "
                                                        "the half and difference angles)")
                       ->check(CLI::IsMember(kinds))
                       ->capture_default_str();
    plot->add_option("--svg", a.svg, "SVG file to write the figure to")->check(kNotEmpty);
    plot->add_option("--compare", a.compare, "A second preset, B, drawn beside the first in the lobe, albedo and slice "
                                            "figures (as the lab's compare mode)")
        ->check(kNotEmpty);
    plot->add_option("--png", a.png, "PNG file to write the figure to")->check(kNotEmpty);
    plot->add_option("--csv", a.csv, "CSV file to write the figure's curves to")->check(kNotEmpty);
    a.scaleOption = plot->add_option("--scale", a.scale, "The PNG's scale: 1 is 720 pixels wide")
                        ->check(kFinite)
                        ->check(CLI::Range(kMinFigureScale, kMaxFigureScale))
                        ->capture_default_str();
    a.lightOption = plot->add_option("--light", a.light, "The attenuation figure's light, from 1")
                        ->check(CLI::Range(1, 64))
                        ->capture_default_str();
    plot->add_flag("--log", a.log, "Logarithmic radial scale in the lobe and overlay figures, log colours in the slice");
    a.componentOption = plot->add_option("--component", a.component, "The slice figure's image: diffuse, specular or total "
                                                                     "(its CSV has all three)")
                            ->check(CLI::IsMember({"diffuse", "specular", "total"}))
                            ->capture_default_str();
    a.themeOption = plot->add_option("--theme", a.theme, "The figure's colours: light (dark on white, for paper and slides) "
                                                         "or dark (light on near black, as the lab's dark theme)")
                        ->check(kThemeName)
                        ->capture_default_str();
    a.overlayOption = plot->add_option("--overlay-deg", a.overlayDeg, "The overlay figure's three incident angles in degrees, "
                                                                      "e.g. 60,25,10")
                          ->delimiter(',')
                          ->expected(3)
                          ->check(kFinite)
                          ->check(CLI::Range(-90.0f, 90.0f));
}

// False (with the message printed) for options that would do nothing: --figure, --scale or
// --light without a file to write them to.
bool figureOutputs(const FigureArguments& a, FigureOutputs& out) {
    out.request.kind = *figureKindFrom(a.kind); // checked by IsMember
    out.request.scale = a.log ? RadialScale::Log : RadialScale::Linear;
    out.request.light = a.light - 1;
    out.request.overlayDeg = glm::vec3(a.overlayDeg[0], a.overlayDeg[1], a.overlayDeg[2]); // expected(3)
    out.request.theme = *themeFrom(a.theme); // checked by kThemeName
    out.request.component = a.component == "diffuse" ? PlotComponent::Diffuse
                            : a.component == "total" ? PlotComponent::Total : PlotComponent::Specular; // IsMember
    if (a.componentOption->count() && out.request.kind != FigureKind::Slice) {
        print(stderr, "lab plot: --component is the slice figure's: give --figure slice\n");
        return false;
    }
    if (a.lightOption->count() && out.request.kind == FigureKind::Slice) {
        print(stderr, "lab plot: --light is the attenuation figure's; the slice is for a unit white light, as --out\n");
        return false;
    }
    out.files.pngScale = a.scale;
    if (!a.svg.empty()) {
        out.files.svg = a.svg;
    }
    if (!a.png.empty()) {
        out.files.png = a.png;
    }
    if (!a.csv.empty()) {
        out.files.csv = a.csv;
    }
    if (!a.compare.empty()) {
        out.compare = a.compare;
        if (out.request.kind != FigureKind::Lobe && out.request.kind != FigureKind::Albedo &&
            out.request.kind != FigureKind::Slice) {
            print(stderr, "lab plot: --compare draws B in the lobe, albedo and slice figures, not in --figure " +
                              std::string(toString(out.request.kind)) + "\n");
            return false;
        }
        if (!out.any()) {
            print(stderr, "lab plot: --compare is a figure's B: give --svg, --png or --csv FILE too\n");
            return false;
        }
    }
    if (a.scaleOption->count() && !out.files.png) {
        print(stderr, "lab plot: --scale is the PNG's: give --png FILE too\n");
        return false;
    }
    if ((a.kindOption->count() || a.lightOption->count() || a.overlayOption->count() || a.themeOption->count() || a.log ||
         a.componentOption->count()) &&
        !out.any()) {
        print(stderr, "lab plot: --figure, --light, --overlay-deg, --theme, --component and --log choose a figure: give --svg, "
                      "--png or --csv FILE too\n");
        return false;
    }
    return true;
}

// `lab render`'s arguments as typed.
struct RenderArguments {
    std::vector<std::string> presets;
    std::string out, size = "512x512";
    std::vector<std::string> sweeps;
    std::string view, palette, range;
    int light = 0; // 0: not given
    bool legend = false;
};

CLI::App* addRenderCommand(CLI::App& app, RenderArguments& a) {
    CLI::App* render = app.add_subcommand("render", "Render presets headless to PNG (no display or GPU needed)");
    render->add_option("presets", a.presets, "Preset files")->required();
    render->add_option("--out", a.out, "The PNG file; a folder when there are several presets")->required()->check(kNotEmpty);
    render->add_option("--size", a.size, "Image size (with --sweep: each cell's)")->check(SizeValidator())->capture_default_str();
    render->add_option("--sweep", a.sweeps,
                       "KEY=V1,V2,...: one preset as a labelled grid, KEY's values along the columns (a second "
                       "--sweep: down the rows), e.g. --sweep material.shininess=10,20,30,50")
        ->allow_extra_args(false)
        ->take_all();
    render->add_option("--view", a.view, "What to draw instead of the lit model: " + viewNames());
    render->add_option("--light", a.light, "The light a factor view shows, from 1 (default 1)")
        ->check(CLI::Range(1, 1000));
    render->add_option("--palette", a.palette, "A value view's colours: viridis (default) or grey");
    render->add_option("--range", a.range,
                       "LO,HI: the values at a value view's first and last colour (default: the smallest and "
                       "largest on the model, printed)");
    render->add_flag("--legend", a.legend, "Add the value view's legend under the image");
    return render;
}

// "LO,HI" with LO < HI, both finite; nullopt with `error`.
std::optional<ValueRange> parseRange(const std::string& text, std::string& error) {
    std::size_t comma = text.find(',');
    char* end = nullptr;
    std::string lo = text.substr(0, comma), hi = comma == std::string::npos ? "" : text.substr(comma + 1);
    float a = std::strtof(lo.c_str(), &end);
    bool loOk = !lo.empty() && end && *end == '\0';
    float b = std::strtof(hi.c_str(), &end);
    bool hiOk = !hi.empty() && end && *end == '\0';
    if (comma == std::string::npos || !loOk || !hiOk || !std::isfinite(a) || !std::isfinite(b)) {
        error = "--range: expected LO,HI (two numbers), got " + inQuotes(text, 60);
        return std::nullopt;
    }
    if (!(a < b)) {
        error = "--range: LO must be less than HI, got " + inQuotes(text, 60);
        return std::nullopt;
    }
    return ValueRange{a, b};
}

// --view and its options; false with the message printed.
bool renderViewLine(const RenderArguments& a, CommandLine& line) {
    RenderView& v = line.view;
    std::string error;
    if (!a.view.empty()) {
        std::optional<ViewMode> mode = viewFromName(a.view);
        if (!mode) {
            print(stderr, "lab render: --view: no view " + inQuotes(a.view, 60) + suggestion(a.view, viewNameList()) +
                              "; the views are " + viewNames() + "\n");
            return false;
        }
        v.mode = *mode;
    }
    if (!a.palette.empty() && a.palette != "viridis" && a.palette != "grey") {
        print(stderr, "lab render: --palette: expected viridis or grey, got " + inQuotes(a.palette, 60) + "\n");
        return false;
    }
    v.palette = a.palette == "grey" ? ValuePalette::Grey : ValuePalette::Viridis;
    if (!a.range.empty() && !(v.range = parseRange(a.range, error))) {
        print(stderr, "lab render: " + error + "\n");
        return false;
    }
    v.light = a.light > 0 ? a.light - 1 : 0;
    v.legend = a.legend;
    const std::string notFor = ", not to --view " + std::string(viewName(v.mode)) + "\n";
    if (a.light > 0 && !isFactor(v.mode)) {
        print(stderr, "lab render: --light applies to a factor view (--view n-dot-l, d, spot, ...)" + notFor);
        return false;
    }
    if ((!a.palette.empty() || !a.range.empty() || a.legend) && !showsValue(v.mode)) {
        print(stderr, "lab render: --palette, --range and --legend apply to a value view (--view n-dot-l, d, "
                      "gouraud-error, ...)" + notFor);
        return false;
    }
    return true;
}

// False (with the message printed) for a --sweep that does not parse.
bool renderLine(const RenderArguments& a, CommandLine& line) {
    std::string error;
    line.command = CommandLine::Command::Render;
    line.presets = toPaths(a.presets);
    line.out = a.out;
    line.size = *parseSize(a.size, error); // validated by SizeValidator
    for (const std::string& text : a.sweeps) {
        std::optional<SweepAxis> axis = parseSweepAxis(text, error);
        if (!axis) {
            print(stderr, "lab render: --sweep " + error + "\n");
            return false;
        }
        line.sweeps.push_back(std::move(*axis));
    }
    return renderViewLine(a, line);
}

// `lab plot`'s arguments as typed.
struct PlotArguments {
    std::string preset, out, albedoOut;
    FigureArguments figure;
};

CLI::App* addPlotCommand(CLI::App& app, CommandLine& line, PlotArguments& a) {
    CLI::App* plot = app.add_subcommand("plot", "Write the polar-plot data (reflected intensity) and the albedo as CSV");
    plot->add_option("preset", a.preset, "Preset file")->required();
    plot->add_option("--out", a.out, "CSV file to write the polar-plot data to")->check(kNotEmpty);
    plot->add_option("--albedo", a.albedoOut, "CSV file to write the albedo of each term against the incident angle to")
        ->check(kNotEmpty);
    plot->add_option("--incident-deg", line.incidentDeg, "Incident angle in degrees (default: the preset's plot.incident_deg)")
        ->check(kFinite)
        ->check(CLI::Range(limits::kPlotIncidentDeg.min, limits::kPlotIncidentDeg.max));
    addFigureOptions(plot, a.figure);
    return plot;
}

// False (with the message printed) when there is nothing to write or a figure option is idle.
bool plotLine(const PlotArguments& a, CommandLine& line) {
    line.command = CommandLine::Command::Plot;
    line.presets = {a.preset};
    line.out = a.out;
    if (!a.albedoOut.empty()) {
        line.albedoOut = a.albedoOut;
    }
    if (!figureOutputs(a.figure, line.figure)) {
        return false;
    }
    if (a.out.empty() && a.albedoOut.empty() && !line.figure.any()) {
        print(stderr, "lab plot: nothing to write: give --out FILE.csv (the polar plot), --albedo FILE.csv (the albedo), "
                      "--svg/--png FILE (a figure) or several\n");
        return false;
    }
    return true;
}

void checkLine(const CheckArguments& a, CommandLine& line) {
    std::string error;
    line.command = CommandLine::Command::Check;
    line.presets = toPaths(a.presets);
    line.check.golden = a.golden;
    line.check.report = a.report;
    line.check.size = *parseSize(a.size, error);           // validated by SizeValidator
    line.check.sweepSize = *parseSize(a.sweepSize, error); // likewise
    if (!a.junit.empty()) {
        line.check.junit = a.junit;
    }
    if (!a.html.empty()) {
        line.check.html = a.html;
    }
}

// `lab exercise check` and `lab share`, as typed.
struct ExerciseArguments {
    std::string exercise, attempt, diff;
};

CLI::App* addExerciseCommand(CLI::App& app, ExerciseArguments& a, CLI::App*& check) {
    CLI::App* exercise = app.add_subcommand("exercise", "Exercises: check a student's attempt");
    exercise->require_subcommand(1, 1);
    check = exercise->add_subcommand("check", "Whether an attempt (a preset) solves an exercise: exit 0 solved, 1 not yet, "
                                              "2 bad input or a field the exercise does not open changed");
    check->add_option("exercise", a.exercise, "Exercise file (\"format\": \"lighting-lab-exercise\")")->required()->check(kNotEmpty);
    check->add_option("attempt", a.attempt, "The attempt: a preset file (e.g. the student's saved scene)")->required()->check(kNotEmpty);
    check->add_option("--diff", a.diff, "PNG file to write the difference of the two renders to")->check(kNotEmpty);
    return exercise;
}

// `lab fit`, as typed.
struct FitArguments {
    std::string preset, brdf, distribution, out;
    CLI::Option* distributionOption = nullptr;
};

std::vector<std::string> choiceNames(std::span<const FieldChoice> choices) {
    std::vector<std::string> names;
    for (const FieldChoice& c : choices) {
        names.emplace_back(c.name);
    }
    return names;
}

CLI::App* addFitCommand(CLI::App& app, FitArguments& a) {
    CLI::App* fit = app.add_subcommand("fit", "Fit a reflection model to a preset's specular reflection (least squares over "
                                              "the incident angles 0-75 degrees) and write the fitted preset");
    fit->add_option("preset", a.preset, "Preset file whose specular reflection is fitted")->required()->check(kNotEmpty);
    fit->add_option("--brdf", a.brdf, "The model to fit: phong, blinn-phong or cook-torrance")
        ->required()
        ->check(CLI::IsMember(choiceNames(kBrdfChoices)));
    a.distributionOption = fit->add_option("--distribution", a.distribution, "Cook-Torrance's distribution: beckmann "
                                                                             "(default), gaussian or ggx")
                               ->check(CLI::IsMember(choiceNames(kDistributionChoices)));
    fit->add_option("--out", a.out, "JSON file to write the fitted preset to")->required()->check(kNotEmpty);
    return fit;
}

// False (with the message printed) for --distribution without --brdf cook-torrance.
bool fitLine(const FitArguments& a, CommandLine& line) {
    line.command = CommandLine::Command::Fit;
    line.presets = {a.preset};
    line.out = a.out;
    for (const FieldChoice& c : kBrdfChoices) {
        if (c.name == a.brdf) {
            line.fit.brdf = static_cast<BrdfModel>(c.value);
        }
    }
    for (const FieldChoice& c : kDistributionChoices) {
        if (c.name == a.distribution) {
            line.fit.distribution = static_cast<Distribution>(c.value);
        }
    }
    if (a.distributionOption->count() && line.fit.brdf != BrdfModel::CookTorrance) {
        print(stderr, "lab fit: --distribution is Cook-Torrance's: give --brdf cook-torrance, or leave it out\n");
        return false;
    }
    return true;
}

struct ShareArguments {
    std::string file, base, qr;
};

CLI::App* addShareCommand(CLI::App& app, ShareArguments& a) {
    CLI::App* share = app.add_subcommand("share", "Print the link that opens a preset or an exercise in the course's "
                                                  "page, and write its QR code");
    share->add_option("file", a.file, "Preset or exercise file")->required()->check(kNotEmpty);
    share->add_option("--base", a.base, "The course page's address, e.g. https://course.example.org/lab/")
        ->required()
        ->check(kNotEmpty);
    share->add_option("--qr", a.qr, "PNG file to write the link's QR code to")->check(kNotEmpty);
    return share;
}

void exerciseLine(const ExerciseArguments& a, CommandLine& line) {
    line.command = CommandLine::Command::ExerciseCheck;
    line.exercise = a.exercise;
    line.attempt = a.attempt;
    if (!a.diff.empty()) {
        line.diffOut = a.diff;
    }
}

void shareLine(const ShareArguments& a, CommandLine& line) {
    line.command = CommandLine::Command::Share;
    line.shared = a.file;
    line.base = a.base;
    if (!a.qr.empty()) {
        line.qrOut = a.qr;
    }
}

} // namespace

namespace {

// The interactive lab's own options (no subcommand), as typed.
struct LabArguments {
    std::string preset, deck, layoutFile, screenshotFolder = ".", windowSize, theme;
};

void addLabOptions(CLI::App& app, CommandLine& line, LabArguments& a) {
    app.add_option("--preset", a.preset, "Open the lab with this preset, or a folder of presets to step through in name order");
    app.add_option("--deck", a.deck, "Open the lab with this deck: a lecture's slides with speaker notes (presets/decks/lecture.json)")
        ->excludes("--preset");
    app.add_flag("--presenter", line.presenter, "Start in presenter mode (large UI for a projector)");
    app.add_flag("--fullscreen", line.fullscreen, "Start fullscreen");
    app.add_option("--size", a.windowSize, "Window size (default: 1600x900, or the screen's work area if smaller)")
        ->check(SizeValidator());
    app.add_option("--screenshot-dir", a.screenshotFolder, "Folder for screenshots (F12)")->capture_default_str();
    app.add_option("--frame-budget", line.frameBudgetMs,
                   "While dragging or while a light moves, draw the 3D view at a lower resolution when a frame takes "
                   "longer than this many milliseconds (0: always full resolution)")
        ->check(kFinite)
        ->check(CLI::Range(0.0f, 1000.0f))
        ->capture_default_str();
    app.add_option("--share-base", line.shareBase,
                   "The course page's address (https://.../lab/): the QR code (Q) opens the scene there. Remembered in "
                   "$XDG_CONFIG_HOME/lighting-lab/settings.json")
        ->check(CLI::Validator([](std::string& text) { return shareBaseProblem(text); }, "URL"));
    app.add_option("--theme", a.theme, "The lab's colours, dark or light (a projector in a lit room), the plots' and the "
                                     "exported figures' too. Remembered as --share-base is")->check(kThemeName);
    // For GUI tests: the screen rectangles of the main widgets, rewritten every frame.
    app.add_option("--layout-file", a.layoutFile, "")->group("");

}

} // namespace

std::variant<CommandLine, int> parseCommandLine(int argc, const char* const* argv) {
    CLI::App app{"Lighting Lab: an interactive lab for local illumination (Phong, Blinn-Phong, Cook-Torrance)", "lab"};
    app.set_version_flag("--version", "lab " LAB_VERSION);
    app.require_subcommand(0, 1);
    CommandLine line;
    LabArguments lab;
    addLabOptions(app, line, lab);

    RenderArguments renderArguments;
    CLI::App* render = addRenderCommand(app, renderArguments);
    PlotArguments plotArguments;
    CLI::App* plot = addPlotCommand(app, line, plotArguments);
    CheckArguments checkArguments;
    CLI::App* check = addCheckCommand(app, line, checkArguments);
    ExerciseArguments exerciseArguments;
    CLI::App* exerciseCheck = nullptr;
    addExerciseCommand(app, exerciseArguments, exerciseCheck);
    ShareArguments shareArguments;
    CLI::App* share = addShareCommand(app, shareArguments);
    FitArguments fitArguments;
    CLI::App* fit = addFitCommand(app, fitArguments);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // Help and version to stdout, errors to stderr; CLI11 echoes the arguments, so escaped.
        std::ostringstream out, err;
        int status = app.exit(e, out, err);
        print(stdout, out.str());
        print(stderr, err.str());
        return status == 0 ? kExitOk : kExitBadInput;
    }

    std::string error;
    if (!lab.theme.empty()) {
        line.theme = themeFrom(lab.theme); // checked by kThemeName
    }
    if (!lab.preset.empty() || !lab.deck.empty()) {
        line.preset = lab.deck.empty() ? lab.preset : lab.deck; // a deck opens as a file: its format says what it is
    }
    if (!lab.layoutFile.empty()) {
        line.layoutFile = lab.layoutFile;
    }
    line.screenshotFolder = lab.screenshotFolder;
    if (!lab.windowSize.empty()) {
        line.windowSize = *parseSize(lab.windowSize, error); // validated by SizeValidator
    }
    if ((*render && !renderLine(renderArguments, line)) || (*plot && !plotLine(plotArguments, line)) ||
        (*fit && !fitLine(fitArguments, line))) {
        return kExitBadInput;
    }
    if (*check) { // one subcommand at most (require_subcommand)
        checkLine(checkArguments, line);
    } else if (*exerciseCheck) {
        exerciseLine(exerciseArguments, line);
    } else if (*share) {
        shareLine(shareArguments, line);
    }
    return line;
}

} // namespace lab
