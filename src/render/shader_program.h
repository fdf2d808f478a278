#pragma once
// A linked GLSL program. Compile and link failures throw ShaderError carrying the shader's file name
// and the driver's log, so a broken shader says where it is broken.
#include <stdexcept>
#include <string>

#include <glad/gl.h>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/embedded_shaders.h"

namespace render {

class ShaderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class ShaderProgram {
public:
    ShaderProgram(const EmbeddedShader& vertex, const EmbeddedShader& fragment);
    // Looks both up among the embedded shaders.
    ShaderProgram(std::string_view vertex_name, std::string_view fragment_name);
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const { glUseProgram(id_); }
    GLuint id() const { return id_; }

    // Setters for the program in use; a uniform the driver optimised away is silently ignored.
    void set(const char* name, bool value) const;
    void set(const char* name, int value) const;
    void set(const char* name, float value) const;
    void set(const char* name, const glm::vec2& value) const;
    void set(const char* name, const glm::vec3& value) const;
    void set(const char* name, const glm::mat3& value) const;
    void set(const char* name, const glm::mat4& value) const;
    void set_array(const char* name, const glm::vec3* values, int count) const;

private:
    GLuint id_ = 0;
};

}  // namespace render
