# SPDX-License-Identifier: MIT
"""A picture shows inline in Jupyter: IPython's display formatter (what the
Jupyter kernel calls to turn a cell's value into display data) gives it an
image/png that decodes to the very pixels."""

import io

import numpy as np
from IPython.core.formatters import DisplayFormatter
from PIL import Image as PilImage

import litkit


def test_a_rendered_picture_is_displayed_as_a_png():
    img = litkit.render(litkit.default_scene(), width=64, height=48)
    data, _ = DisplayFormatter().format(img)
    assert "image/png" in data
    with PilImage.open(io.BytesIO(data["image/png"])) as shown:
        assert shown.size == (64, 48)
        assert np.array_equal(np.asarray(shown.convert("RGB")), img)


def test_what_is_no_longer_a_picture_is_displayed_as_an_array():
    img = litkit.render(litkit.default_scene(), width=64, height=48)
    for value in (img[:, :, 0], img.astype(float) / 255, img[0]):
        data, _ = DisplayFormatter().format(value)
        assert "image/png" not in data and "text/plain" in data


def test_the_renderers_pictures_display_too():
    renderer = litkit.Renderer(litkit.default_scene())
    data, _ = DisplayFormatter().format(renderer.render(width=16, height=12))
    assert data["image/png"].startswith(b"\x89PNG")
