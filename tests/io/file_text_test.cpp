// Reading whole files (file_text.h): a large file is mapped, a small one copied, both give the file's
// bytes exactly; a mapped file that another program truncates while it is read gives zeros in place of
// the lost bytes and is reported as shrunk, never a SIGBUS; a SIGBUS anywhere else still ends the
// process as before. The truncations run in child processes, so that a crash fails the test only.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "io/files/file_text.h"
#include "io/obj/obj_error.h"
#include "scratch_folder.h"

namespace rgbio {
namespace {

using FileTextRead = test::ScratchFolder;

// Printable bytes from a fixed seed, so that every offset has its own expected value.
std::string random_text(std::size_t size) {
    std::mt19937 random(7);
    std::string text(size, ' ');
    for (char& c : text) c = static_cast<char>('!' + random() % 90);
    return text;
}

TEST_F(FileTextRead, LargeAndSmallFilesGiveTheirBytesExactly) {
    for (std::size_t size : {std::size_t(0), std::size_t(100), std::size_t(9) << 20}) {
        const std::string content = random_text(size);
        write("file.txt", content);
        const FileText text = read_file_text(path("file.txt"));
        EXPECT_TRUE(text.view() == content) << size << " bytes";
        EXPECT_NO_THROW(text.check_not_shrunk());
    }
}

// /proc's files tell stat they have 0 bytes: they are read to their end (issue 30, low items); before,
// each was "empty (0 bytes)". The oracle reads the same file with a stream.
TEST_F(FileTextRead, SystemFilesWithoutASizeAreReadToTheirEnd) {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    const std::string expected((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(expected.empty());
    ASSERT_EQ(std::filesystem::file_size("/proc/self/cmdline"), 0u) << "the case this test is about";
    const FileText text = read_file_text("/proc/self/cmdline");
    EXPECT_EQ(text.view(), expected);
    write("empty.obj", "");
    EXPECT_TRUE(read_file_text(path("empty.obj")).view().empty());
}

TEST_F(FileTextRead, AFileTruncatedWhileReadGivesZerosAndIsReportedAsShrunk) {
    const std::size_t size = std::size_t(9) << 20, kept = std::size_t(1) << 20;
    const std::string content = random_text(size);
    write("shrinking.obj", content);
    EXPECT_TRUE(test::in_child([&] {
        const FileText text = read_file_text(path("shrinking.obj"));
        std::filesystem::resize_file(path("shrinking.obj"), kept);
        const std::string_view bytes = text.view();
        // Every byte read: the kept ones as they were, the lost ones (a SIGBUS each page) as zeros.
        if (bytes.substr(0, kept) != std::string_view(content).substr(0, kept)) return false;
        if (bytes.find_first_not_of('\0', kept) != std::string_view::npos) return false;
        try {
            text.check_not_shrunk();
        } catch (const ObjError& e) {
            return e.problem() == ObjProblem::Unreadable && e.file() == path("shrinking.obj") &&
                   std::string(e.what()).find("the file shrank while reading") != std::string::npos;
        }
        return false;
    }));
}

TEST_F(FileTextRead, ASigbusOutsideTheFilesBeingReadStillEndsTheProcess) {
    write("read.txt", random_text(std::size_t(9) << 20));
    write("other.txt", random_text(std::size_t(1) << 20));
    const int status = test::wait_status_of_child([&] {
        const rlimit no_core{0, 0};
        ::setrlimit(RLIMIT_CORE, &no_core);
        const FileText text = read_file_text(path("read.txt"));  // installs the handler
        const int fd = ::open(path("other.txt").c_str(), O_RDONLY);
        auto* other = static_cast<const volatile char*>(::mmap(nullptr, std::size_t(1) << 20, PROT_READ, MAP_PRIVATE, fd, 0));
        std::filesystem::resize_file(path("other.txt"), 0);
        return 100 + other[4096];  // beyond the end: SIGBUS
    });
    // A handler that took the signal for a file being read would have put a zero there, and the child
    // would have exited with 100.
#if defined(__SANITIZE_ADDRESS__)
    // The sanitizer's own handler, which ours passes the signal on to, reports it and exits.
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0 && WEXITSTATUS(status) != 100) << "wait status " << status;
#else
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGBUS) << "wait status " << status;
#endif
}

}  // namespace
}  // namespace rgbio
