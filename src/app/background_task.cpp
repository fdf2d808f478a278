#include "app/background_task.h"

#include <cmath>
#include <new>
#include <thread>
#include <utility>

#include "detail/remesh.h"
#include "io/mesh_export.h"

namespace app {

struct BackgroundTask::Shared {
    rgb::Progress progress;  // reported by the thread, read by the window
    std::atomic<bool> done{false};
    std::optional<std::string> error;
    std::optional<LoadedDocument> document;
    std::optional<LodLevels> lods;
    std::atomic<const char*> phase{"starting"};  // a remesh's phase (string literals)
    std::atomic<bool> stop{false};                // set when the task is dropped
    std::string summary;
};

namespace {

std::atomic<int> threads_running{0};

// Runs `work` on a thread of its own, counted while it runs.
template <class Work>
void start_thread(Work&& work) {
    ++threads_running;
    std::thread([work = std::forward<Work>(work)]() mutable {
        work();
        --threads_running;
    }).detach();
}

// The message of whatever the work threw.
std::string describe(const std::exception& failure) {
    return dynamic_cast<const std::bad_alloc*>(&failure) != nullptr ? std::string("out of memory") : std::string(failure.what());
}

}  // namespace

BackgroundTask::BackgroundTask(Kind kind, std::string path)
    : kind_(kind), path_(std::move(path)), start_(std::chrono::steady_clock::now()), shared_(std::make_shared<Shared>()) {}

BackgroundTask::~BackgroundTask() { shared_->stop.store(true, std::memory_order_relaxed); }

int BackgroundTask::running() { return threads_running.load(); }

std::unique_ptr<BackgroundTask> BackgroundTask::open(const std::string& path, render::PositionSource source) {
    std::unique_ptr<BackgroundTask> task(new BackgroundTask(Kind::Open, path));
    start_thread([shared = task->shared_, path, source] {
        try {
            shared->document.emplace(load_document(path, source, rgb::ProgressSpan(&shared->progress)));
        } catch (const std::exception& failure) {
            shared->error = describe(failure);
        }
        shared->done.store(true, std::memory_order_release);
    });
    return task;
}

std::unique_ptr<BackgroundTask> BackgroundTask::save(rgb::Mesh copy, const std::string& path, const rgbio::SaveOptions& options) {
    std::unique_ptr<BackgroundTask> task(new BackgroundTask(Kind::Save, path));
    rgbio::SaveOptions watched = options;
    watched.progress = rgb::ProgressSpan(&task->shared_->progress);
    start_thread([shared = task->shared_, mesh = std::move(copy), path, options = std::move(watched)] {
        try {
            rgbio::save_mesh_file(mesh, path, options);
        } catch (const std::exception& failure) {
            shared->error = describe(failure);
        }
        shared->done.store(true, std::memory_order_release);
    });
    return task;
}

std::unique_ptr<BackgroundTask> BackgroundTask::remesh(std::shared_ptr<const rgb::BaseMesh> dense, std::size_t cage_triangles,
                                                       const std::string& path, render::PositionSource source) {
    std::unique_ptr<BackgroundTask> task(new BackgroundTask(Kind::Remesh, path));
    start_thread([shared = task->shared_, dense = std::move(dense), cage_triangles, path, source] {
        try {
            // The remesh takes most of the time; building the document the rest.
            constexpr double kRemeshShare = 0.95;
            rgbdetail::RemeshOptions options;
            options.cage_triangles = cage_triangles;
            options.source_name = path;
            options.progress = [&shared](double share, const char* phase) {
                shared->phase.store(phase, std::memory_order_relaxed);
                shared->progress.reach(kRemeshShare * share);
                return !shared->stop.load(std::memory_order_relaxed);
            };
            rgbdetail::Remeshed remeshed = rgbdetail::remesh(dense->positions(), dense->faces(), options);
            shared->phase.store("building the display", std::memory_order_relaxed);
            LoadedDocument loaded{rgb::Mesh(remeshed.base), std::make_shared<const rgbio::BaseAttributes>(), render::SurfaceGeometry(source),
                                  SurfaceIndex(), {}, std::nullopt};
            reserve_room(loaded.mesh, loaded.geometry, loaded.index, kRoomFactor * loaded.mesh.num_faces());
            loaded.geometry.rebuild(loaded.mesh);
            loaded.index.rebuild(loaded.mesh, loaded.geometry);
            const rgbdetail::RemeshReport& report = remeshed.report;
            const std::string levels = report.finest_detail_level > report.detail_level
                                           ? "levels " + std::to_string(report.detail_level) + ".." + std::to_string(report.finest_detail_level)
                                           : "level " + std::to_string(report.detail_level);
            shared->summary = "a cage of " + std::to_string(report.cage_triangles) + " triangles with the detail of " + path + " to " +
                              levels + " (" + std::to_string(report.detail_points) + " points, " +
                              std::to_string(report.nearest_points) + " nearest instead of a ray hit)";
            shared->document.emplace(std::move(loaded));
        } catch (const rgbdetail::Stopped&) {
            shared->error = "stopped";
        } catch (const std::exception& failure) {
            shared->error = describe(failure);
        }
        shared->done.store(true, std::memory_order_release);
    });
    return task;
}

std::unique_ptr<BackgroundTask> BackgroundTask::lods(rgb::Mesh copy, std::vector<rgbio::ScriptLine> requests, rgbio::LodSetOptions options) {
    std::unique_ptr<BackgroundTask> task(new BackgroundTask(Kind::Lods, options.output.value_or("")));
    start_thread([shared = task->shared_, mesh = std::move(copy), requests = std::move(requests), options = std::move(options)]() mutable {
        try {
            // Making the levels takes most of the time, measuring their errors and the displays the rest.
            constexpr double kLevelsShare = 0.8, kErrorsShare = 0.9;
            options.progress = [&shared](std::size_t step, std::size_t levels) {
                shared->progress.reach(step < levels ? kLevelsShare * static_cast<double>(step) / static_cast<double>(levels) : kLevelsShare);
                return !shared->stop.load(std::memory_order_relaxed);
            };
            LodLevels made{rgbio::make_lod_set(mesh, requests, options), {}, 0};
            shared->progress.reach(kErrorsShare);
            for (const rgbio::LodSetLevel& level : made.set.levels) {
                render::SurfaceGeometry& display = made.displays.emplace_back(written_source(options.save.positions));
                display.rebuild(level.mesh);
            }
            shared->lods.emplace(std::move(made));
        } catch (const std::exception& failure) {
            shared->error = describe(failure);
        }
        shared->done.store(true, std::memory_order_release);
    });
    return task;
}

double BackgroundTask::seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

double BackgroundTask::fraction() const { return done() ? 1.0 : shared_->progress.fraction(); }

std::string BackgroundTask::status() const {
    const int percent = static_cast<int>(std::floor(100.0 * fraction()));
    if (kind_ == Kind::Remesh) return "Making a cage of " + path_ + ": " + phase() + ", " + std::to_string(percent) + "%, Esc stops";
    if (kind_ == Kind::Lods)
        return (path_.empty() ? std::string("Making the LODs: ") : "Exporting the LODs to " + path_ + ": ") + std::to_string(percent) + "%, Esc stops";
    return (kind_ == Kind::Open ? "Opening " : "Saving ") + path_ + ": " + std::to_string(percent) + "%";
}

std::string BackgroundTask::phase() const { return shared_->phase.load(std::memory_order_relaxed); }

const std::string& BackgroundTask::summary() const { return shared_->summary; }

bool BackgroundTask::done() const { return shared_->done.load(std::memory_order_acquire); }

const std::optional<std::string>& BackgroundTask::error() const { return shared_->error; }

LoadedDocument BackgroundTask::take_document() {
    LoadedDocument document = std::move(*shared_->document);
    shared_->document.reset();
    return document;
}

LodLevels BackgroundTask::take_lods() {
    LodLevels lods = std::move(*shared_->lods);
    shared_->lods.reset();
    return lods;
}

}  // namespace app
