// SPDX-License-Identifier: MIT
// How the command-line tool sets up its heap before it does anything else.
#pragma once

namespace litkit_cli {

// Backs the process's heap with transparent huge pages where the system
// allows them (Linux with glibc, THP in "madvise" or "always" mode), so
// that the tens of megabytes a large scene's set-up touches fault in 2 MiB
// at a time instead of 4 KiB. Does nothing elsewhere, and never fails: at
// worst the heap stays as it was. Process-wide, so it belongs to the tool,
// not to the library. Why and the measurements: docs/design.md, "The heap".
void use_large_pages_for_the_heap();

}  // namespace litkit_cli
