# SPDX-License-Identifier: MIT
# %% [markdown]
# # litkit in a notebook: the lighting models side by side
#
# A notebook as a Python script: each `# %%` starts a cell (Jupyter with
# jupytext, VS Code and Spyder run them one by one), and the whole file runs
# as a script too. From the repository root, after building:
#
#     PYTHONPATH=build/python python3 examples/python/lighting_models.py
#
# writes `lighting_models.png` beside this file: the Utah teapot in the four
# classic reflection models (rows) and the four shading models (columns).
# `docs/python.md` explains every call used here. The notebook
# `lighting_models.ipynb` beside it is made from this file
# (`scripts/make-notebook.py`): edit this one.

# %%
import pathlib
import sys

import numpy as np

import litkit

# In a notebook there is no __file__: run it from the repository root.
here = pathlib.Path(globals().get("__file__", "examples/python/lighting_models.py")).parent
scene = litkit.load(here.parent / "teapot.toml")
scene  # a cell's last value: <litkit.Scene 3 lights, 1 objects, 640x480, blinn-phong/phong>

# %% [markdown]
# One picture: a NumPy array of shape (height, width, 3), `uint8`. As a
# cell's last value Jupyter shows it as the picture (`Image._repr_png_`).

# %%
img = litkit.render(scene, reflection="phong", shading="gouraud", width=320, height=240)
print(img.shape, img.dtype, "mean brightness", img.mean().round(1))
img

# %% [markdown]
# Sixteen pictures from one prepared scene: the teapot's mesh and normals are
# built once (`mesh_builds`), each picture costs only its rendering.

# %%
REFLECTIONS = ["lambert", "half-lambert", "phong", "blinn-phong"]
SHADINGS = litkit.shading_models()  # flat, gouraud, phong, faceted
TILE_WIDTH, TILE_HEIGHT = 200, 150
GRID_FOV = 32  # closer than the file's 40 degrees: the tiles are small

scene.observer.fov = GRID_FOV
renderer = litkit.Renderer(scene)
grid = np.concatenate([
    np.concatenate([renderer.render(reflection=reflection, shading=shading,
                                    width=TILE_WIDTH, height=TILE_HEIGHT)
                    for shading in SHADINGS], axis=1)
    for reflection in REFLECTIONS], axis=0).view(litkit.Image)
print("rows:", REFLECTIONS, "columns:", SHADINGS, "meshes built:", renderer.mesh_builds)
grid

# %% [markdown]
# Another observer through the same renderer: still one mesh build.

# %%
scene.observer.position = (4.0, 3.0, 4.5)
side = renderer.render(scene, width=320, height=240)
print("meshes built:", renderer.mesh_builds)
side

# %% [markdown]
# One surface point by hand: a point light 2 units above the point, whose
# normal leans 37 degrees away from it; the eye 3 units away. `shade` gives
# the colour before clamping and gamma; `shade_terms` the working (L, f, D, S
# per light).

# %%
material = litkit.Material(color=(0.8, 0.3, 0.2), kd=0.7, ks=0.5, shininess=32)
lights = [litkit.Light("ambient", intensity=0.5), litkit.Light("point", position=(0, 2, 0))]
normal = (0.6, 0.8, 0.0)  # unit length, as shade() requires
for model in REFLECTIONS:
    r, g, b = litkit.shade(model, material, lights, (0, 0, 0), normal, (0, 1, 3))
    print(f"{model:13s} I = ({r:.4f}, {g:.4f}, {b:.4f})")
terms = litkit.shade_terms("blinn-phong", material, lights, (0, 0, 0), normal, (0, 1, 3))
print("point light: f =", round(terms["lights"][1]["factor"], 4),
      "D =", round(terms["lights"][1]["diffuse"], 4),
      "S =", round(terms["lights"][1]["specular"], 6))

# %% [markdown]
# Errors are `litkit.Error`, with the place and the message `litkit check` prints.

# %%
try:
    litkit.loads(litkit.default_scene_toml().replace("size = 2", "size = -2"), name="mine.toml")
except litkit.Error as error:
    print(error.file, error.line, error.column)
    print(error)

# %%
# As a script (not in a notebook), the grid is saved: to a PNG path given as
# its argument, else beside this file.
if "__file__" in globals():
    given = [a for a in sys.argv[1:] if a.endswith(".png")]
    output = pathlib.Path(given[0]) if given else here / "lighting_models.png"
    grid.save(output)
    print("wrote", output)
