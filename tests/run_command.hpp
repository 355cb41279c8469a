// SPDX-License-Identifier: MIT
// Running a shell command from a test and collecting what it printed.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace litkit_test {

struct CommandRun {
    int status = -1;     // exit status; -1 if it did not exit normally
    std::string output;  // stdout and stderr together
};

// Runs `command_line` with sh, standard input from /dev/null (not a terminal).
inline CommandRun run_command(const std::string& command_line) {
    const std::string command = command_line + " < /dev/null 2>&1";
    CommandRun run;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return run;
    std::array<char, 4096> buffer;
    std::size_t n;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        run.output.append(buffer.data(), n);
    const int raw = ::pclose(pipe);
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return run;
}

}  // namespace litkit_test
