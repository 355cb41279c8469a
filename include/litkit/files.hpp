// Whole-or-nothing file output (docs/spec.md §6: a failed run leaves no partial file
// and the previous file untouched).
#pragma once

#include <filesystem>
#include <string_view>

namespace litkit {

// Writes `bytes` to a temporary file beside `path`, flushes it, then renames
// it over `path`. Throws IoError (Access::Write) and removes the temporary
// file on any failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// True when `a` and `b` name the same existing file (through links, "..",
// hard links). False when either does not exist.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace litkit
