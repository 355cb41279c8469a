// Errors the library throws. The library never prints or exits: it throws one
// of these, and the caller (the CLI, a test, a user's program) decides how to
// show it. Every error about a scene carries the place it comes from.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace litkit {

// A place in a source file, printed the way compilers and editors expect:
// "scene.toml:14:12". Line and column are 1-based; 0 means "unknown".
struct FileLoc {
    std::string file;
    std::uint32_t line = 0;
    std::uint32_t column = 0;

    std::string to_string() const;
};

enum class Severity { Error, Warning };

// One problem found in the input, e.g.
// "scene.toml:14:12: error: lights[0] 'key': position [0, -3, 0] is inside object 'box'".
struct Diagnostic {
    FileLoc location;
    Severity severity = Severity::Error;
    std::string message;

    std::string to_string() const;
};

// The one base of every error litkit throws, so that one `catch` reports them
// all: what() is the one-line (for SceneError, one line per problem)
// diagnostic that `litkit check` prints, and location() says where, when
// there is a place ("scene.toml:14:12"; empty otherwise).
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& what, FileLoc location = {});
    const FileLoc& location() const noexcept { return location_; }

private:
    FileLoc location_;
};

// A function of the library was called with arguments outside its contract
// (a sphere of radius 0, a pixel outside the image, a light capacity of 0).
class ArgumentError : public Error {
public:
    using Error::Error;
};

// Invalid input: the scene (or a value given on the command line) breaks a
// rule. Holds every problem found, not just the first; location() is the
// first one's. CLI exit status 2.
class SceneError : public Error {
public:
    // `warnings` are those found alongside the errors, kept apart so that
    // diagnostics() holds exactly the errors.
    explicit SceneError(std::vector<Diagnostic> diagnostics, std::vector<Diagnostic> warnings = {});
    const std::vector<Diagnostic>& diagnostics() const noexcept { return diagnostics_; }
    const std::vector<Diagnostic>& warnings() const noexcept { return warnings_; }

private:
    std::vector<Diagnostic> diagnostics_;
    std::vector<Diagnostic> warnings_;
};

// A file could not be read or written (missing, unreadable, not UTF-8, not
// TOML, disk full). CLI exit status 1. `location` is set when the failure has
// a place, such as a TOML syntax error.
class IoError : public Error {
public:
    enum class Access { Read, Write };
    IoError(std::string path, std::string reason, FileLoc location = {},
            Access access = Access::Read);
    const std::string& path() const noexcept { return path_; }
    const std::string& reason() const noexcept { return reason_; }

private:
    std::string path_;
    std::string reason_;
};

}  // namespace litkit
