// diagnostics.h — errors as values with a place.
//
// Every loader in lab/core reports problems as Diagnostics instead of throwing or printing:
// each names the file, the place inside it (a JSON path such as `lights[2].attenuation`, a
// glTF object such as `accessors[3]`, or a line and column) and what was expected. The caller
// decides how to show them: stderr for the command line, a popup in the GUI, the page on the web.
#pragma once

#include <string>
#include <vector>

namespace lab {

struct Diagnostic {
    std::string file;    // as the user named it, e.g. "red.json"; may be empty
    std::string where;   // JSON path or object inside the file; may be empty
    std::string message; // what is wrong and what was expected

    // "file: where: message", leaving out the empty parts.
    std::string str() const {
        std::string s;
        for (const std::string* part : {&file, &where}) {
            if (!part->empty()) {
                s += *part;
                s += ": ";
            }
        }
        return s + message;
    }
};

using Diagnostics = std::vector<Diagnostic>;

// Something the user asked for that could not be done: a title, and why.
struct Problem {
    std::string title; // "Cannot open red.json (nothing was changed)"
    Diagnostics diagnostics;
};

// All diagnostics, one per line.
inline std::string toString(const Diagnostics& diagnostics) {
    std::string s;
    for (const Diagnostic& d : diagnostics) {
        s += d.str();
        s += '\n';
    }
    return s;
}

// The title, then every diagnostic, one per line.
inline std::string toString(const Problem& problem) { return problem.title + "\n" + toString(problem.diagnostics); }

} // namespace lab
