# SPDX-License-Identifier: MIT
"""litkit.render and litkit.Renderer draw what `litkit render` draws: the
arrays are compared pixel for pixel with the CLI's PNG, decoded by Pillow."""

import io

import numpy as np
import pytest
from conftest import EXAMPLES, read_png
from PIL import Image as PilImage

import litkit

SIZE = ("--width", 160, "--height", 120)

CASES = [
    # (scene file, reflection, shading): None keeps the scene's own model.
    ("reflection-models.toml", None, None),
    ("reflection-models.toml", "blinn-phong", "gouraud"),
    ("teapot.toml", "lambert", "flat"),
    ("spot-light.toml", "half-lambert", "phong"),
    ("mesh.toml", "phong", "faceted"),
    ("torus.toml", "cook-torrance", "gouraud"),
    ("gooch.toml", None, None),
    ("more-reflection-models.toml", "toon", "phong"),
]


@pytest.mark.parametrize("scene_file,reflection,shading", CASES)
def test_array_equals_the_png_litkit_render_writes(cli_render, scene_file, reflection, shading):
    path = EXAMPLES / scene_file
    options = list(SIZE)
    if reflection:
        options += ["--reflection", reflection]
    if shading:
        options += ["--shading", shading]
    expected = cli_render([path], *options)

    img = litkit.render(litkit.load(path), reflection=reflection, shading=shading,
                        width=160, height=120)

    assert isinstance(img, np.ndarray) and isinstance(img, litkit.Image)
    assert img.dtype == np.uint8 and img.shape == (120, 160, 3)
    assert expected.shape == img.shape
    assert np.array_equal(img, expected)
    assert img.std() > 0  # a picture, not a blank


def test_default_scene_at_its_own_size(cli_render):
    img = litkit.render(litkit.default_scene())
    assert img.shape == (600, 800, 3)
    assert np.array_equal(img, cli_render([]))


def test_several_files_merge_as_on_the_command_line(cli_render):
    files = sorted((EXAMPLES / "multi-file").glob("*.toml"))
    assert len(files) >= 2
    expected = cli_render(files, *SIZE)
    img = litkit.render(litkit.load(*files), width=160, height=120)
    assert np.array_equal(img, expected)
    assert np.array_equal(litkit.render(litkit.load(files), width=160, height=120), expected)


def test_scene_from_text_and_from_a_dict_equal_the_file(cli_render):
    path = EXAMPLES / "point-light.toml"
    expected = cli_render([path], *SIZE)
    from_text = litkit.loads(path.read_text(), name=str(path))
    assert np.array_equal(litkit.render(from_text, width=160, height=120), expected)
    as_dict = litkit.load(path).to_dict()
    from_dict = litkit.loads(as_dict)
    assert np.array_equal(litkit.render(from_dict, width=160, height=120), expected)


def test_a_dict_written_by_hand(cli_render, tmp_path):
    scene = {
        "room": {"width": 10, "height": 10, "depth": 20},
        "observer": {"position": [0, 1, 6], "look_at": [0, 0, 0]},
        "lighting": {"reflection": "blinn-phong", "shading": "phong"},
        "output": {"width": 96, "height": 64, "background": [10, 20, 30]},
        "lights": [{"type": "ambient", "intensity": 1.0},
                   {"type": "point", "position": [2, 3, 3], "intensity": 12}],
        "objects": [{"type": "sphere", "radius": 1.5, "name": "ball",
                     "material": {"color": [40, 160, 220], "ks": 0.6, "shininess": 48}}],
    }
    path = tmp_path / "by-hand.toml"
    path.write_text(litkit.dumps(scene))
    expected = cli_render([path])
    img = litkit.render(litkit.loads(scene))
    assert img.shape == (64, 96, 3)
    assert np.array_equal(img, expected)
    assert tuple(img[0, 0]) == (10, 20, 30)  # the background the dict asked for


def test_a_scene_changed_in_python_renders_as_the_same_scene_written_out(cli_render, tmp_path):
    scene = litkit.load(EXAMPLES / "reflection-models.toml")
    scene.observer.position = (1.0, 2.0, 9.0)
    scene.output.width, scene.output.height = 200, 100
    scene.shading = "gouraud"
    written = tmp_path / "changed.toml"
    written.write_text(scene.to_toml(str(written)))
    assert np.array_equal(litkit.render(scene), cli_render([written]))


def test_renderer_draws_other_observers_without_building_meshes_again(cli_render, tmp_path):
    scene = litkit.load(EXAMPLES / "teapot.toml")
    renderer = litkit.Renderer(scene, threads=2)
    first = renderer.render(width=160, height=120)
    assert np.array_equal(first, cli_render([EXAMPLES / "teapot.toml"], *SIZE))

    for position in [(3.0, 2.0, 5.0), (-4.0, 1.0, 3.0)]:
        scene.observer.position = position
        img = renderer.render(scene, reflection="blinn-phong", width=120, height=90)
        written = tmp_path / "moved.toml"
        written.write_text(scene.to_toml(str(written)))
        assert np.array_equal(img, cli_render([written], "--reflection", "blinn-phong",
                                              "--width", 120, "--height", 90))
        assert not np.array_equal(img[:, :, :], first[:90, :120, :])
    assert renderer.mesh_builds == 1
    assert renderer.thread_count == 2
    assert renderer.triangle_count > 1000

    # Moving an object is a new mesh: built again.
    moved = renderer.scene.to_dict()
    moved["objects"][0]["position"][0] += 0.5
    renderer.render(litkit.loads(moved))
    assert renderer.mesh_builds == 2


def test_threads_change_nothing_in_the_picture():
    scene = litkit.load(EXAMPLES / "sphere.toml")
    one = litkit.render(scene, threads=1, width=200, height=150)
    two = litkit.render(scene, threads=2, width=200, height=150)
    assert np.array_equal(one, two)


def test_repr_png_is_the_picture():
    img = litkit.render(litkit.default_scene(), width=64, height=48)
    data = img._repr_png_()
    assert data.startswith(b"\x89PNG\r\n\x1a\n")
    with PilImage.open(io.BytesIO(data)) as decoded:
        assert np.array_equal(np.asarray(decoded.convert("RGB")), img)
    # What is no longer an RGB picture does not pretend to be one.
    assert img[:, :, 0]._repr_png_() is None
    assert (img * 0.5)._repr_png_() is None


def test_save_writes_the_png(tmp_path):
    img = litkit.render(litkit.default_scene(), width=64, height=48)
    img.save(tmp_path / "out.png")
    assert np.array_equal(read_png(tmp_path / "out.png"), img)


def test_the_default_scene_text_is_the_default_scene():
    text_scene = litkit.loads(litkit.default_scene_toml())
    assert np.array_equal(litkit.render(text_scene, width=80, height=60),
                          litkit.render(litkit.default_scene(), width=80, height=60))


def test_a_scene_without_lighting_uses_phong_as_the_clis_yes(cli_render, tmp_path):
    scene = litkit.load(EXAMPLES / "sphere.toml").to_dict()
    del scene["lighting"]
    path = tmp_path / "no-lighting.toml"
    path.write_text(litkit.dumps(scene))
    loaded = litkit.load(path)
    assert loaded.reflection is None and loaded.shading is None
    img = litkit.render(loaded, width=160, height=120)
    assert np.array_equal(img, cli_render([path], *SIZE))
    assert np.array_equal(img, litkit.render(loaded, reflection="phong", shading="phong",
                                             width=160, height=120))
