#include "io/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/obj_error.h"

namespace rgbio {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
    throw SaveError("cannot save " + path + ": " + what + ": " + std::strerror(error));
}

// Closes the descriptor and removes the temporary file unless the rename went through.
class TemporaryFile {
public:
    TemporaryFile(const std::string& target) : path_(target + ".tmp-XXXXXX") {
        fd_ = ::mkstemp(path_.data());
        if (fd_ < 0) fail(target, "cannot create a temporary file in its folder", errno);
    }
    ~TemporaryFile() {
        if (fd_ >= 0) ::close(fd_);
        if (!committed_) ::unlink(path_.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    int fd() const { return fd_; }
    const std::string& path() const { return path_; }
    int close() {
        const int result = ::close(fd_);
        fd_ = -1;
        return result;
    }
    void committed() { committed_ = true; }

private:
    std::string path_;
    int fd_ = -1;
    bool committed_ = false;
};

}  // namespace

void write_file_atomically(const std::string& path, std::string_view content) {
    TemporaryFile temporary(path);
    while (!content.empty()) {
        const ssize_t written = ::write(temporary.fd(), content.data(), content.size());
        if (written < 0) {
            if (errno == EINTR) continue;
            fail(path, "write failed", errno);
        }
        content.remove_prefix(static_cast<std::size_t>(written));
    }
    // A new file gets the usual permissions (mkstemp creates it 0600).
    const mode_t mask = ::umask(0);
    ::umask(mask);
    if (::fchmod(temporary.fd(), 0666 & ~mask) != 0) fail(path, "cannot set permissions", errno);
    if (::fsync(temporary.fd()) != 0) fail(path, "flushing to disk failed", errno);
    if (temporary.close() != 0) fail(path, "closing failed", errno);
    if (::rename(temporary.path().c_str(), path.c_str()) != 0) fail(path, "cannot replace the file", errno);
    temporary.committed();
    // Make the rename itself durable.
    const std::string folder = std::filesystem::path(path).parent_path().empty() ? "." : std::filesystem::path(path).parent_path().string();
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

}  // namespace rgbio
