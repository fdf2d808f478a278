#pragma once
// Reading a whole file into memory. A saved 6M-triangle file is 370 MB. A large file is mapped
// rather than copied (read into fresh memory, every page was zero-filled by the kernel and then
// written again: about a fifth of the system time of loading such a file); its pages are brought
// in by parallel pieces so that the progress moves while a large file comes off a slow disk. A
// small file (or one that cannot be mapped) is read into memory whose bytes are not initialised, by
// parallel preads.
//
// A mapped file that another program truncates while it is being read would end the process with
// SIGBUS at the first access beyond its new end. A handler (installed with the first mapping, and
// passing every other SIGBUS on to the handler before it) puts zero bytes in place of the missing
// pages instead and marks the text as shrunk: the reader then reports "the file shrank while
// reading" (check_not_shrunk) whatever it made of the zeros.
#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "rgb/support/progress.h"

namespace rgbio {

class FileText {
public:
    FileText() = default;
    FileText(FileText&& other) noexcept;
    FileText& operator=(FileText&& other) noexcept;
    ~FileText() { release(); }

    std::string_view view() const { return {mapped_ ? mapped_ : bytes_.get(), size_}; }
    // Gives the memory back (a saved file's text is not needed once its state is parsed).
    void release();
    // Throws ObjError(Unreadable), naming the file, if the file shrank while its text was read;
    // call it after each use of the text and before reporting any other problem found in it.
    void check_not_shrunk() const;

private:
    friend FileText read_file_text(const std::string& path, const rgb::ProgressSpan& progress);
    std::string path_;
    std::unique_ptr<char[]> bytes_;
    char* mapped_ = nullptr;
    std::size_t size_ = 0;
    std::atomic<bool>* shrunk_ = nullptr;  // the mapping's flag, set by the SIGBUS handler
    bool shrank_ = false;                  // the flag's last value, kept when the text is released
};

// The whole file's bytes; throws ObjError(Unreadable) naming the system's reason (missing, a
// directory, not a regular file, no permission, read error, the file shrank). `progress` hears of
// the bytes read.
FileText read_file_text(const std::string& path, const rgb::ProgressSpan& progress = {});

// The same as a string, for files of a few kilobytes (material libraries, scripts).
std::string read_text_file(const std::string& path, const rgb::ProgressSpan& progress = {});

}  // namespace rgbio
