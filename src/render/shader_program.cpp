#include "render/shader_program.h"

#include <string>

#include <glm/gtc/type_ptr.hpp>

namespace render {
namespace {

std::string info_log(GLuint object, bool is_program) {
    GLint length = 0;
    if (is_program)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
    if (length > 0) {
        if (is_program)
            glGetProgramInfoLog(object, length, nullptr, log.data());
        else
            glGetShaderInfoLog(object, length, nullptr, log.data());
    }
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

GLuint compile(GLenum stage, const EmbeddedShader& shader) {
    GLuint id = glCreateShader(stage);
    const char* text = shader.source.data();
    const GLint length = static_cast<GLint>(shader.source.size());
    glShaderSource(id, 1, &text, &length);
    glCompileShader(id);
    GLint ok = GL_FALSE;
    glGetShaderiv(id, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string log = info_log(id, false);
        glDeleteShader(id);
        throw ShaderError("shaders/" + std::string(shader.name) + ": compile error:\n" + log);
    }
    return id;
}

}  // namespace

ShaderProgram::ShaderProgram(const EmbeddedShader& vertex, const EmbeddedShader& fragment) {
    GLuint vs = compile(GL_VERTEX_SHADER, vertex);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragment);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    glLinkProgram(id_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string log = info_log(id_, true);
        glDeleteProgram(id_);
        throw ShaderError("shaders/" + std::string(vertex.name) + " + shaders/" + std::string(fragment.name) +
                          ": link error:\n" + log);
    }
}

ShaderProgram::ShaderProgram(std::string_view vertex_name, std::string_view fragment_name)
    : ShaderProgram(embedded_shader(vertex_name), embedded_shader(fragment_name)) {}

ShaderProgram::~ShaderProgram() { glDeleteProgram(id_); }

void ShaderProgram::set(const char* name, bool value) const { glUniform1i(glGetUniformLocation(id_, name), value ? 1 : 0); }
void ShaderProgram::set(const char* name, int value) const { glUniform1i(glGetUniformLocation(id_, name), value); }
void ShaderProgram::set(const char* name, float value) const { glUniform1f(glGetUniformLocation(id_, name), value); }
void ShaderProgram::set(const char* name, const glm::vec2& value) const {
    glUniform2fv(glGetUniformLocation(id_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec3& value) const {
    glUniform3fv(glGetUniformLocation(id_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat3& value) const {
    glUniformMatrix3fv(glGetUniformLocation(id_, name), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat4& value) const {
    glUniformMatrix4fv(glGetUniformLocation(id_, name), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set_array(const char* name, const glm::vec3* values, int count) const {
    glUniform3fv(glGetUniformLocation(id_, name), count, glm::value_ptr(values[0]));
}

}  // namespace render
