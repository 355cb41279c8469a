// SPDX-License-Identifier: MIT
// libFuzzer targets over the mesh readers (docs/reliability.md): fuzz_ply,
// fuzz_stl and fuzz_gltf, this file compiled once per format
// (LITKIT_FUZZ_FORMAT: 1 PLY, 2 STL, 3 glTF). Any bytes may come in; the
// only acceptable ways out are a mesh that keeps the readers' promises
// (every index below the positions, every position finite, every file
// normal index below the file normals) or an IoError. Anything else (another
// exception, a crash, a sanitizer report, a leak, a hang) is a bug, and is
// left to reach libFuzzer.
//
// Build and run: scripts/fuzz.sh [SECONDS] fuzz_ply (or fuzz_stl, fuzz_gltf).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "geometry/mesh_formats.hpp"
#include "litkit/error.hpp"
#include "litkit/mesh.hpp"

namespace {

litkit::Mesh read(std::string_view bytes) {
#if LITKIT_FUZZ_FORMAT == 1
    return litkit::detail::parse_ply(bytes, "fuzz.ply");
#elif LITKIT_FUZZ_FORMAT == 2
    return litkit::detail::parse_stl(bytes, "fuzz.stl");
#else
    // The folder does not exist: a buffer file's URI never reaches a real
    // file, and a crash replays the same from any working folder.
    return litkit::detail::parse_gltf(bytes, "no-such-folder/fuzz.gltf");
#endif
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        const litkit::Mesh mesh = read(bytes);
        if (!litkit::check_mesh_data(mesh).empty()) std::abort();
        if (mesh.triangle_file_normals.size() != mesh.triangles.size() ||
            mesh.triangle_faces.size() != mesh.triangles.size())
            std::abort();
        for (const auto& corners : mesh.triangle_file_normals)
            for (const std::uint32_t normal : corners)
                if (normal != litkit::missing_file_normal && normal >= mesh.file_normals.size())
                    std::abort();
    } catch (const litkit::IoError& error) {
        static_cast<void>(error.location().to_string());
        static_cast<void>(std::string(error.what()));
    }
    return 0;
}
