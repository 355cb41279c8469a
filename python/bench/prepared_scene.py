# SPDX-License-Identifier: MIT
"""Times litkit.render (checks the scene, builds meshes, renders) against
Renderer.render with a new observer each frame (checks the scene, renders;
meshes kept), and the copy of the picture into NumPy. Timing only, nothing
passes or fails here; docs/python.md records a run.

    PYTHONPATH=build/python python3 python/bench/prepared_scene.py [SCENE] [FRAMES]
"""

import os
import statistics
import sys
import time

import litkit

path = sys.argv[1] if len(sys.argv) > 1 else "examples/teapot.toml"
frames = int(sys.argv[2]) if len(sys.argv) > 2 else 20
scene = litkit.load(path)
size = {"width": 640, "height": 480}


def median_ms(step):
    step(0)  # warm-up
    times = []
    for frame in range(frames):
        start = time.perf_counter()
        step(frame)
        times.append((time.perf_counter() - start) * 1000.0)
    return statistics.median(times), min(times)


def moved(frame):
    x, y, z = scene.observer.position
    scene.observer.position = (x + 0.01 * (frame % 2 * 2 - 1), y, z)
    return scene


renderer = litkit.Renderer(scene)
one_shot = median_ms(lambda frame: litkit.render(moved(frame), **size))
prepared = median_ms(lambda frame: renderer.render(moved(frame), **size))
same = median_ms(lambda frame: renderer.render(**size))
print(f"scene: {path}, 640x480, {renderer.triangle_count} triangles, "
      f"{renderer.thread_count} threads, load {os.getloadavg()[0]:.1f}")
for label, (median, least) in [("litkit.render (mesh built every time)", one_shot),
                               ("Renderer.render(scene), new observer", prepared),
                               ("Renderer.render() (nothing to check)", same)]:
    print(f"{label:38s} median {median:.1f} ms, min {least:.1f} ms")
print(f"meshes built by the Renderer: {renderer.mesh_builds}")
