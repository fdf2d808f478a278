// The writers of other formats (io/formats/format_writers.h) under a write that fails part way, as on
// a full disk: each throws SaveError naming the file, keeps the old file byte for byte and leaves no
// temporary behind (they stream through AtomicFileWriter, as the OBJ writer does: atomic_file_test.cpp).
#include <csignal>

#include <sys/resource.h>

#include <gtest/gtest.h>

#include "io/formats/format_writers.h"
#include "io/obj/obj_error.h"
#include "scratch_folder.h"

namespace rgbio {
namespace {

using ExportWriteFailure = test::ScratchFolder;
using test::in_child;

// A tetrahedron with a level and colour per face: every writer's file of it is well over 64 bytes.
ExportMesh tetrahedron_export() {
    ExportMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    mesh.levels = {0, 1, 2, 3};
    mesh.rgb_colours = {0, 1, 2, 0};
    return mesh;
}

TEST_F(ExportWriteFailure, KeepsTheOldFileInEveryFormat) {
    struct Case {
        const char* name;
        OutputFormat format;
        MshEncoding msh;
    };
    for (const Case& c : {Case{"out.ply", OutputFormat::Ply, MshEncoding::Ascii}, Case{"out.stl", OutputFormat::Stl, MshEncoding::Ascii},
                          Case{"out.vtu", OutputFormat::Vtu, MshEncoding::Ascii}, Case{"out.msh", OutputFormat::Msh, MshEncoding::Ascii},
                          Case{"binary.msh", OutputFormat::Msh, MshEncoding::Binary}}) {
        write(c.name, "old content\n");
        // RLIMIT_FSIZE makes write() fail part way (EFBIG), as a full disk (ENOSPC) does.
        EXPECT_TRUE(in_child([&] {
            std::signal(SIGXFSZ, SIG_IGN);
            const rlimit limit{64, 64};
            ::setrlimit(RLIMIT_FSIZE, &limit);
            try {
                save_export_mesh(tetrahedron_export(), path(c.name), c.format, c.msh);
            } catch (const SaveError& e) {
                return std::string(e.what()).starts_with("cannot save " + path(c.name));
            }
            return false;
        })) << c.name;
        EXPECT_EQ(read(folder_ / c.name), "old content\n") << c.name;
        std::filesystem::remove(folder_ / c.name);
        EXPECT_EQ(entries(), 0u) << c.name << ": a temporary file was left behind";
    }
}

}  // namespace
}  // namespace rgbio
