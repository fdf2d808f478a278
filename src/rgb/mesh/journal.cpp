#include "rgb/mesh/journal.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>

#include "rgb/mesh/mesh.h"

namespace rgb {

namespace {

// A step: a header byte (removed faces in bits 0-2, added faces in bits 3-5, a removed vertex in
// bit 6, an added vertex in bit 7), the removed faces (slot, corners, type), the removed vertex
// (slot, level with flags, insertion position, address, and its limit if the mesh had cached it, so
// that what shows the vertex again need not recompute it), the added vertex's slot, the added
// faces' slots, and a trailer byte with the length of all that.
constexpr std::size_t kFaceBytes = 4 + 3 * 4 + 1;
constexpr std::size_t kVertexBytes = 4 + 1 + 3 * 8 + 3 * 4;
constexpr std::size_t kLimitBytes = 3 * 8;
constexpr std::size_t kMaxFaces = 6;
constexpr std::size_t kMaxStepBytes = 1 + kMaxFaces * kFaceBytes + kVertexBytes + kLimitBytes + 4 + kMaxFaces * 4 + 1;
static_assert(kMaxStepBytes - 1 <= 255, "a step's length must fit its trailer byte");
constexpr std::uint8_t kRemovedVertexBit = 1u << 6;
constexpr std::uint8_t kAddedVertexBit = 1u << 7;
constexpr std::uint8_t kBoundaryBit = 1u << 6;  // in the level byte
constexpr std::uint8_t kLimitBit = 1u << 7;     // in the level byte
constexpr std::uint32_t kFirstChunkBytes = 4096;
constexpr std::uint32_t kLargestChunkBytes = 1u << 20;

class Reader {
public:
    explicit Reader(const std::uint8_t* at) : at_(at) {}
    template <class T>
    T read() {
        T value;
        std::memcpy(&value, at_, sizeof value);
        at_ += sizeof value;
        return value;
    }

private:
    const std::uint8_t* at_;
};

// The vertex among `faces`' corners whose address is `point`: one end of a recreated vertex's parent
// edge, for the observers' vertex_added.
VertexId corner_at(const Mesh& mesh, std::span<const NewFace> faces, VertexId recreated, const SurfacePoint& point) {
    const SurfacePoint key = canonical(mesh.base(), reduced(point));
    for (const NewFace& f : faces)
        for (VertexId c : f.v)
            if (c != recreated && mesh.address(c) == key) return c;
    throw std::logic_error("journal: a recreated vertex's parent edge is not among its faces' corners");
}

}  // namespace

std::size_t JournalRecord::bytes() const {
    std::size_t total = chunks_.capacity() * sizeof(Chunk);
    for (const Chunk& c : chunks_) total += c.capacity;
    return total;
}

JournalRecord::Cursor JournalRecord::end() const {
    return chunks_.empty() ? Cursor{} : Cursor{chunks_.size() - 1, chunks_.back().size, steps_};
}

void JournalRecord::truncate(const Cursor& at) {
    if (at.steps == 0) {
        *this = JournalRecord();
        return;
    }
    chunks_.resize(at.chunk + 1);
    chunks_.back().size = at.offset;
    steps_ = at.steps;
}

Journal::Journal(Mesh& mesh) : mesh_(mesh) { mesh_.add_observer(this); }

Journal::~Journal() { mesh_.remove_observer(this); }

void Journal::start() {
    record_ = JournalRecord();
    recording_ = true;
    step_open_ = false;
}

JournalRecord Journal::stop() {
    drop_incomplete_step();
    recording_ = false;
    step_open_ = false;
    return std::exchange(record_, JournalRecord());
}

bool Journal::take_unrecorded_change() { return std::exchange(unrecorded_change_, false); }

// ---- recording ----------------------------------------------------------------------------------

bool Journal::enter(Phase phase) {
    if (!recording_) {
        unrecorded_change_ = unrecorded_change_ || !reverting_;
        return false;
    }
    // Within one replacement the phases only go forward, and each vertex phase happens once.
    const bool same_step = step_open_ && (phase > phase_ || (phase == phase_ && (phase == Phase::FacesRemoved || phase == Phase::FacesAdded)));
    if (!same_step) {
        // Every replacement removes a face first; anything else is one the journal cannot reverse.
        if (phase != Phase::FacesRemoved)
            throw std::logic_error("journal: a replacement that removes no face, or more than one vertex");
        drop_incomplete_step();
        start_step();
    }
    phase_ = phase;
    return true;
}

void Journal::start_step() {
    auto& chunks = record_.chunks_;
    if (chunks.empty() || chunks.back().capacity - chunks.back().size < kMaxStepBytes) {
        const std::uint32_t capacity =
            chunks.empty() ? kFirstChunkBytes : std::min(2 * chunks.back().capacity, kLargestChunkBytes);
        JournalRecord::Chunk chunk{std::make_unique_for_overwrite<std::uint8_t[]>(capacity), 0, capacity};
        chunks.push_back(std::move(chunk));
    }
    JournalRecord::Chunk& chunk = chunks.back();
    step_start_ = chunk.size;
    chunk.data[chunk.size++] = 0;  // header
    chunk.data[chunk.size++] = 1;  // trailer: the header alone so far
    step_open_ = true;
    ++record_.steps_;
}

// A step that never got to its additions belongs to a replacement that failed before changing the mesh.
void Journal::drop_incomplete_step() {
    if (!step_open_ || phase_ >= Phase::VertexAdded) return;
    record_.chunks_.back().size = step_start_;
    --record_.steps_;
    step_open_ = false;
}

// Room for a whole step was made when it started, so this cannot fail.
void Journal::append(const void* bytes, std::size_t n) {
    JournalRecord::Chunk& chunk = record_.chunks_.back();
    std::uint8_t* trailer = &chunk.data[chunk.size - 1];
    std::memcpy(trailer, bytes, n);
    chunk.size += static_cast<std::uint32_t>(n);
    chunk.data[chunk.size - 1] = static_cast<std::uint8_t>(chunk.size - 1 - step_start_);
}

void Journal::face_removed(const Mesh& mesh, FaceId f) {
    if (!enter(Phase::FacesRemoved)) return;
    std::uint8_t& header = record_.chunks_.back().data[step_start_];
    if ((header & 7u) == kMaxFaces) throw std::logic_error("journal: a replacement of more than six faces");
    ++header;
    std::array<std::uint8_t, kFaceBytes> bytes;
    std::memcpy(bytes.data(), &f.idx, 4);
    for (int i = 0; i < 3; ++i) std::memcpy(bytes.data() + 4 + 4 * i, &mesh.face_vertices(f)[i].idx, 4);
    bytes[16] = Mesh::pack(mesh.type(f));
    append(bytes.data(), bytes.size());
}

void Journal::vertex_removed(const Mesh& mesh, VertexId v) {
    if (!enter(Phase::VertexRemoved)) return;
    record_.chunks_.back().data[step_start_] |= kRemovedVertexBit;
    const SurfacePoint address = mesh.address(v);
    const std::optional<glm::dvec3> limit = mesh.cached_limit(v);
    std::array<std::uint8_t, kVertexBytes + kLimitBytes> bytes;
    std::memcpy(bytes.data(), &v.idx, 4);
    bytes[4] = static_cast<std::uint8_t>(mesh.level(v) | (mesh.is_boundary(v) ? kBoundaryBit : 0) | (limit ? kLimitBit : 0));
    std::memcpy(bytes.data() + 5, &mesh.insertion_position(v), 24);
    std::memcpy(bytes.data() + 29, &address.face, 4);
    std::memcpy(bytes.data() + 33, &address.a[1], 4);
    std::memcpy(bytes.data() + 37, &address.a[2], 4);
    if (limit) std::memcpy(bytes.data() + kVertexBytes, &*limit, kLimitBytes);
    append(bytes.data(), limit ? bytes.size() : kVertexBytes);
}

void Journal::vertex_added(const Mesh&, VertexId v, VertexId, VertexId) {
    if (!enter(Phase::VertexAdded)) return;
    record_.chunks_.back().data[step_start_] |= kAddedVertexBit;
    append(&v.idx, 4);
}

void Journal::face_added(const Mesh&, FaceId f) {
    if (!enter(Phase::FacesAdded)) return;
    std::uint8_t& header = record_.chunks_.back().data[step_start_];
    header = static_cast<std::uint8_t>(header + 8);  // cannot pass six: a replacement creates at most six faces
    append(&f.idx, 4);
}

// ---- reverting ----------------------------------------------------------------------------------

void Journal::revert(const JournalRecord& record) {
    JournalRecord::Cursor cursor = record.end();
    revert_some(record, cursor, record.steps());
}

bool Journal::revert_some(const JournalRecord& record, JournalRecord::Cursor& cursor, std::size_t max_steps) {
    struct Reverting {
        bool& flag;
        explicit Reverting(bool& f) : flag(f) { flag = true; }
        ~Reverting() { flag = false; }
    } guard(reverting_);
    for (; cursor.steps > 0 && max_steps > 0; --max_steps) {
        // A chunk may be empty (a step dropped as incomplete was its only one); earlier steps exist.
        while (cursor.offset == 0) cursor.offset = record.chunks_[--cursor.chunk].size;
        const std::uint8_t* data = record.chunks_[cursor.chunk].data.get();
        const std::uint32_t start = cursor.offset - 1 - data[cursor.offset - 1];
        revert_step(&data[start]);
        // Moved only once the step is undone: a step that threw is still to be undone.
        cursor.offset = start;
        --cursor.steps;
    }
    return cursor.steps == 0;
}

void Journal::revert_step(const std::uint8_t* step) {
    const std::uint8_t header = step[0];
    Reader in(step + 1);
    std::array<FaceId, kMaxFaces> removed_slots;
    InlineVector<NewFace, kMaxFaces> recreated;
    for (std::size_t i = 0; i < (header & 7u); ++i) {
        removed_slots[i] = FaceId(in.read<std::uint32_t>());
        NewFace face;
        for (VertexId& c : face.v) c = VertexId(in.read<std::uint32_t>());
        face.type = Mesh::unpack(in.read<std::uint8_t>());
        recreated.push_back(face);
    }
    std::optional<Mesh::NewVertex> vertex;
    VertexId vertex_slot;
    std::optional<glm::dvec3> limit;
    if ((header & kRemovedVertexBit) != 0) {
        vertex_slot = VertexId(in.read<std::uint32_t>());
        const std::uint8_t info = in.read<std::uint8_t>();
        Mesh::NewVertex v{info & ~(kBoundaryBit | kLimitBit), in.read<glm::dvec3>(), (info & kBoundaryBit) != 0, {}, {}};
        SurfacePoint address;
        address.face = in.read<std::uint32_t>();
        address.level = v.level;
        address.a[1] = in.read<std::uint32_t>();
        address.a[2] = in.read<std::uint32_t>();
        address.a[0] = (std::uint32_t(1) << address.level) - address.a[1] - address.a[2];
        v.address = address;
        vertex = v;
        if ((info & kLimitBit) != 0) limit = in.read<glm::dvec3>();
    }
    InlineVector<VertexId, 1> removed_vertex;
    if ((header & kAddedVertexBit) != 0) removed_vertex.push_back(VertexId(in.read<std::uint32_t>()));
    InlineVector<FaceId, kMaxFaces> added;
    for (std::size_t i = 0; i < ((header >> 3) & 7u); ++i) added.push_back(FaceId(in.read<std::uint32_t>()));

    // Checked before anything changes: what the step added is there, and the recreated vertex gets
    // its old slot (the free list's top, or the slot of the vertex this removes).
    for (FaceId f : added)
        if (!mesh_.is_live(f)) throw std::logic_error("journal: the mesh is not the one the record left");
    if (vertex) {
        const VertexId next = removed_vertex.empty() ? mesh_.next_vertex_slot() : removed_vertex[0];
        if (next != vertex_slot) throw std::logic_error("journal: the mesh is not the one the record left");
        const PointStencil stencil = parent_stencil(mesh_.base(), *vertex->address);
        vertex->a = corner_at(mesh_, recreated, vertex_slot, stencil.ends[0]);
        vertex->b = corner_at(mesh_, recreated, vertex_slot, stencil.ends[1]);
    }
    const FaceList created = mesh_.replace_faces(added, recreated, removed_vertex, vertex ? &*vertex : nullptr);
    if (!std::equal(created.begin(), created.end(), removed_slots.begin()))
        throw std::logic_error("journal: the mesh is not the one the record left");
    // A function of the base mesh alone, so the value computed before is the value.
    if (limit) mesh_.cache_limit(vertex_slot, *limit);
}

}  // namespace rgb
