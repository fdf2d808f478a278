#include "io/files/atomic_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/files/save_target.h"
#include "io/files/temporary_cleanup.h"
#include "io/files/temporary_names.h"
#include "io/obj/obj_error.h"

namespace rgbio {

namespace {

[[noreturn]] void fail(const std::string& named, const std::string& what, int error) {
    throw SaveError("cannot save " + named + ": " + what + ": " + std::strerror(error));
}

mode_t current_umask() {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return mask;
}

}  // namespace

// The temporary file: created next to the real file, removed on destruction unless renamed into
// place or kept as the only complete copy.
struct AtomicFileWriter::Temporary {
    Temporary(SaveTarget resolved, const std::string& named)
        : target(std::move(resolved)), path(temporary_pattern(target.folder, target.name)) {
        // What saves killed before they could clean up left here (temporary_names.h).
        remove_stale_temporaries(target.folder);
        // A termination signal between creating the file and registering it would leave the file:
        // it waits until the registration is made.
        const DeferredTerminationSignals held;
        fd = ::mkostemp(path.data(), O_CLOEXEC);
        if (fd < 0) fail(named, "cannot create a temporary file in its folder", errno);
        registration = std::make_unique<TemporaryRegistration>(path.c_str());
        // Held while this process lives: a save in another pid namespace sees the file in use.
        ::flock(fd, LOCK_SH | LOCK_NB);
    }
    ~Temporary() {
        if (fd >= 0) ::close(fd);
        if (!gone && !kept) ::unlink(path.c_str());
        // After the unlink: a signal in between finds the name already gone, which is harmless.
        registration.reset();
    }
    Temporary(const Temporary&) = delete;
    Temporary& operator=(const Temporary&) = delete;

    SaveTarget target;
    std::string path;
    int fd = -1;
    std::unique_ptr<TemporaryRegistration> registration;
    bool gone = false;  // renamed into place
    bool kept = false;  // holds the only complete copy after a failed write in place
};

AtomicFileWriter::AtomicFileWriter(const std::string& path)
    : named_(path), temporary_(std::make_unique<Temporary>(resolve_save_target(path), path)) {
    const int fd = temporary_->fd;
    if (const auto& existing = temporary_->target.existing) {
        // A new inode would split the file from its other hard links, or change its owner.
        in_place_ = existing->st_nlink > 1 || ::fchown(fd, existing->st_uid, existing->st_gid) != 0;
        // After fchown, which may clear set-user-ID bits.
        if (!in_place_ && ::fchmod(fd, existing->st_mode & 07777) != 0) fail(named_, "cannot set permissions", errno);
    } else if (::fchmod(fd, 0666 & ~current_umask()) != 0) {  // mkstemp made it 0600
        fail(named_, "cannot set permissions", errno);
    }
    // At its full size at once, with room for the record that crosses it: grown by doubling, the
    // buffer took fresh pages at each step (twice its size in page faults).
    buffer_.reserve(kBufferBytes + kRecordRoom);
}

AtomicFileWriter::~AtomicFileWriter() = default;

void AtomicFileWriter::write(std::string_view chunk) {
    if (buffer_.size() + chunk.size() < kBufferBytes) {
        buffer_ += chunk;
        return;
    }
    flush();
    write_out(chunk);
}

void AtomicFileWriter::flush() {
    write_out(buffer_);
    buffer_.clear();
}

void AtomicFileWriter::write_out(std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t written = ::write(temporary_->fd, bytes.data(), bytes.size());
        if (written < 0) {
            if (errno == EINTR) continue;
            fail(named_, "write failed", errno);
        }
        bytes.remove_prefix(static_cast<std::size_t>(written));
        size_ += static_cast<std::size_t>(written);
    }
}

void AtomicFileWriter::commit() {
    flush();
    if (::fsync(temporary_->fd) != 0) fail(named_, "flushing to disk failed", errno);
    if (in_place_) overwrite_in_place();
    else replace_by_rename();
    temporary_.reset();
}

void AtomicFileWriter::replace_by_rename() {
    Temporary& temporary = *temporary_;
    const int fd = std::exchange(temporary.fd, -1);
    if (::close(fd) != 0) fail(named_, "closing failed", errno);
    if (::rename(temporary.path.c_str(), temporary.target.path.c_str()) != 0) fail(named_, "cannot replace the file", errno);
    temporary.gone = true;
    // Make the rename itself durable.
    const int folder = ::open(temporary.target.folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
}

void AtomicFileWriter::overwrite_in_place() {
    Temporary& temporary = *temporary_;
    const struct stat& before = *temporary.target.existing;
    const int file = ::open(temporary.target.path.c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC);
    if (file < 0) fail(named_, "cannot open it for writing", errno);
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }  // also releases the lock
    } closer{file};
    // Another save in place of this file (through any of its names) waits until this one is done:
    // two overlapping would leave a mix of both, or one cut to the other's length.
    while (::flock(file, LOCK_EX) != 0)
        if (errno != EINTR) fail(named_, "cannot lock it for writing", errno);
    struct stat now {};
    if (::fstat(file, &now) != 0 || now.st_dev != before.st_dev || now.st_ino != before.st_ino)
        throw SaveError("cannot save " + named_ + ": the file was replaced by another program while saving; nothing written");
    // A full disk must fail before the file is touched: reserve the blocks first (beyond the current
    // end, without changing the file's size or content). A file-size limit already stopped the
    // temporary file, which has the same size.
    if (::fallocate(file, FALLOC_FL_KEEP_SIZE, 0, static_cast<off_t>(size_)) != 0 && errno != EOPNOTSUPP && errno != ENOSYS)
        fail(named_, "no room for the new content (the file is unchanged)", errno);

    const DeferredTerminationSignals held;
    const auto failed_midway = [&](const char* what) {
        const int error = errno;
        temporary.kept = true;
        temporary.registration->release();
        // Under a name no later save removes as a stale temporary.
        if (const std::string kept = kept_temporary_name(temporary.path); ::rename(temporary.path.c_str(), kept.c_str()) == 0)
            temporary.path = kept;
        fail(named_, std::string(what) + " (the file is now incomplete; the complete content is in " + temporary.path + ")", error);
    };
    buffer_.resize(std::size_t{1} << 20);
    for (std::size_t offset = 0; offset < size_;) {
        const ssize_t got = ::pread(temporary.fd, buffer_.data(), std::min(buffer_.size(), size_ - offset), static_cast<off_t>(offset));
        if (got <= 0) {
            if (got < 0 && errno == EINTR) continue;
            if (got == 0) errno = EIO;
            failed_midway("reading the prepared content back failed");
        }
        for (std::size_t done = 0; done < static_cast<std::size_t>(got);) {
            const ssize_t put = ::pwrite(file, buffer_.data() + done, static_cast<std::size_t>(got) - done, static_cast<off_t>(offset + done));
            if (put < 0) {
                if (errno == EINTR) continue;
                failed_midway("writing in place failed");
            }
            done += static_cast<std::size_t>(put);
        }
        offset += static_cast<std::size_t>(got);
    }
    buffer_.clear();
    if (::ftruncate(file, static_cast<off_t>(size_)) != 0) failed_midway("truncating failed");
    if (::fsync(file) != 0) failed_midway("flushing to disk failed");
}

void write_file_atomically(const std::string& path, std::string_view content) {
    AtomicFileWriter writer(path);
    writer.write(content);
    writer.commit();
}

}  // namespace rgbio
