// fit_command.cpp — `lab fit`: one reflection model fitted to a preset's specular lobe (core/plots/fit.h).
#include "cli/commands.h"

#include "cli/command_kit.h"
#include "cli/output.h"
#include "core/io/paths.h"
#include "core/plots/fit.h"

namespace lab {

namespace fs = std::filesystem;

int runFit(const fs::path& presetFile, const FitRequest& request, const fs::path& out) {
    Diagnostics diagnostics;
    std::optional<LoadedPreset> preset = loadPreset(presetFile, diagnostics);
    if (!preset) {
        printDiagnostics(diagnostics);
        return kExitBadInput;
    }
    RunFiles files;
    addPresetInputs(files, *preset);
    files.output(out, "--out");
    if (!filesUsable(files, "lab fit")) {
        return kExitBadInput;
    }
    // A glTF model without a camera (or lights) in its file is framed, as `lab render` and the GUI
    // frame it: the fit keeps that framing, which is the view of A it is compared with.
    if (!frameForCells(*preset, diagnostics)) {
        printDiagnostics(diagnostics);
        return kExitBadInput;
    }
    std::string error;
    std::optional<FitResult> fit = fitSpecular(preset->preset, request, error);
    if (!fit) {
        print(stderr, "lab fit: " + presetFile.string() + ": " + error + "\n");
        return kExitBadInput;
    }
    // A glTF model is named relative to the preset's folder: relative to the output's now.
    Preset& fitted = fit->fitted;
    if (!fitted.model.gltf.empty()) {
        const std::optional<fs::path> outFile = absolutePath(out), presetFolder = absolutePath(preset->folder());
        if (!outFile || !presetFolder) { // (filesUsable has refused a removed working folder for --out)
            print(stderr, "lab fit: the working folder has been removed: name the preset and --out from the root\n");
            return kExitBadInput;
        }
        const fs::path outFolder = outFile->parent_path();
        std::optional<fs::path> relative = relativeInside(outFolder, *presetFolder / fitted.model.gltf);
        if (!relative) {
            print(stderr, "lab fit: --out: the model " + fitted.model.gltf + " would be outside " + outFolder.string() +
                              "; write the fitted preset in a folder that holds its model\n");
            return kExitBadInput;
        }
        fitted.model.gltf = relative->generic_string();
    }
    if (!savePreset(fitted, out, diagnostics)) {
        printDiagnostics(diagnostics);
        return kExitBadInput;
    }
    print(stdout, fit->summary() + "\n");
    for (const std::string& bound : fit->boundsThatBind()) {
        print(stdout, "  bound: " + bound + "\n");
    }
    print(stdout, out.string() + "\n");
    return kExitOk;
}

} // namespace lab
