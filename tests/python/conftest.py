# SPDX-License-Identifier: MIT
"""What every Python test shares: the built CLI, the source tree's examples,
and the PNGs `litkit render` writes, decoded independently (Pillow).

ctest sets LITKIT_CLI, LITKIT_SOURCE_DIR and PYTHONPATH (tests/CMakeLists.txt);
run by hand as
    PYTHONPATH=build/python LITKIT_CLI=build/litkit python3 -m pytest tests/python
"""

import os
import pathlib
import subprocess

import numpy as np
import pytest
from PIL import Image as PilImage

SOURCE_DIR = pathlib.Path(os.environ.get("LITKIT_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
CLI = os.environ.get("LITKIT_CLI", str(SOURCE_DIR / "build" / "litkit"))
EXAMPLES = SOURCE_DIR / "examples"


def run_cli(*arguments, check=True):
    """Runs `litkit ARGUMENTS...`; returns the CompletedProcess (text)."""
    result = subprocess.run([CLI, *map(str, arguments)], capture_output=True, text=True,
                            stdin=subprocess.DEVNULL)
    if check and result.returncode != 0:
        raise AssertionError(f"litkit {' '.join(map(str, arguments))} failed "
                             f"({result.returncode}):\n{result.stderr}")
    return result


def read_png(path):
    """The PNG as an (height, width, 3) uint8 array, decoded by Pillow."""
    with PilImage.open(path) as picture:
        assert picture.mode == "RGB", picture.mode
        return np.asarray(picture.convert("RGB"))


@pytest.fixture
def cli_render(tmp_path):
    """cli_render(scene_files, *options) -> the array of the PNG `litkit render` writes."""
    counter = iter(range(1_000_000))

    def render(scenes, *options):
        output = tmp_path / f"cli-{next(counter)}.png"
        run_cli("render", *scenes, *options, "--yes", "-o", output)
        return read_png(output)

    return render
