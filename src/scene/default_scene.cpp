// SPDX-License-Identifier: MIT
// The built-in default scene of docs/spec.md §7 (R12), as the text `litkit init`
// writes and the playground starts with.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "litkit/lighting.hpp"
#include "litkit/mesh.hpp"
#include "litkit/scene.hpp"

namespace litkit {

namespace {

// The file with its lists of choices left as @names@: filled in from the
// library's own lists (filled_in_text below), so that a model added to the family
// appears in the starting file without another edit.
constexpr std::string_view text_with_lists = R"toml(# litkit scene: the built-in default scene.
#
# `litkit init` writes this file as a starting point; `litkit render` with no
# scene draws it. Change a number, render again, and see what it does.
# Coordinates: right-handed, +y is up, units are metres. Lines starting with
# '#' are comments.

# The room is a box centred at the origin: here x, y and z each run from -5
# to 5. It is not drawn; everything in the scene must fit inside it.
[room]
width = 10
height = 10
depth = 10

# The camera. It stands at `position` and looks at `look_at`; `fov` is the
# vertical field of view in degrees. (Also possible: `up`, `near`, `far`.)
[observer]
position = [3.5, 1, 4]
look_at = [-2, -3, -2]      # the centre of the cube
fov = 30

# How light is computed. Try the other models and compare:
@models@
[lighting]
reflection = "phong"
shading = "phong"

# The picture: its size in pixels and the colour where no object is.
[output]
width = 800
height = 600
background = [25, 28, 36]   # colours are [red, green, blue], 0-255, or "#rrggbb"

# One point light at the centre of the room. Its light fades with the square
# of the distance, so it needs some intensity to reach the cube about 4 m away.
# Other light types: @other lights@.
[[lights]]
name = "bulb"
type = "point"
position = [0, 0, 0]
color = [255, 255, 255]
intensity = 15

# One cube, below and behind the light so that the three faces you see are lit.
# `rotation` turns it about x, then y, then z (degrees). Other object types:
# sphere, torus, teapot, and mesh (an OBJ file).
[[objects]]
name = "cube"
type = "cube"
size = 2
position = [-2, -3, -2]
rotation = [0, 30, 0]
# ka: ambient, kd: diffuse (matte), ks: specular (shine), shininess: how
# small and sharp the highlight is.
material = { color = [200, 80, 60], ka = 0.1, kd = 0.7, ks = 0.5, shininess = 32 }
)toml";

// "#   label a | b | c", wrapped before column 80 with the names lined up.
std::string choice_lines(std::string_view label, std::span<const std::string_view> names) {
    std::string text = "#   " + std::string(label);
    const std::size_t indent = text.size();
    std::size_t line_length = indent;
    for (std::size_t i = 0; i < names.size(); ++i) {
        const std::string word = std::string(names[i]) + (i + 1 < names.size() ? " |" : "");
        if (i > 0 && line_length + 1 + word.size() > 79) {
            text += "\n#" + std::string(indent - 1, ' ');
            line_length = indent;
        }
        text += " " + word;
        line_length += 1 + word.size();
    }
    return text;
}

void fill_in(std::string& text, std::string_view key, const std::string& value) {
    text.replace(text.find(key), key.size(), value);
}

std::string filled_in_text() {
    std::vector<std::string_view> reflections;
    for (const ReflectionModel& model : reflection_models()) reflections.push_back(model.name);
    std::string other_lights;
    for (std::string_view kind : light_kind_names) {
        if (kind == "point") continue;  // the scene's own light
        other_lights += (other_lights.empty() ? "" : ", ") + std::string(kind);
    }
    std::string text(text_with_lists);
    fill_in(text, "@models@",
            choice_lines("reflection:", reflections) + "\n" +
                choice_lines("shading:   ", shading_names) + "\n" +
                "# and how vertex normals are found (file: a mesh file's own normals):\n" +
                choice_lines("normals:   ", normals_names));
    fill_in(text, "@other lights@", other_lights);
    return text;
}

}  // namespace

std::string_view default_scene_toml() {
    static const std::string text = filled_in_text();  // built once, never changed
    return text;
}

Scene default_scene() { return parse_scene(default_scene_toml(), "default.toml"); }

}  // namespace litkit
