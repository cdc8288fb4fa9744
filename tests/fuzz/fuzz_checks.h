// fuzz_checks.h — what "the lab behaved" means for each untrusted input path.
//
// Each check runs one input through the lab and returns "" when the outcome is acceptable —
// a result that satisfies the invariants below, or a refusal with at least one message — and a
// description of the failure otherwise. The libFuzzer targets (fuzz_*.cpp) abort on a failure;
// tests/fuzz_regression_test.cpp runs the same checks over the seeds and every crash found.
// (A crash, hang or sanitizer report is a failure by itself.)
#pragma once

#include "cli/command_line.h"
#include "core/gltf.h"
#include "core/preset.h"
#include "render/offscreen.h" // kMaxRenderSide
#include "core/file_io.h"

#include <cmath>
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

// Command-line arguments, one per line (at most 64): parsed, never run.
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
    if (line.command != CommandLine::Command::Lab && line.presets.empty()) {
        return "a command without its preset";
    }
    for (const Size& s : {line.size, line.check.size}) {
        if (s.width < 1 || s.height < 1 || s.width > kMaxRenderSide || s.height > kMaxRenderSide) {
            return "a size outside the limits was accepted";
        }
    }
    if (line.incidentDeg && !(*line.incidentDeg >= -90.0f && *line.incidentDeg <= 90.0f)) {
        return "an incident angle outside [-90, 90] was accepted";
    }
    return "";
}

} // namespace lab::fuzz
