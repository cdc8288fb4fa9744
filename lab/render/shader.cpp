// shader.cpp — shader assembly, compilation and readable error logs.
#include "render/shader.h"

#include "core/io/safe_text.h"
#include "render/shader_sources.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <utility>

namespace lab {

namespace {

// The parts of an assembled stage start at these line numbers (`#line`), so a line in a
// compiler log tells which file it is in. Source-string numbers in `#line` would be neater, but
// Mesa reports every error as source 0. The stage body starts at 1, so its lines are its own.
struct Part {
    const char* name;
    long firstLine;
};
constexpr Part kPrelude{"prelude (precision and defines)", 100001};
constexpr Part kApi{"lighting_api.glsl", 200001};
constexpr Part kLighting{"lighting.glsl", 300001};
constexpr Part kView{"view.glsl", 400001};

std::string lineDirective(const Part& part) { return "\n#line " + std::to_string(part.firstLine) + "\n"; }

// The version line stays first (GLSL requires it); everything after it is numbered by its part.
std::string prelude(const std::vector<std::string>& defines) {
    std::string s = "#version 300 es";
    s += lineDirective(kPrelude);
    s += "precision highp float;\nprecision highp int;\n";
    for (const std::string& d : defines) {
        s += "#define " + d + "\n";
    }
    return s;
}

std::string assemble(std::string_view body, std::string_view lighting, const std::vector<std::string>& defines) {
    std::string s = prelude(defines);
    s += lineDirective(kApi);
    s += shaderSource("lighting_api.glsl");
    s += lineDirective(kLighting);
    s += lighting;
    s += lineDirective(kView);
    s += shaderSource("view.glsl");
    s += "\n#line 1\n";
    s += body;
    return s;
}

// "file:line" for a line number of the assembled source.
std::string place(long line, std::string_view bodyName) {
    for (const Part* part : {&kView, &kLighting, &kApi, &kPrelude}) {
        if (line >= part->firstLine) {
            return std::string(part->name) + ":" + std::to_string(line - part->firstLine + 1);
        }
    }
    return std::string(bodyName) + ":" + std::to_string(line);
}

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The digits of `line` from `at` as a number; `end` is left after them.
long readNumber(const std::string& line, std::size_t at, std::size_t& end) {
    long number = 0;
    for (end = at; end < line.size() && isDigit(line[end]); ++end) {
        number = std::min(number * 10 + (line[end] - '0'), 1'000'000'000L);
    }
    return number;
}

} // namespace

// Mesa writes "0:12(5): error: ...", ANGLE "ERROR: 0:12: ...", NVIDIA "0(12) : error ...".
void readableLog(std::string_view log, std::string_view bodyName, Diagnostics& out) {
    std::istringstream lines{std::string(log)};
    std::string line;
    std::size_t kept = 0, left = 0;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        if (line.empty()) {
            continue;
        }
        if (kept == kMaxLogLines) {
            ++left;
            continue;
        }
        ++kept;
        line = shortened(line, 1000);
        for (std::size_t at = line.find('0'); at != std::string::npos; at = line.find('0', at + 1)) {
            if ((at > 0 && line[at - 1] != ' ') || at + 2 >= line.size() || !isDigit(line[at + 2])) {
                continue;
            }
            std::size_t end = 0;
            if (line[at + 1] == ':') {
                long number = readNumber(line, at + 2, end);
                line.replace(at, end - at, place(number, bodyName));
                break;
            }
            if (line[at + 1] == '(') {
                long number = readNumber(line, at + 2, end);
                if (end < line.size() && line[end] == ')') {
                    line.replace(at, end + 1 - at, place(number, bodyName));
                    break;
                }
            }
        }
        out.push_back({"", "", line});
    }
    if (left > 0) {
        out.push_back({"", "", "(and " + std::to_string(left) + " more lines of the driver's log)"});
    }
}

namespace {

// The code point of the UTF-8 sequence at `text[at]` and its length in bytes; 0 and 1 where
// the bytes are not UTF-8.
std::pair<unsigned, std::size_t> decodeUtf8(std::string_view text, std::size_t at) {
    unsigned char lead = static_cast<unsigned char>(text[at]);
    std::size_t length = lead >= 0xF0 && lead < 0xF8 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 && lead < 0xE0 ? 2 : 0;
    if (length == 0 || lead >= 0xF8 || at + length > text.size()) {
        return {0, 1};
    }
    unsigned code = lead & (0x7Fu >> length);
    for (std::size_t k = 1; k < length; ++k) {
        unsigned char c = static_cast<unsigned char>(text[at + k]);
        if ((c & 0xC0) != 0x80) {
            return {0, 1};
        }
        code = (code << 6) | (c & 0x3Fu);
    }
    return {code, length};
}

// The first non-ASCII character of each line of `text`, as diagnostics naming `file`.
void findNonAscii(std::string_view file, std::string_view text, Diagnostics& out, int& budget) {
    int lineNumber = 1;
    int column = 1;
    bool reported = false; // this line's first character is reported, the rest are not
    for (std::size_t at = 0; at < text.size() && budget > 0;) {
        char c = text[at];
        if (c == '\n') {
            ++lineNumber;
            column = 1;
            reported = false;
            ++at;
            continue;
        }
        if (static_cast<unsigned char>(c) < 0x80) {
            ++column;
            ++at;
            continue;
        }
        auto [code, length] = decodeUtf8(text, at);
        if (!reported) {
            char what[96];
            if (code != 0) {
                std::snprintf(what, sizeof what, "non-ASCII character U+%04X '%.*s'", code, static_cast<int>(length),
                              text.data() + at);
            } else {
                std::snprintf(what, sizeof what, "byte 0x%02X (not ASCII, not UTF-8)", static_cast<unsigned char>(c));
            }
            out.push_back({"", "",
                           std::string(file) + ":" + std::to_string(lineNumber) + ": column " + std::to_string(column) +
                               ": " + what + "; GLSL ES and WebGL accept only ASCII, in comments too"});
            reported = true;
            --budget;
        }
        ++column;
        at += length;
    }
}

// The info log of a shader or a program (`getiv`, `getLog`: glGetShaderiv/glGetShaderInfoLog or
// the program versions), without its terminating NUL.
template <typename GetIv, typename GetLog>
std::string infoLog(GLuint object, GetIv getiv, GetLog getLog) {
    GLint length = 0;
    getiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    getLog(object, length, nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

GLuint compile(GLenum type, const std::string& source, std::string_view bodyName, Diagnostics& out) {
    GLuint shader = glCreateShader(type);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::size_t before = out.size();
        readableLog(infoLog(shader, glGetShaderiv, glGetShaderInfoLog), bodyName, out);
        if (out.size() == before) {
            out.push_back({std::string(bodyName), "", "does not compile (the driver gave no log)"});
        }
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

} // namespace

std::string_view shaderSource(std::string_view name) {
    for (const EmbeddedShader& file : kEmbeddedShaders) {
        if (file.name == name) {
            return file.text;
        }
    }
    return {};
}

StageSources builtinStageSources() {
    return {std::string(shaderSource("lit.vert")), std::string(shaderSource("lit.frag")),
            std::string(shaderSource("lighting.glsl"))};
}

bool checkAscii(const StageSources& sources, Diagnostics& diagnostics, int maxLines) {
    std::size_t before = diagnostics.size();
    int budget = maxLines;
    findNonAscii("lit.vert", sources.vertex, diagnostics, budget);
    findNonAscii("lit.frag", sources.fragment, diagnostics, budget);
    findNonAscii("lighting.glsl", sources.lighting, diagnostics, budget);
    return diagnostics.size() == before;
}

namespace {

// Compiles the two assembled stages (their bodies named `vertexName`, `fragmentName` in the
// log) and links them.
std::optional<GLuint> compileAndLink(const std::string& vertex, const std::string& fragment, std::string_view vertexName,
                                     std::string_view fragmentName, Diagnostics& diagnostics) {
    // Both stages include lighting.glsl: an error there is in both logs, and reported once.
    Diagnostics log;
    GLuint vs = compile(GL_VERTEX_SHADER, vertex, vertexName, log);
    GLuint fs = compile(GL_FRAGMENT_SHADER, fragment, fragmentName, log);
    for (Diagnostic& x : log) {
        auto same = [&](const Diagnostic& y) { return y.file == x.file && y.message == x.message; };
        if (std::find_if(diagnostics.begin(), diagnostics.end(), same) == diagnostics.end()) {
            diagnostics.push_back(std::move(x));
        }
    }
    if (!vs || !fs) {
        if (vs) {
            glDeleteShader(vs);
        }
        if (fs) {
            glDeleteShader(fs);
        }
        return std::nullopt;
    }
    GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        diagnostics.push_back({"program", "", "does not link: " + infoLog(program, glGetProgramiv, glGetProgramInfoLog)});
        glDeleteProgram(program);
        return std::nullopt;
    }
    return program;
}

} // namespace

std::optional<GLuint> buildProgram(const StageSources& sources, const std::vector<std::string>& defines,
                                   Diagnostics& diagnostics) {
    if (!checkAscii(sources, diagnostics)) {
        return std::nullopt;
    }
    return compileAndLink(assemble(sources.vertex, sources.lighting, defines),
                          assemble(sources.fragment, sources.lighting, defines), "lit.vert", "lit.frag", diagnostics);
}

std::optional<GLuint> buildPlainProgram(std::string_view vertexFile, std::string_view fragmentFile,
                                        Diagnostics& diagnostics) {
    auto bare = [](std::string_view body) { return prelude({}) + "\n#line 1\n" + std::string(body); };
    return compileAndLink(bare(shaderSource(vertexFile)), bare(shaderSource(fragmentFile)), vertexFile, fragmentFile,
                          diagnostics);
}

} // namespace lab
