#include <string>
#include <vector>

#include "cli/dispatch.h"

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    return cli::dispatch(args);
}
