// run_files.h — what one command reads and what it will write, checked before it writes anything.
//
// A command names its inputs (the presets, exercises and attempts it reads, their glTF models, the
// goldens it compares with) and its outputs, each with the flag that named it. problem() is ""
// when every output can be written without touching an input, else one line naming the flag, the
// file and why; the command then exits with status 2 having written nothing:
//   - an output that is an input: the same file once links are resolved (core/io/paths.h
//     sameFile), `lab share p.json --qr p.json`, `lab check ... --junit g/p.png`. The only output
//     that may be an input is a golden `lab check --update` was asked to write, which replaces
//     itself (replacing());
//   - two outputs on one file (the later would replace the earlier);
//   - an output that cannot be written (core/io/file_io.h writeProblem): a folder, a device, a FIFO,
//     a folder that does not exist or cannot be written in. Outputs in a folder the command makes
//     first (`lab check`'s report folder) are checked by the command for that folder.
// It does not write, create folders or print: the command does, after asking.
#pragma once

#include "core/io/paths.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lab {

class RunFiles {
public:
    // A file the run reads; `what` names it in a message: "the preset p.json", "the attempt a.json".
    void input(const std::filesystem::path& file, std::string what);
    // A file the run writes, named by `flag` ("--qr", "--report"); `folderMade` when its folder is
    // made by the command before writing (then only the file itself is checked for writing).
    void output(const std::filesystem::path& file, std::string flag, bool folderMade = false);
    // A golden that `lab check --update` writes: it may be the input of the same path (itself).
    void replacing(const std::filesystem::path& file, std::string flag, bool folderMade = false);

    // "" or the first problem: "--qr p.json: is the preset p.json, which this run reads".
    std::string problem() const;

private:
    struct Entry {
        std::filesystem::path file;
        std::string label; // what, for an input; the flag, for an output
        FileIdentity id;
        bool folderMade = false;
        bool replaces = false;
    };
    std::vector<Entry> inputs_, outputs_;
};

} // namespace lab
