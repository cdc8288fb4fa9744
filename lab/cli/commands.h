// commands.h — the headless commands behind `lab render`, `lab plot`, `lab check` and the others.
//
// Each returns the process exit status: 0 success, 2 bad input (a message on stderr naming the
// file and place; for `check` also a golden that does not read), 1 an internal failure or, for
// `check`, an image or plot that differs or a missing golden. Output files are written atomically. Nothing here parses argv (main.cpp does).
#pragma once

#include "core/io/image.h"
#include "core/plots/figures.h"
#include "core/plots/fit.h"
#include "core/scene/sweep.h"
#include "core/scene/view_mode.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lab {

enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2 };

struct Size {
    int width = 512;
    int height = 512;
};

// "WxH" → Size; nullopt (with `error`) unless both are integers in [1, kMaxRenderSide].
std::optional<Size> parseSize(const std::string& text, std::string& error);

// `lab render --view NAME [--light N] [--palette viridis|grey] [--range LO,HI] [--legend]`: a view
// of the model instead of the lit render (core/scene/view_mode.h). A value view without --range
// finds its automatic range and prints it; --legend adds the legend band under the image
// (core/plots/legend.h). A view that does not apply to a preset is bad input.
struct RenderView {
    ViewMode mode = ViewMode::Lit;
    int light = 0; // an index into preset.lights (--light counts from 1)
    ValuePalette palette = ValuePalette::Viridis;
    std::optional<ValueRange> range;
    bool legend = false;
};

int runRender(const std::vector<std::filesystem::path>& presets, const std::filesystem::path& out, Size size,
              const RenderView& view = {});

// `lab render PRESET --sweep KEY=V1,... [--sweep KEY2=...] --out FILE.png`: one preset as a
// labelled grid (core/scene/sweep.h), each cell `size` and rendered as `lab render` renders a preset.
// With a value view, the cells share one range: the fixed one, or the union of their automatic
// ranges (printed), so that they compare.
int runSweep(const std::vector<std::filesystem::path>& presets, const std::vector<SweepAxis>& sweeps,
             const std::filesystem::path& out, Size size, const RenderView& view = {});

// `lab plot --figure KIND --svg/--png/--csv`: one figure (core/plots/figures.h) and where it goes; the
// incident angle is runPlot's.
struct FigureOutputs {
    FigureRequest request;
    FigureFiles files;
    std::optional<std::filesystem::path> compare; // --compare B.json: B in the lobe, albedo and slice figures
    bool any() const { return files.svg || files.png || files.csv; }
};

// `out` (the polar plot; none when empty) and `albedoOut` (core/plots/energy.h's albedoCsv), each written
// when given, and the figure's files.
int runPlot(const std::filesystem::path& preset, const std::filesystem::path& out,
            std::optional<float> incidentDeg, const std::optional<std::filesystem::path>& albedoOut = std::nullopt,
            const FigureOutputs& figure = {});

// `lab check` (check.cpp): each preset's render against <golden>/<name>.png, its sweep (a preset's
// `sweep`) cell by cell against <name>.sweep.png, its lobe CSV against <name>.plot.csv where
// that golden exists (every preset's with `plots`). A preset's `check` block overrides
// `tolerance` and `plotTolerance` for it. The report folder gets report.txt, index.html and the
// golden, actual and difference files of each failure.
struct CheckOptions {
    std::filesystem::path golden;
    std::filesystem::path report = "lab-check"; // where report.txt, index.html and the failures' files go
    std::optional<std::filesystem::path> junit;  // JUnit XML
    std::optional<std::filesystem::path> html;   // the HTML page again, elsewhere
    bool update = false;
    bool plots = false; // every preset's plot is checked (else those with a golden CSV)
    Size size;
    Size sweepSize{128, 128}; // each cell of a preset's sweep
    Tolerance tolerance;
    double plotTolerance = 1e-5;
};

int runCheck(const std::vector<std::filesystem::path>& presets, const CheckOptions& options);

// `lab exercise check EXERCISE ATTEMPT [--diff FILE.png]` (exercise_commands.cpp): 0 when the attempt
// (a preset) reaches the exercise's target (core/exercise/exercise.h), 1 when not yet (its score
// printed), 2 for bad input, an attempt that changed a field the exercise does not open included
// (each named by its JSON path). --diff writes the difference image of the two renders.
int runExerciseCheck(const std::filesystem::path& exercise, const std::filesystem::path& attempt,
                     const std::optional<std::filesystem::path>& diffOut);

// `lab share FILE --base URL [--qr FILE.png]` (exercise_commands.cpp): prints the link that opens the
// preset or exercise in the course's page (core/share/share_link.h: a shipped one by name, any
// other as what differs from the defaults) and writes its QR code (8 pixels a module). A link too
// long for a version-20 code is refused with --qr (exit 2), noted without.
int runShare(const std::filesystem::path& file, const std::string& base,
             const std::optional<std::filesystem::path>& qrOut, const std::filesystem::path& shippedPresets);

// `lab fit PRESET --brdf MODEL [--distribution D] --out FITTED.json` (fit_command.cpp): the preset
// with `request`'s model fitted to its specular reflection (core/plots/fit.h), everything else as it
// was (a glTF model's path made relative to FITTED's folder), written atomically; prints the
// parameters and the remaining error, and each bound that binds. 2 for bad input or nothing to fit.
int runFit(const std::filesystem::path& preset, const FitRequest& request, const std::filesystem::path& out);

// No GUI in this build (or no display): renders the preset (or the defaults) to a PNG in the
// temporary folder and prints its path.
int runPreview(const std::optional<std::filesystem::path>& preset);

} // namespace lab
