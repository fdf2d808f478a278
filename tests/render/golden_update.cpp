// Rewrites the golden images: `golden_update DIR` renders every case of golden_cases.h into DIR. Run
// through the target render_golden_update, by a person who then looks at every changed PNG before
// committing it (golden/README.md). It is not a test and no test runs it: a test run never writes
// into the source tree.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>

#include "golden_cases.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: golden_update DIR   (writes DIR/<case>.png for every golden case)\n";
        return 2;
    }
    if (const char* ci = std::getenv("CI"); ci != nullptr && std::string_view(ci) == "true") {
        std::cerr << "golden_update: CI=true: golden images are only rewritten by a person, who reviews them\n";
        return 1;
    }
    const std::filesystem::path dir = argv[1];
    for (const render_test::GoldenCase& c : render_test::golden_cases()) {
        const std::filesystem::path path = dir / (c.name + ".png");
        std::ofstream out(path, std::ios::binary);
        out << render::encode_png(render_test::render_golden(c));
        if (!out.flush()) {
            std::cerr << "golden_update: cannot write " << path << '\n';
            return 1;
        }
        std::cout << "wrote " << path << '\n';
    }
    return 0;
}
