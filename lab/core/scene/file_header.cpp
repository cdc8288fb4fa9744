// file_header.cpp — the format and version check (file_header.h).
#include "core/scene/file_header.h"

#include "core/io/safe_text.h"

#include <nlohmann/json.hpp>

namespace lab {

std::optional<HeaderProblem> fileHeaderProblem(const nlohmann::ordered_json& object, const FileFormat& expected) {
    const std::string quoted = "\"" + std::string(expected.format) + "\"";
    auto format = object.find("format");
    if (format == object.end()) {
        return HeaderProblem{"format", "missing; expected " + quoted};
    }
    if (!format->is_string() || format->get<std::string>() != expected.format) {
        std::string got = shortened(format->dump(), 80);
        std::string hint;
        for (const FileFormat& other : {kPresetFile, kExerciseFile, kDeckFile}) {
            if (other.format != expected.format && format->is_string() && format->get<std::string>() == other.format) {
                hint = " (this is " + std::string(other.what) + ", not " + std::string(expected.what) + ")";
            }
        }
        return HeaderProblem{"format", "expected " + quoted + ", got " + got + hint};
    }
    const std::string newest = std::to_string(expected.version);
    auto version = object.find("version");
    if (version == object.end()) {
        return HeaderProblem{"version", "missing; expected " + newest};
    }
    if (!version->is_number_integer() && !version->is_number_unsigned()) {
        return HeaderProblem{"version", "expected an integer, got " + shortened(version->dump(), 40)};
    }
    if (version->get<double>() > expected.version) {
        return HeaderProblem{"version", "version " + version->dump() + " is newer than this program reads (" + newest +
                                            "); update Lighting Lab"};
    }
    if (version->get<double>() < 1) {
        return HeaderProblem{"version", "expected " + newest + ", got " + version->dump()};
    }
    return std::nullopt;
}

} // namespace lab
