// shader.cpp — shader assembly, compilation and readable error logs.
#include "render/shader.h"

#include "render/shader_sources.h"

#include <cctype>
#include <sstream>

namespace lab {

namespace {

// The parts of an assembled stage start at these line numbers (`#line`), so a line in a
// compiler log tells which file it is in. Source-string numbers in `#line` would be neater, but
// Mesa reports every error as source 0.
constexpr int kApiFirstLine = 100001;
constexpr int kLightingFirstLine = 200001;

std::string assemble(std::string_view body, const std::vector<std::string>& defines) {
    std::string s = "#version 300 es\nprecision highp float;\nprecision highp int;\n";
    for (const std::string& d : defines) {
        s += "#define " + d + "\n";
    }
    s += "#line " + std::to_string(kApiFirstLine) + "\n";
    s += shaderSource("lighting_api.glsl");
    s += "\n#line " + std::to_string(kLightingFirstLine) + "\n";
    s += shaderSource("lighting.glsl");
    s += "\n#line 1\n";
    s += body;
    return s;
}

// "file:line" for a line number of the assembled source.
std::string place(long line, std::string_view bodyName) {
    if (line >= kLightingFirstLine) {
        return "lighting.glsl:" + std::to_string(line - kLightingFirstLine + 1);
    }
    if (line >= kApiFirstLine) {
        return "lighting_api.glsl:" + std::to_string(line - kApiFirstLine + 1);
    }
    return std::string(bodyName) + ":" + std::to_string(line);
}

// Mesa writes "0:12(5): error: ...", ANGLE "ERROR: 0:12: ...". Rewrite "0:12" as "lit.frag:12".
void readableLog(const std::string& log, std::string_view bodyName, Diagnostics& out) {
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty()) {
            continue;
        }
        std::size_t at = line.find("0:");
        if (at != std::string::npos && (at == 0 || line[at - 1] == ' ') && at + 2 < line.size() &&
            std::isdigit(static_cast<unsigned char>(line[at + 2]))) {
            std::size_t end = at + 2;
            long number = 0;
            while (end < line.size() && std::isdigit(static_cast<unsigned char>(line[end]))) {
                number = number * 10 + (line[end++] - '0');
            }
            line.replace(at, end - at, place(number, bodyName));
        }
        out.push_back({"", "", line});
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
    return {std::string(shaderSource("lit.vert")), std::string(shaderSource("lit.frag"))};
}

std::optional<GLuint> buildProgram(const StageSources& sources, const std::vector<std::string>& defines,
                                   Diagnostics& diagnostics) {
    GLuint vs = compile(GL_VERTEX_SHADER, assemble(sources.vertex, defines), "lit.vert", diagnostics);
    GLuint fs = compile(GL_FRAGMENT_SHADER, assemble(sources.fragment, defines), "lit.frag", diagnostics);
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

} // namespace lab
