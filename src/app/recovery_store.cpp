#include "app/recovery_store.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>

#include <signal.h>

#include "io/files/atomic_file.h"

namespace app {
namespace {

constexpr const char* kNoteHeader = "rgbsub recovery 1";

bool process_running(int pid) { return pid > 0 && (::kill(pid, 0) == 0 || errno != ESRCH); }

// The process id in "recovery-PID.txt", if the name has that form.
std::optional<int> note_owner(const std::filesystem::path& file) {
    const std::string name = file.filename().string();
    const std::string prefix = "recovery-", suffix = ".txt";
    if (!name.starts_with(prefix) || !name.ends_with(suffix) || name.size() <= prefix.size() + suffix.size()) return std::nullopt;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }) || digits.size() > 9) return std::nullopt;
    return std::stoi(digits);
}

}  // namespace

RecoveryStore::RecoveryStore(std::filesystem::path folder, int process_id) : folder_(std::move(folder)), process_id_(process_id) {}

std::optional<std::filesystem::path> RecoveryStore::default_folder() {
    if (const char* state = std::getenv("XDG_STATE_HOME"); state != nullptr && *state == '/') return std::filesystem::path(state) / "rgbsub";
    if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') return std::filesystem::path(home) / ".local/state/rgbsub";
    return std::nullopt;
}

std::filesystem::path RecoveryStore::mesh_file() const { return folder_ / ("recovery-" + std::to_string(process_id_) + ".obj"); }

std::filesystem::path RecoveryStore::note_file() const { return folder_ / ("recovery-" + std::to_string(process_id_) + ".txt"); }

void RecoveryStore::make_folder() const {
    if (std::filesystem::create_directories(folder_)) std::filesystem::permissions(folder_, std::filesystem::perms::owner_all);
}

// Absolute: the session that recovers may run in another working folder.
void RecoveryStore::write_note(const std::string& document_path) const {
    std::error_code error;
    const std::string absolute =
        document_path.empty() ? document_path : std::filesystem::absolute(document_path, error).lexically_normal().string();
    rgbio::write_file_atomically(note_file().string(), std::string(kNoteHeader) + "\n" + (error ? document_path : absolute) + "\n");
}

void RecoveryStore::remove_own() const {
    std::error_code ignored;
    std::filesystem::remove(note_file(), ignored);
    std::filesystem::remove(mesh_file(), ignored);
}

std::vector<RecoveryStore::Orphan> RecoveryStore::orphans() const {
    std::vector<Orphan> found;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder_, error)) {
        const std::optional<int> owner = note_owner(entry.path());
        if (!owner || *owner == process_id_ || process_running(*owner)) continue;
        Orphan orphan;
        orphan.note_file = entry.path();
        orphan.mesh_file = entry.path();
        orphan.mesh_file.replace_extension(".obj");
        std::ifstream note(orphan.note_file);
        std::string header;
        if (!std::getline(note, header) || header != kNoteHeader || !std::filesystem::is_regular_file(orphan.mesh_file, error)) continue;
        std::getline(note, orphan.document_path);
        orphan.written = std::filesystem::last_write_time(orphan.mesh_file, error);
        found.push_back(std::move(orphan));
    }
    std::sort(found.begin(), found.end(), [](const Orphan& a, const Orphan& b) { return a.written > b.written; });
    return found;
}

void RecoveryStore::remove(const Orphan& orphan) {
    std::error_code ignored;
    std::filesystem::remove(orphan.note_file, ignored);
    std::filesystem::remove(orphan.mesh_file, ignored);
}

}  // namespace app
