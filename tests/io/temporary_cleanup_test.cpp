// A save interrupted by SIGINT, SIGTERM or SIGHUP leaves the old file and no temporary file, and the
// process still dies of that signal (so its parent sees the conventional status).
#include <csignal>
#include <filesystem>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "io/files/atomic_file.h"
#include "scratch_folder.h"

namespace rgbio {
namespace {

using TemporaryCleanup = test::ScratchFolder;

TEST_F(TemporaryCleanup, InterruptedSaveLeavesOnlyTheOldFile) {
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
        write("mesh.obj", "old\n");
        const int status = test::wait_status_of_child([&] {
            AtomicFileWriter writer(path("mesh.obj"));
            writer.write(std::string(3 * AtomicFileWriter::kBufferBytes, 'x'));  // on disk in the temporary file
            if (entries() != 2) return 10;  // the temporary file must exist for the check to mean anything
            ::raise(signal);
            return 11;  // not reached: the signal ends the process
        });
        ASSERT_TRUE(WIFSIGNALED(status)) << "signal " << signal << ": the child exited with " << WEXITSTATUS(status);
        EXPECT_EQ(WTERMSIG(status), signal);
        EXPECT_EQ(read(path("mesh.obj")), "old\n");
        EXPECT_EQ(entries(), 1u) << "signal " << signal << " left a temporary file";
    }
}

// Signals outside a save behave as before: the process dies of them and nothing is removed.
TEST_F(TemporaryCleanup, SignalAfterASaveRemovesNothing) {
    const int status = test::wait_status_of_child([&] {
        write_file_atomically(path("mesh.obj"), "saved\n");
        ::raise(SIGTERM);
        return 11;
    });
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGTERM);
    EXPECT_EQ(read(path("mesh.obj")), "saved\n");
    EXPECT_EQ(entries(), 1u);
}

// A program that handles a signal itself keeps its handler (meaningful when this test runs in a
// process of its own, as under ctest, so that the first save happens after the handler is set).
TEST_F(TemporaryCleanup, OwnHandlersAreKept) {
    const int status = test::wait_status_of_child([&] {
        static volatile std::sig_atomic_t seen = 0;
        std::signal(SIGINT, [](int) { seen = 1; });
        write_file_atomically(path("mesh.obj"), "saved\n");
        ::raise(SIGINT);
        return seen == 1 ? 0 : 1;
    });
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace rgbio
