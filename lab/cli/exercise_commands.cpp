// exercise_commands.cpp — `lab exercise check` and `lab share`.
#include "cli/commands.h"

#include "cli/command_kit.h"
#include "cli/output.h"
#include "cli/settings.h"
#include "core/exercise/exercise.h"
#include "core/exercise/score.h"
#include "core/io/file_io.h"
#include "core/io/safe_text.h"
#include "core/share/qr_code.h"
#include "core/share/share_link.h"

namespace lab {

namespace fs = std::filesystem;

namespace {

// An exercise's file and the glTF models its start and target name (cli/run_files.h).
void addExerciseInputs(RunFiles& files, const LoadedExercise& exercise) {
    files.input(exercise.file, "the exercise " + exercise.file.string());
    for (const Preset* p : {&exercise.exercise.start, &exercise.exercise.target}) {
        addModelInput(files, *p, exercise.folder(), exercise.file);
    }
}

// The file's name when it is one of the shipped presets (or exercises) itself: the link names it.
std::optional<std::string> shippedName(const fs::path& file, const fs::path& folder) {
    std::error_code ec;
    const std::optional<fs::path> absolute = absolutePath(file);
    if (folder.empty() || !absolute || !fs::is_directory(folder, ec) || !fs::equivalent(absolute->parent_path(), folder, ec)) {
        return std::nullopt;
    }
    return file.stem().string();
}

} // namespace

int runExerciseCheck(const fs::path& exerciseFile, const fs::path& attemptFile, const std::optional<fs::path>& diffOut) {
    Diagnostics diagnostics;
    std::optional<LoadedExercise> exercise = loadExercise(exerciseFile, diagnostics);
    std::optional<LoadedPreset> attempt;
    if (exercise) {
        attempt = loadPreset(attemptFile, diagnostics);
    }
    if (!exercise || !attempt) {
        printDiagnostics(diagnostics);
        return kExitBadInput;
    }
    std::vector<std::string> locked =
        lockedChanges(exercise->exercise, attempt->preset, exercise->folder(), attempt->folder());
    if (!locked.empty()) {
        std::string open;
        for (const std::string& o : exercise->exercise.open) {
            open += (open.empty() ? "" : ", ") + o;
        }
        for (const std::string& field : locked) {
            print(stderr, attemptFile.string() + ": " + field + ": changed from the exercise's start, but the exercise "
                          "does not open this field (open: " + open + ")\n");
        }
        return kExitBadInput;
    }
    RunFiles files;
    addExerciseInputs(files, *exercise);
    addPresetInputs(files, *attempt, "the attempt");
    if (diffOut) {
        files.output(*diffOut, "--diff");
    }
    if (!filesUsable(files, "lab exercise check")) {
        return kExitBadInput;
    }
    Gpu gpu;
    if (!gpu.start()) {
        return kExitFailure;
    }
    const Exercise& e = exercise->exercise;
    // The attempt, the target and the start (d(start), core/exercise/score.h), as the lab renders them.
    LoadedPreset tried{attemptAsScored(e, attempt->preset), attempt->file};
    LoadedPreset target{targetAsScored(e), exercise->file};
    LoadedPreset start{startAsScored(e), exercise->file};
    std::optional<Image> a = gpu.renderer.render(tried, kExerciseRenderSide, kExerciseRenderSide, diagnostics);
    std::optional<Image> t = a ? gpu.renderer.render(target, kExerciseRenderSide, kExerciseRenderSide, diagnostics)
                               : std::nullopt;
    std::optional<Image> s = t ? gpu.renderer.render(start, kExerciseRenderSide, kExerciseRenderSide, diagnostics)
                               : std::nullopt;
    if (!a || !t || !s) {
        printDiagnostics(diagnostics);
        return kExitFailure;
    }
    ExerciseScore score = scoreExercise(e, attempt->preset, *a, *t, startDifference(e, *s, *t));
    print(stdout, attemptFile.string() + ": " + score.summary() + "\n");
    if (diffOut) {
        std::string error;
        if (!writePng(score.image.diff, *diffOut, error)) { // checked above: a full disk, say
            print(stderr, "lab exercise check: --diff " + diffOut->string() + " was not written: " + error + "\n");
            return kExitBadInput;
        }
    }
    return score.solved ? kExitOk : kExitFailure;
}


namespace {

// A link carries the scene, not its model file: only the shipped presets' and exercises' glTF models
// (which the course page has) can be linked. False, with the message, for another file that names one.
bool modelsLinkable(const fs::path& file, bool shipped, std::initializer_list<std::pair<const char*, const Preset*>> scenes) {
    for (const auto& [where, preset] : scenes) {
        if (!shipped && !preset->model.gltf.empty()) {
            print(stderr, file.string() + ": " + where + "model.gltf: a link carries the scene, not its model file; only the "
                          "shipped presets' glTF models can be linked (publish the model with the course page and make "
                          "it a shipped preset)\n");
            return false;
        }
    }
    return true;
}

} // namespace

int runShare(const fs::path& file, const std::string& base, const std::optional<fs::path>& qrOut,
             const fs::path& shippedPresets) {
    if (std::string problem = shareBaseProblem(base); !problem.empty()) {
        print(stderr, "lab share: --base: " + problem + "\n");
        return kExitBadInput;
    }
    std::string error;
    std::optional<std::string> text = readFile(file, kMaxExerciseBytes, error);
    if (!text) {
        print(stderr, file.string() + ": " + error + "\n");
        return kExitBadInput;
    }
    Diagnostics diagnostics;
    std::string fragment;
    RunFiles files;
    if (isExerciseText(*text)) {
        std::optional<LoadedExercise> exercise = loadExercise(file, diagnostics);
        if (!exercise) {
            printDiagnostics(diagnostics);
            return kExitBadInput;
        }
        std::optional<std::string> shipped = shippedName(file, shippedPresets / "exercises");
        const Exercise& e = exercise->exercise;
        if (!modelsLinkable(file, shipped.has_value(), {{"start.", &e.start}, {"target.", &e.target}})) {
            return kExitBadInput;
        }
        addExerciseInputs(files, *exercise);
        fragment = exerciseLink(e, shipped);
    } else {
        std::optional<LoadedPreset> preset = loadPreset(file, diagnostics);
        if (!preset) {
            printDiagnostics(diagnostics);
            return kExitBadInput;
        }
        std::optional<std::string> shipped = shippedName(file, shippedPresets);
        if (!modelsLinkable(file, shipped.has_value(), {{"", &preset->preset}})) {
            return kExitBadInput;
        }
        addPresetInputs(files, *preset);
        fragment = presetLink(preset->preset, shipped);
    }
    if (qrOut) {
        files.output(*qrOut, "--qr");
    }
    if (!filesUsable(files, "lab share")) {
        return kExitBadInput;
    }
    if (fragment.size() > kMaxLinkChars) {
        print(stderr, file.string() + ": the link would be " + std::to_string(fragment.size()) + " characters, more than the " +
                          std::to_string(kMaxLinkChars) + " a link may have (the page refuses longer ones): shorten "
                          "the description and instructions, or publish the file with the course page and link it by "
                          "name (#preset=NAME, #exercise=NAME)\n");
        return kExitBadInput;
    }
    const std::string url = shareUrl(base, fragment);
    std::optional<QrCode> code = encodeQr(url, error);
    if (!code) {
        std::string why = file.string() + ": the link is too long for a QR code that can be read across a room: " + error +
                          ". Shorten the description and instructions, or publish the file with the course page and "
                          "link it by name (#preset=NAME, #exercise=NAME)\n";
        if (qrOut) {
            print(stderr, why);
            return kExitBadInput;
        }
        print(stderr, "lab share: note: " + why);
    }
    print(stdout, url + "\n");
    if (qrOut && code) {
        if (!writePng(qrImage(*code, 8), *qrOut, error)) { // checked above: a full disk, say
            print(stderr, "lab share: --qr " + qrOut->string() + " was not written: " + error + "\n");
            return kExitBadInput;
        }
        print(stderr, qrOut->string() + ": QR code version " + std::to_string(code->version) + " (" +
                          std::to_string(code->size) + "x" + std::to_string(code->size) + " modules), " +
                          std::to_string(url.size()) + " bytes\n");
    }
    return kExitOk;
}

} // namespace lab
