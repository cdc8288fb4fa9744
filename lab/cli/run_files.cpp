// run_files.cpp — a command's inputs and outputs, checked before anything is written.
#include "cli/run_files.h"

#include "core/io/file_io.h"

#include <map>

namespace lab {

namespace fs = std::filesystem;

void RunFiles::input(const fs::path& file, std::string what) {
    inputs_.push_back({file, std::move(what), fileIdentity(file)});
}

void RunFiles::output(const fs::path& file, std::string flag, bool folderMade) {
    outputs_.push_back({file, std::move(flag), fileIdentity(file), folderMade});
}

void RunFiles::replacing(const fs::path& file, std::string flag, bool folderMade) {
    outputs_.push_back({file, std::move(flag), fileIdentity(file), folderMade, true});
}

std::string RunFiles::problem() const {
    std::map<FileIdentity, const Entry*> read, written;
    for (const Entry& in : inputs_) {
        read.emplace(in.id, &in);
    }
    for (const Entry& out : outputs_) {
        const std::string named = out.label + " " + out.file.string() + ": ";
        std::error_code ec;
        std::string why = out.folderMade ? (fs::is_directory(out.file, ec) ? "is a folder" : "") : writeProblem(out.file);
        if (!why.empty()) {
            return named + why;
        }
        if (auto it = read.find(out.id); it != read.end()) {
            const Entry& in = *it->second;
            bool itself = out.replaces && absolutePath(out.file) && absolutePath(out.file) == absolutePath(in.file);
            if (!itself) {
                return named + "is " + in.label + ", which this run reads";
            }
        }
        if (auto [it, fresh] = written.emplace(out.id, &out); !fresh) {
            return named + it->second->label + " writes that file too" +
                   (it->second->file == out.file ? "" : " (as " + it->second->file.string() + ")");
        }
    }
    return "";
}

} // namespace lab
