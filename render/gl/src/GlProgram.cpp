#include "GlProgram.h"

#include "marbler/Error.h"
#include "marbler/gl/ShaderSource.h"

#include <algorithm>
#include <cstring>

namespace marbler::gl {
namespace {

const char* stageName(GLenum type) {
    switch (type) {
    case GL_VERTEX_SHADER:
        return "vertex";
    case GL_FRAGMENT_SHADER:
        return "fragment";
    case GL_COMPUTE_SHADER:
        return "compute";
    case GL_GEOMETRY_SHADER:
        return "geometry";
    default:
        return "shader";
    }
}

std::string shaderLog(QOpenGLFunctions_4_3_Core& gl, GLuint shader) {
    GLint length = 0;
    gl.glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    gl.glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

std::string programLog(QOpenGLFunctions_4_3_Core& gl, GLuint program) {
    GLint length = 0;
    gl.glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    gl.glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

} // namespace

GLuint buildProgram(QOpenGLFunctions_4_3_Core& gl, const std::string& name,
                    const std::vector<ShaderStage>& stages) {
    GLuint program = gl.glCreateProgram();
    std::vector<GLuint> shaders;
    auto cleanup = [&] {
        for (GLuint s : shaders)
            gl.glDeleteShader(s);
    };
    for (const ShaderStage& stage : stages) {
        GLuint shader = gl.glCreateShader(stage.type);
        shaders.push_back(shader);
        const char* text = stage.source.c_str();
        gl.glShaderSource(shader, 1, &text, nullptr);
        gl.glCompileShader(shader);
        GLint ok = GL_FALSE;
        gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            std::string log = shaderLog(gl, shader);
            cleanup();
            gl.glDeleteProgram(program);
            throw RuntimeFailure("GL: the " + std::string(stageName(stage.type)) + " shader of " + name +
                                 " does not compile:\n" + log + "\n--- assembled source ---\n" +
                                 numberLines(stage.source));
        }
        gl.glAttachShader(program, shader);
    }
    gl.glLinkProgram(program);
    GLint ok = GL_FALSE;
    gl.glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string log = programLog(gl, program);
        std::string sources;
        for (const ShaderStage& stage : stages)
            sources +=
                "--- " + std::string(stageName(stage.type)) + " source ---\n" + numberLines(stage.source);
        cleanup();
        gl.glDeleteProgram(program);
        throw RuntimeFailure("GL: program " + name + " does not link:\n" + log + "\n" + sources);
    }
    for (GLuint s : shaders)
        gl.glDetachShader(program, s);
    cleanup();
    return program;
}

GlProgram::GlProgram(QOpenGLFunctions_4_3_Core& gl, const std::string& name,
                     const std::vector<ShaderStage>& stages)
    : mGl(&gl)
    , mId(buildProgram(gl, name, stages)) {}

GLint GlProgram::uniform(const char* name) const {
    return mGl->glGetUniformLocation(mId, name);
}

void GlProgram::release() {
    if (mGl && mId) mGl->glDeleteProgram(mId);
    mId = 0;
}

} // namespace marbler::gl
