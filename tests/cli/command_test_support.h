#pragma once
// Running subcommands in this process through the dispatcher, as `rgbsub ARGS...` would, with what
// they print captured; and a fresh folder per test for their files.
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/dispatch.h"
#include "scratch_folder.h"

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

// The io tests' scratch folder, with write() handing back the file's path for the command line and
// read() taking a name in the folder.
class CommandFolder : public rgbio::test::ScratchFolder {
protected:
    std::string write(const std::string& name, const std::string& text) const {
        ScratchFolder::write(name, text);
        return path(name);
    }
    std::string read(const std::string& name) const { return ScratchFolder::read(folder_ / name); }
};

}  // namespace cli::test
