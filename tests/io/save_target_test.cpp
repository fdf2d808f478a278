// A save writes to what the user named: symbolic links lead to the real file, which keeps its mode,
// owner and hard links; folders, FIFOs, sockets, devices and read-only files are refused with a
// message naming what they are, and left exactly as they were.
#include <csignal>
#include <cstddef>
#include <iostream>
#include <iterator>
#include <filesystem>
#include <fstream>

#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "io/files/atomic_file.h"
#include "io/files/save_target.h"
#include "io/obj/obj_error.h"
#include "scratch_folder.h"

namespace rgbio {
namespace {

namespace fs = std::filesystem;

using SaveTarget = test::ScratchFolder;
using test::in_child;

// The SaveError message of saving to `path`, or "" if the save succeeded.
std::string save_error(const std::string& path, const std::string& content = "v 1 2 3\n") {
    try {
        write_file_atomically(path, content);
    } catch (const SaveError& e) {
        return e.what();
    }
    return "";
}

// Root enters a mount namespace directly; other users through a user namespace that maps them to
// root inside it (as `unshare -Urm` does).
bool enter_private_mount_namespace() {
    const uid_t uid = ::getuid();
    const gid_t gid = ::getgid();
    if (::unshare(CLONE_NEWNS) != 0) {
        if (::unshare(CLONE_NEWUSER | CLONE_NEWNS) != 0) return false;
        std::ofstream("/proc/self/setgroups") << "deny";
        std::ofstream("/proc/self/uid_map") << "0 " << uid << " 1";
        std::ofstream("/proc/self/gid_map") << "0 " << gid << " 1";
    }
    return ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0;
}

struct stat status_of(const std::string& path) {
    struct stat s {};
    EXPECT_EQ(::lstat(path.c_str(), &s), 0) << path;
    return s;
}

TEST_F(SaveTarget, SymbolicLinksAreFollowedToTheRealFile) {
    fs::create_directory(folder_ / "real");
    write("real/mesh.obj", "old\n");
    fs::create_symlink("real/mesh.obj", folder_ / "near.obj");  // relative to the link's folder
    fs::create_symlink(folder_ / "near.obj", folder_ / "far.obj");  // a chain, absolute
    write_file_atomically(path("far.obj"), "new\n");
    EXPECT_EQ(read(path("real/mesh.obj")), "new\n");
    EXPECT_TRUE(fs::is_symlink(path("near.obj")));
    EXPECT_TRUE(fs::is_symlink(path("far.obj")));
    EXPECT_EQ(fs::read_symlink(path("near.obj")), "real/mesh.obj");
    // The temporary file went to the real file's folder, and nothing is left of it.
    EXPECT_EQ(entries(), 3u);
    EXPECT_EQ(std::distance(fs::directory_iterator(folder_ / "real"), fs::directory_iterator()), 1);
}

TEST_F(SaveTarget, DanglingLinkCreatesItsTarget) {
    fs::create_symlink("made.obj", folder_ / "link.obj");
    write_file_atomically(path("link.obj"), "new\n");
    EXPECT_EQ(read(path("made.obj")), "new\n");
    EXPECT_TRUE(fs::is_symlink(path("link.obj")));
}

TEST_F(SaveTarget, LinkLoopIsRefused) {
    fs::create_symlink("b.obj", folder_ / "a.obj");
    fs::create_symlink("a.obj", folder_ / "b.obj");
    EXPECT_EQ(save_error(path("a.obj")), "cannot save " + path("a.obj") + ": too many levels of symbolic links");
}

TEST_F(SaveTarget, ModeIsKept) {
    for (mode_t mode : {0600, 0640, 0755, 0604}) {
        write("mesh.obj", "old\n");
        ASSERT_EQ(::chmod(path("mesh.obj").c_str(), mode), 0);
        write_file_atomically(path("mesh.obj"), "new\n");
        EXPECT_EQ(status_of(path("mesh.obj")).st_mode & 07777, mode);
        EXPECT_EQ(read(path("mesh.obj")), "new\n");
    }
}

// Only root can make a file that belongs to someone else; the save must give it back to them.
TEST_F(SaveTarget, OwnerIsKept) {
    ASSERT_EQ(::geteuid(), 0u) << "run the tests as root (./test.sh does): making a file owned by another user takes privileges";
    write("mesh.obj", "old\n");
    ASSERT_EQ(::chown(path("mesh.obj").c_str(), 65534, 65534), 0);
    write_file_atomically(path("mesh.obj"), "new\n");
    EXPECT_EQ(status_of(path("mesh.obj")).st_uid, 65534u);
    EXPECT_EQ(status_of(path("mesh.obj")).st_gid, 65534u);
    EXPECT_EQ(read(path("mesh.obj")), "new\n");
}

// A user who may write someone else's file (group-writable) cannot give a new file that owner, so
// the file is written in place: same inode, same owner. The child enters the folder before it drops to
// that user and names the file relative to it: the folder lies wherever the temporary folder is (under
// a home of mode 0700, say), where the other user could not walk the path down to it.
TEST_F(SaveTarget, FileOfAnotherOwnerIsWrittenInPlace) {
    ASSERT_EQ(::geteuid(), 0u) << "run the tests as root (./test.sh does): making a file owned by another user takes privileges";
    write("mesh.obj", "old content that is longer than the new one\n");
    ASSERT_EQ(::chmod(path("mesh.obj").c_str(), 0664), 0);
    ASSERT_EQ(::chown(path("mesh.obj").c_str(), 0, 65534), 0);
    ASSERT_EQ(::chmod(folder_.c_str(), 0777), 0);
    const ino_t inode = status_of(path("mesh.obj")).st_ino;
    EXPECT_TRUE(in_child([&] {
        if (::chdir(folder_.c_str()) != 0 || ::setgid(65534) != 0 || ::setuid(65534) != 0) return false;
        return save_error("mesh.obj", "new\n").empty();
    }));
    EXPECT_EQ(read(path("mesh.obj")), "new\n");
    EXPECT_EQ(status_of(path("mesh.obj")).st_ino, inode);
    EXPECT_EQ(status_of(path("mesh.obj")).st_uid, 0u);
    EXPECT_EQ(entries(), 1u);
}

TEST_F(SaveTarget, HardLinksStayOneFile) {
    write("a.obj", "old content, longer than the new\n");
    ASSERT_EQ(::chmod(path("a.obj").c_str(), 0640), 0);
    fs::create_hard_link(path("a.obj"), path("b.obj"));
    const ino_t inode = status_of(path("a.obj")).st_ino;
    const std::string big(3 * AtomicFileWriter::kBufferBytes + 5, 'x');  // streamed, then copied in place
    write_file_atomically(path("a.obj"), big);
    EXPECT_EQ(status_of(path("a.obj")).st_ino, inode);
    EXPECT_EQ(status_of(path("b.obj")).st_ino, inode);
    EXPECT_EQ(status_of(path("a.obj")).st_nlink, 2u);
    EXPECT_EQ(status_of(path("a.obj")).st_mode & 07777, 0640u);
    EXPECT_TRUE(read(path("b.obj")) == big);
    write_file_atomically(path("b.obj"), "short\n");  // shrinking truncates
    EXPECT_EQ(read(path("a.obj")), "short\n");
    EXPECT_EQ(entries(), 2u);
}

// A size limit stops the temporary file (it has the final size) before the file is touched.
TEST_F(SaveTarget, HardLinkedFileOverTheSizeLimitIsUnchanged) {
    write("a.obj", "old\n");
    fs::create_hard_link(path("a.obj"), path("b.obj"));
    EXPECT_TRUE(in_child([&] {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        return save_error(path("a.obj"), std::string(1 << 20, 'x')) == "cannot save " + path("a.obj") + ": write failed: File too large";
    }));
    EXPECT_EQ(read(path("a.obj")), "old\n");
    EXPECT_EQ(entries(), 2u);
}

// A disk that is full for the claim of space in place, without mounting one: a seccomp filter (no
// privilege needed) answers fallocate, which only that claim calls, with ENOSPC as a full disk does,
// while the temporary file's writes go through.
bool refuse_space_claims() {
    sock_filter filter[] = {
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_fallocate, 0, 1),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | (ENOSPC & SECCOMP_RET_DATA)),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
    };
    const sock_fprog program{static_cast<unsigned short>(std::size(filter)), filter};
    return ::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 && ::prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &program) == 0;
}

// A full disk with room for the temporary file but not for the content in place: the space is
// claimed before the file is touched. Two disks, each in a child process: a 64 KiB tmpfs (16 pages)
// mounted in a private mount namespace, where this process may mount one (2 pages of old file + 10 of
// temporary file leave 4, and the file needs 8 more); and always, needing no privilege at all, the
// folder with its claims of space refused (refuse_space_claims).
TEST_F(SaveTarget, HardLinkedFileOnAFullDiskIsUnchanged) {
    fs::create_directory(folder_ / "disk");
    fs::create_directory(folder_ / "claims_refused");
    enum : int { kHeld = 0, kBroken = 1, kNoDisk = 2 };
    const auto save_on_a_full_disk = [&](const std::string& disk) {
        const std::string old(8 << 10, 'o');
        std::ofstream(disk + "/a.obj", std::ios::binary) << old;
        fs::create_hard_link(disk + "/a.obj", disk + "/b.obj");
        const std::string message = save_error(disk + "/a.obj", std::string(40 << 10, 'n'));
        const bool held = message == "cannot save " + disk + "/a.obj: no room for the new content (the file is unchanged): No space left on device" &&
                          read(disk + "/b.obj") == old && fs::hard_link_count(disk + "/a.obj") == 2 &&
                          std::distance(fs::directory_iterator(disk), fs::directory_iterator()) == 2;
        return int(held ? kHeld : kBroken);
    };
    const int on_tmpfs = test::wait_status_of_child([&] {
        const std::string disk = path("disk");
        if (!enter_private_mount_namespace() || ::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=64k") != 0) return int(kNoDisk);
        return save_on_a_full_disk(disk);
    });
    ASSERT_TRUE(WIFEXITED(on_tmpfs));
    if (WEXITSTATUS(on_tmpfs) == kNoDisk) std::cout << "no tmpfs could be mounted here: the refused claims alone stand for a full disk\n";
    else EXPECT_EQ(WEXITSTATUS(on_tmpfs), kHeld) << "on a full tmpfs";
    const int refused = test::wait_status_of_child([&] {
        if (!refuse_space_claims()) return int(kNoDisk);
        return save_on_a_full_disk(path("claims_refused"));
    });
    ASSERT_TRUE(WIFEXITED(refused));
    EXPECT_EQ(WEXITSTATUS(refused), kHeld) << "with every claim of space refused";
}

TEST_F(SaveTarget, ReadOnlyFileIsRefused) {
    write("mesh.obj", "old\n");
    ASSERT_EQ(::chmod(path("mesh.obj").c_str(), 0444), 0);
    EXPECT_EQ(save_error(path("mesh.obj")),
              "cannot save " + path("mesh.obj") + ": it is a read-only file (mode 0444); make it writable to replace it");
    EXPECT_EQ(read(path("mesh.obj")), "old\n");
    EXPECT_EQ(status_of(path("mesh.obj")).st_mode & 07777, 0444u);
    EXPECT_EQ(entries(), 1u);
}

TEST_F(SaveTarget, FifoIsRefusedAndLeftAFifo) {
    ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0644), 0);
    EXPECT_EQ(save_error(path("pipe")), "cannot save " + path("pipe") + ": it is a FIFO (named pipe); rgbsub saves only to regular files");
    fs::create_symlink("pipe", folder_ / "link.obj");
    EXPECT_EQ(save_error(path("link.obj")), "cannot save " + path("link.obj") + ": it leads to " + folder_.string() +
                                                "/pipe, a FIFO (named pipe); rgbsub saves only to regular files");
    EXPECT_TRUE(fs::is_fifo(path("pipe")));
    EXPECT_EQ(entries(), 2u);
}

// /dev/stdout leads through /proc/self/fd/1 to "pipe:[N]" when the output is piped: a link that
// names no path. The same link to a pipe of the test's own, reached through /proc.
TEST_F(SaveTarget, ProcLinkToAPipeIsRefused) {
    int ends[2];
    ASSERT_EQ(::pipe(ends), 0);
    const std::string link = "/proc/self/fd/" + std::to_string(ends[1]);
    EXPECT_EQ(save_error(link), "cannot save " + link + ": it leads to a FIFO (named pipe); rgbsub saves only to regular files");
    ::close(ends[0]);
    ::close(ends[1]);
}

TEST_F(SaveTarget, SocketIsRefused) {
    const int listener = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    ASSERT_LT(path("socket").size(), sizeof address.sun_path);
    path("socket").copy(address.sun_path, sizeof address.sun_path - 1);
    ASSERT_EQ(::bind(listener, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    EXPECT_EQ(save_error(path("socket")), "cannot save " + path("socket") + ": it is a socket; rgbsub saves only to regular files");
    EXPECT_TRUE(fs::is_socket(path("socket")));
    ::close(listener);
}

// A character device made in the test's own folder (the numbers of /dev/null, which discards
// writes, so nothing could be harmed even if the refusal failed).
TEST_F(SaveTarget, CharacterDeviceIsRefused) {
    ASSERT_EQ(::mknod(path("null").c_str(), S_IFCHR | 0666, ::makedev(1, 3)), 0)
        << "cannot create a character device here: run the tests as root (./test.sh does)";
    EXPECT_EQ(save_error(path("null")), "cannot save " + path("null") + ": it is a character device; rgbsub saves only to regular files");
    EXPECT_TRUE(fs::is_character_file(path("null")));
    EXPECT_EQ(entries(), 1u);
}

TEST_F(SaveTarget, FoldersAndEmptyNamesAreRefused) {
    fs::create_directory(folder_ / "sub");
    EXPECT_EQ(save_error(path("sub")), "cannot save " + path("sub") + ": it is a folder; rgbsub saves only to regular files");
    EXPECT_EQ(save_error(path("sub") + "/"), "cannot save " + path("sub") + "/: the name ends with '/', so it names a folder, not a file");
    EXPECT_EQ(save_error(""), "cannot save '': the file name is empty");
    EXPECT_TRUE(fs::is_empty(folder_ / "sub"));
    EXPECT_EQ(entries(), 1u);
}

// What an output's extension selects (glTF binary or JSON, ...) does not depend on its case.
TEST(SaveExtension, ComparedWithoutRegardToCase) {
    EXPECT_TRUE(has_extension("out/NAME.GLB", ".glb"));
    EXPECT_TRUE(has_extension("name.Gltf", ".gltf"));
    EXPECT_TRUE(has_extension("name.glb", ".glb"));
    EXPECT_FALSE(has_extension("name.glbx", ".glb"));
    EXPECT_FALSE(has_extension("glb", ".glb"));
    EXPECT_FALSE(has_extension("name.glb/", ".glb"));
}

}  // namespace
}  // namespace rgbio
