#pragma once
// Folder io/files (atomic saving, save targets, temporary cleanup, reading files): includes io/obj
// and the core.
// Saving a file so that nothing is lost: readers see either the old or the complete new content,
// a failed or interrupted save leaves the old file as it was and no temporary file behind.
//
// How: the content is streamed into a temporary file (mkstemp: a unique name) in the real file's
// folder, every write checked; then it is fsynced, given the old file's mode and owner (a new file
// gets 0666 minus the umask) and renamed over the real file (atomic within one file system), and the
// folder is fsynced. Where the target is (symbolic links followed, non-regular and read-only targets
// refused) is decided by save_target.h. SIGINT, SIGTERM and SIGHUP during a save remove the
// temporary file (temporary_cleanup.h). The temporary name is the file's name (shortened to fit the
// 255-byte limit on names) plus ".tmp-rgbsub-PID-XXXXXX", so that the next save into the folder can
// remove one that a save killed by another signal left (temporary_names.h).
//
// Written in place instead, like `cp` would: an existing file with several hard links (a rename would
// make the name a new inode and split it from its other links) and an existing file whose owner or
// group this process cannot give to a new file (it belongs to someone else). The complete content is
// still prepared in the temporary file first; then space for it is reserved in the file (fallocate),
// so a full disk or a size limit is reported before the file is touched; the file is overwritten,
// truncated and fsynced with SIGINT, SIGTERM and SIGHUP held back. That phase is not atomic against
// a crash or an I/O error: if a write fails there, the temporary file is kept (renamed
// NAME.new-rgbsub-PID-XXXXXX) and the error names it, as it then holds the only complete copy. That phase holds an exclusive flock on the file, so two
// saves in place at the same time take turns and the file ends as one of them, whole.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace rgbio {

class AtomicFileWriter {
public:
    // Write out the buffer once it holds this much: a few large writes, little memory.
    static constexpr std::size_t kBufferBytes = std::size_t{4} << 20;
    // What a record appended past kBufferBytes before flush_if_full usually needs.
    static constexpr std::size_t kRecordRoom = std::size_t{64} << 10;

    // Resolves the target and creates the temporary file. Throws SaveError.
    explicit AtomicFileWriter(const std::string& path);
    // Without commit(): removes the temporary file; the target stays as it was.
    ~AtomicFileWriter();
    AtomicFileWriter(const AtomicFileWriter&) = delete;
    AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

    void write(std::string_view chunk);
    // For formatting in place: append to buffer(), then call flush_if_full() between records.
    std::string& buffer() { return buffer_; }
    void flush_if_full() {
        if (buffer_.size() >= kBufferBytes) flush();
    }
    // Writes the rest and replaces the target. Throws SaveError; the target is then untouched (except
    // for an I/O error while writing in place, see above).
    void commit();

private:
    struct Temporary;
    void flush();
    void write_out(std::string_view bytes);
    void replace_by_rename();
    void overwrite_in_place();

    std::string named_;  // as the user gave it, for messages
    std::unique_ptr<Temporary> temporary_;
    std::string buffer_;
    std::size_t size_ = 0;  // bytes in the temporary file
    bool in_place_ = false;
};

// The whole content at once. Throws SaveError.
void write_file_atomically(const std::string& path, std::string_view content);

}  // namespace rgbio
