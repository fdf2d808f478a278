#include "io/files/save_target.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "io/obj/obj_error.h"

namespace rgbio {

bool has_extension(const std::string& path, std::string_view extension) {
    const std::string actual = std::filesystem::path(path).extension().string();
    return std::equal(actual.begin(), actual.end(), extension.begin(), extension.end(),
                      [](unsigned char a, unsigned char b) { return std::tolower(a) == std::tolower(b); });
}
namespace {

constexpr int kMaxLinkHops = 40;  // as the kernel's own limit on nested symbolic links

[[noreturn]] void refuse(const std::string& named, const std::string& reason) {
    throw SaveError("cannot save " + (named.empty() ? std::string("''") : named) + ": " + reason);
}

const char* kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

std::string folder_of(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string read_link(const std::string& link, const std::string& named) {
    std::vector<char> buffer(256);
    for (;;) {
        const ssize_t length = ::readlink(link.c_str(), buffer.data(), buffer.size());
        if (length < 0) refuse(named, std::string("cannot read the symbolic link ") + link + ": " + std::strerror(errno));
        if (static_cast<std::size_t>(length) < buffer.size()) return std::string(buffer.data(), static_cast<std::size_t>(length));
        buffer.resize(2 * buffer.size());
    }
}

}  // namespace

SaveTarget resolve_save_target(const std::string& named) {
    if (named.empty()) refuse(named, "the file name is empty");
    if (named.back() == '/') refuse(named, "the name ends with '/', so it names a folder, not a file");
    std::string path = named;
    for (int hop = 0;; ++hop) {
        struct stat entry {};
        if (::lstat(path.c_str(), &entry) != 0) {
            // A "magic" link of /proc (what /dev/stdout leads to) names no path, e.g. "pipe:[123]";
            // the kernel still follows it, and what it reaches must be a regular file too.
            struct stat reached {};
            if (hop > 0 && ::stat(named.c_str(), &reached) == 0 && !S_ISREG(reached.st_mode))
                refuse(named, std::string("it leads to ") + kind_of(reached.st_mode) + "; rgbsub saves only to regular files");
            // Anything else lstat cannot see (no such file, parent not a folder, no access) is left to
            // the creation of the temporary file, whose error names the folder's problem.
            return {path, folder_of(path), path.substr(path.rfind('/') + 1), std::nullopt};
        }
        if (!S_ISLNK(entry.st_mode)) {
            const std::string via = path == named ? "it is " : "it leads to " + path + ", ";
            if (!S_ISREG(entry.st_mode))
                refuse(named, via + kind_of(entry.st_mode) + "; rgbsub saves only to regular files");
            if ((entry.st_mode & 0222) == 0) {
                char mode[8];
                std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(entry.st_mode & 07777));
                refuse(named, via + "a read-only file (mode " + mode + "); make it writable to replace it");
            }
            if (::faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) != 0)
                refuse(named, via + "a file this user may not write: " + std::strerror(errno));
            return {path, folder_of(path), path.substr(path.rfind('/') + 1), entry};
        }
        if (hop == kMaxLinkHops) refuse(named, "too many levels of symbolic links");
        const std::string target = read_link(path, named);
        path = target.starts_with('/') ? target : folder_of(path) + "/" + target;
    }
}

}  // namespace rgbio
