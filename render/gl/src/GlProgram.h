#pragma once
/// Compiling and linking GLSL programs; failures throw RuntimeFailure carrying the assembled
/// source with line numbers and the driver's log.

#include <QOpenGLFunctions_4_3_Core>

#include <string>
#include <utility>
#include <vector>

namespace marbler::gl {

/// One shader stage: its GL type (GL_VERTEX_SHADER, ...) and its assembled source.
struct ShaderStage {
    GLenum type = 0;
    std::string source;
};

/// Compiles and links; `name` names the program in errors. Returns the program object.
GLuint buildProgram(QOpenGLFunctions_4_3_Core& gl, const std::string& name,
                    const std::vector<ShaderStage>& stages);

/// A linked program and the uniform locations it was asked for, so a render looks them up once.
class GlProgram {
public:
    GlProgram() = default;
    GlProgram(QOpenGLFunctions_4_3_Core& gl, const std::string& name, const std::vector<ShaderStage>& stages);
    GLuint id() const { return mId; }
    /// The location of a uniform (-1 if the linker removed it: setting it is then a no-op).
    GLint uniform(const char* name) const;
    void release();

private:
    QOpenGLFunctions_4_3_Core* mGl = nullptr;
    GLuint mId = 0;
};

} // namespace marbler::gl
