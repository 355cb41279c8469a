# SPDX-License-Identifier: MIT
"""`litkit turntable -o spin.png` read by a real APNG decoder (Pillow's):
every frame, in order, equals the PNG frame the turntable writes into a
folder, with the delay asked for and looping forever."""

import numpy as np
from conftest import read_png, run_cli
from PIL import Image as PilImage

SIZE = ["--frames", "5", "--width", "40", "--height", "30"]


def test_pillow_reads_every_frame(tmp_path):
    run_cli("turntable", *SIZE, "--delay", "80", "-o", tmp_path / "spin.png")
    run_cli("turntable", *SIZE, "-o", f"{tmp_path / 'frames'}/")
    with PilImage.open(tmp_path / "spin.png") as picture:
        assert picture.format == "PNG"
        assert picture.is_animated
        assert picture.n_frames == 5
        assert picture.info.get("loop") == 0
        for k in range(5):
            picture.seek(k)
            assert picture.info["duration"] == 80
            frame = np.asarray(picture.convert("RGB"))
            assert np.array_equal(frame, read_png(tmp_path / "frames" / f"frame-{k:03d}.png")), k
