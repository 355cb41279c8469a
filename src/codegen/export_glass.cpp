// SPDX-License-Identifier: MIT
// Glass in the program of `litkit export --format cpp` (gl_glass.hpp): the
// scene for the shaders' rays as arrays in main.cpp, and the lines that
// hand it to GlassBuffers (src/gl/opengl_core.inc), as the GL backend does.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "codegen/gl_glass.hpp"
#include "codegen/glsl_expr.hpp"

namespace litkit::detail {

namespace {

std::string literal(float value) { return glsl::float_literal(value) + "f"; }

// `floats` as rows of four (one texel each) of a float array named `name`.
std::string float_array(const std::string& name, const std::vector<float>& floats) {
    std::string text = "const float " + name + "[] = {\n";
    for (std::size_t i = 0; i < floats.size(); i += 4) {
        text += "   ";
        for (std::size_t k = i; k < i + 4 && k < floats.size(); ++k) {
            text += ' ';
            text += literal(floats[k]);
            text += ',';
        }
        text += '\n';
    }
    if (floats.empty()) text += "    0.0f,  // none\n";
    return text + "};\n";
}

// The nodes hold integers in some floats' bits: written as the bits.
std::string bits_array(const std::string& name, const std::vector<float>& floats) {
    std::string text = "const std::uint32_t " + name + "[] = {\n";
    char word[16];
    for (std::size_t i = 0; i < floats.size(); i += 4) {
        text += "   ";
        for (std::size_t k = i; k < i + 4 && k < floats.size(); ++k) {
            std::snprintf(word, sizeof word, " 0x%08xu,", std::bit_cast<std::uint32_t>(floats[k]));
            text += word;
        }
        text += '\n';
    }
    if (floats.empty()) text += "    0u,  // none\n";
    return text + "};\n";
}

std::string int_list(std::span<const int> values) {
    std::string text;
    for (const int v : values) text += std::to_string(v) + ", ";
    return text;
}

}  // namespace

GlassSource glass_source(const GlassData& data, std::span<const int> glass_object) {
    GlassSource source;
    source.declarations =
        "\n"
        "// Glass (docs/spec.md §10): the scene as the glass programs' rays see it\n"
        "// (GlassScene in part 1: every triangle in world space under a hierarchy,\n"
        "// the objects' surfaces and glass), and per object its number for those\n"
        "// programs (-1: opaque) and its first triangle in the faces' buffer.\n"
        "// Defined at the end of the file.\n"
        "extern const GlassScene glass_scene;\n"
        "extern const int glass_object_of[];\n"
        "extern const int glass_face_base[];\n";
    source.setup =
        "        glass_ = std::make_unique<GlassBuffers>(glass_scene);\n"
        "        for (std::size_t i = 0; i < objects.size(); ++i) {\n"
        "            items_[i].glass_object = glass_object_of[i];\n"
        "            items_[i].face_base = glass_face_base[i];\n"
        "        }\n";
    std::string& a = source.arrays;
    a += "// Glass: 7 texels of 4 floats a triangle, in the hierarchy's leaf order.\n";
    a += float_array("glass_triangles", data.triangles);
    a += "// The hierarchy: 2 texels a node, depth first; some floats' bits are integers.\n";
    a += bits_array("glass_node_bits", data.nodes);
    a += "// The objects' surfaces and glass, and each triangle's face normal.\n";
    a += float_array("glass_objects", data.objects);
    a += float_array("glass_faces", data.faces);
    a += "const int glass_object_of[] = {" + int_list(glass_object) + "};\n";
    a += "const int glass_face_base[] = {" + int_list(data.face_base) + "};\n";
    a += "\n"
         "std::vector<float> floats_of_bits(const std::uint32_t* bits, std::size_t count) {\n"
         "    std::vector<float> floats(count);\n"
         "    std::memcpy(floats.data(), bits, count * sizeof(float));\n"
         "    return floats;\n"
         "}\n"
         "\n"
         "const GlassScene glass_scene = {\n"
         "    std::vector<float>(std::begin(glass_triangles), std::end(glass_triangles)),\n"
         "    floats_of_bits(glass_node_bits, std::size(glass_node_bits)),\n"
         "    std::vector<float>(std::begin(glass_objects), std::end(glass_objects)),\n"
         "    std::vector<float>(std::begin(glass_faces), std::end(glass_faces)),\n"
         "    " +
         std::to_string(data.node_count) +
         ",  // nodes\n"
         "    " +
         literal(data.room_ior) +
         ",  // n_r\n"
         "    " +
         std::to_string(data.max_depth) +
         ",  // max_depth\n"
         "    " +
         literal(data.min_distance) +
         ",  // secondary rays' nearest hit\n"
         "    glm::vec3(" +
         literal(data.background_light.x) + ", " + literal(data.background_light.y) + ", " +
         literal(data.background_light.z) +
         "),  // (background / 255)^gamma\n"
         "};\n";
    source.numbers =
        data.triangles.size() + data.nodes.size() + data.objects.size() + data.faces.size();
    return source;
}

}  // namespace litkit::detail
