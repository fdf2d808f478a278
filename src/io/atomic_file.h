#pragma once
// Replacing a file so that readers see either the old or the complete new content, never a part:
// write a temporary file in the same folder, flush and fsync it, then rename it over the target
// (rename is atomic within one file system) and fsync the folder.
#include <string>
#include <string_view>

namespace rgbio {

// Throws SaveError naming the path and the system's reason. On failure the target is untouched
// and the temporary file is removed.
void write_file_atomically(const std::string& path, std::string_view content);

}  // namespace rgbio
