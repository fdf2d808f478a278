#pragma once
// Typed indices into the flat arrays of rgb::Mesh (pmp-library style). A handle is just a slot
// number; whether the slot is live is the mesh's business (Mesh::is_live).
#include <cstdint>
#include <functional>
#include <limits>

namespace rgb {

template <class Tag>
struct Handle {
    static constexpr std::uint32_t invalid_index = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t idx = invalid_index;

    constexpr Handle() = default;
    constexpr explicit Handle(std::uint32_t i) : idx(i) {}
    constexpr bool valid() const { return idx != invalid_index; }
    constexpr friend bool operator==(Handle a, Handle b) { return a.idx == b.idx; }
    constexpr friend bool operator!=(Handle a, Handle b) { return a.idx != b.idx; }
    constexpr friend bool operator<(Handle a, Handle b) { return a.idx < b.idx; }
};

using VertexId = Handle<struct VertexTag>;
using FaceId = Handle<struct FaceTag>;
// Halfedge 3*f+i runs from corner i to corner i+1 (mod 3) of face f, so next/prev/face are
// arithmetic and only the opposite halfedge is stored.
using HalfedgeId = Handle<struct HalfedgeTag>;

}  // namespace rgb

template <class Tag>
struct std::hash<rgb::Handle<Tag>> {
    std::size_t operator()(rgb::Handle<Tag> h) const noexcept { return std::hash<std::uint32_t>{}(h.idx); }
};
