#include "io/files/temporary_names.h"

#include <cerrno>
#include <charconv>
#include <memory>
#include <optional>
#include <string_view>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rgbio {

namespace {

constexpr std::size_t kMaxNameBytes = 255;  // NAME_MAX of Linux file systems
// The kept name's mark has the temporary mark's length, so a renamed name still fits.
constexpr std::string_view kTemporaryMark = ".tmp-rgbsub-", kKeptMark = ".new-rgbsub-";
static_assert(kTemporaryMark.size() == kKeptMark.size());
constexpr std::size_t kPidDigits = 10;                   // any pid_t
constexpr std::string_view kUniqueLetters = "-XXXXXX";  // mkstemp's, after the pid

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_alphanumeric(char c) { return is_digit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// The process id in a name of temporary_pattern's form, or nothing for any other name.
std::optional<pid_t> temporary_pid(std::string_view name) {
    const std::size_t mark = name.rfind(kTemporaryMark);
    if (mark == std::string_view::npos) return std::nullopt;
    const std::string_view rest = name.substr(mark + kTemporaryMark.size());
    pid_t pid = 0;
    const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), pid);
    const std::size_t digits = static_cast<std::size_t>(end - rest.data());
    if (ec != std::errc() || digits == 0 || digits > kPidDigits || !is_digit(rest[0]) || pid <= 0) return std::nullopt;
    const std::string_view letters = rest.substr(digits);
    if (letters.size() != kUniqueLetters.size() || letters[0] != '-') return std::nullopt;
    for (char c : letters.substr(1))
        if (!is_alphanumeric(c)) return std::nullopt;
    return pid;
}

bool process_is_gone(pid_t pid) { return pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH; }

// Removes `name` in `folder` if it is a regular file of this user that no process holds a lock on.
void remove_if_unlocked(int folder, const char* name) {
    const int fd = ::openat(folder, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return;
    struct stat info {};
    if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_uid == ::geteuid() && ::flock(fd, LOCK_EX | LOCK_NB) == 0)
        ::unlinkat(folder, name, 0);
    ::close(fd);  // also releases the lock
}

}  // namespace

std::string temporary_pattern(const std::string& folder, const std::string& name) {
    std::string shortened = name;
    const std::size_t room = kMaxNameBytes - kTemporaryMark.size() - kPidDigits - kUniqueLetters.size();
    if (shortened.size() > room) {
        std::size_t cut = room;
        while (cut > 0 && (static_cast<unsigned char>(shortened[cut]) & 0xC0) == 0x80) --cut;
        shortened.resize(cut);
    }
    return folder + "/" + shortened + std::string(kTemporaryMark) + std::to_string(::getpid()) + std::string(kUniqueLetters);
}

std::string kept_temporary_name(const std::string& path) {
    std::string kept = path;
    const std::size_t mark = kept.rfind(kTemporaryMark);
    if (mark != std::string::npos) kept.replace(mark, kTemporaryMark.size(), kKeptMark);
    return kept;
}

void remove_stale_temporaries(const std::string& folder) {
    const std::unique_ptr<DIR, int (*)(DIR*)> entries(::opendir(folder.c_str()), ::closedir);
    if (!entries) return;
    const int folder_fd = ::dirfd(entries.get());
    while (const dirent* entry = ::readdir(entries.get())) {
        const std::optional<pid_t> pid = temporary_pid(entry->d_name);
        if (pid && process_is_gone(*pid)) remove_if_unlocked(folder_fd, entry->d_name);
    }
}

}  // namespace rgbio
