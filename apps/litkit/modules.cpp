// SPDX-License-Identifier: MIT
#include "modules.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <vector>

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;

// Where a module may be: beside the executable as the build tree lays them
// out, then as `cmake --install` lays them out, relative to the executable
// so that an installed tree can be moved (or installed with --prefix or
// DESTDIR) and still find its own modules.
std::vector<fs::path> module_candidates(const std::string& file_name) {
    std::error_code error;
    const fs::path executable = fs::read_symlink("/proc/self/exe", error);
    if (error) return {};
    const fs::path folder = executable.parent_path();
    return {folder / file_name,
            (folder / LITKIT_MODULE_DIR_FROM_BIN / file_name).lexically_normal()};
}

}  // namespace

OpenedModule open_module_file(const std::string& file_name, const char* entry,
                              const std::string& purpose) {
    const std::vector<fs::path> candidates = module_candidates(file_name);
    if (candidates.empty()) {
        throw ModuleError{purpose + " cannot find its module " + file_name +
                          ": this executable's own path is unknown (/proc/self/exe)"};
    }
    std::error_code error;
    const auto found = std::find_if(candidates.begin(), candidates.end(),
                                    [&](const fs::path& path) { return fs::exists(path, error); });
    if (found == candidates.end()) {
        std::string looked;
        for (const fs::path& path : candidates)
            looked += (looked.empty() ? "" : ", ") + path.string();
        throw ModuleError{purpose + " needs its module " + file_name +
                          ", which is not installed with this litkit (looked for " + looked +
                          "); build litkit again, or install it again"};
    }
    OpenedModule opened{found->string()};
    // RTLD_NOW: a symbol missing from a library the module needs is an error
    // here, not a crash in the middle of the run.
    void* handle = ::dlopen(opened.path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* reason = ::dlerror();
        throw ModuleError{purpose + " cannot load its module " + opened.path + ": " +
                          (reason ? reason : "unknown reason")};
    }
    opened.entry = ::dlsym(handle, entry);
    if (!opened.entry) refuse_foreign_module(opened.path);
    return opened;
}

void refuse_foreign_module(const std::string& path) {
    throw ModuleError{path + " is not a module of litkit " LITKIT_VERSION
                             " (another build's?); install litkit again"};
}

}  // namespace litkit_cli
