// Saving never leaves a partial file: failures (file too large / disk full, read-only folder,
// parent not a folder) keep the old file byte for byte and leave no temporary behind; streamed
// chunks arrive in order whatever their sizes; names up to the file system's limit save; saves to
// one hard-linked file at the same time leave one of them whole.
#include <algorithm>
#include <csignal>
#include <filesystem>
#include <latch>
#include <thread>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "io/files/atomic_file.h"
#include "io/obj/obj_error.h"
#include "scratch_folder.h"

namespace rgbio {
namespace {

namespace fs = std::filesystem;

using AtomicFile = test::ScratchFolder;
using test::in_child;

bool save_fails(const std::string& path, const std::string& content) {
    try {
        write_file_atomically(path, content);
    } catch (const SaveError& e) {
        return std::string(e.what()).find("cannot save " + path) == 0;
    }
    return false;
}

TEST_F(AtomicFile, WritesTheContentAndLeavesNoTemporary) {
    const fs::path target = folder_ / "mesh.obj";
    write_file_atomically(target.string(), "v 1 2 3\n");
    write_file_atomically(target.string(), "v 4 5 6\n");
    EXPECT_EQ(read(target), "v 4 5 6\n");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, FullDiskKeepsTheOldFile) {
    const fs::path target = folder_ / "mesh.obj";
    write_file_atomically(target.string(), "old content\n");
    const std::string big(1 << 20, 'x');
    // RLIMIT_FSIZE makes write() fail part-way (EFBIG), exactly like a full disk (ENOSPC) does.
    EXPECT_TRUE(in_child([&] {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        return save_fails(target.string(), big);
    }));
    EXPECT_EQ(read(target), "old content\n");
    EXPECT_EQ(entries(), 1u) << "a temporary file was left behind";
}

TEST_F(AtomicFile, ReadOnlyFolderKeepsTheOldFile) {
    const fs::path target = folder_ / "mesh.obj";
    write_file_atomically(target.string(), "old content\n");
    fs::permissions(folder_, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read | fs::perms::group_exec |
                                 fs::perms::others_read | fs::perms::others_exec);
    // Root ignores permission bits, so the child drops to an unprivileged user first.
    EXPECT_TRUE(in_child([&] {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) return false;
        return save_fails(target.string(), "new content\n");
    }));
    EXPECT_EQ(read(target), "old content\n");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, ParentThatIsAFileFails) {
    const fs::path file = folder_ / "not_a_folder";
    write_file_atomically(file.string(), "x");
    const std::string target = (file / "mesh.obj").string();
    try {
        write_file_atomically(target, "v 0 0 0\n");
        FAIL() << "no error";
    } catch (const SaveError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot save " + target + ": cannot create a temporary file in its folder: Not a directory");
    }
}

// Chunk sizes around and across the buffer size; the expected file is their plain concatenation.
TEST_F(AtomicFile, StreamedChunksArriveInOrder) {
    const std::size_t buffer = AtomicFileWriter::kBufferBytes;
    std::string expected;
    {
        AtomicFileWriter writer(path("stream.obj"));
        char fill = 'a';
        for (std::size_t size : {std::size_t{1}, buffer - 2, std::size_t{1}, std::size_t{5}, 3 * buffer + 7, std::size_t{0}, buffer}) {
            const std::string chunk(size, fill++);
            writer.write(chunk);
            expected += chunk;
        }
        writer.buffer() += "formatted in place\n";
        writer.flush_if_full();
        expected += "formatted in place\n";
        writer.commit();
    }
    EXPECT_TRUE(read(path("stream.obj")) == expected) << "the streamed file differs from the chunks written";
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, AbandonedWriterKeepsTheOldFileAndLeavesNoTemporary) {
    write_file_atomically(path("mesh.obj"), "old content\n");
    {
        AtomicFileWriter writer(path("mesh.obj"));
        writer.write(std::string(3 * AtomicFileWriter::kBufferBytes, 'x'));  // reaches the temporary file
        EXPECT_EQ(entries(), 2u);
    }  // destroyed without commit, as when formatting throws
    EXPECT_EQ(read(path("mesh.obj")), "old content\n");
    EXPECT_EQ(entries(), 1u);
}

// A streamed save larger than the buffer fails part-way through, after writes already succeeded.
TEST_F(AtomicFile, FullDiskDuringAStreamedSaveKeepsTheOldFile) {
    write_file_atomically(path("mesh.obj"), "old content\n");
    EXPECT_TRUE(in_child([&] {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{AtomicFileWriter::kBufferBytes + 4096, AtomicFileWriter::kBufferBytes + 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        try {
            AtomicFileWriter writer(path("mesh.obj"));
            for (int i = 0; i < 3; ++i) writer.write(std::string(AtomicFileWriter::kBufferBytes, 'x'));
            writer.commit();
        } catch (const SaveError& e) {
            return std::string(e.what()) == "cannot save " + path("mesh.obj") + ": write failed: File too large";
        }
        return false;
    }));
    EXPECT_EQ(read(path("mesh.obj")), "old content\n");
    EXPECT_EQ(entries(), 1u);
}

// 250 bytes is a legal name (the limit is 255); the temporary name must shorten it, not fail.
TEST_F(AtomicFile, LongestNamesSave) {
    for (std::size_t length : {250u, 255u}) {
        const std::string name = std::string(length - 4, 'n') + ".obj";
        write_file_atomically(path(name), "v 1 2 3\n");
        write_file_atomically(path(name), "v 4 5 6\n");
        EXPECT_EQ(read(path(name)), "v 4 5 6\n");
        fs::remove(path(name));
    }
    EXPECT_EQ(entries(), 0u);
}

// The temporary name is the file's name cut to 226 bytes plus ".tmp-rgbsub-PID-XXXXXX" (room for a
// pid of 10 digits); a two-byte character across the cut is dropped whole. Here "x" + 126 two-byte
// characters: byte 226 is the second byte of the 113th, so the name keeps "x" and 112 characters (225
// bytes).
TEST_F(AtomicFile, TemporaryNamesDoNotSplitCharacters) {
    std::string name = "x";
    for (int i = 0; i < 126; ++i) name += "\xc3\xa9";
    AtomicFileWriter writer(path(name));
    const std::string temporary = fs::directory_iterator(folder_)->path().filename().string();
    const std::string pid = std::to_string(::getpid());
    EXPECT_EQ(temporary.size(), 225u + 12u + pid.size() + 7u);
    EXPECT_EQ(temporary.substr(0, 225), name.substr(0, 225));
    EXPECT_EQ(temporary.substr(225, 12 + pid.size() + 1), ".tmp-rgbsub-" + pid + "-");
    writer.commit();
    EXPECT_EQ(entries(), 1u);
    EXPECT_TRUE(fs::exists(path(name)));
}

// A save killed by a signal it cannot catch leaves its temporary file; the next save into the folder
// removes it once its process is gone (issue 30, low items), and only it: not a live save's temporary
// file, not a file of another program with a similar name. Before, such files stayed for good.
TEST_F(AtomicFile, TheNextSaveRemovesWhatAKilledSaveLeft) {
    write_file_atomically(path("mesh.obj"), "old content\n");
    const pid_t killed = ::fork();
    if (killed == 0) {
        AtomicFileWriter writer(path("mesh.obj"));
        writer.write("part of the new content");
        ::kill(::getpid(), SIGKILL);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(killed, &status, 0), killed);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    const std::string left = "mesh.obj.tmp-rgbsub-" + std::to_string(killed) + "-";
    auto names = [&] {
        std::vector<std::string> found;
        for (const auto& entry : fs::directory_iterator(folder_)) found.push_back(entry.path().filename().string());
        std::sort(found.begin(), found.end());
        return found;
    };
    const std::vector<std::string> before = names();
    ASSERT_EQ(before.size(), 2u);
    ASSERT_TRUE(before[1].starts_with(left)) << before[1];
    write("other.obj.tmp-abc123", "another program's file");
    write("notes.tmp-rgbsub-1-XYZ", "not of our form");
    AtomicFileWriter live(path("other.obj"));  // a save under way in a live process
    write_file_atomically(path("mesh.obj"), "new content\n");
    EXPECT_EQ(read(path("mesh.obj")), "new content\n");
    const std::vector<std::string> after = names();
    ASSERT_EQ(after.size(), 4u);
    EXPECT_EQ(after[0], "mesh.obj");
    EXPECT_EQ(after[1], "notes.tmp-rgbsub-1-XYZ");
    EXPECT_EQ(after[2], "other.obj.tmp-abc123");
    EXPECT_TRUE(after[3].starts_with("other.obj.tmp-rgbsub-" + std::to_string(::getpid()) + "-")) << after[3];
}

TEST_F(AtomicFile, NewFilesGetTheUsualPermissions) {
    const mode_t previous = ::umask(027);
    write_file_atomically(path("new.obj"), "v 1 2 3\n");
    ::umask(previous);
    EXPECT_EQ(fs::status(path("new.obj")).permissions(), fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

// Two saves through the two names of a hard-linked file (written in place) overlap: each writes
// the whole file in turn, so it ends as one of them, never a mix or one cut to the other's length.
// The contents differ in size, so an overlap without a lock shows as a mix or a wrong length.
TEST_F(AtomicFile, SavesToOneHardLinkedFileAtOnceLeaveOneOfThemWhole) {
    write_file_atomically(path("a.obj"), "old content\n");
    fs::create_hard_link(path("a.obj"), path("b.obj"));
    const std::string longer(3 * AtomicFileWriter::kBufferBytes, 'l'), shorter(AtomicFileWriter::kBufferBytes + 1, 's');
    for (int round = 0; round < 16; ++round) {
        std::latch start(2);
        auto save = [&](const std::string& name, const std::string& content) {
            start.arrive_and_wait();
            write_file_atomically(path(name), content);
        };
        std::thread other(save, "b.obj", std::cref(shorter));
        save("a.obj", longer);
        other.join();
        const std::string saved = read(path("a.obj"));
        ASSERT_TRUE(saved == longer || saved == shorter) << "round " << round << ": a file of " << saved.size()
                                                         << " bytes that is neither save";
        ASSERT_EQ(fs::hard_link_count(path("a.obj")), 2u);
    }
    EXPECT_EQ(entries(), 2u);
}

}  // namespace
}  // namespace rgbio
