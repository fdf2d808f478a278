#pragma once
// Owning wrappers for GL object names (move-only), so renderer members clean up after themselves.
#include <utility>

#include <glad/gl.h>

namespace render {

template <void (*Create)(GLsizei, GLuint*), void (*Destroy)(GLsizei, const GLuint*)>
class GlName {
public:
    GlName() { Create(1, &id_); }
    ~GlName() {
        if (id_ != 0) Destroy(1, &id_);
    }
    GlName(GlName&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlName& operator=(GlName&& other) noexcept {
        std::swap(id_, other.id_);
        return *this;
    }
    GlName(const GlName&) = delete;
    GlName& operator=(const GlName&) = delete;
    GLuint get() const { return id_; }

private:
    GLuint id_ = 0;
};

// glad exposes GL entry points as function-pointer variables, so wrap them in real functions.
inline void create_buffers(GLsizei n, GLuint* ids) { glGenBuffers(n, ids); }
inline void delete_buffers(GLsizei n, const GLuint* ids) { glDeleteBuffers(n, ids); }
inline void create_vertex_arrays(GLsizei n, GLuint* ids) { glGenVertexArrays(n, ids); }
inline void delete_vertex_arrays(GLsizei n, const GLuint* ids) { glDeleteVertexArrays(n, ids); }
inline void create_textures(GLsizei n, GLuint* ids) { glGenTextures(n, ids); }
inline void delete_textures(GLsizei n, const GLuint* ids) { glDeleteTextures(n, ids); }

using GlBuffer = GlName<create_buffers, delete_buffers>;
using GlTexture = GlName<create_textures, delete_textures>;
using GlVertexArray = GlName<create_vertex_arrays, delete_vertex_arrays>;

}  // namespace render
