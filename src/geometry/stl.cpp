// SPDX-License-Identifier: MIT
// STL mesh files (docs/scene-format.md, "Mesh files"), ASCII and binary,
// read by a reader of our own: Debian has no STL library to read them with.
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/mesh_formats.hpp"
#include "geometry/mesh_text.hpp"
#include "litkit/error.hpp"

namespace litkit::detail {

namespace {

constexpr std::size_t binary_header_bytes = 84;    // 80 free bytes, the triangle count
constexpr std::size_t binary_triangle_bytes = 50;  // normal, 3 corners, attribute

void add_triangle(Mesh& mesh, const glm::vec3 (&corners)[3], std::size_t face) {
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::vec3& corner : corners) mesh.positions.push_back(corner);
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.triangle_file_normals.push_back(
        {missing_file_normal, missing_file_normal, missing_file_normal});
    mesh.triangle_faces.push_back(static_cast<std::uint32_t>(face));
}

Mesh parse_binary(std::string_view bytes, const std::string& name) {
    const BinaryBytes data{bytes, /*big_endian=*/false};
    const std::uint32_t count = data.read<std::uint32_t>(80);
    Mesh mesh;
    mesh.positions.reserve(std::size_t{3} * count);
    mesh.triangles.reserve(count);
    static const char* const axes[] = {"x", "y", "z"};
    for (std::uint32_t t = 0; t < count; ++t) {
        const std::size_t start = binary_header_bytes + binary_triangle_bytes * t;
        glm::vec3 corners[3];
        for (int corner = 0; corner < 3; ++corner) {
            for (int axis = 0; axis < 3; ++axis) {
                const std::size_t offset = start + 12 + 12 * corner + 4 * axis;
                const float value = data.read<float>(offset);
                if (!std::isfinite(value))
                    throw IoError(name,
                                  "triangle " + std::to_string(t + 1) + ", corner " +
                                      std::to_string(corner + 1) + ": the " + axes[axis] +
                                      " coordinate is not a finite number" + at_byte(offset),
                                  FileLoc{name});
                corners[corner][axis] = value;
            }
        }
        add_triangle(mesh, corners, t);
    }
    if (mesh.triangles.empty())
        throw IoError(name, "the file has no faces (binary STL, 0 triangles)", FileLoc{name});
    return mesh;
}

class AsciiReader {
  public:
    AsciiReader(std::string_view text, const std::string& name,
                std::vector<std::uint32_t>* face_lines)
        : words_(text), name_(name), face_lines_(face_lines) {}

    Mesh read() {
        expect("solid", "an ASCII STL file starts with 'solid'");
        skip_line();  // the solid's name
        while (true) {
            const MeshWord word = words_.next_word();
            if (word.text == "facet") {
                read_facet(word);
            } else if (word.text == "endsolid") {
                skip_line();
                const MeshWord after = words_.next_word();
                if (after.text.empty()) break;
                if (after.text != "solid")
                    fail(after, "expected 'solid' or the end of the file after 'endsolid', found " +
                                    quoted_word(after.text));
                skip_line();
            } else if (word.text.empty()) {
                fail(word, "the file ends before 'endsolid'");
            } else {
                fail(word, "expected 'facet' or 'endsolid', found " + quoted_word(word.text));
            }
        }
        if (mesh_.triangles.empty()) throw IoError(name_, "the file has no faces", FileLoc{name_});
        return std::move(mesh_);
    }

  private:
    [[noreturn]] void fail(const MeshWord& where, const std::string& reason) const {
        throw IoError(name_, reason, FileLoc{name_, where.line, where.column});
    }
    MeshWord expect(std::string_view keyword, const std::string& why = {}) {
        const MeshWord word = words_.next_word();
        if (word.text != keyword) {
            const std::string found =
                word.text.empty() ? "the end of the file" : quoted_word(word.text);
            fail(word.text.empty() ? words_.here() : word,
                 why.empty() ? "expected '" + std::string(keyword) + "', found " + found
                             : why + ", found " + found);
        }
        return word;
    }
    void skip_line() {
        while (words_.line_has_more()) words_.next_word();
    }
    // Three numbers; `finite` refuses infinities and NaN.
    glm::vec3 read_vector(const char* what, bool finite) {
        static const char* const axes[] = {"x", "y", "z"};
        glm::vec3 vector;
        for (int axis = 0; axis < 3; ++axis) {
            const MeshWord word = words_.next_word();
            if (word.text.empty())
                fail(words_.here(),
                     std::string(what) + " needs 3 coordinates, found " + std::to_string(axis));
            double value = 0;
            std::string problem = read_finite(word.text, value);
            if (!finite && problem == "is not a finite number") problem.clear();
            if (!problem.empty())
                fail(word, std::string(what) + " " + axes[axis] + " coordinate " +
                               quoted_word(word.text) + " " + problem);
            vector[axis] = static_cast<float>(value);
        }
        return vector;
    }
    void read_facet(const MeshWord& facet) {
        const std::size_t face = mesh_.triangles.size();
        if (face_lines_) face_lines_->push_back(facet.line);
        expect("normal");
        read_vector("facet normal", /*finite=*/false);  // not used (docs/scene-format.md)
        expect("outer");
        expect("loop");
        glm::vec3 corners[3];
        for (glm::vec3& corner : corners) {
            expect("vertex", "expected 'vertex' (a facet has three)");
            corner = read_vector("vertex", /*finite=*/true);
        }
        expect("endloop", "expected 'endloop' after a facet's three vertices");
        expect("endfacet");
        add_triangle(mesh_, corners, face);
    }

    MeshWords words_;
    const std::string& name_;
    std::vector<std::uint32_t>* face_lines_;
    Mesh mesh_;
};

// ASCII: "solid" first, and no zero byte where a binary file has its count
// (whose high byte is zero below 16,777,216 triangles): binary files whose
// free header starts with "solid" are common.
bool is_ascii(std::string_view bytes) {
    MeshWords words(bytes.substr(0, 512));
    return words.next_word().text == "solid" &&
           bytes.substr(0, binary_header_bytes).find('\0') == std::string_view::npos;
}

}  // namespace

Mesh parse_stl(std::string_view bytes, const std::string& name,
               std::vector<std::uint32_t>* face_lines) {
    // A binary file's size is fixed by its count: that decides first.
    if (bytes.size() >= binary_header_bytes) {
        const std::uint64_t count = BinaryBytes{bytes}.read<std::uint32_t>(80);
        const std::uint64_t expected = binary_header_bytes + binary_triangle_bytes * count;
        if (expected == bytes.size()) return parse_binary(bytes, name);
        if (!is_ascii(bytes))
            throw IoError(name,
                          "binary STL: the count at byte 80 says " + std::to_string(count) +
                              " triangles, which take 84 + 50 × " + std::to_string(count) + " = " +
                              std::to_string(expected) + " bytes, but the file has " +
                              std::to_string(bytes.size()) +
                              (expected > bytes.size() ? " (it is cut short)" : ""),
                          FileLoc{name});
    } else if (!is_ascii(bytes)) {
        throw IoError(name,
                      "not an STL file: it neither starts with 'solid' (ASCII) nor holds the "
                      "84-byte header of a binary STL",
                      FileLoc{name});
    }
    return AsciiReader(bytes, name, face_lines).read();
}

}  // namespace litkit::detail
