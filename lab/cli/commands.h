// commands.h — the headless commands behind `lab render`, `lab plot` and `lab check`.
//
// Each returns the process exit status: 0 success, 2 bad input (a message on stderr naming the
// file and place), 1 an internal failure or, for `check`, an image that differs or a missing
// golden. Output files are written atomically. Nothing here parses argv (main.cpp does).
#pragma once

#include "core/image.h"

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

int runRender(const std::vector<std::filesystem::path>& presets, const std::filesystem::path& out, Size size);

// `out` (the polar plot; none when empty) and `albedoOut` (core/energy.h's albedoCsv), each written
// when given.
int runPlot(const std::filesystem::path& preset, const std::filesystem::path& out,
            std::optional<float> incidentDeg, const std::optional<std::filesystem::path>& albedoOut = std::nullopt);

struct CheckOptions {
    std::filesystem::path golden;
    std::filesystem::path report = "lab-check"; // where report.txt, actual and diff images go
    bool update = false;
    Size size;
    Tolerance tolerance;
};

int runCheck(const std::vector<std::filesystem::path>& presets, const CheckOptions& options);

// No GUI in this build (or no display): renders the preset (or the defaults) to a PNG in the
// temporary folder and prints its path.
int runPreview(const std::optional<std::filesystem::path>& preset);

} // namespace lab
