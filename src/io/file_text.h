#pragma once
// Reading a whole file into memory. A saved 6M-triangle file is 370 MB: a std::string of that size
// is zero-filled first, which faults in every page on one thread before the reading writes them
// all again. FileText's bytes are not initialised, and the file is read in parallel pieces (each
// thread faults in its own part), so reading costs little more than the kernel's copy.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "rgb/progress.h"

namespace rgbio {

class FileText {
public:
    std::string_view view() const { return {bytes_.get(), size_}; }
    // Gives the memory back (a saved file's text is not needed once its state is parsed).
    void release() {
        bytes_.reset();
        size_ = 0;
    }

private:
    friend FileText read_file_text(const std::string& path, const rgb::ProgressSpan& progress);
    std::unique_ptr<char[]> bytes_;
    std::size_t size_ = 0;
};

// The whole file's bytes; throws ObjError(Unreadable) naming the system's reason (missing, a
// directory, not a regular file, no permission, read error, the file shrank). `progress` hears of
// the bytes read.
FileText read_file_text(const std::string& path, const rgb::ProgressSpan& progress = {});

// The same as a string, for files of a few kilobytes (material libraries, scripts).
std::string read_text_file(const std::string& path, const rgb::ProgressSpan& progress = {});

}  // namespace rgbio
