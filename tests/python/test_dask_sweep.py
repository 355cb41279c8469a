# SPDX-License-Identifier: MIT
"""examples/python/dask_sweep.py: a sweep over reflection models on a Dask
LocalCluster of two worker processes; every picture it writes is, byte for
byte, the PNG `litkit render --reflection MODEL` writes."""

import os
import subprocess
import sys

import pytest
from conftest import EXAMPLES, run_cli

pytest.importorskip("dask.distributed", reason="python3-distributed (scripts/install-deps.sh)")

MODELS = ["lambert", "phong", "toon", "cook-torrance"]
SIZE = ["--width", "48", "--height", "36"]


def test_the_sweep_equals_the_command_line(tmp_path):
    scene = EXAMPLES / "teapot.toml"
    result = subprocess.run(
        [sys.executable, str(EXAMPLES / "python" / "dask_sweep.py"), str(scene),
         str(tmp_path / "sweep"), "--workers", "2", "--models", *MODELS, *SIZE],
        capture_output=True, text=True, stdin=subprocess.DEVNULL, env=os.environ, timeout=120)
    assert result.returncode == 0, result.stderr
    assert f"wrote {len(MODELS)} pictures" in result.stdout
    assert sorted(p.name for p in (tmp_path / "sweep").iterdir()) == sorted(
        f"{model}.png" for model in MODELS)
    for model in MODELS:
        expected = tmp_path / f"cli-{model}.png"
        run_cli("render", scene, "--reflection", model, *SIZE, "-o", expected)
        assert (tmp_path / "sweep" / f"{model}.png").read_bytes() == expected.read_bytes(), model
