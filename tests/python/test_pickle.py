# SPDX-License-Identifier: MIT
"""Scenes pickle (as their TOML text), so that another process, a Dask or
multiprocessing worker, renders the same picture."""

import pickle

import numpy as np
import pytest
from conftest import EXAMPLES

import litkit


@pytest.mark.parametrize("name", ["teapot.toml", "coloured-glass.toml", "mesh-formats.toml"])
def test_a_pickled_scene_renders_the_same_picture(name):
    scene = litkit.load(EXAMPLES / name)
    scene.observer.fov = 33.5  # a change made in Python travels too
    copy = pickle.loads(pickle.dumps(scene))
    assert copy.observer.fov == 33.5
    assert copy.to_toml() == scene.to_toml()
    size = {"width": 80, "height": 60}
    assert np.array_equal(litkit.render(copy, **size), litkit.render(scene, **size))


def test_a_scene_without_lighting_stays_without():
    scene = litkit.default_scene()
    scene.reflection = scene.shading = None
    copy = pickle.loads(pickle.dumps(scene))
    assert copy.reflection is None and copy.shading is None


def test_a_scene_with_a_mesh_from_arrays_does_not_pickle():
    scene = litkit.default_scene()
    scene.add_mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float),
                   np.array([[0, 1, 2]]), name="tri", position=(2, -4, -3))
    with pytest.raises(litkit.ArgumentError, match="in-memory mesh"):
        pickle.dumps(scene)


def test_a_bad_state_is_refused():
    scene = litkit.Scene.__new__(litkit.Scene)  # as pickle makes one before its state
    with pytest.raises(litkit.ArgumentError, match="one TOML text"):
        scene.__setstate__((1, 2))
