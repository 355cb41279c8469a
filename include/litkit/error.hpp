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

// Invalid input: the scene (or a value given on the command line) breaks a
// rule. Holds every problem found, not just the first. CLI exit status 2.
class SceneError : public std::runtime_error {
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
class IoError : public std::runtime_error {
public:
    enum class Access { Read, Write };
    IoError(std::string path, std::string reason, FileLoc location = {},
            Access access = Access::Read);
    const std::string& path() const noexcept { return path_; }
    const std::string& reason() const noexcept { return reason_; }
    const FileLoc& location() const noexcept { return location_; }

private:
    std::string path_;
    std::string reason_;
    FileLoc location_;
};

}  // namespace litkit
