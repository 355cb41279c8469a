# SPDX-License-Identifier: MIT
"""examples/python/lighting_models.py runs and its picture is what
`litkit render` draws, tile by tile."""

import runpy
import sys

import numpy as np
from conftest import EXAMPLES, read_png

import litkit

SCRIPT = EXAMPLES / "python" / "lighting_models.py"


def test_the_notebook_runs_and_its_grid_is_the_clis_pictures(tmp_path, monkeypatch, cli_render):
    output = tmp_path / "grid.png"
    monkeypatch.setattr(sys, "argv", [str(SCRIPT), str(output)])
    names = runpy.run_path(str(SCRIPT), run_name="__main__")
    grid = read_png(output)
    rows, columns = names["REFLECTIONS"], names["SHADINGS"]
    width, height = names["TILE_WIDTH"], names["TILE_HEIGHT"]
    assert grid.shape == (height * len(rows), width * len(columns), 3)

    scene = litkit.load(EXAMPLES / "teapot.toml")
    scene.observer.fov = names["GRID_FOV"]
    scene_file = tmp_path / "teapot-grid.toml"
    scene_file.write_text(scene.to_toml(str(scene_file)))
    for row, reflection in enumerate(rows):
        for column, shading in enumerate(columns):
            tile = grid[row * height:(row + 1) * height, column * width:(column + 1) * width]
            expected = cli_render([scene_file], "--reflection", reflection, "--shading", shading,
                                  "--width", width, "--height", height)
            assert np.array_equal(tile, expected), (reflection, shading)
    assert names["renderer"].mesh_builds == 1
