# SPDX-License-Identifier: MIT
"""examples/python/lighting_models.ipynb: made from the `# %%` script beside
it (scripts/make-notebook.py), and run headlessly as Jupyter runs it
(nbclient and an IPython kernel): no error output, and each picture it
shows is the picture `litkit render` draws of the same scene."""

import base64
import io
import subprocess
import sys

import numpy as np
import pytest
from conftest import EXAMPLES, SOURCE_DIR
from PIL import Image as PilImage

import litkit

nbformat = pytest.importorskip("nbformat", reason="python3-nbformat (scripts/install-deps.sh)")
nbclient = pytest.importorskip("nbclient", reason="python3-nbclient (scripts/install-deps.sh)")

NOTEBOOK = EXAMPLES / "python" / "lighting_models.ipynb"
SCRIPT = EXAMPLES / "python" / "lighting_models.py"


def test_the_notebook_is_made_from_the_script():
    result = subprocess.run([sys.executable, str(SOURCE_DIR / "scripts" / "make-notebook.py"),
                             "--check", str(SCRIPT), str(NOTEBOOK)], capture_output=True,
                            text=True)
    assert result.returncode == 0, result.stderr
    nbformat.validate(nbformat.read(NOTEBOOK, as_version=4))


def decode(data):
    with PilImage.open(io.BytesIO(base64.b64decode(data))) as picture:
        assert picture.mode == "RGB", picture.mode
        return np.asarray(picture)


def scene_file(tmp_path, name, change):
    """The teapot example, changed as the notebook changes it, as a file for the CLI."""
    scene = litkit.load(EXAMPLES / "teapot.toml")
    change(scene)
    path = tmp_path / f"{name}.toml"
    path.write_text(scene.to_toml(str(path)))
    return path


@pytest.fixture
def executed(tmp_path):
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    # Run from the repository root, as the notebook asks; the kernel inherits
    # this process's environment (PYTHONPATH: the build tree's package).
    client = nbclient.NotebookClient(notebook, timeout=300, kernel_name="python3",
                                     resources={"metadata": {"path": str(SOURCE_DIR)}})
    client.execute()
    return notebook


def test_the_notebook_runs_without_errors_and_shows_the_clis_pictures(executed, tmp_path,
                                                                        cli_render):
    fov = 32
    closer = scene_file(tmp_path, "closer", lambda s: setattr(s.observer, "fov", fov))

    def moved(scene):
        scene.observer.fov = fov
        scene.observer.position = (4.0, 3.0, 4.5)

    side = scene_file(tmp_path, "side", moved)

    def grid():
        rows = ["lambert", "half-lambert", "phong", "blinn-phong"]
        return np.concatenate([
            np.concatenate([cli_render([closer], "--reflection", r, "--shading", s,
                                       "--width", 200, "--height", 150)
                            for s in litkit.shading_models()], axis=1) for r in rows], axis=0)

    # Each picture by the variable its cell ends with.
    expected = {
        "img": lambda: cli_render([EXAMPLES / "teapot.toml"], "--reflection", "phong",
                                  "--shading", "gouraud", "--width", 320, "--height", 240),
        "grid": grid,
        "side": lambda: cli_render([side], "--width", 320, "--height", 240),
    }
    shown = []
    for cell in executed.cells:
        if cell.cell_type != "code":
            continue
        for output in cell.outputs:
            assert output.output_type != "error", output
            assert not (output.output_type == "stream" and output.name == "stderr"), output.text
            if "image/png" in output.get("data", {}):
                name = cell.source.splitlines()[-1].strip()
                assert name in expected, f"no expected picture for a cell ending in {name!r}"
                picture = decode(output.data["image/png"])
                assert np.array_equal(picture, expected[name]()), name
                shown.append(name)
    assert shown == ["img", "grid", "side"]
    # The notebook (no __file__) saves nothing into the source tree.
    assert not any(o.get("text", "").startswith("wrote") for c in executed.cells
                   if c.cell_type == "code" for o in c.outputs)
