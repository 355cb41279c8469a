// SPDX-License-Identifier: MIT
// What the mesh format tests (test_mesh_formats.cpp, test_gltf.cpp) share:
// binary files built from explicit values, files written to a folder of
// the test's own, and errors checked for their message and place.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/mesh.hpp"

namespace litkit_test {

using Triangle = std::array<std::uint32_t, 3>;

// obj/closed_cube.obj's cube, which ply/cube.ply, stl/cube.stl and
// gltf/cube.gltf write again: its vertices, and its quads (a b c d), each
// the triangles (a b c) (a c d).
inline const std::vector<glm::vec3> cube_vertices = {
    {-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, -0.5f}, {-0.5f, 0.5f, -0.5f},
    {-0.5f, -0.5f, 0.5f},  {0.5f, -0.5f, 0.5f},  {0.5f, 0.5f, 0.5f},  {-0.5f, 0.5f, 0.5f}};
inline const std::vector<Triangle> cube_triangles = {{4, 5, 6}, {4, 6, 7}, {1, 0, 3}, {1, 3, 2},
                                                     {5, 1, 2}, {5, 2, 6}, {0, 4, 7}, {0, 7, 3},
                                                     {7, 6, 2}, {7, 2, 3}, {0, 1, 5}, {0, 5, 4}};

// The mesh's positions, exactly.
inline void expect_positions(const litkit::Mesh& mesh, const std::vector<glm::vec3>& expected) {
    ASSERT_EQ(mesh.positions.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(mesh.positions[i].x, expected[i].x) << "position " << i;
        EXPECT_EQ(mesh.positions[i].y, expected[i].y) << "position " << i;
        EXPECT_EQ(mesh.positions[i].z, expected[i].z) << "position " << i;
    }
}

static_assert(std::endian::native == std::endian::little,
              "the byte builders below lay little-endian values out as the machine does");

// Bytes of a binary file, each value appended in the chosen byte order.
struct Bytes {
    std::string data;
    bool big_endian = false;

    template <typename T>
    Bytes& put(T value) {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        if (big_endian) std::reverse(raw, raw + sizeof(T));
        data.append(raw, sizeof(T));
        return *this;
    }
    Bytes& text(std::string_view text) {
        data += text;
        return *this;
    }
};

// A fresh folder for this test process's files, removed when it ends.
inline const std::filesystem::path& scratch_folder() {
    struct Folder {
        std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("litkit-formats-" + std::to_string(::getpid()));
        Folder() {
            std::filesystem::remove_all(path);
            std::filesystem::create_directories(path);
        }
        ~Folder() {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    };
    static const Folder folder;
    return folder.path;
}

inline std::filesystem::path write_file(const std::string& name, std::string_view bytes) {
    const std::filesystem::path path = scratch_folder() / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<long>(bytes.size()));
    return path;
}

// Runs `read`, which must throw an IoError whose reason holds `reason` and
// whose place is `line`:`column` of the file (0: none).
inline void expect_io_error(const std::function<void()>& read, const std::string& reason,
                            std::uint32_t line = 0, std::uint32_t column = 0) {
    try {
        read();
        ADD_FAILURE() << "no error; expected: " << reason;
    } catch (const litkit::IoError& error) {
        EXPECT_NE(error.reason().find(reason), std::string::npos)
            << error.reason() << "\n  does not hold: " << reason;
        EXPECT_EQ(error.location().line, line) << error.what();
        EXPECT_EQ(error.location().column, column) << error.what();
    }
}

}  // namespace litkit_test
