# SPDX-License-Identifier: MIT
"""Meshes from NumPy arrays (Scene.add_mesh): drawn as the same mesh read
from an OBJ file is drawn, and checked as a file is (shapes, types, NaN,
indices out of range), with a litkit.Error that names the bad entry."""

import numpy as np
import pytest

import litkit

# A unit cube, counter-clockwise seen from outside, by hand.
CUBE_VERTICES = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5)
                          for z in (-0.5, 0.5)], dtype=np.float64)
# Vertex k is (x, y, z) with x = bit 2, y = bit 1, z = bit 0 of k.
CUBE_FACES = np.array([
    [0, 1, 3], [0, 3, 2],  # x = -0.5
    [4, 6, 7], [4, 7, 5],  # x = +0.5
    [0, 4, 5], [0, 5, 1],  # y = -0.5
    [2, 3, 7], [2, 7, 6],  # y = +0.5
    [0, 2, 6], [0, 6, 4],  # z = -0.5
    [1, 5, 7], [1, 7, 3],  # z = +0.5
], dtype=np.int32)

SCENE = """
[room]
width = 10
height = 10
depth = 10
[observer]
position = [2, 1.5, 4]
look_at = [0, 0, 0]
[lighting]
reflection = "phong"
shading = "flat"
[output]
width = 96
height = 72
[[lights]]
type = "point"
position = [2, 3, 3]
intensity = 8
"""


def scene_with_mesh(**placement):
    scene = litkit.loads(SCENE)
    index = scene.add_mesh(CUBE_VERTICES, CUBE_FACES, name="box", **placement)
    assert index == 0 and scene.object_count == 1
    return scene


def test_each_face_points_outwards():
    for a, b, c in CUBE_FACES:
        p, q, r = CUBE_VERTICES[a], CUBE_VERTICES[b], CUBE_VERTICES[c]
        centre = (p + q + r) / 3
        assert np.dot(np.cross(q - p, r - p), centre) > 0


def test_a_mesh_from_arrays_draws_as_the_same_mesh_from_an_obj_file(tmp_path, cli_render):
    obj = tmp_path / "box.obj"
    obj.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in CUBE_VERTICES) +
                   "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in CUBE_FACES))
    scene_file = tmp_path / "box.toml"
    scene_file.write_text(SCENE + '[[objects]]\nname = "box"\ntype = "mesh"\nfile = "box.obj"\n'
                          'position = [0.2, 0, 0]\nrotation = [0, 30, 0]\nscale = 1.5\n'
                          'material = { color = [200, 80, 60], ks = 0.3 }\n')
    material = litkit.Material(color=(200 / 255, 80 / 255, 60 / 255), ks=0.3)
    scene = scene_with_mesh(position=(0.2, 0, 0), rotation=(0, 30, 0), scale=1.5,
                            material=material)
    picture = litkit.render(scene)
    assert np.array_equal(picture, cli_render([scene_file]))
    assert len(np.unique(picture.reshape(-1, 3), axis=0)) > 3  # three lit faces and background


def test_lists_and_other_number_types_are_taken():
    scene = litkit.loads(SCENE)
    scene.add_mesh(CUBE_VERTICES.astype(np.float32).tolist(), CUBE_FACES.astype(np.uint64))
    scene.add_mesh(CUBE_VERTICES.astype(np.int64) * 0 + CUBE_VERTICES.astype(int),
                   CUBE_FACES.tolist(), position=(3, 0, 0))
    assert scene.object_count == 2


@pytest.mark.parametrize("vertices, faces, message", [
    (CUBE_VERTICES[:, :2], CUBE_FACES, "vertices must have the shape (N, 3) with at least one "
                                       "row, not (8, 2)"),
    (CUBE_VERTICES.ravel(), CUBE_FACES, "vertices must have the shape (N, 3) with at least one "
                                        "row, not (24,)"),
    (CUBE_VERTICES, CUBE_FACES[:, :2], "faces must have the shape (M, 3) with at least one row, "
                                       "not (12, 2)"),
    (CUBE_VERTICES, np.zeros((0, 3), int), "faces must have the shape (M, 3) with at least one "
                                           "row, not (0, 3)"),
    (CUBE_VERTICES, CUBE_FACES.astype(float), "faces must hold integers, not float64"),
    (CUBE_VERTICES.astype(str), CUBE_FACES, "vertices must hold numbers, not <U"),
    (np.where(np.arange(24).reshape(8, 3) == 10, np.nan, CUBE_VERTICES), CUBE_FACES,
     "vertices[3][1] is nan, not a finite 32-bit float"),
    (np.where(np.arange(24).reshape(8, 3) == 0, 1e300, CUBE_VERTICES), CUBE_FACES,
     "vertices[0][0] is 1e+300, not a finite 32-bit float"),
    (CUBE_VERTICES, np.where(CUBE_FACES == 7, 8, CUBE_FACES),
     "faces[2][2] is 8, not an index of vertices (0 to 7)"),
    (CUBE_VERTICES, np.where(CUBE_FACES == 5, -1, CUBE_FACES),
     "faces[3][2] is -1, not an index of vertices (0 to 7)"),
])
def test_bad_arrays_are_errors_that_name_the_entry(vertices, faces, message):
    scene = litkit.loads(SCENE)
    with pytest.raises(litkit.ArgumentError) as raised:
        scene.add_mesh(vertices, faces)
    assert isinstance(raised.value, litkit.Error)
    assert message in str(raised.value)
    assert scene.object_count == 0


def test_the_scene_rules_apply_and_a_refused_mesh_leaves_the_scene_alone():
    scene = scene_with_mesh()
    with pytest.raises(litkit.SceneError) as raised:
        scene.add_mesh(CUBE_VERTICES, CUBE_FACES, name="box", position=(2, 0, 0))
    assert "box" in str(raised.value)
    with pytest.raises(litkit.Error):
        scene.add_mesh(CUBE_VERTICES, CUBE_FACES, scale=0)
    assert scene.object_count == 1


def test_a_scene_holding_arrays_has_no_toml():
    with pytest.raises(litkit.ArgumentError):
        scene_with_mesh().to_toml()
