# SPDX-License-Identifier: MIT
"""A sweep on Dask: one scene in every reflection model, each picture rendered
as a task on a cluster, written as a PNG named after its model.

From the repository root, after building:

    PYTHONPATH=build/python python3 examples/python/dask_sweep.py \\
        examples/teapot.toml sweep/ --workers 2 --width 320 --height 240

writes sweep/lambert.png, sweep/phong.png, ... (docs/python.md, "Many
machines"). Each picture equals what `litkit render SCENE --reflection MODEL`
draws. Here the cluster is a LocalCluster of worker processes on this
machine; give `--scheduler tcp://HOST:8786` to use a cluster started
elsewhere (`dask scheduler`, `dask worker`), whose workers import the same
litkit and can read the scene's mesh files under the same paths.

The scene travels to the workers pickled (as its TOML text, mesh files named
by absolute path); litkit.render releases the GIL, so threads of one worker
render side by side too.
"""

import argparse
import pathlib

from dask.distributed import Client, LocalCluster

import litkit


def render_png(scene, reflection, width, height, threads):
    """One task: the scene in one reflection model, as PNG file bytes."""
    picture = litkit.render(scene, reflection=reflection, width=width, height=height,
                            threads=threads)
    return litkit.encode_png(picture)


def sweep(client, scene, models, width=None, height=None, threads=1):
    """{model: PNG bytes} of `scene` in each model, rendered by the client's workers."""
    scene_on_cluster = client.scatter(scene, broadcast=True)  # sent once, not once a task
    futures = {model: client.submit(render_png, scene_on_cluster, model, width, height, threads,
                                    key=f"render-{model}")
               for model in models}
    return dict(zip(futures, client.gather(list(futures.values()))))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", help="the scene file")
    parser.add_argument("output", type=pathlib.Path, help="the folder for MODEL.png")
    parser.add_argument("--models", nargs="*", default=litkit.reflection_models(),
                        help="reflection models (default: every one)")
    parser.add_argument("--width", type=int)
    parser.add_argument("--height", type=int)
    parser.add_argument("--workers", type=int, default=2, help="local worker processes")
    parser.add_argument("--scheduler", help="a running cluster's address instead")
    arguments = parser.parse_args()

    scene = litkit.load(arguments.scene)
    if arguments.scheduler:
        client = Client(arguments.scheduler)
    else:
        cluster = LocalCluster(n_workers=arguments.workers, threads_per_worker=1,
                               processes=True, dashboard_address=None)
        client = Client(cluster)
    with client:
        pictures = sweep(client, scene, arguments.models, arguments.width, arguments.height)
    if not arguments.scheduler:
        cluster.close()
    arguments.output.mkdir(parents=True, exist_ok=True)
    for model, png in pictures.items():
        (arguments.output / f"{model}.png").write_bytes(png)
    print(f"wrote {len(pictures)} pictures into {arguments.output}")


if __name__ == "__main__":  # worker processes import this file without running it
    main()
