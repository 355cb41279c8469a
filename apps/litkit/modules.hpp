// SPDX-License-Identifier: MIT
// The commands' large libraries, loaded only by the commands that use them
// (docs/design.md, "Modules"): litkit-view.so (SDL2, Dear ImGui, libepoxy)
// for `litkit view`, litkit-gl.so (libepoxy, and through it EGL and OpenGL)
// for `--backend gl`. Every other run starts without them.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>

#include "litkit/scene.hpp"

namespace litkit_cli {

// What a module's interface begins with, so that the CLI uses only a module
// built from the same litkit with the same layout of what crosses (a stale
// module of another build or install is refused, not called).
struct ModuleStamp {
    const char* version;         // LITKIT_VERSION
    std::size_t scene_size;      // sizeof(litkit::Scene)
    std::size_t options_size;    // sizeof the options the module takes
    std::size_t interface_size;  // sizeof the module's interface

    bool operator==(const ModuleStamp& other) const {
        return std::strcmp(version, other.version) == 0 && scene_size == other.scene_size &&
               options_size == other.options_size && interface_size == other.interface_size;
    }
};

template <class Interface, class Options>
constexpr ModuleStamp module_stamp() {
    return {LITKIT_VERSION, sizeof(litkit::Scene), sizeof(Options), sizeof(Interface)};
}

// Why a module cannot be used, worded for "error: " (exit status 1, like a
// file that cannot be read).
struct ModuleError {
    std::string message;
};

struct OpenedModule {
    std::string path;
    void* entry = nullptr;  // the address of the module's entry function
};

// Finds `file_name` beside this executable (the build tree), else in the
// installed library folder (lib/litkit, relative to bin/), loads it and its
// libraries and looks up `entry`. `purpose` words the errors ("litkit
// view"). Throws ModuleError. A module stays loaded to the end of the process.
OpenedModule open_module_file(const std::string& file_name, const char* entry,
                              const std::string& purpose);

[[noreturn]] void refuse_foreign_module(const std::string& path);

// The interface a module's entry function returns (its first member is a
// ModuleStamp), checked against the stamp this CLI was built with.
template <class Interface, class Options>
const Interface& open_module(const std::string& file_name, const char* entry,
                             const std::string& purpose) {
    const OpenedModule opened = open_module_file(file_name, entry, purpose);
    const auto* interface = reinterpret_cast<const Interface* (*)()>(opened.entry)();
    if (!interface || !(interface->stamp == module_stamp<Interface, Options>()))
        refuse_foreign_module(opened.path);
    return *interface;
}

}  // namespace litkit_cli
