// Writes a closed benchmark mesh: a torus of U x V quads (2UV triangles) with deterministic bumps,
// so that it has no symmetry a benchmark could profit from. Vertex coordinates in shortest
// round-trip form. Usage: make_bench_mesh U V OUT.obj
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: make_bench_mesh U V OUT.obj\n");
        return 1;
    }
    const int u = std::atoi(argv[1]), v = std::atoi(argv[2]);
    if (u < 3 || v < 3) {
        std::fprintf(stderr, "make_bench_mesh: U and V must be at least 3\n");
        return 1;
    }
    std::FILE* out = std::fopen(argv[3], "w");
    if (out == nullptr) {
        std::perror(argv[3]);
        return 3;
    }
    std::string text;
    char buffer[32];
    auto number = [&](double x) {
        const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
        text += ' ';
        text.append(buffer, end);
    };
    const double pi = std::numbers::pi;
    for (int i = 0; i < u; ++i)
        for (int j = 0; j < v; ++j) {
            const double a = 2 * pi * i / u, b = 2 * pi * j / v;
            const double bump = 0.08 * std::sin(5 * a + 3 * b) + 0.05 * std::cos(11 * a - 7 * b);
            const double r = 1.0 + (0.4 + bump) * std::cos(b);
            text += 'v';
            number(r * std::cos(a));
            number(r * std::sin(a));
            number((0.4 + bump) * std::sin(b));
            text += '\n';
        }
    for (int i = 0; i < u; ++i)
        for (int j = 0; j < v; ++j) {
            const int p = i * v + j + 1, q = ((i + 1) % u) * v + j + 1, r = ((i + 1) % u) * v + (j + 1) % v + 1,
                      s = i * v + (j + 1) % v + 1;
            text += "f " + std::to_string(p) + ' ' + std::to_string(q) + ' ' + std::to_string(r) + '\n';
            text += "f " + std::to_string(p) + ' ' + std::to_string(r) + ' ' + std::to_string(s) + '\n';
        }
    const bool ok = std::fwrite(text.data(), 1, text.size(), out) == text.size();
    if (std::fclose(out) != 0 || !ok) {
        std::perror(argv[3]);
        return 3;
    }
    return 0;
}
