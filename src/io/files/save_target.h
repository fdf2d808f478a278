#pragma once
// What a save to a user-given path really writes to, decided before anything is written.
//
// A save writes to what the user named: a symbolic link is followed to the real file (a dangling
// link creates its target), which keeps its mode and owner. Targets that are not regular files
// (folders, character or block devices, FIFOs, sockets) and existing files that are read-only are
// refused, so a save never replaces a device entry or a file the user protected. What an output's
// extension selects (glTF binary or JSON, OBJ) is read without regard to case (has_extension).
#include <optional>
#include <string>
#include <string_view>

#include <sys/stat.h>

namespace rgbio {

// Whether `path` ends in `extension` (".glb"), compared without regard to ASCII case: NAME.GLB is
// a .glb as much as name.glb is.
bool has_extension(const std::string& path, std::string_view extension);

struct SaveTarget {
    std::string path;                  // the real file: `named` with symbolic links followed
    std::string folder;                // where it lives, for the temporary file
    std::string name;                  // its last component
    std::optional<struct stat> existing;  // the file as it is now, if it exists
};

// Throws SaveError ("cannot save NAMED: reason") for an empty name, a name ending in '/', a link
// loop, a target that is not a regular file, and an existing file that is read-only (no write bit)
// or that this process may not write.
SaveTarget resolve_save_target(const std::string& named);

}  // namespace rgbio
