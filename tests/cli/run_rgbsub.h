#pragma once
// Runs the rgbsub executable (RGBSUB_BINARY) through the shell, exactly as a user would, and
// returns what the user sees: the exit code and stdout and stderr together.
#include <sys/wait.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace cli_test {

struct Outcome {
    int exit_code = -1;  // -1: the process did not exit normally (killed by a signal)
    std::string output;
};

// Each argument is passed as one word, whatever it contains. `shell_prefix` runs before the
// command in the same shell (e.g. "ulimit -f 4;" or "env -u DISPLAY").
inline Outcome run_rgbsub(const std::vector<std::string>& arguments, const std::string& shell_prefix = "") {
    std::string command = shell_prefix + " '" RGBSUB_BINARY "'";
    for (const std::string& argument : arguments) {
        command += " '";
        for (char c : argument) command += c == '\'' ? std::string("'\\''") : std::string(1, c);
        command += '\'';
    }
    command += " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
    Outcome run;
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) run.output.append(buffer, n);
    const int status = pclose(pipe);
    if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
    return run;
}

}  // namespace cli_test
