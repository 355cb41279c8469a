// SPDX-License-Identifier: MIT
// libFuzzer target over the Wavefront OBJ reader (load_obj) and what a scene
// does next with the mesh it returns: the vertex normals of every weighting,
// creased corner normals, the closed-mesh test and the signed volume. Any
// bytes may come in; the only acceptable way out besides a Mesh is an
// IoError (a file that cannot be read or parsed). Anything else — another
// exception, a crash, a sanitizer report, a leak, a hang, or a mesh that
// mesh_to_obj writes and load_obj does not read back as the same — is a
// bug, and is left to reach libFuzzer.
//
// load_obj reads a path (and reads the file again to place an error at its
// line), so each input is written to one file of this process's own first,
// in /dev/shm where there is one (memory: on this project's machines a file
// in /tmp made the runs four times slower), else in the temporary folder.
//
// Build and run: scripts/fuzz.sh [SECONDS] obj.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "litkit/error.hpp"
#include "litkit/mesh.hpp"
#include "litkit/shapes.hpp"

namespace {

// The input's file, removed when the process ends normally.
struct InputFile {
    std::filesystem::path path;
    ~InputFile() {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
    }
};

void write_file(const std::filesystem::path& path, std::string_view text) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (file == nullptr) std::abort();  // the fuzzer's own temporary file: not an input's fault
    if (!text.empty() && std::fwrite(text.data(), 1, text.size(), file) != text.size())
        std::abort();
    if (std::fclose(file) != 0) std::abort();
}

litkit::Mesh read(const std::filesystem::path& path, std::string_view text) {
    write_file(path, text);
    return litkit::load_obj(path);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const InputFile input{(std::filesystem::is_directory("/dev/shm")
                                      ? std::filesystem::path("/dev/shm")
                                      : std::filesystem::temp_directory_path()) /
                                 ("litkit-fuzz-obj-" + std::to_string(::getpid()) + ".obj")};
    const std::filesystem::path& path = input.path;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const litkit::Mesh mesh = read(path, text);
        for (const litkit::Normals weighting : {litkit::Normals::Mean, litkit::Normals::Area,
                                                litkit::Normals::Angle, litkit::Normals::Max}) {
            static_cast<void>(litkit::vertex_normals(mesh, weighting));
        }
        static_cast<void>(litkit::corner_normals(mesh, litkit::Normals::Angle, 30.0f));
        static_cast<void>(litkit::bounds(mesh));
        if (litkit::is_closed(mesh)) static_cast<void>(litkit::signed_volume(mesh));
        // mesh.hpp: what mesh_to_obj writes, load_obj reads back as the same
        // positions and triangles.
        const litkit::Mesh again = read(path, litkit::mesh_to_obj(mesh));
        if (again.positions != mesh.positions || again.triangles != mesh.triangles) std::abort();
    } catch (const litkit::IoError& error) {
        // The CLI prints the location: formatting it is on the path too.
        static_cast<void>(error.location().to_string());
    }
    return 0;
}
