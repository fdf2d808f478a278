#include <string>
#include <vector>

#include <malloc.h>

#include "cli/dispatch.h"

namespace {

// A command runs once and exits, through phases that each allocate and free arrays of megabytes
// (reading, checking, building, refining, saving). By default malloc maps each such array afresh and
// unmaps it when freed, so every phase pays the first-touch page faults again (11 us a 4 KiB page on
// a VM: a third of the time of reading a 52k-triangle file). Kept in the heap instead, freed arrays
// serve the next phase: malloc maps nothing itself (the largest threshold it accepts is 32 MiB, and
// at millions of triangles most arrays are larger: reading a 6.3M-triangle OBJ took 399k page faults
// with that threshold, 267k without mapping, 6.3 -> 4.7 s), and never gives the heap's top back.
// Arrays meant to arrive untouched (rgb/support/zeroed_vector.h) map themselves.
void keep_freed_memory_for_reuse() {
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_TOP_PAD, 64 << 20);
}

}  // namespace

int main(int argc, char** argv) {
    keep_freed_memory_for_reuse();
    const std::vector<std::string> args(argv + 1, argv + argc);
    return cli::dispatch(args);
}
