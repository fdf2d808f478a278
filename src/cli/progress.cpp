#include "cli/progress.h"

#include <cstdio>

#include <unistd.h>

namespace cli {

Progress::Progress(std::string label) : label_(std::move(label)), visible_(::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
    if (visible_) std::fputs("\r\033[K", stderr);
}

void Progress::update(std::size_t done, std::size_t total, const std::string& detail) {
    if (!visible_) return;
    std::fprintf(stderr, "\r\033[K%s %zu/%zu %s", label_.c_str(), done, total, detail.c_str());
    std::fflush(stderr);
}

}  // namespace cli
