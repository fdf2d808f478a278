// Progress benchmark: what watching a load or save costs, and how evenly the fraction moves.
// Saves the bunny refined uniformly (default level 5: 3,762,176 triangles) to a temporary file, then
// opens it as the editor does (app::load_document: read, parse, restore, display geometry, picking
// index) and saves it back, alternately with and without a rgb::Progress, and prints
//   - wall time of each run, and the medians with and without the progress,
//   - for one watched run, the time at which the fraction passed each tenth (an even bar passes them
//     at even times).
// Run on demand: ./load_progress_bench [level] [runs]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "app/loaded_document.h"
#include "io/mesh_file.h"
#include "rgb/lod/refine.h"
#include "rgb/support/progress.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// The times at which the listener heard each further tenth.
struct Tenths {
    Clock::time_point start = Clock::now();
    std::vector<double> at;
    rgb::Progress progress{[this](double f) {
        while (static_cast<double>(at.size()) < 10.0 * f + 1e-9) at.push_back(seconds_since(start));
    }};
};

void print_tenths(const char* what, const Tenths& tenths, double total) {
    std::printf("  %s: tenths passed at", what);
    for (double t : tenths.at) std::printf(" %.0f%%", 100.0 * t / total);
    std::printf(" of %.2f s\n", total);
}

}  // namespace

int main(int argc, char** argv) {
    const int level = argc > 1 ? std::atoi(argv[1]) : 5;
    const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
    rgb::Mesh mesh = rgbio::load_mesh(std::string(RGBSUB_SOURCE_DIR) + "/assets/bunny.obj");
    rgb::refine_uniform(mesh, level);
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("rgbsub_load_progress_" + std::to_string(::getpid()) + ".obj");
    rgbio::save_mesh(mesh, file.string());
    std::printf("bunny at level %d: %zu triangles, %.0f MB saved\n", level, mesh.num_faces(),
                static_cast<double>(std::filesystem::file_size(file)) / 1e6);
    std::vector<double> open_plain, open_watched, save_plain, save_watched;
    for (int run = 0; run < runs; ++run) {
        auto start = Clock::now();
        app::load_document(file.string(), render::PositionSource::Displayed);
        open_plain.push_back(seconds_since(start));
        Tenths opening;
        start = Clock::now();
        app::load_document(file.string(), render::PositionSource::Displayed, rgb::ProgressSpan(&opening.progress));
        open_watched.push_back(seconds_since(start));
        if (run == 0) print_tenths("open", opening, open_watched.back());

        const std::string copy = file.string() + ".copy.obj";
        start = Clock::now();
        rgbio::save_mesh(mesh, copy);
        save_plain.push_back(seconds_since(start));
        std::filesystem::remove(copy);  // both saves write a new file (replacing one costs its removal)
        Tenths saving;
        rgbio::SaveOptions options;
        options.progress = rgb::ProgressSpan(&saving.progress);
        start = Clock::now();
        rgbio::save_mesh(mesh, copy, options);
        save_watched.push_back(seconds_since(start));
        if (run == 0) print_tenths("save", saving, save_watched.back());
        std::filesystem::remove(copy);
        std::printf("  run %d: open %.3f s, watched %.3f s | save %.3f s, watched %.3f s\n", run, open_plain.back(),
                    open_watched.back(), save_plain.back(), save_watched.back());
    }
    std::printf("  median: open %.3f s, watched %.3f s | save %.3f s, watched %.3f s\n", median(open_plain), median(open_watched),
                median(save_plain), median(save_watched));
    std::filesystem::remove(file);
    return 0;
}
