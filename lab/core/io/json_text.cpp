// json_text.cpp — nesting depth and line/column positions of JSON text.
#include "core/io/json_text.h"

namespace lab {

bool jsonNestingWithin(std::string_view text, int maxDepth) {
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            if (c == '\\') {
                ++i;
            } else if (c == '"') {
                inString = false;
            }
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > maxDepth) {
                return false;
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return true;
}

std::optional<Diagnostic> jsonTextProblem(std::string_view text, const std::string& file, int maxDepth) {
    if (!jsonNestingWithin(text, maxDepth)) {
        return Diagnostic{file, "", "JSON nested deeper than " + std::to_string(maxDepth) + " levels"};
    }
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
        return Diagnostic{file, lineColumn(text, nul), "a NUL byte, which JSON text never holds (inside a string it is written \\u0000)"};
    }
    return std::nullopt;
}

std::string parseErrorDetail(std::string_view what) {
    const std::size_t place = what.find("parse error");
    const std::size_t colon = place == std::string_view::npos ? place : what.find(": ", place);
    return std::string(colon == std::string_view::npos ? what : what.substr(colon + 2));
}

std::string lineColumn(std::string_view text, std::size_t offset) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

} // namespace lab
