// field_path.cpp — the field path grammar (field_path.h).
#include "core/scene/field_path.h"

#include "core/io/safe_text.h"

namespace lab {

namespace {

bool nameChar(char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; }

} // namespace

std::optional<std::vector<PathStep>> parseFieldPath(std::string_view path) {
    std::vector<PathStep> steps;
    std::size_t i = 0;
    while (i < path.size()) {
        std::size_t start = i;
        while (i < path.size() && nameChar(path[i])) {
            ++i;
        }
        if (i == start) {
            return std::nullopt;
        }
        steps.push_back({std::string(path.substr(start, i - start))});
        while (i < path.size() && path[i] == '[') {
            std::size_t close = path.find(']', i);
            if (close == std::string_view::npos || close == i + 1 || close - i > 4) {
                return std::nullopt;
            }
            std::size_t index = 0;
            for (std::size_t k = i + 1; k < close; ++k) {
                if (path[k] < '0' || path[k] > '9') {
                    return std::nullopt;
                }
                index = index * 10 + static_cast<std::size_t>(path[k] - '0');
            }
            steps.push_back({"", index});
            i = close + 1;
        }
        if (i < path.size()) {
            if (path[i] != '.' || i + 1 == path.size()) {
                return std::nullopt;
            }
            ++i;
        }
    }
    if (steps.empty()) {
        return std::nullopt;
    }
    return steps;
}

std::string canonicalPath(std::string_view path) {
    std::optional<std::vector<PathStep>> steps = parseFieldPath(path);
    if (!steps) {
        return std::string(path);
    }
    std::string out;
    for (const PathStep& s : *steps) {
        out += s.isIndex() ? "[" + std::to_string(s.index) + "]" : (out.empty() ? "" : ".") + s.name;
    }
    return out;
}

std::string pathInMessage(std::string_view path) {
    return path.size() <= 120 && parseFieldPath(path) ? std::string(path) : inQuotes(path);
}

bool covers(std::string_view prefix, std::string_view path) {
    if (!path.starts_with(prefix)) {
        return false;
    }
    return path.size() == prefix.size() || path[prefix.size()] == '.' || path[prefix.size()] == '[';
}

} // namespace lab
