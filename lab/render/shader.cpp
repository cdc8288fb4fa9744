// shader.cpp — shader assembly, compilation and readable error logs.
#include "render/shader.h"

#include "render/shader_sources.h"

#include <array>
#include <sstream>

namespace lab {

namespace {

// Source-string numbers used in `#line 1 N`, so logs can be mapped back to names.
constexpr std::array<std::string_view, 4> kPartNames{"(prelude)", "lighting_api.glsl", "lighting.glsl", ""};

std::string assemble(std::string_view body, std::string_view bodyName, const std::vector<std::string>& defines) {
    std::string s = "#version 300 es\nprecision highp float;\nprecision highp int;\n";
    for (const std::string& d : defines) {
        s += "#define " + d + "\n";
    }
    s += "#line 1 1\n";
    s += shaderSource("lighting_api.glsl");
    s += "\n#line 1 2\n";
    s += shaderSource("lighting.glsl");
    s += "\n#line 1 3\n";
    s += body;
    (void)bodyName;
    return s;
}

// Mesa writes "3:12(5): error: ..."; ANGLE and others "ERROR: 3:12: ...". Replace the
// source-string number with the file name.
std::string readableLog(const std::string& log, std::string_view bodyName, const std::string& stage,
                        Diagnostics& out) {
    std::istringstream lines(log);
    std::string line, all;
    while (std::getline(lines, line)) {
        if (line.empty()) {
            continue;
        }
        for (std::size_t i = 0; i < 4; ++i) {
            std::string number = std::to_string(i) + ":";
            std::size_t at = line.find(number);
            if (at != std::string::npos && (at == 0 || line[at - 1] == ' ')) {
                std::string name(i == 3 ? bodyName : kPartNames[i]);
                line.replace(at, number.size(), name + ":");
                break;
            }
        }
        out.push_back({stage, "", line});
        all += line + "\n";
    }
    return all;
}

GLuint compile(GLenum type, const std::string& source, std::string_view bodyName, Diagnostics& out) {
    GLuint shader = glCreateShader(type);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
        std::size_t before = out.size();
        readableLog(log, bodyName, std::string(bodyName), out);
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
    GLuint vs = compile(GL_VERTEX_SHADER, assemble(sources.vertex, "lit.vert", defines), "lit.vert", diagnostics);
    GLuint fs = compile(GL_FRAGMENT_SHADER, assemble(sources.fragment, "lit.frag", defines), "lit.frag", diagnostics);
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
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program, length, nullptr, log.data());
        log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
        diagnostics.push_back({"program", "", "does not link: " + log});
        glDeleteProgram(program);
        return std::nullopt;
    }
    return program;
}

} // namespace lab
