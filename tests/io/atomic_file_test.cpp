// Saving never leaves a partial file: failures (file too large / disk full, read-only folder,
// parent not a folder) keep the old file byte for byte and leave no temporary behind.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "io/atomic_file.h"
#include "io/obj_error.h"

namespace rgbio {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() / ("rgbsub_atomic_" + std::to_string(::getpid()) + "_" +
                                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override {
        fs::permissions(folder_, fs::perms::owner_all);
        fs::remove_all(folder_);
    }
    static std::string read(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder_), fs::directory_iterator())); }
    fs::path folder_;
};

// Runs `check` in a child process (so limits and identities do not leak into the test process)
// and returns whether it returned true.
bool in_child(const std::function<bool()>& check) {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(check() ? 0 : 1);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

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

}  // namespace
}  // namespace rgbio
