// SPDX-License-Identifier: MIT
// Errors across a module's boundary (modules.hpp, docs/design.md "Modules").
//
// The `litkit` executable carries its own copy of the C++ run-time (it links
// libstdc++ statically, so that no run loads libstdc++.so: docs/design.md
// "Start-up"); a module and the libraries it brings (Dear ImGui) use
// libstdc++.so. Plain data crosses between the two safely (the same headers
// lay out std::string and std::vector alike, and both allocate with the one
// malloc), but an exception must not: each run-time keeps its own record of
// the exceptions in flight. So nothing is thrown across the boundary. The
// side that calls across catches what the call threw on the far side as a
// CaughtError, and throws it again on its own side as the same litkit error.
// This file is compiled into the executable and into each module, once per
// run-time.
#pragma once

#include <string>
#include <vector>

#include "litkit/error.hpp"

namespace litkit_cli {

// What was thrown, as data.
struct CaughtError {
    enum class Kind {
        None,         // nothing was thrown
        Scene,        // litkit::SceneError
        Io,           // litkit::IoError
        Gl,           // litkit::GlError
        Argument,     // litkit::ArgumentError
        Litkit,       // another litkit::Error
        OutOfMemory,  // std::bad_alloc
        Other,        // any other exception: its what(), thrown again as std::runtime_error
    };
    Kind kind = Kind::None;
    std::string what;
    litkit::FileLoc location;
    std::vector<litkit::Diagnostic> diagnostics;  // Scene
    std::vector<litkit::Diagnostic> warnings;     // Scene
    std::string path;                             // Io
    std::string reason;                           // Io
    litkit::IoError::Access access = litkit::IoError::Access::Read;
};

// Inside a `catch (...)`: the exception being handled, as data.
CaughtError catch_current() noexcept;

// Throws `error` again on this side of the boundary (`error.kind` is not None).
[[noreturn]] void throw_again(const CaughtError& error);

// Calls `f`; what it throws is caught into `error`. True when it returned.
template <class F>
bool call_catching(F&& f, CaughtError& error) noexcept {
    try {
        f();
        return true;
    } catch (...) {
        error = catch_current();
        return false;
    }
}

}  // namespace litkit_cli
