// SPDX-License-Identifier: MIT
#include "litkit/error.hpp"

#include <string_view>
#include <utility>

namespace litkit {

namespace {

// One problem is one line: a newline or another control character in a
// name or path (which a scene chooses) is shown escaped, so that no scene
// can split a message or forge a diagnostic line.
std::string printable(std::string_view text) {
    static constexpr char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte != 0x7f) {
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else {
            out += "\\x";
            out += hex[byte >> 4];
            out += hex[byte & 15];
        }
    }
    return out;
}

}  // namespace

std::string FileLoc::to_string() const {
    std::string text = printable(file);
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
    return text + printable(message);
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
    : Error(join_diagnostics(diagnostics),
            diagnostics.empty() ? FileLoc{} : diagnostics.front().location),
      diagnostics_(std::move(diagnostics)),
      warnings_(std::move(warnings)) {}

IoError::IoError(std::string path, std::string reason, FileLoc location, Access access)
    : Error((location.line > 0 ? location.to_string() + ": " : std::string()) + "error: cannot " +
                (access == Access::Read ? "read" : "write") + " '" + printable(path) +
                "': " + printable(reason),
            location),
      path_(std::move(path)),
      reason_(std::move(reason)),
      access_(access) {}

}  // namespace litkit
