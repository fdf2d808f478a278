#include "io/files/file_text.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <functional>
#include <mutex>
#include <string>
#include <utility>

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/obj/obj_error.h"
#include "rgb/support/parallel.h"

namespace rgbio {

namespace {

// Files from this size on are mapped; below it, a copy costs less than a mapping and its handler.
constexpr std::size_t kMapFrom = std::size_t(4) << 20;
// Read (or brought in) in pieces of this size, so that the progress moves on a slow disk.
constexpr std::size_t kPieceBytes = std::size_t(16) << 20;
const char* const kShrank = "the file shrank while reading";
// A file whose size the system does not say (stat gives 0 for /proc's files) is read to its end, up
// to this much.
constexpr std::size_t kMaxUnsizedBytes = std::size_t(64) << 20;

// The bytes of `fd` up to its end; empty when it has none.
std::string read_to_end(int fd, const std::function<ObjError(const std::string&)>& unreadable) {
    std::string content;
    char chunk[1 << 16];
    for (;;) {
        const ssize_t got = ::read(fd, chunk, sizeof chunk);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) throw unreadable(std::strerror(errno));
        if (got == 0) return content;
        if (content.size() + static_cast<std::size_t>(got) > kMaxUnsizedBytes)
            throw unreadable("its size is not given (a /proc or other system file) and it holds more than " +
                             std::to_string(kMaxUnsizedBytes >> 20) + " MiB");
        content.append(chunk, static_cast<std::size_t>(got));
    }
}

// The mapped files being read, for the SIGBUS handler, which may take no lock: a slot is free while
// begin is 0, claimed (by compare-exchange) while it is 1, and in use once it is the first byte.
struct Watched {
    std::atomic<std::uintptr_t> begin{0}, end{0};
    std::atomic<bool> shrunk{false};
};
constexpr std::size_t kWatchedMappings = 64;
Watched watched[kWatchedMappings];
struct sigaction sigbus_before;
std::uintptr_t page_size = 4096;

// A SIGBUS in a watched mapping is a page beyond the end of a file that shrank: the page becomes
// zeros (the access then goes on) and the mapping is marked. Any other SIGBUS goes where it went
// before this handler was installed.
void on_sigbus(int signal, siginfo_t* info, void* context) {
    const auto address = reinterpret_cast<std::uintptr_t>(info->si_addr);
    for (Watched& w : watched) {
        const std::uintptr_t begin = w.begin.load(std::memory_order_acquire);
        if (begin <= 1 || address < begin || address >= w.end.load(std::memory_order_acquire)) continue;
        void* page = reinterpret_cast<void*>(address & ~(page_size - 1));
        if (::mmap(page, page_size, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) == MAP_FAILED) break;
        w.shrunk.store(true, std::memory_order_relaxed);
        return;
    }
    if (sigbus_before.sa_flags & SA_SIGINFO) {
        sigbus_before.sa_sigaction(signal, info, context);
    } else if (sigbus_before.sa_handler != SIG_DFL && sigbus_before.sa_handler != SIG_IGN) {
        sigbus_before.sa_handler(signal);
    } else {
        // The access faults again on return, and the signal then takes its default course.
        ::sigaction(SIGBUS, &sigbus_before, nullptr);
    }
}

// Watches [begin, begin + size); null when every slot is taken (the file is then read, not mapped).
std::atomic<bool>* watch(const char* begin, std::size_t size) {
    static std::once_flag installed;
    std::call_once(installed, [] {
        page_size = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
        struct sigaction action {};
        action.sa_sigaction = on_sigbus;
        action.sa_flags = SA_SIGINFO;
        sigemptyset(&action.sa_mask);
        ::sigaction(SIGBUS, &action, &sigbus_before);
    });
    for (Watched& w : watched) {
        std::uintptr_t free = 0;
        if (!w.begin.compare_exchange_strong(free, 1)) continue;
        w.shrunk.store(false, std::memory_order_relaxed);
        w.end.store(reinterpret_cast<std::uintptr_t>(begin) + size, std::memory_order_release);
        w.begin.store(reinterpret_cast<std::uintptr_t>(begin), std::memory_order_release);
        return &w.shrunk;
    }
    return nullptr;
}

void unwatch(std::atomic<bool>* shrunk) {
    for (Watched& w : watched)
        if (&w.shrunk == shrunk) {
            w.end.store(0, std::memory_order_release);
            w.begin.store(0, std::memory_order_release);
        }
}

}  // namespace

FileText::FileText(FileText&& other) noexcept { *this = std::move(other); }

FileText& FileText::operator=(FileText&& other) noexcept {
    if (this == &other) return *this;
    release();
    path_ = std::move(other.path_);
    bytes_ = std::move(other.bytes_);
    mapped_ = std::exchange(other.mapped_, nullptr);
    size_ = std::exchange(other.size_, 0);
    shrunk_ = std::exchange(other.shrunk_, nullptr);
    shrank_ = std::exchange(other.shrank_, false);
    return *this;
}

void FileText::release() {
    if (mapped_) {
        shrank_ = shrank_ || shrunk_->load(std::memory_order_relaxed);
        // Unwatched first: once unmapped, the addresses may be another mapping's.
        unwatch(shrunk_);
        ::munmap(mapped_, size_);
        mapped_ = nullptr;
        shrunk_ = nullptr;
    }
    bytes_.reset();
    size_ = 0;
}

void FileText::check_not_shrunk() const {
    if (shrank_ || (shrunk_ && shrunk_->load(std::memory_order_relaxed)))
        throw ObjError(ObjProblem::Unreadable, path_, 0, std::string("cannot read the file: ") + kShrank);
}

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
    text.path_ = path;
    if (info.st_size == 0) {
        // Empty, or a system file whose size stat does not give: reading tells which.
        std::string content;
        try {
            content = read_to_end(fd, unreadable);
        } catch (...) {
            ::close(fd);
            throw;
        }
        ::close(fd);
        text.size_ = content.size();
        text.bytes_.reset(new char[content.size()]);
        std::memcpy(text.bytes_.get(), content.data(), content.size());
        progress.done();
        return text;
    }
    text.size_ = static_cast<std::size_t>(info.st_size);
    rgb::ProgressCounter read(progress, text.size_);
    const std::size_t blocks = rgb::parallel_blocks(text.size_, 4 * kPieceBytes);
    if (text.size_ >= kMapFrom) {
        void* mapped = ::mmap(nullptr, text.size_, PROT_READ, MAP_PRIVATE, fd, 0);
        if (mapped != MAP_FAILED) {
            text.mapped_ = static_cast<char*>(mapped);
            text.shrunk_ = watch(text.mapped_, text.size_);
            if (!text.shrunk_) {
                ::munmap(mapped, text.size_);
                text.mapped_ = nullptr;
            }
        }
    }
    if (text.mapped_) {
        ::close(fd);
        // The pages brought in now, in parallel pieces, rather than one fault at a time by the parse.
        // A kernel without MADV_POPULATE_READ (before Linux 5.14) brings them in as the parse reads.
        try {
            rgb::parallel_blocks_for(text.size_, blocks, [&](std::size_t, std::size_t begin, std::size_t end) {
                begin = begin / page_size * page_size;
                for (std::size_t done = begin; done < end;) {
                    const std::size_t piece = std::min(end - done, kPieceBytes);
                    if (::madvise(text.mapped_ + done, piece, MADV_POPULATE_READ) != 0 && errno != EINVAL && errno != EINTR)
                        throw unreadable(errno == EFAULT ? kShrank : std::strerror(errno));
                    done += piece;
                    read.add(piece);
                }
            });
        } catch (...) {
            text.release();
            throw;
        }
        progress.done();
        return text;
    }
    text.bytes_.reset(new char[text.size_]);
    try {
        rgb::parallel_blocks_for(text.size_, blocks, [&](std::size_t, std::size_t begin, std::size_t end) {
            for (std::size_t done = begin; done < end;) {
                const ssize_t got = ::pread(fd, text.bytes_.get() + done, std::min(end - done, kPieceBytes), static_cast<off_t>(done));
                if (got < 0 && errno == EINTR) continue;
                if (got <= 0) throw unreadable(got < 0 ? std::strerror(errno) : kShrank);
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
    const FileText text = read_file_text(path, progress);
    std::string copy(text.view());
    text.check_not_shrunk();
    return copy;
}

}  // namespace rgbio
