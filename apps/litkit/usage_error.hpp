// SPDX-License-Identifier: MIT
// The exit statuses of docs/spec.md §6, and the usage problems that the
// commands find after CLI11's own parsing.
#pragma once

#include <string>

namespace litkit_cli {

// docs/spec.md §6: 0 success, 1 a file could not be read or written, 2
// invalid input or usage.
constexpr int exit_success = 0;
constexpr int exit_io = 1;
constexpr int exit_invalid = 2;

// A usage problem found after CLI11's own parsing (exit status 2).
struct UsageError {
    std::string message;
};

}  // namespace litkit_cli
