#pragma once
// Opening and saving on another thread, so that the window keeps drawing. The thread works only on
// what it owns: the document it reads (mesh, display geometry, picking index), or a copy of the mesh
// it writes. The editor takes the result from its own thread once done() says it is there; the
// result is the only thing shared, handed over under a release/acquire flag. Dropping a task lets
// its thread finish on its own and throws the result away.
#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "app/loaded_document.h"
#include "io/mesh_file.h"
#include "rgb/support/progress.h"

namespace app {

class BackgroundTask {
public:
    enum class Kind { Open, Save };

    // Reads `path` with load_document.
    static std::unique_ptr<BackgroundTask> open(const std::string& path, render::PositionSource source);
    // Writes `copy` to `path` with rgbio::save_mesh_file (atomically; glTF for .glb and .gltf).
    static std::unique_ptr<BackgroundTask> save(rgb::Mesh copy, const std::string& path, const rgbio::SaveOptions& options);

    ~BackgroundTask();
    // Threads of tasks, dropped or not, that have not finished yet.
    static int running();
    BackgroundTask(const BackgroundTask&) = delete;
    BackgroundTask& operator=(const BackgroundTask&) = delete;

    Kind kind() const { return kind_; }
    const std::string& path() const { return path_; }
    double seconds() const;
    // How far the reading or writing is, in [0, 1], never decreasing; 1 once done.
    double fraction() const;
    // "Opening PATH: 43%" or "Saving PATH: 43%", for the status line.
    std::string status() const;
    bool done() const;
    // Once done: the failure, if it failed ("FILE:LINE: problem" for a file that cannot be read).
    const std::optional<std::string>& error() const;
    // Once done, an open that worked: the document (once).
    LoadedDocument take_document();

private:
    struct Shared;
    BackgroundTask(Kind kind, std::string path);

    Kind kind_;
    std::string path_;
    std::chrono::steady_clock::time_point start_;
    std::shared_ptr<Shared> shared_;
};

}  // namespace app
