// Budgets in the editor and in scripts (issue 29 item 2): the editor's Automatic LOD driven to a
// triangle budget through the editor's own calls, frames run as the window runs them (one
// Editor::update a frame at the slice JobPacer gives frames that draw in 4 ms, the display's changes
// taken each frame), against the same budget as a script line of `rgbsub apply --timings`, interleaved
// (the two alternate which goes first, round by round, so that a busy machine slows both alike):
//   - plain: the bunny, Automatic LOD at the least *max edge* the panel offers (0.05% of the size),
//     against `budget B`;
//   - torus: the 52k-triangle torus of the engine speed table to 1.5M, where a script's budget keeps
//     its uniform start;
//   - detail: the same after "Set all" to level 2, against `level 2` then `budget B` (the budget line
//     removes the detail first; level 1 for --smoke);
//   - cage: a cage with detail (`rgbsub remesh` of the bunny at level 3; 1 for --smoke), Automatic LOD at the least
//     *max distance* the panel offers, against `budget B` on the cage.
// For each: engine time per split (the editor's job steps, the CLI's line), per output triangle, the
// editor's wall time from the click to the mesh done and shown (no drawing here: the window adds its
// draws, one a frame), its frames and the p95 and longest frame. The editor's result is checked
// against the CLI's output (the same vertices: a conforming RGB mesh is the one its vertices make).
// Run on demand: ./budget_paths_bench [--rounds N] [--budget B] [--cage-budget B] [--cases plain,torus,detail,cage]
//                                      [--editor-only]   (no CLI runs and no check: for a profiler)
//                ./budget_paths_bench --smoke   (small budgets, one round)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include "frame_timing.h"
#include "app/editor.h"
#include "app/job_pacer.h"
#include "app/loaded_document.h"
#include "io/mesh_file.h"

namespace {

using bench::percentile;
using bench::thread_cpu_ms;
using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

const auto kSlice = std::chrono::microseconds(static_cast<long long>(1000.0 * app::JobPacer::slice_ms(4.0)));
// The least the panel's sliders offer (editor_panels.cpp): 0.05% of the size, 0.0001%.
constexpr double kLeastMaxEdge = 0.05 / 100.0, kLeastMaxDistance = 0.0001 / 100.0;

double ms_since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// A command of the setup; throws with its output when it fails.
void run_or_throw(const std::string& command, const fs::path& log) {
    if (std::system((command + " > " + shell_quote(log) + " 2>&1").c_str()) != 0) {
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        throw std::runtime_error("failed: " + command + "\n" + text.str());
    }
}

struct Run {
    double engine_ms = 0.0, wall_ms = 0.0, cpu_ms = 0.0;  // cpu: the editor's main thread, the CLI's whole process
    std::size_t splits = 0, removals = 0, triangles = 0;
    // The editor's frames.
    std::size_t frames = 0;
    double catch_up_ms = 0.0, p95_frame_ms = 0.0, max_frame_ms = 0.0;
};

// `rgbsub apply MESH SCRIPT -o OUT --timings`, whole process; the engine figures of its last line.
Run cli_run(const std::string& rgbsub, const fs::path& mesh, const fs::path& script, const fs::path& out, const fs::path& log) {
    const auto start = Clock::now();
    rusage before{}, after{};
    getrusage(RUSAGE_CHILDREN, &before);
    run_or_throw(shell_quote(rgbsub) + " apply " + shell_quote(mesh) + " " + shell_quote(script) + " -o " + shell_quote(out) + " --timings",
                 log);
    Run r;
    r.wall_ms = ms_since(start);
    getrusage(RUSAGE_CHILDREN, &after);
    auto ms = [](const timeval& t) { return 1e3 * static_cast<double>(t.tv_sec) + 1e-3 * static_cast<double>(t.tv_usec); };
    r.cpu_ms = ms(after.ru_utime) + ms(after.ru_stime) - ms(before.ru_utime) - ms(before.ru_stime);
    std::ifstream in(log);
    std::string line, last;
    while (std::getline(in, line))
        if (line.find(" ms, ") != std::string::npos) last = line;
    // "SCRIPT:LINE: budget B: 1234.5 ms, 348164 splits, 1 removals, 700000 triangles"
    const std::size_t at = last.rfind(": ");
    if (at == std::string::npos ||
        std::sscanf(last.c_str() + at + 2, "%lf ms, %zu splits, %zu removals, %zu triangles", &r.engine_ms, &r.splits, &r.removals,
                    &r.triangles) != 4)
        throw std::runtime_error("no timings line in " + log.string());
    return r;
}

// The live vertices' base-space positions, sorted: equal for two meshes with the same vertices.
std::vector<glm::dvec3> vertex_set(const rgb::Mesh& mesh) {
    std::vector<glm::dvec3> points;
    points.reserve(mesh.num_vertices());
    for (rgb::VertexId v : mesh.vertices()) points.push_back(mesh.base_space_position(v));
    std::sort(points.begin(), points.end(), [](const glm::dvec3& a, const glm::dvec3& b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    });
    return points;
}

// Automatic LOD in the editor on MESH (after "Set all" to `set_level` first, when above 0), from the
// click to the mesh done and shown.
Run editor_run(const fs::path& mesh, std::size_t budget, int set_level, std::vector<glm::dvec3>* vertices) {
    app::Editor editor;
    editor.document().adopt(app::load_document(mesh.string(), render::PositionSource::Displayed), mesh.string());
    editor.reset_view();
    auto frame = [&](std::vector<double>* frame_ms, Run* r) {
        editor.update(kSlice);
        editor.document().take_display_changes();
        const app::EngineTiming& t = editor.timing();
        if (frame_ms) frame_ms->push_back(t.frame_ms + t.geometry_ms);
        if (r) {
            r->engine_ms += t.frame_ms;
            r->catch_up_ms += t.geometry_ms;
        }
    };
    if (set_level > 0) {
        editor.start_flood_fill(set_level);
        while (editor.job() != nullptr || !editor.document().display_up_to_date()) frame(nullptr, nullptr);
    }
    app::AutoLodSettings& settings = editor.auto_lod_settings();
    settings.triangle_budget = budget;
    settings.max_edge_fraction = kLeastMaxEdge;
    settings.max_distance_fraction = kLeastMaxDistance;
    const std::size_t vertices_before = editor.document().mesh().num_vertices();
    Run r;
    std::vector<double> frame_ms;
    const auto start = Clock::now();
    const double cpu_start = thread_cpu_ms();
    editor.start_auto_lod();
    while (editor.job() != nullptr || !editor.document().display_up_to_date()) frame(&frame_ms, &r);
    r.wall_ms = ms_since(start);
    r.cpu_ms = thread_cpu_ms() - cpu_start;
    const rgb::Mesh& result = editor.document().mesh();
    r.triangles = result.num_faces();
    // From the base, every vertex added is a split; over detail the run first removes it (down to the base).
    const std::size_t base = result.num_base_vertices();
    r.removals = vertices_before - base;
    r.splits = result.num_vertices() - base;
    r.frames = frame_ms.size();
    r.p95_frame_ms = percentile(frame_ms, 0.95);
    r.max_frame_ms = percentile(frame_ms, 1.0);
    if (vertices) *vertices = vertex_set(result);
    return r;
}

struct Case {
    std::string name;
    fs::path mesh, script;
    std::size_t budget = 0;
    int set_level = 0;
};

struct Results {
    std::vector<Run> editor, cli;
};

double median_of(const std::vector<Run>& runs, double (*field)(const Run&)) {
    std::vector<double> v;
    for (const Run& r : runs) v.push_back(field(r));
    return percentile(v, 0.5);
}

void print_case(const Case& c, const Results& res) {
    std::printf("%s: budget %zu\n", c.name.c_str(), c.budget);
    for (const auto& [who, runs] : {std::pair{"editor", &res.editor}, std::pair{"cli   ", &res.cli}}) {
        for (const Run& r : *runs) {
            std::printf("  %s engine %8.1f ms  %6.0f ns/split  %6.0f ns/triangle | wall %8.1f ms  cpu %8.1f ms | %zu splits, %zu removals, %zu "
                        "triangles",
                        who, r.engine_ms, 1e6 * r.engine_ms / static_cast<double>(std::max<std::size_t>(r.splits, 1)),
                        1e6 * r.engine_ms / static_cast<double>(std::max<std::size_t>(r.triangles, 1)), r.wall_ms, r.cpu_ms, r.splits, r.removals,
                        r.triangles);
            if (runs == &res.editor)
                std::printf(" | %zu frames, catch-up %.0f ms, frame p95 %.1f ms, max %.1f ms", r.frames, r.catch_up_ms, r.p95_frame_ms,
                            r.max_frame_ms);
            std::printf("\n");
        }
    }
    std::vector<double> ratios;
    for (std::size_t i = 0; i < std::min(res.editor.size(), res.cli.size()); ++i)
        ratios.push_back((res.editor[i].engine_ms / static_cast<double>(std::max<std::size_t>(res.editor[i].splits, 1))) /
                         (res.cli[i].engine_ms / static_cast<double>(std::max<std::size_t>(res.cli[i].splits, 1))));
    const auto engine = [](const Run& r) { return r.engine_ms; };
    std::printf("  medians: engine editor %.1f ms, cli %.1f ms; editor / cli per split: pair ratios", median_of(res.editor, engine),
                median_of(res.cli, engine));
    for (double x : ratios) std::printf(" %.2f", x);
    std::printf(", median %.2f; editor wall to done and shown %.1f ms\n", percentile(ratios, 0.5),
                median_of(res.editor, [](const Run& r) { return r.wall_ms; }));
}

double load_average() {
    double load[1] = {0.0};
    return getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

}  // namespace

int main(int argc, char** argv) {
    // The editor runs inside rgbsub (`rgbsub edit`), whose main keeps freed memory in the heap
    // (src/cli/main.cpp): the same here, so that the editor's figures are the process's.
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_TOP_PAD, 64 << 20);
    int rounds = 3;
    std::size_t budget = 700000, torus_budget = 1500000, cage_budget = 300000;
    std::string torus_size = "204 128";
    int dense_level = 3;   // the cage's dense mesh: the bunny at this level
    int detail_level = 2;  // the detail case's "Set all" and `level` line
    std::string cases = "plain,torus,detail,cage";
    bool editor_only = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--smoke") {
            rounds = 1;
            budget = 20000;
            torus_budget = 20000;
            torus_size = "40 20";
            dense_level = 1;
            detail_level = 1;
            cage_budget = 10000;
        } else if (a == "--rounds" && i + 1 < argc) {
            rounds = std::atoi(argv[++i]);
        } else if (a == "--budget" && i + 1 < argc) {
            budget = std::strtoull(argv[++i], nullptr, 10);
        } else if (a == "--cage-budget" && i + 1 < argc) {
            cage_budget = std::strtoull(argv[++i], nullptr, 10);
        } else if (a == "--editor-only") {
            editor_only = true;
        } else if (a == "--cases" && i + 1 < argc) {
            cases = argv[++i];
        } else {
            std::fprintf(stderr, "usage: budget_paths_bench [--smoke] [--rounds N] [--budget B] [--cage-budget B] [--cases plain,torus,detail,cage] [--editor-only]\n");
            return 1;
        }
    }
    const std::string rgbsub = RGBSUB_BINARY;
    const fs::path work = fs::temp_directory_path() / ("rgbsub_budget_paths_" + std::to_string(getpid()));
    fs::create_directories(work);
    int status = 0;
    try {
        const fs::path bunny = fs::path(RGBSUB_SOURCE_DIR) / "assets" / "bunny.obj";
        auto script = [&](const std::string& name, const std::string& text) {
            std::ofstream(work / name) << text;
            return work / name;
        };
        std::vector<Case> all;
        if (cases.find("plain") != std::string::npos)
            all.push_back({"plain bunny", bunny, script("budget.txt", "budget " + std::to_string(budget) + "\n"), budget, 0});
        if (cases.find("torus") != std::string::npos) {
            run_or_throw(shell_quote(RGBSUB_MAKE_BENCH_MESH) + " " + torus_size + " " + shell_quote(work / "torus.obj"), work / "setup.log");
            all.push_back({"torus " + torus_size, work / "torus.obj", script("torus_budget.txt", "budget " + std::to_string(torus_budget) + "\n"),
                           torus_budget, 0});
        }
        if (cases.find("detail") != std::string::npos)
            all.push_back({"bunny at level " + std::to_string(detail_level) + ", then the budget", bunny,
                           script("level_budget.txt", "level " + std::to_string(detail_level) + "\nbudget " + std::to_string(budget) + "\n"),
                           budget, detail_level});
        if (cases.find("cage") != std::string::npos) {
            // A cage with detail: the bunny at level 3 (235k triangles) as the dense mesh, a cage of 3000
            // triangles (for --smoke level 1, 14,696 triangles, and 1500).
            const std::string level = std::to_string(dense_level);
            run_or_throw(shell_quote(rgbsub) + " refine " + shell_quote(bunny) + " --level " + level + " --plain -o " + shell_quote(work / "dense.obj"),
                         work / "setup.log");
            run_or_throw(shell_quote(rgbsub) + " remesh " + shell_quote(work / "dense.obj") + " --cage-triangles " +
                             std::to_string(dense_level == 3 ? 3000 : 1500) + " -o " + shell_quote(work / "cage.obj"),
                         work / "setup.log");
            all.push_back({"cage with detail (the bunny at level " + level + ")", work / "cage.obj",
                           script("cage_budget.txt", "budget " + std::to_string(cage_budget) + "\n"), cage_budget, 0});
        }
        std::printf("slice %.1f ms a frame (JobPacer, drawing 4 ms); %d rounds, editor and CLI alternating first\n",
                    static_cast<double>(kSlice.count()) / 1000.0, rounds);
        for (const Case& c : all) {
            Results res;
            for (int round = 0; round < rounds; ++round) {
                const double load = load_average();
                std::vector<glm::dvec3> vertices;
                const fs::path out = work / "out.obj";
                const bool check = round == 0 && !editor_only;
                auto editor = [&] { res.editor.push_back(editor_run(c.mesh, c.budget, c.set_level, check ? &vertices : nullptr)); };
                auto cli = [&] {
                    if (!editor_only) res.cli.push_back(cli_run(rgbsub, c.mesh, c.script, out, work / "cli.log"));
                };
                if (round % 2 == 0) {
                    editor();
                    cli();
                } else {
                    cli();
                    editor();
                }
                std::printf("  (%s round %d, load %.1f)\n", c.name.c_str(), round + 1, load);
                if (check) {
                    const rgb::Mesh saved = rgbio::load_mesh(out.string());
                    const bool same = vertices == vertex_set(saved) && res.editor.back().triangles == saved.num_faces();
                    std::printf("  the editor's result %s the CLI's\n", same ? "is" : "IS NOT");
                    if (!same) status = 1;
                }
            }
            print_case(c, res);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "budget_paths_bench: %s\n", e.what());
        status = 1;
    }
    fs::remove_all(work);
    return status;
}
