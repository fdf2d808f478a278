#pragma once
// Opening and saving on another thread, so that the window keeps drawing. The thread works only on
// what it owns: the document it reads (mesh, display geometry, picking index), or a copy of the mesh
// it writes. The editor takes the result from its own thread once done() says it is there; the
// result is the only thing shared, handed over under a release/acquire flag. Dropping a task lets
// its thread finish on its own and throws the result away.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/loaded_document.h"
#include "app/lod_levels.h"
#include "io/mesh_file.h"
#include "rgb/support/progress.h"

namespace app {

class BackgroundTask {
public:
    enum class Kind { Open, Save, Remesh, Lods };

    // Reads `path` with load_document.
    static std::unique_ptr<BackgroundTask> open(const std::string& path, render::PositionSource source);
    // Writes `copy` to `path` with rgbio::save_mesh_file (atomically; the format by the extension).
    static std::unique_ptr<BackgroundTask> save(rgb::Mesh copy, const std::string& path, const rgbio::SaveOptions& options);

    // Makes a cage of about `cage_triangles` triangles for the dense mesh `dense` that keeps its
    // detail (rgbdetail::remesh) and builds the document of it at level 0 (mesh, geometry, index);
    // `path` names the dense mesh's file. Dropping the task stops the remesh at its next progress
    // report (rgbdetail::Stopped), throwing the work away.
    static std::unique_ptr<BackgroundTask> remesh(std::shared_ptr<const rgb::BaseMesh> dense, std::size_t cage_triangles,
                                                  const std::string& path, render::PositionSource source);

    // Makes the levels of detail of `requests` from `copy` with rgbio::make_lod_set (writing them
    // to options.output, if set, as `rgbsub lods` does) and each level's display. Dropping the task
    // stops it before its next level (the files of a set stopped are removed).
    static std::unique_ptr<BackgroundTask> lods(rgb::Mesh copy, std::vector<rgbio::ScriptLine> requests, rgbio::LodSetOptions options);

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
    // "Opening PATH: 43%", "Saving PATH: 43%", "Making a cage of PATH: fitting the cage, 43%" or
    // "Making the LODs: 43%" ("Exporting the LODs to PATH: 43%"), for the status line.
    std::string status() const;
    // A remesh's phase now ("making the cage", "fitting the cage", "sampling the detail", ...).
    std::string phase() const;
    bool done() const;
    // Once done: the failure, if it failed ("FILE:LINE: problem" for a file that cannot be read).
    const std::optional<std::string>& error() const;
    // Once done, a remesh that worked: what it did, in a line.
    const std::string& summary() const;
    // Once done, an open or remesh that worked: the document (once).
    LoadedDocument take_document();
    // Once done, LODs made: the levels (once).
    LodLevels take_lods();

private:
    struct Shared;
    BackgroundTask(Kind kind, std::string path);

    Kind kind_;
    std::string path_;
    std::chrono::steady_clock::time_point start_;
    std::shared_ptr<Shared> shared_;
};

}  // namespace app
