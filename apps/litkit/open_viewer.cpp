#include "open_viewer.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;

// Where the module may be: beside the executable as the build tree lays
// them out, then as `cmake --install` lays them out, relative to the
// executable so that an installed tree can be moved (or installed with
// --prefix or DESTDIR) and still find its own module.
std::vector<fs::path> module_candidates() {
    std::error_code error;
    const fs::path executable = fs::read_symlink("/proc/self/exe", error);
    if (error) return {};
    const fs::path folder = executable.parent_path();
    return {folder / LITKIT_VIEWER_MODULE_NAME,
            (folder / LITKIT_VIEWER_MODULE_FROM_BIN / LITKIT_VIEWER_MODULE_NAME).lexically_normal()};
}

}  // namespace

const ViewerModule& open_viewer_module() {
    const std::vector<fs::path> candidates = module_candidates();
    if (candidates.empty()) {
        throw ViewerModuleError{"litkit view cannot find its module " +
                                std::string(LITKIT_VIEWER_MODULE_NAME) +
                                ": this executable's own path is unknown (/proc/self/exe)"};
    }
    std::error_code error;
    const auto found = std::find_if(candidates.begin(), candidates.end(),
                                    [&](const fs::path& path) { return fs::exists(path, error); });
    if (found == candidates.end()) {
        std::string looked;
        for (const fs::path& path : candidates) looked += (looked.empty() ? "" : ", ") + path.string();
        throw ViewerModuleError{"litkit view needs its window module, which is not installed with "
                                "this litkit (looked for " + looked +
                                "); build the target litkit_view, or install litkit again"};
    }
    const std::string path = found->string();
    // RTLD_NOW: a symbol missing from a library the module needs is an error
    // here, not a crash in the middle of the session.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* reason = ::dlerror();
        throw ViewerModuleError{"litkit view cannot load its module " + path + ": " +
                                (reason ? reason : "unknown reason")};
    }
    using Entry = const ViewerModule* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(handle, "litkit_viewer_module"));
    const ViewerModule* module = entry ? entry() : nullptr;
    if (!module || !module->run || std::string(module->version) != LITKIT_VERSION ||
        module->options_size != sizeof(ViewerOptions) || module->scene_size != sizeof(litkit::Scene)) {
        ::dlclose(handle);
        throw ViewerModuleError{path + " is not the viewer module of litkit " LITKIT_VERSION
                                       " (another build's?); install litkit again"};
    }
    return *module;
}

}  // namespace litkit_cli
