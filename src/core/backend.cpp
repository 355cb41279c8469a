// SPDX-License-Identifier: MIT
#include "litkit/backend.hpp"

#include <array>

namespace litkit {

namespace {
// The one list of backends, in the enumeration's order.
constexpr auto backend_table = std::to_array<BackendInfo>({
    {Backend::Cpu, "cpu", "litkit's own renderer"},
    {Backend::Gl, "gl", "OpenGL 3.3 on a headless EGL context"},
});
}  // namespace

std::span<const BackendInfo> backends() { return backend_table; }

std::string_view to_string(Backend backend) {
    for (const BackendInfo& info : backend_table)
        if (info.id == backend) return info.name;
    return "?";
}

std::optional<Backend> parse_backend(std::string_view text) {
    for (const BackendInfo& info : backend_table)
        if (info.name == text) return info.id;
    return std::nullopt;
}

}  // namespace litkit
