# SPDX-License-Identifier: MIT
"""litkit.explain: `litkit explain --pixel` from Python, and the ray tree of a
pixel that sees glass as Python data (docs/spec.md §10.3)."""

import math

import pytest

import litkit
from conftest import run_cli

# A glass ball (t = 1, ior 1.5) in front of a red cube on a grey-blue
# background: the pixel at the centre looks through the ball at the cube.
GLASS_SCENE = """
[room]
width = 20
height = 20
depth = 20

[observer]
position = [0, 0, 6]
look_at = [0, 0, 0]

[lighting]
reflection = "phong"
shading = "phong"

[output]
width = 60
height = 45
background = [40, 60, 90]

[[lights]]
type = "directional"
direction = [-0.3, -0.4, -1]

[[lights]]
type = "ambient"
intensity = 0.3

[[objects]]
name = "wall"
type = "cube"
size = 3
position = [0, 0, -4]
material = { color = [230, 60, 50] }

[[objects]]
name = "lens"
type = "sphere"
radius = 1.5
segments = 32
rings = 16
position = [0.2, 0.1, 1]
material = { color = [255, 255, 255], transmission = 1, ior = 1.5 }
"""


def glass_scene():
    return litkit.loads(GLASS_SCENE)


def test_explain_is_the_command_and_the_picture():
    e = litkit.explain(None, 400, 300)
    assert e.hit and e.object == "cube"
    assert e.text == run_cli("explain", "--pixel", "400,300").stdout
    assert str(e) == e.text
    assert tuple(litkit.render()[300, 400]) == e.rgb
    assert e.ray_tree == []  # an opaque cube


def test_explain_background_and_outside():
    e = litkit.explain(litkit.default_scene(), 0, 0)
    assert not e.hit and e.object is None and e.sum is None
    with pytest.raises(litkit.ArgumentError):
        litkit.explain(None, 800, 0)


def test_glass_pixel_has_its_ray_tree():
    scene = glass_scene()
    e = litkit.explain(scene, 30, 22)
    assert e.object == "lens"
    assert tuple(litkit.render(scene)[22, 30]) == e.rgb
    tree = e.ray_tree
    assert len(tree) >= 3
    first = tree[0]
    assert first["kind"] == "camera" and first["parent"] is None and first["depth"] == 1
    assert first["object"] == "lens" and first["outcome"] == "interface"
    assert not first["inside"]
    # Snell's law and the Fresnel factor, in their angle form, from θ₁.
    t1 = math.radians(first["theta1"])
    t2 = math.asin(math.sin(t1) / 1.5)
    assert first["theta2"] == pytest.approx(math.degrees(t2), abs=1e-3)
    if t1 > 1e-3:
        rs = math.sin(t1 - t2) / math.sin(t1 + t2)
        rp = math.tan(t1 - t2) / math.tan(t1 + t2)
        assert first["fresnel"] == pytest.approx((rs * rs + rp * rp) / 2, abs=1e-5)
    # Every node after its parent, one level deeper; the contributions add
    # up to the pixel's L.
    for index, node in enumerate(tree[1:], start=1):
        assert node["index"] == index
        assert 0 <= node["parent"] < index
        assert node["depth"] == tree[node["parent"]]["depth"] + 1
        assert node["kind"] in ("reflected", "refracted")
    for channel in range(3):
        total = sum(node["contribution"][channel] for node in tree)
        assert total == pytest.approx(e.sum[channel], abs=1e-5)
    assert "ray tree (docs/spec.md §10.2)" in e.text
