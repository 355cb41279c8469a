# SPDX-License-Identifier: MIT
"""Anti-aliasing (docs/spec.md §11) from Python: the samples keyword of
render, Renderer.render and explain, and Scene.output.samples, drawing what
`litkit render --samples N` draws, checked as the command line checks it."""

import numpy as np
import pytest
from conftest import EXAMPLES

import litkit


@pytest.mark.parametrize("samples", [4, 16])
def test_samples_keyword_draws_what_the_cli_draws(cli_render, samples):
    path = EXAMPLES / "reflection-models.toml"
    expected = cli_render([path], "--width", 160, "--height", 120, "--samples", samples)
    img = litkit.render(litkit.load(path), width=160, height=120, samples=samples)
    assert np.array_equal(img, expected)
    one = litkit.render(litkit.load(path), width=160, height=120)
    assert not np.array_equal(img, one)  # the edges are smoothed
    renderer = litkit.Renderer(litkit.load(path))
    assert np.array_equal(renderer.render(width=160, height=120, samples=samples), expected)
    assert np.array_equal(renderer.render(width=160, height=120), one)


def test_scene_field_is_read_written_and_checked():
    scene = litkit.loads(litkit.default_scene_toml().replace("[output]",
                                                             "[output]\nsamples = 8"))
    assert scene.output.samples == 8
    assert "samples = 8" in scene.to_toml()
    scene.output.samples = 3
    with pytest.raises(litkit.SceneError) as raised:
        litkit.render(scene)
    assert "samples must be 1, 4, 8 or 16, found 3" in str(raised.value)


@pytest.mark.parametrize("samples", [0, 2, 3, 32])
def test_other_counts_raise_argument_error(samples):
    with pytest.raises(litkit.ArgumentError) as raised:
        litkit.render(samples=samples, width=8, height=6)
    assert str(raised.value) == f"samples must be 1, 4, 8 or 16, found {samples}"


def test_explain_lists_the_samples(cli_render):
    scene = litkit.default_scene()
    e = litkit.explain(scene, 237, 300, samples=4)
    assert len(e.samples) == 4
    assert [s["position"] for s in e.samples] == [(0.375, 0.125), (0.875, 0.375),
                                                  (0.125, 0.625), (0.625, 0.875)]
    # The mean of the samples' L, after gamma, is the pixel of the picture.
    mean = np.mean([s["light"] for s in e.samples], axis=0)
    gamma = scene.output.gamma
    assert tuple(int(v) for v in np.floor(255 * mean ** (1 / gamma) + 0.5)) == e.rgb
    picture = cli_render([], "--samples", 4)
    assert tuple(picture[300, 237]) == e.rgb
    assert litkit.explain(scene, 237, 300).samples == []
