// The built-in default scene of docs/spec.md §7 (R12), as the text `litkit init`
// writes.
#include "litkit/scene.hpp"

namespace litkit {

std::string_view default_scene_toml() {
    return R"toml(# litkit scene: the built-in default scene.
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
#   reflection: lambert | half-lambert | phong | blinn-phong
#   shading:    flat | gouraud | phong | faceted
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
# Other light types: ambient, directional, spot.
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
}

Scene default_scene() { return parse_scene(default_scene_toml(), "default.toml"); }

}  // namespace litkit
