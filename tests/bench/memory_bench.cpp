// Peak memory per triangle of every path that builds a mesh (issue 30 item 4), measured as whole
// rgbsub processes: each command runs in a child process at three sizes, its peak resident set
// (wait4's ru_maxrss, the kernel's VmHWM) is taken against the triangles it made, and the slope
// between the smallest and largest size is the path's bytes per triangle (the fixed cost of the
// process and its small input cancels out). The constants in src/io/script/triangle_limit.cpp are
// these slopes with a margin; this prints both, and the ratio, so a change that makes a path dearer
// shows here.
//
// Usage: ./memory_bench [--smoke]   (--smoke: smaller sizes, a few seconds; the numbers are then
// dominated by the fixed cost and only show that every path runs)
// Not a test: run on demand; it needs about 1 GB of memory and some minutes (the tolerance path).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "io/script/triangle_limit.h"

namespace {

namespace fs = std::filesystem;

// A torus of m x n quads cut into 2mn triangles: every vertex regular, so every level is uniform.
void write_torus(const fs::path& file, int m, int n) {
    std::ofstream out(file);
    out.precision(17);
    const double pi = std::acos(-1.0), big = 1.0, small = 0.35;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < n; ++j) {
            const double u = 2 * pi * i / m, v = 2 * pi * j / n;
            out << "v " << (big + small * std::cos(v)) * std::cos(u) << ' ' << (big + small * std::cos(v)) * std::sin(u) << ' '
                << small * std::sin(v) << '\n';
        }
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < n; ++j) {
            const int a = i * n + j + 1, b = ((i + 1) % m) * n + j + 1, c = ((i + 1) % m) * n + (j + 1) % n + 1, d = i * n + (j + 1) % n + 1;
            out << "f " << a << ' ' << b << ' ' << c << "\nf " << a << ' ' << c << ' ' << d << '\n';
        }
}

struct Run {
    long peak_kb = 0;
    std::string output;  // stdout and stderr
};

// Runs rgbsub with the arguments in a child process; exits on failure (a benchmark of a broken path
// measures nothing).
Run run(const std::vector<std::string>& arguments, const fs::path& folder) {
    const fs::path log = folder / "run.log";
    std::fflush(stdout);  // else the child's exit would print the table's buffered lines again
    const pid_t child = fork();
    if (child == 0) {
        std::vector<char*> argv;
        static const std::string binary = RGBSUB_BINARY;
        argv.push_back(const_cast<char*>(binary.c_str()));
        for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        if (!std::freopen(log.c_str(), "w", stdout) || dup2(fileno(stdout), 2) < 0) _exit(127);
        execv(binary.c_str(), argv.data());
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    if (child < 0 || wait4(child, &status, 0, &usage) != child) {
        std::perror("fork/wait4");
        std::exit(1);
    }
    Run r;
    r.peak_kb = usage.ru_maxrss;
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    r.output = text.str();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::cerr << "rgbsub";
        for (const std::string& a : arguments) std::cerr << ' ' << a;
        std::cerr << " failed:\n" << r.output;
        std::exit(1);
    }
    return r;
}

std::size_t face_lines(const fs::path& obj) {
    std::ifstream in(obj);
    std::size_t faces = 0;
    for (std::string line; std::getline(in, line);) faces += line.size() > 2 && line[0] == 'f' && line[1] == ' ';
    return faces;
}

// The number after `key` in text (render's report of the view's detail).
std::size_t number_after(const std::string& text, const std::string& key) {
    const std::size_t at = text.find(key);
    if (at == std::string::npos) {
        std::cerr << "no '" << key << "' in:\n" << text;
        std::exit(1);
    }
    return std::stoull(text.substr(at + key.size()));
}

struct Sample {
    std::size_t triangles = 0;
    long peak_kb = 0;
};

struct Path {
    std::string name;
    rgbio::MemoryUse use;
    // Runs the path at size i (0, 1, 2) and returns the triangles it made and its peak.
    std::function<Sample(int)> measure;
};

}  // namespace

int main(int argc, char** argv) {
    const bool smoke = argc > 1 && std::string(argv[1]) == "--smoke";
    const fs::path folder = fs::temp_directory_path() / ("rgbsub_memory_bench_" + std::to_string(getpid()));
    fs::create_directories(folder);
    const std::string torus = (folder / "torus.obj").string(), out = (folder / "out.obj").string();
    write_torus(torus, 24, 24);  // 1,152 triangles; level 3: 73,728
    const int shift = smoke ? 2 : 0;  // two levels less: 16 times fewer triangles

    auto refine = [&](std::vector<std::string> criterion) {
        std::vector<std::string> arguments{"refine", torus, "-o", out};
        arguments.insert(arguments.end(), criterion.begin(), criterion.end());
        const Run r = run(arguments, folder);
        return Sample{face_lines(out), r.peak_kb};
    };
    auto level = [&](int i) { return std::to_string(3 + i - shift); };
    // Lengths a factor 2 apart (about 4 times the triangles each), tolerances a factor 2 (about twice:
    // the tolerance path is the slowest, some 0.5 ms per triangle on a busy 2-core machine).
    auto scaled = [&](double first, double factor, int i) {
        std::ostringstream text;
        text.precision(17);
        text << first / std::pow(factor, i - shift);
        return text.str();
    };
    const std::vector<Path> paths{
        {"refine --level", rgbio::MemoryUse::Level, [&](int i) { return refine({"--level", level(i)}); }},
        {"refine --max-edge", rgbio::MemoryUse::MaxEdge, [&](int i) { return refine({"--max-edge", scaled(0.04, 2.0, i)}); }},
        {"refine --tolerance", rgbio::MemoryUse::Tolerance, [&](int i) { return refine({"--tolerance", scaled(4e-3, 2.0, i)}); }},
        {"render --screen-lod", rgbio::MemoryUse::ScreenLod,
         [&](int i) {
             // Edges of 8, 4 and 2 pixels at 1024x768: about 4 times the triangles each.
             const Run r = run({"render", torus, "-o", (folder / "out.png").string(), "--screen-lod", scaled(8.0 * (1 << shift), 2.0, i + shift)},
                               folder);
             return Sample{number_after(r.output, "detail for the view: "), r.peak_kb};
         }},
        {"apply budget", rgbio::MemoryUse::Budget,
         [&](int i) {
             const fs::path script = folder / "budget.txt";
             std::ofstream(script) << "budget " << (75'000ul << (2 * i)) / (smoke ? 16 : 1) << '\n';
             const Run r = run({"apply", torus, script.string(), "-o", out}, folder);
             return Sample{face_lines(out), r.peak_kb};
         }},
        {"load a saved file (info)", rgbio::MemoryUse::Load,
         [&](int i) {
             const std::string saved = (folder / "saved.obj").string();
             run({"refine", torus, "-o", saved, "--level", level(i)}, folder);
             const Run r = run({"info", saved}, folder);
             return Sample{face_lines(saved), r.peak_kb};
         }},
        {"open in the editor", rgbio::MemoryUse::Editor,
         [&](int i) {
             // One headless editor frame (OSMesa): the document, its display geometry, its picking
             // index and the GL buffers, as the editor holds every triangle it shows.
             const std::string saved = (folder / "saved.obj").string();
             run({"refine", torus, "-o", saved, "--level", level(i)}, folder);
             const Run r = run({"edit", saved, "--screenshot", (folder / "frame.png").string()}, folder);
             return Sample{face_lines(saved), r.peak_kb};
         }},
        {"remesh (per detail point)", rgbio::MemoryUse::Remesh,
         [&](int i) {
             const std::string dense = (folder / "dense.obj").string();
             run({"refine", torus, "-o", dense, "--level", std::to_string(2 + i - std::min(shift, 1)), "--plain"}, folder);
             const Run r = run({"remesh", dense, "-o", out, "--cage-triangles", "300"}, folder);
             const std::size_t end = r.output.find(" points"), begin = r.output.rfind(' ', end - 1) + 1;
             return Sample{std::stoull(r.output.substr(begin, end - begin)), r.peak_kb};
         }},
    };
    std::printf("%-28s %12s %10s %12s %12s %10s\n", "path", "triangles", "peak MB", "bytes/tri", "estimate", "ratio");
    for (const Path& path : paths) {
        std::vector<Sample> samples;
        for (int i = 0; i < 3; ++i) {
            samples.push_back(path.measure(i));
            std::printf("%-28s %12zu %10.1f\n", path.name.c_str(), samples.back().triangles, samples.back().peak_kb / 1024.0);
            std::fflush(stdout);
        }
        const double slope = 1024.0 * double(samples[2].peak_kb - samples[0].peak_kb) / double(samples[2].triangles - samples[0].triangles);
        const double estimate = double(rgbio::bytes_per_triangle(path.use));
        std::printf("%-28s %12s %10s %12.0f %12.0f %10.2f\n", path.name.c_str(), "", "", slope, estimate, estimate / slope);
    }
    fs::remove_all(folder);
    return 0;
}
