#include "litkit/error.hpp"

#include <utility>

namespace litkit {

std::string FileLoc::to_string() const {
    std::string text = file;
    if (line > 0) {
        text += ':' + std::to_string(line);
        if (column > 0) text += ':' + std::to_string(column);
    }
    return text;
}

std::string Diagnostic::to_string() const {
    std::string text = location.to_string();
    if (!text.empty()) text += ": ";
    text += severity == Severity::Error ? "error: " : "warning: ";
    return text + message;
}

namespace {
std::string join_diagnostics(const std::vector<Diagnostic>& diagnostics) {
    std::string text;
    for (const Diagnostic& d : diagnostics) {
        if (!text.empty()) text += '\n';
        text += d.to_string();
    }
    return text;
}
}  // namespace

Error::Error(const std::string& what, FileLoc location)
    : std::runtime_error(what), location_(std::move(location)) {}

SceneError::SceneError(std::vector<Diagnostic> diagnostics, std::vector<Diagnostic> warnings)
    : Error(join_diagnostics(diagnostics), diagnostics.empty() ? FileLoc{} : diagnostics.front().location),
      diagnostics_(std::move(diagnostics)),
      warnings_(std::move(warnings)) {}

IoError::IoError(std::string path, std::string reason, FileLoc location, Access access)
    : Error((location.line > 0 ? location.to_string() + ": " : std::string()) + "error: cannot " +
                (access == Access::Read ? "read" : "write") + " '" + path + "': " + reason,
            location),
      path_(std::move(path)),
      reason_(std::move(reason)) {}

}  // namespace litkit
