#include "io/file_text.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/obj_error.h"
#include "rgb/parallel.h"

namespace rgbio {

FileText read_file_text(const std::string& path, const rgb::ProgressSpan& progress) {
    auto unreadable = [&](const std::string& why) { return ObjError(ObjProblem::Unreadable, path, 0, "cannot read the file: " + why); };
    // O_NONBLOCK: opening a FIFO must not wait for a writer; the check below refuses it anyway.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw unreadable(std::strerror(errno));
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        ::close(fd);
        throw unreadable(S_ISDIR(info.st_mode) ? "it is a directory" : "it is not a regular file");
    }
    FileText text;
    text.size_ = static_cast<std::size_t>(info.st_size);
    text.bytes_.reset(new char[text.size_]);
    // Each block in pieces, so that the progress moves while a large file comes off a slow disk.
    constexpr std::size_t kPieceBytes = std::size_t(16) << 20;
    rgb::ProgressCounter read(progress, text.size_);
    try {
        rgb::parallel_blocks_for(text.size_, rgb::parallel_blocks(text.size_, 4 * kPieceBytes), [&](std::size_t, std::size_t begin, std::size_t end) {
            for (std::size_t done = begin; done < end;) {
                const ssize_t got = ::pread(fd, text.bytes_.get() + done, std::min(end - done, kPieceBytes), static_cast<off_t>(done));
                if (got < 0 && errno == EINTR) continue;
                if (got <= 0) throw unreadable(got < 0 ? std::strerror(errno) : "the file shrank while reading");
                done += static_cast<std::size_t>(got);
                read.add(static_cast<std::uint64_t>(got));
            }
        });
    } catch (...) {
        ::close(fd);
        throw;
    }
    ::close(fd);
    progress.done();
    return text;
}

std::string read_text_file(const std::string& path, const rgb::ProgressSpan& progress) {
    return std::string(read_file_text(path, progress).view());
}

}  // namespace rgbio
