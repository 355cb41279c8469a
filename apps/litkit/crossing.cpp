// SPDX-License-Identifier: MIT
#include "crossing.hpp"

#include <exception>
#include <new>
#include <stdexcept>

#include "litkit/gl_renderer.hpp"

namespace litkit_cli {

CaughtError catch_current() noexcept {
    using Kind = CaughtError::Kind;
    CaughtError caught;
    try {
        try {
            throw;
        } catch (const litkit::SceneError& error) {
            caught.kind = Kind::Scene;
            caught.diagnostics = error.diagnostics();
            caught.warnings = error.warnings();
        } catch (const litkit::IoError& error) {
            caught.kind = Kind::Io;
            caught.path = error.path();
            caught.reason = error.reason();
            caught.access = error.access();
        } catch (const litkit::GlError&) {
            caught.kind = Kind::Gl;
        } catch (const litkit::ArgumentError&) {
            caught.kind = Kind::Argument;
        } catch (const litkit::Error&) {
            caught.kind = Kind::Litkit;
        } catch (const std::bad_alloc&) {
            caught.kind = Kind::OutOfMemory;
        } catch (const std::exception&) {
            caught.kind = Kind::Other;
        }
    } catch (...) {
        caught.kind = Kind::Other;
    }
    // what() and the location, whichever the kind (a second look, so that
    // each branch above stays about its own members).
    try {
        try {
            throw;
        } catch (const litkit::Error& error) {
            caught.what = error.what();
            caught.location = error.location();
        } catch (const std::exception& error) {
            caught.what = error.what();
        }
    } catch (...) {
        if (caught.what.empty()) caught.what = "unknown error";
    }
    return caught;
}

void throw_again(const CaughtError& error) {
    using Kind = CaughtError::Kind;
    switch (error.kind) {
        case Kind::Scene:
            throw litkit::SceneError(error.diagnostics, error.warnings);
        case Kind::Io:
            throw litkit::IoError(error.path, error.reason, error.location, error.access);
        case Kind::Gl:
            throw litkit::GlError(error.what);
        case Kind::Argument:
            throw litkit::ArgumentError(error.what, error.location);
        case Kind::Litkit:
            throw litkit::Error(error.what, error.location);
        case Kind::OutOfMemory:
            throw std::bad_alloc();
        case Kind::None:
        case Kind::Other:
            break;
    }
    throw std::runtime_error(error.what);
}

}  // namespace litkit_cli
