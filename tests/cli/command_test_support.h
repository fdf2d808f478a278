#pragma once
// Running subcommands in this process through the dispatcher, as `rgbsub ARGS...` would, with what
// they print captured; and a fresh folder per test for their files.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/dispatch.h"

namespace cli::test {

struct CommandRun {
    int exit_code = -1;
    std::string out;  // std::cout
    std::string err;  // std::cerr
};

// Points a stream at a string buffer for its lifetime, restoring it even when the command throws.
class StreamCapture {
public:
    explicit StreamCapture(std::ostream& stream) : stream_(stream), old_(stream.rdbuf(buffer_.rdbuf())) {}
    ~StreamCapture() { stream_.rdbuf(old_); }
    StreamCapture(const StreamCapture&) = delete;
    StreamCapture& operator=(const StreamCapture&) = delete;
    std::string text() const { return buffer_.str(); }

private:
    std::ostream& stream_;
    std::ostringstream buffer_;
    std::streambuf* old_;
};

inline CommandRun run_command(const std::vector<std::string>& args) {
    const StreamCapture out(std::cout), err(std::cerr);
    CommandRun run;
    run.exit_code = dispatch(args);
    run.out = out.text();
    run.err = err.text();
    return run;
}

class CommandFolder : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = std::filesystem::temp_directory_path() /
                  ("rgbsub_cli_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(folder_);
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }

    std::string path(const std::string& name) const { return (folder_ / name).string(); }
    // Writes `text` to `name` in the folder and returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(folder_ / name, std::ios::binary) << text;
        return path(name);
    }
    std::string read(const std::string& name) const {
        std::ifstream in(folder_ / name, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }

    std::filesystem::path folder_;
};

}  // namespace cli::test
