#include "render/surface_buffer.h"

#include <algorithm>
#include <cstddef>

namespace render {
namespace {

// Headroom on reallocation so that a growing mesh does not re-upload everything on every edit.
constexpr double kGrowthFactor = 1.5;

// The appearance's attribute locations (shaders/surface.vert).
constexpr GLuint kMaterialColour = 3, kVertexColour = 4, kTexcoord = 5, kTexture = 6;

const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

template <class Vertex>
void sub_data(GLuint buffer, std::span<const Vertex> vertices, std::size_t first, std::size_t count) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(first * sizeof(Vertex)), static_cast<GLsizeiptr>(count * sizeof(Vertex)),
                    vertices.data() + first);
}

}  // namespace

SurfaceBuffer::SurfaceBuffer() {
    glBindVertexArray(vertex_array_.get());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
    constexpr auto stride = static_cast<GLsizei>(sizeof(SurfaceVertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(SurfaceVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(SurfaceVertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribIPointer(2, 1, GL_UNSIGNED_INT, stride, offset(offsetof(SurfaceVertex, code)));
    glBindBuffer(GL_ARRAY_BUFFER, appearance_buffer_.get());
    constexpr auto look = static_cast<GLsizei>(sizeof(AppearanceVertex));
    glVertexAttribPointer(kMaterialColour, 4, GL_UNSIGNED_BYTE, GL_TRUE, look, offset(offsetof(AppearanceVertex, material_rgba)));
    glVertexAttribPointer(kVertexColour, 4, GL_UNSIGNED_BYTE, GL_TRUE, look, offset(offsetof(AppearanceVertex, vertex_rgba)));
    glVertexAttribPointer(kTexcoord, 2, GL_FLOAT, GL_FALSE, look, offset(offsetof(AppearanceVertex, texcoord)));
    glVertexAttribIPointer(kTexture, 1, GL_UNSIGNED_INT, look, offset(offsetof(AppearanceVertex, texture)));
    glBindVertexArray(0);
}

void SurfaceBuffer::use_appearance(bool on) {
    with_appearance_ = on;
    glBindVertexArray(vertex_array_.get());
    for (GLuint index : {kMaterialColour, kVertexColour, kTexcoord, kTexture}) {
        if (on) glEnableVertexAttribArray(index);
        else glDisableVertexAttribArray(index);
    }
    glBindVertexArray(0);
}

void SurfaceBuffer::upload_all(std::span<const SurfaceVertex> vertices, std::span<const AppearanceVertex> appearance) {
    const bool with_appearance = !appearance.empty();
    if (vertices.size() > capacity_ || with_appearance != with_appearance_) {
        capacity_ = std::max(capacity_, static_cast<std::size_t>(static_cast<double>(vertices.size()) * kGrowthFactor));
        glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_ * sizeof(SurfaceVertex)), nullptr, GL_DYNAMIC_DRAW);
        glBindBuffer(GL_ARRAY_BUFFER, appearance_buffer_.get());
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(with_appearance ? capacity_ * sizeof(AppearanceVertex) : 0), nullptr,
                     GL_DYNAMIC_DRAW);
        use_appearance(with_appearance);
    }
    sub_data(buffer_.get(), vertices, 0, vertices.size());
    if (with_appearance) sub_data(appearance_buffer_.get(), appearance, 0, appearance.size());
    count_ = vertices.size();
    bytes_uploaded_ += vertices.size_bytes() + appearance.size_bytes();
    ++upload_calls_;
}

void SurfaceBuffer::upload(std::span<const SurfaceVertex> vertices, std::span<const AppearanceVertex> appearance,
                           std::span<const SlotRange> ranges) {
    if (vertices.size() > capacity_ || appearance.empty() == with_appearance_) {
        upload_all(vertices, appearance);
        return;
    }
    for (const SlotRange& range : ranges) {
        const std::size_t first = 3 * std::size_t{range.first}, count = 3 * std::size_t{range.count};
        sub_data(buffer_.get(), vertices, first, count);
        bytes_uploaded_ += count * sizeof(SurfaceVertex);
        if (with_appearance_) {
            sub_data(appearance_buffer_.get(), appearance, first, count);
            bytes_uploaded_ += count * sizeof(AppearanceVertex);
        }
        ++upload_calls_;
    }
    count_ = vertices.size();
}

void SurfaceBuffer::draw() const {
    if (count_ == 0) return;
    // Without an appearance the attributes read the context's current values (shared by every
    // vertex array, default alpha 1): zero says "the file gives none".
    if (!with_appearance_) {
        for (GLuint index : {kMaterialColour, kVertexColour, kTexcoord}) glVertexAttrib4f(index, 0.0f, 0.0f, 0.0f, 0.0f);
        glVertexAttribI4ui(kTexture, kNoTexture, 0, 0, 0);
    }
    glBindVertexArray(vertex_array_.get());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(count_));
    glBindVertexArray(0);
}

}  // namespace render
