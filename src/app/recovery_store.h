#pragma once
// Where the editor keeps a recovery copy of unsaved work, and finding the copies that sessions which
// did not exit cleanly left behind. Each session writes `recovery-PID.obj` (a saved file, state
// included, so it resumes exactly) and then `recovery-PID.txt` naming the document's own file; a
// copy whose process no longer runs is an orphan, offered at the next start.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace app {

class RecoveryStore {
public:
    // The folder is made when first written to.
    RecoveryStore(std::filesystem::path folder, int process_id);
    // $XDG_STATE_HOME/rgbsub, or ~/.local/state/rgbsub; none without either variable.
    static std::optional<std::filesystem::path> default_folder();

    // This session's copy: the mesh, and the note written after it.
    std::filesystem::path mesh_file() const;
    std::filesystem::path note_file() const;
    // Makes the folder, private to the user. Throws std::filesystem::filesystem_error.
    void make_folder() const;
    // Writes the note (atomically), the document's path made absolute. Throws rgbio::SaveError.
    void write_note(const std::string& document_path) const;
    // Removes this session's copy (a clean exit, or nothing left unsaved).
    void remove_own() const;

    struct Orphan {
        std::filesystem::path mesh_file, note_file;
        std::string document_path;  // empty for an untitled document
        std::filesystem::file_time_type written;
    };
    // Complete copies of sessions that are no longer running, newest first.
    std::vector<Orphan> orphans() const;
    static void remove(const Orphan& orphan);

private:
    std::filesystem::path folder_;
    int process_id_;
};

}  // namespace app
