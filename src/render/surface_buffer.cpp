#include "render/surface_buffer.h"

#include <cstddef>

namespace render {
namespace {

// Headroom on reallocation so that a growing mesh does not re-upload everything on every edit.
constexpr double kGrowthFactor = 1.5;

const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

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
    glBindVertexArray(0);
}

void SurfaceBuffer::upload_all(std::span<const SurfaceVertex> vertices) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
    if (vertices.size() > capacity_) {
        capacity_ = static_cast<std::size_t>(static_cast<double>(vertices.size()) * kGrowthFactor);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_ * sizeof(SurfaceVertex)), nullptr, GL_DYNAMIC_DRAW);
    }
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(vertices.size_bytes()), vertices.data());
    count_ = vertices.size();
    bytes_uploaded_ += vertices.size_bytes();
    ++upload_calls_;
}

void SurfaceBuffer::upload(std::span<const SurfaceVertex> vertices, std::span<const SlotRange> ranges) {
    if (vertices.size() > capacity_) {
        upload_all(vertices);
        return;
    }
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
    for (const SlotRange& range : ranges) {
        const std::span<const SurfaceVertex> part = vertices.subspan(3 * std::size_t{range.first}, 3 * std::size_t{range.count});
        glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(3 * std::size_t{range.first} * sizeof(SurfaceVertex)),
                        static_cast<GLsizeiptr>(part.size_bytes()), part.data());
        bytes_uploaded_ += part.size_bytes();
        ++upload_calls_;
    }
    count_ = vertices.size();
}

void SurfaceBuffer::draw() const {
    if (count_ == 0) return;
    glBindVertexArray(vertex_array_.get());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(count_));
    glBindVertexArray(0);
}

}  // namespace render
