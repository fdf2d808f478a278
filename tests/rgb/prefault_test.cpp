// Prefault and ZeroedVector: memory faulted in on another thread keeps every value written to it,
// whatever the timing, and ends up resident; arrays that only grow read zero where never written.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include <malloc.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh_room_prefault.h"
#include "rgb/support/prefault.h"
#include "rgb/support/zeroed_vector.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

// Pages of [p, p + n) that are resident, by mincore.
std::size_t resident_pages(std::byte* p, std::size_t n) {
    const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(p) & ~(page - 1);
    const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + n + page - 1) & ~(page - 1);
    std::vector<unsigned char> in_core((end - begin) / page);
    EXPECT_EQ(::mincore(reinterpret_cast<void*>(begin), end - begin, in_core.data()), 0);
    std::size_t resident = 0;
    for (unsigned char c : in_core) resident += c & 1;
    return resident;
}

struct Mapping {
    explicit Mapping(std::size_t size) : size(size) {
        void* p = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        EXPECT_NE(p, MAP_FAILED);
        // Small pages, so that what one write makes resident does not depend on the system's setting.
        ::madvise(p, size, MADV_NOHUGEPAGE);
        bytes = static_cast<std::byte*>(p);
    }
    ~Mapping() { ::munmap(bytes, size); }
    std::span<std::byte> span() const { return {bytes, size}; }
    std::byte* bytes;
    std::size_t size;
};

TEST(Prefault, LeavesRangesResidentAndUnchanged) {
    constexpr std::size_t kSize = 8u << 20;
    Mapping a(kSize), b(kSize / 2);
    a.bytes[12345] = std::byte{7};
    ASSERT_LT(resident_pages(a.bytes, kSize), 16u);
    {
        const rgb::Prefault prefault({a.span(), b.span()});
        // Joined only at the end of the scope: wait for the pages here as a user of them would not.
        for (int i = 0; i < 2000 && resident_pages(b.bytes, b.size) * 4096 < b.size; ++i) ::usleep(1000);
    }
    EXPECT_EQ(resident_pages(a.bytes, kSize) * 4096, kSize);
    EXPECT_EQ(resident_pages(b.bytes, b.size) * 4096, b.size);
    for (std::size_t i = 0; i < kSize; ++i) ASSERT_EQ(a.bytes[i], std::byte(i == 12345 ? 7 : 0)) << i;
}

// The owner writes while the other thread faults the same pages in: every write stays.
TEST(Prefault, KeepsWhatTheOwnerWritesMeanwhile) {
    constexpr std::size_t kSize = 32u << 20;
    Mapping m(kSize);
    {
        const rgb::Prefault prefault({m.span()});
        for (std::size_t i = 0; i < kSize; i += 1000) m.bytes[i] = std::byte(i / 1000 % 251 + 1);
    }
    for (std::size_t i = 0; i < kSize; ++i) ASSERT_EQ(m.bytes[i], i % 1000 ? std::byte{0} : std::byte(i / 1000 % 251 + 1)) << i;
}

// Empty, tiny and unaligned ranges, and a stop before anything was done.
TEST(Prefault, TakesAnyRangesAndStopsAtOnce) {
    Mapping m(4u << 20);
    { const rgb::Prefault none({}); }
    { const rgb::Prefault small({m.span().subspan(1, 100), m.span().subspan(3, 0)}); }
    { const rgb::Prefault unaligned({m.span().subspan(17, m.size - 40)}); }
    for (std::size_t i = 0; i < m.size; ++i) ASSERT_EQ(m.bytes[i], std::byte{0});
}

// Gives the pages inside [room) back to the kernel, so that they are faulted in again (as zeros) on
// their next use. Only for memory nothing reads before writing: an array's capacity beyond its size.
void drop_pages(std::span<std::byte> room) {
    const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(room.data()) + page - 1) & ~(page - 1);
    const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(room.data()) + room.size()) & ~(page - 1);
    if (begin < end) {
        ASSERT_EQ(::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED), 0);
    }
}

// The room's thread is part way through reading a large room when the mesh outgrows it: it stops
// before the arrays move (a read of the freed arrays would crash, or be reported under
// AddressSanitizer), and the mesh is the one refined without it.
TEST(MeshRoomPrefault, StopsBeforeTheMeshOutgrowsItsRoom) {
    constexpr std::size_t kFaces = std::size_t(1) << 21, kVertices = kFaces / 2;
    rgb::Mesh mesh = make_rgb_mesh(octahedron());
    mesh.reserve(kFaces, kVertices);
    const std::span<std::byte> faces_room = mesh.room_ahead(kFaces, kVertices).front();
    // The room comes from malloc, which may hand back a block an earlier test freed, still resident
    // (glibc serves blocks of up to 32 MiB from its heap once a program freed one that large): then
    // there is nothing left to fault in. Out of memory first, whatever ran before.
    drop_pages(faces_room);
    {
        const rgb::MeshRoomPrefault room(mesh, kFaces, kVertices);
        for (int i = 0; i < 2000 && resident_pages(faces_room.data(), faces_room.size()) < 64; ++i) ::usleep(100);
        ASSERT_LT(resident_pages(faces_room.data(), faces_room.size()) * 4096, faces_room.size());
        mesh.reserve(2 * kFaces, 2 * kVertices);
        rgb::refine_uniform(mesh, 3);
    }
    rgb::Mesh plain = make_rgb_mesh(octahedron());
    rgb::refine_uniform(plain, 3);
    EXPECT_TRUE(same_mesh(plain, mesh));
}

TEST(ZeroedVector, GrowsWithZeros) {
    rgb::ZeroedVector<std::uint64_t> v;
    for (std::size_t size : {std::size_t(10), std::size_t(1000), std::size_t(1) << 20, std::size_t(3) << 20}) {
        const std::size_t old = v.size();
        for (std::size_t i = 0; i < old; ++i) ASSERT_EQ(v[i], i * 3 + 1);
        v.resize(size);
        for (std::size_t i = old; i < size; ++i) ASSERT_EQ(v[i], 0u) << i;
        for (std::size_t i = 0; i < size; ++i) v[i] = i * 3 + 1;
    }
    v.push_back(5);
    EXPECT_EQ(v.back(), 5u);
}

// With malloc told to keep freed memory for reuse (as the command line tool does), a large array still
// arrives as fresh pages: zero without being written, none of them resident, so that the first writes
// or a Prefault bring them in rather than a clearing on the allocating thread.
// (Under AddressSanitizer its allocator takes no malloc options and the array comes through it, so
// that it checks the accesses: there only the zeros are checked.)
// In a child process: malloc's options cannot be given back (setting one ends glibc's own adjustment
// of its thresholds), and the tests after this one must find malloc as a fresh process does.
TEST(ZeroedVector, ALargeArrayArrivesUntouchedWhateverMallocKeeps) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        enum : int { kHeld = 0, kNoOptions = 1, kResident = 2, kNotZero = 3 };
#if !defined(__SANITIZE_ADDRESS__)
        if (mallopt(M_MMAP_MAX, 0) != 1 || mallopt(M_TRIM_THRESHOLD, 1 << 30) != 1) ::_exit(kNoOptions);
#endif
        constexpr std::size_t kItems = std::size_t(1) << 20;  // 8 MiB
        { const std::vector<std::uint64_t> freed(kItems, ~std::uint64_t(0)); }  // what the heap now keeps
        rgb::ZeroedVector<std::uint64_t> v(kItems);
#if !defined(__SANITIZE_ADDRESS__)
        if (resident_pages(reinterpret_cast<std::byte*>(v.data()), kItems * sizeof(std::uint64_t)) != 0) ::_exit(kResident);
#endif
        for (std::size_t i = 0; i < kItems; ++i)
            if (v[i] != 0) ::_exit(kNotZero);
        ::_exit(kHeld);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: malloc took no options, 2: pages resident, 3: an element not zero";
}

}  // namespace
}  // namespace rgbtest
