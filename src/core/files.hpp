// SPDX-License-Identifier: MIT
/// \file
/// Whole-or-nothing file output (docs/spec.md §6: a failed run leaves no partial file
/// and the previous file untouched). docs/reliability.md lists what happens with
/// special files, signals and full disks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace litkit {

/// Writes `bytes` to what `path` names, whole or not at all:
/// - a regular file, or nothing yet: a temporary file with a short name
///   (".litkit-XXXXXX", so any legal name works) in the same folder is
///   written, flushed and renamed over it; a replaced file keeps its mode
///   (and, for root, its owner);
/// - a symbolic link: the file it points to is what gets replaced (the link stays);
/// - a device, FIFO or socket (/dev/null, /dev/stdout, a pipe): written
///   through, never replaced;
/// - a folder, or a name ending in '/': refused with a clear reason.
/// The temporary file is registered (register_temporary) for as long as it
/// exists, so that a signal handler can remove it. Throws IoError
/// (Access::Write) and removes the temporary file on any failure (a full
/// disk, a file size limit).
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

/// Writes the `files` (names within the folder, and their bytes) into
/// `directory`, all of them or none: each is first written and flushed in a
/// temporary folder (".litkit-XXXXXX", registered), on the same file system;
/// a new folder is then renamed into place whole, or, when the folder exists,
/// each file is renamed over its old one with signals held (renames need no
/// space, so a full disk stops the export before anything is touched). Files
/// of the folder that are not written stay; a replaced file keeps its mode.
/// Throws IoError (Access::Write).
void write_folder_atomically(const std::filesystem::path& directory,
                             const std::vector<std::pair<std::string, std::string>>& files);

/// The largest scene or mesh file litkit reads (docs/reliability.md): 256 MiB.
/// Past it a file is refused with its name, before more is read, so that
/// /dev/zero or a runaway pipe cannot exhaust memory.
inline constexpr std::uint64_t max_input_file_bytes = std::uint64_t{256} << 20;

/// Reads the whole of `path` (a regular file, a FIFO, a device, "/dev/fd/N"
/// from process substitution; "-" reads standard input), at most `limit`
/// bytes. Throws IoError (Access::Read) naming the file when it cannot be
/// read or is larger than `limit`.
std::string read_file_limited(const std::filesystem::path& path,
                              std::uint64_t limit = max_input_file_bytes);

/// Writes all of `bytes` to the open descriptor `fd` (retrying short writes
/// and EINTR). Throws IoError (Access::Write) naming `name`.
void write_all(int fd, std::string_view bytes, const std::string& name);

/// True when `a` and `b` name the same existing file (through links, "..",
/// hard links). False when either does not exist.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

/// Temporary files and folders that must not outlive the process. A signal
/// handler calls remove_registered_temporaries(), which is async-signal-safe
/// (unlink and rmdir only, files before folders). This is the library's one
/// piece of process-wide state: a signal handler can reach nothing else.
/// register_temporary returns a slot (or -1 when the 64 slots are full or
/// the path is too long, in which case the path simply is not cleaned).
int register_temporary(const std::filesystem::path& path) noexcept;
/// Forgets the temporary in `slot` (from register_temporary; -1 is ignored),
/// once it is renamed into place or removed.
void unregister_temporary(int slot) noexcept;
/// Removes every registered temporary; async-signal-safe, for a signal handler.
void remove_registered_temporaries() noexcept;

}  // namespace litkit
