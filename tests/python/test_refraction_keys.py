# SPDX-License-Identifier: MIT
"""The scene keys of refraction (docs/spec.md §10.1) in Python: Material's
transmission, ior, absorption_color and absorption_distance, Room.ior,
Scene.max_depth and the max_depth keyword of render, with the checks
``litkit check`` makes."""

import pytest
from conftest import SOURCE_DIR, run_cli

import litkit

OBJ = SOURCE_DIR / "tests" / "data" / "obj"

SCENE = """\
[room]
width = 10
height = 10
depth = 10
ior = 1.25

[observer]
position = [0, 1, 4]

[lighting]
reflection = "phong"
shading = "phong"
max_depth = 5

[output]
width = 40
height = 30

[[lights]]
type = "point"
position = [0, 3, 3]
intensity = 9

[[objects]]
name = "glass"
type = "mesh"
file = "{file}"
material = {{ transmission = 0.75, ior = 1.33, absorption_color = [51, 102, 255], absorption_distance = 2.5 }}
"""


def scene_text(file="closed_cube.obj"):
    return SCENE.format(file=(OBJ / file).as_posix())


def test_material_takes_the_keys_with_the_specs_defaults():
    plain = litkit.Material()
    assert plain.transmission == 0.0
    assert plain.ior == 1.5
    assert tuple(plain.absorption_color) == (1.0, 1.0, 1.0)
    assert plain.absorption_distance == 1.0
    glass = litkit.Material(transmission=0.5, ior=2.42, absorption_color=(0.2, 0.4, 1.0),
                            absorption_distance=3.0)
    assert glass.transmission == 0.5
    assert glass.ior == pytest.approx(2.42)
    assert tuple(glass.absorption_color) == pytest.approx((0.2, 0.4, 1.0))
    assert glass.absorption_distance == 3.0
    glass.ior = 1.33
    assert glass.ior == pytest.approx(1.33)


def test_room_ior_and_max_depth_are_read_and_written_back():
    scene = litkit.loads(scene_text())
    assert scene.room.ior == 1.25
    assert scene.max_depth == 5
    material = scene.to_dict()["objects"][0]["material"]
    assert material["transmission"] == 0.75
    assert material["ior"] == pytest.approx(1.33)
    assert material["absorption_color"] == [51, 102, 255]
    assert material["absorption_distance"] == 2.5
    scene.room.ior = 1.5
    scene.max_depth = 12
    again = litkit.loads(scene.to_toml())
    assert again.room.ior == 1.5 and again.max_depth == 12


def test_defaults_without_the_keys():
    scene = litkit.default_scene()
    assert scene.room.ior == 1.0
    assert scene.max_depth == 8


def test_max_depth_is_an_override_of_one_render():
    scene = litkit.default_scene()
    plain = litkit.render(scene, width=40, height=30)
    # Nothing refracts in the default scene: the picture stays the same.
    assert (litkit.render(scene, width=40, height=30, max_depth=1) == plain).all()
    renderer = litkit.Renderer(scene)
    assert (renderer.render(width=40, height=30, max_depth=16) == plain).all()
    assert renderer.scene.max_depth == 8


def test_a_max_depth_out_of_range_set_in_python_is_refused():
    scene = litkit.default_scene()
    scene.max_depth = 0
    with pytest.raises(litkit.SceneError) as raised:
        litkit.render(scene)
    assert raised.value.message == "lighting: max_depth must be 1–16, found 0"


def test_an_open_mesh_with_transmission_is_the_error_check_prints(tmp_path):
    path = tmp_path / "open.toml"
    path.write_text(scene_text("open_cube.obj"))
    with pytest.raises(litkit.SceneError) as raised:
        litkit.load(path)
    printed = [line for line in run_cli("check", path, check=False).stderr.splitlines()
               if "error: " in line]
    assert [str(raised.value)] == printed
    assert raised.value.message == (
        "objects[0] 'glass': transmission 0.75 needs a closed mesh (docs/spec.md §10.1), and "
        "mesh file 'open_cube.obj' is not closed: its edge from [0.5, 0.5, 0.5] to "
        "[-0.5, 0.5, 0.5] (face 1, line 13) belongs to one triangle only")
    # The closed cube is the valid control.
    closed = tmp_path / "closed.toml"
    closed.write_text(scene_text())
    assert litkit.render(litkit.load(closed)).shape == (30, 40, 3)
