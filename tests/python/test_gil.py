# SPDX-License-Identifier: MIT
"""litkit.render and Renderer.render release the GIL: another Python thread
runs while they work.

Deterministic, not timed: with the interpreter's switch interval set far
beyond the test's length, a thread that holds the GIL keeps it until it
releases it itself. The main thread reads the worker's counter just before
and just after a render; between the two reads it runs no Python code that
releases the GIL except the render. So the counter can move only if the
render released the GIL (with it held, `after == before` exactly).
"""

import sys
import threading

import pytest

import litkit


@pytest.fixture
def worker():
    """A thread counting as fast as it can, releasing the GIL between counts."""
    state = {"count": 0, "stop": False}
    started = threading.Event()

    def count():
        started.set()
        while not state["stop"]:
            state["count"] += 1
            threading.Event().wait(0.0005)  # releases the GIL while it waits

    thread = threading.Thread(target=count, daemon=True)
    old_interval = sys.getswitchinterval()
    thread.start()
    started.wait()
    sys.setswitchinterval(1000.0)
    try:
        yield state
    finally:
        sys.setswitchinterval(old_interval)
        state["stop"] = True
        thread.join()


# A render long enough for the worker to be scheduled during it many times
# over (hundreds of milliseconds for ~2.5 million pixels on one thread).
BIG = {"width": 2048, "height": 1536}


def test_render_lets_other_threads_run(worker):
    scene = litkit.default_scene()
    before = worker["count"]
    img = litkit.render(scene, threads=1, **BIG)
    after = worker["count"]
    assert img.shape == (1536, 2048, 3)
    assert after > before


def test_renderer_lets_other_threads_run(worker):
    renderer = litkit.Renderer(litkit.default_scene(), threads=1)
    before = worker["count"]
    renderer.render(**BIG)
    after = worker["count"]
    assert after > before


def test_without_a_release_the_counter_stands_still(worker):
    # The control: Python code that never releases the GIL (a pure-Python
    # busy loop of comparable length) leaves the counter where it was, so
    # the two tests above can fail.
    before = worker["count"]
    total = 0
    for i in range(3_000_000):
        total += i
    after = worker["count"]
    assert after == before


def test_renders_in_several_threads_at_once_give_the_same_pictures():
    # With the GIL released, these run at the same time in the library: each
    # call has its own renderer, and one Renderer draws one frame at a time.
    from concurrent.futures import ThreadPoolExecutor

    import numpy as np

    scene = litkit.default_scene()
    shared = litkit.Renderer(scene, threads=1)
    jobs = [("phong", "gouraud"), ("lambert", "flat"), ("blinn-phong", "phong"),
            ("gooch", "faceted")] * 2
    expected = [litkit.render(scene, reflection=r, shading=s, width=320, height=240, threads=1)
                for r, s in jobs]
    with ThreadPoolExecutor(max_workers=4) as pool:
        one_shot = list(pool.map(lambda job: litkit.render(
            scene, reflection=job[0], shading=job[1], width=320, height=240, threads=1), jobs))
        through_one = list(pool.map(lambda job: shared.render(
            reflection=job[0], shading=job[1], width=320, height=240), jobs))
    for want, got, got_shared in zip(expected, one_shot, through_one):
        assert np.array_equal(want, got)
        assert np.array_equal(want, got_shared)
