// SPDX-License-Identifier: MIT
/// \file
/// Errors the library throws. The library never prints or exits: it throws one
/// of these, and the caller (the CLI, a test, a user's program) decides how to
/// show it. Every error about a scene carries the place it comes from.
///
/// Whatever the input or the caller can cause (a bad scene, an unreadable
/// file, an argument outside a function's contract, an OpenGL that fails:
/// GlError in litkit/gl_renderer.hpp) is thrown as a subclass of Error.
/// Two others can escape: std::bad_alloc when memory runs out, and
/// std::logic_error (or a subclass) for a broken internal invariant, which
/// is a bug in litkit, never a problem of the input.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

/// litkit: scenes, lighting models, meshes, the CPU renderer, images, the
/// teaching tools and the exporters (docs/spec.md is the contract).
namespace litkit {

/// A place in a source file, printed the way compilers and editors expect:
/// "scene.toml:14:12". Line and column are 1-based; 0 means "unknown".
struct FileLoc {
    /// The file's path as given (or the name text was parsed under); empty: none.
    std::string file;
    std::uint32_t line = 0;    ///< 1-based line; 0: unknown.
    std::uint32_t column = 0;  ///< 1-based column; 0: unknown.

    /// "file:line:column", leaving out the parts that are unknown ("file",
    /// "file:line"); control characters in the name are shown escaped (\\n).
    std::string to_string() const;
};

/// How bad a Diagnostic is: an error stops the scene, a warning does not.
enum class Severity {
    Error,   ///< The input breaks a rule (docs/spec.md §6).
    Warning  ///< Allowed but probably a mistake (no lights, an object out of view).
};

/// One problem found in the input, e.g.
/// "scene.toml:14:12: error: lights[0] 'key': position [0, -3, 0] is inside object 'box'".
struct Diagnostic {
    FileLoc location;                     ///< Where the problem is.
    Severity severity = Severity::Error;  ///< Error or warning.
    std::string message;                  ///< The text after "error: ", without location.

    /// The one-line form above: "location: error: message" (or "warning:"),
    /// without "location: " when there is none.
    std::string to_string() const;
};

/// The base of the errors above, so that one `catch` reports them all:
/// what() is the one-line (for SceneError, one line per problem) diagnostic
/// that `litkit check` prints, and location() says where, when there is a
/// place ("scene.toml:14:12"; empty otherwise).
class Error : public std::runtime_error {
  public:
    /// `what` is the whole diagnostic, location included when there is one.
    explicit Error(const std::string& what, FileLoc location = {});
    /// Where the error is; a default FileLoc when it has no place.
    const FileLoc& location() const noexcept { return location_; }

  private:
    FileLoc location_;
};

/// A function of the library was called with arguments outside its contract
/// (a sphere of radius 0, a pixel outside the image, a light capacity of 0).
class ArgumentError : public Error {
  public:
    using Error::Error;
};

/// Invalid input: the scene (or a value given on the command line) breaks a
/// rule. Holds every problem found, not just the first; location() is the
/// first one's. CLI exit status 2.
class SceneError : public Error {
  public:
    /// `warnings` are those found alongside the errors, kept apart so that
    /// diagnostics() holds exactly the errors.
    explicit SceneError(std::vector<Diagnostic> diagnostics, std::vector<Diagnostic> warnings = {});
    /// Every error found, in the order found.
    const std::vector<Diagnostic>& diagnostics() const noexcept { return diagnostics_; }
    /// The warnings found alongside the errors.
    const std::vector<Diagnostic>& warnings() const noexcept { return warnings_; }

  private:
    std::vector<Diagnostic> diagnostics_;
    std::vector<Diagnostic> warnings_;
};

/// A file could not be read or written (missing, unreadable, not UTF-8, not
/// TOML, disk full). CLI exit status 1. `location` is set when the failure has
/// a place, such as a TOML syntax error.
class IoError : public Error {
  public:
    /// Which way the failed access went; it words the message.
    enum class Access {
        Read,  ///< "error: cannot read 'path': reason"
        Write  ///< "error: cannot write 'path': reason"
    };
    /// `reason` is the cause as the system or parser gives it ("No such file or directory").
    IoError(std::string path, std::string reason, FileLoc location = {},
            Access access = Access::Read);
    /// The file that failed, as given.
    const std::string& path() const noexcept { return path_; }
    /// Why it failed, without the path.
    const std::string& reason() const noexcept { return reason_; }
    /// Reading or writing.
    Access access() const noexcept { return access_; }

  private:
    std::string path_;
    std::string reason_;
    Access access_;
};

}  // namespace litkit
