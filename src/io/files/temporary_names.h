#pragma once
// The names of a save's temporary files, so that one a save left behind can be recognised later.
//
// A save that dies of SIGKILL (or SIGQUIT, SIGUSR1, SIGPIPE, a crash: any signal temporary_cleanup.h
// cannot catch or does not handle) leaves its temporary file. Each is named
// NAME.tmp-rgbsub-PID-XXXXXX: the file's name, our mark, the saving process's id and mkstemp's
// unique letters. The next save into the same folder removes the ones whose process is gone: the
// name has our mark and form, the file is a regular file of this user, the process of that id does
// not exist, and no process holds the shared flock that a live save keeps on its temporary file (a
// save in another pid namespace, whose id means nothing here). Other files, and temporaries of
// saves still running, are never touched.
//
// A temporary file that holds the only complete copy of a file (a write in place failed half-way,
// atomic_file.h) is renamed to NAME.new-rgbsub-PID-XXXXXX, which no save removes.
#include <string>

namespace rgbio {

// The mkstemp pattern for a temporary file of `name` in `folder`: NAME (shortened at a UTF-8
// character boundary so that the whole fits in 255 bytes) + ".tmp-rgbsub-PID-XXXXXX".
std::string temporary_pattern(const std::string& folder, const std::string& name);

// The name a kept temporary file `path` (made from temporary_pattern) is renamed to.
std::string kept_temporary_name(const std::string& path);

// Removes the temporary files in `folder` that saves of processes no longer alive left behind
// (see above). Best effort: what cannot be read or removed stays, silently.
void remove_stale_temporaries(const std::string& folder);

}  // namespace rgbio
