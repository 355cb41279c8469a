// SPDX-License-Identifier: MIT
// libFuzzer target over the scene loader (docs/spec.md §6: "bad input never renders
// and never crashes"). Any bytes may come in; the only acceptable ways out
// are a Scene, a SceneError (invalid input) or an IoError (not UTF-8, not
// TOML). Anything else — another exception, a crash, a sanitizer report, a
// leak, a hang — is a bug, and is left to reach libFuzzer.
//
// Build and run: scripts/fuzz.sh [SECONDS].
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "litkit/error.hpp"
#include "litkit/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        // parse_scene runs the whole load path: TOML, the scene's shape
        // (types, keys, spelling) and then validate_scene (validate.hpp: the
        // value and geometry rules, building each object's mesh). The folder
        // does not exist, so that a relative mesh `file` never reaches a
        // real file and a crash replays the same from any working folder.
        const litkit::Scene scene = litkit::parse_scene(text, "no-such-folder/fuzz.toml");
        for (const litkit::Diagnostic& warning : scene.warnings)
            static_cast<void>(warning.to_string());
        for (const litkit::SceneObject& object : scene.objects)
            static_cast<void>(litkit::object_to_world(object));
    } catch (const litkit::SceneError& error) {
        // The CLI prints every diagnostic: formatting them is on the path too.
        for (const litkit::Diagnostic& diagnostic : error.diagnostics())
            static_cast<void>(diagnostic.to_string());
    } catch (const litkit::IoError& error) {
        static_cast<void>(error.location().to_string());
    }
    return 0;
}
