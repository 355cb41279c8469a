// SPDX-License-Identifier: MIT
// Help for a command line that went wrong: the short usage `litkit` alone
// prints, and "did you mean" for a misspelt command or option.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace litkit_cli {

// The commands with their one-line descriptions, and where to read more.
std::string short_usage(const CLI::App& app);

// Before parsing: `litkit` alone, or a first word that is not a command
// ("litkit rendr"), gets the short usage or a suggestion on stderr and exit
// status 2. Returns nothing when the command line names a command.
std::optional<int> check_command(const CLI::App& app, int argc, char** argv);

// After a parse error: "; did you mean '--width'?" for an unknown option of
// the command being parsed, or "" when nothing is close.
std::string option_suggestion(const CLI::App& app, int argc, char** argv);

}  // namespace litkit_cli
