// SPDX-License-Identifier: MIT
// The nesting limit of scene files (docs/reliability.md): toml++ parses
// tables, arrays and dotted keys by recursion, one stack frame per level, so
// a 100 KB file of 50,000 levels overflows the stack. The text is scanned
// first and refused, located, past the limit.
#pragma once

#include <string>
#include <string_view>

namespace litkit::detail {

// Levels: open '[' and '{' outside strings and comments, plus the dots of
// the key or table header being read. 64 is far beyond any scene (which
// needs 3) and far below what overflows the stack.
inline constexpr int max_toml_nesting = 64;

// Throws IoError located at the character that goes past max_toml_nesting.
void check_nesting(std::string_view text, const std::string& name);

}  // namespace litkit::detail
