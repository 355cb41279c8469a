# SPDX-License-Identifier: MIT
"""litkit from Python: load a scene, render it into a NumPy array, evaluate the
lighting models at one point. docs/python.md is the guide.

    import litkit
    scene = litkit.load("examples/reflection-models.toml")
    img = litkit.render(scene, reflection="blinn-phong", shading="gouraud")
    img.shape          # (600, 800, 3), uint8; shows as a picture in Jupyter

Every error is a ``litkit.Error`` (``SceneError``, ``IoError``,
``ArgumentError``) whose str() is the diagnostic ``litkit check`` prints and
which carries ``file``, ``line``, ``column`` and ``message``.
"""

import os
import sys as _sys
import warnings as _warnings
from collections.abc import Mapping

try:
    import numpy as _numpy  # noqa: F401  (pictures are NumPy arrays)
except ImportError as _missing:
    raise ImportError(
        f"litkit needs NumPy, which {_sys.executable} cannot import: run the python3 litkit "
        "was built for (Debian's /usr/bin/python3 with python3-numpy; docs/python.md) or "
        "install NumPy for this one") from _missing

from . import _litkit, _toml

__version__ = _litkit.__version__  # the C++ library's (CMakeLists.txt's project version)
from ._image import Image
from ._litkit import (  # noqa: F401  (the public API)
    ArgumentError,
    Diagnostic,
    Error,
    IoError,
    Light,
    Material,
    Observer,
    Output,
    Room,
    Scene,
    SceneError,
    default_scene_toml,
    encode_png,
    light_types,
    normals_weightings,
    reflection_models,
    shade,
    shade_terms,
    shading_models,
)

__all__ = [
    "ArgumentError", "Diagnostic", "Error", "Explanation", "Image", "IoError", "Light", "Material",
    "Observer", "Output", "Renderer", "Room", "Scene", "SceneError", "SceneWarning", "check",
    "checks", "default_scene", "default_scene_toml", "dumps", "encode_png", "explain",
    "light_types", "load", "loads", "normals_weightings", "reflection_models", "render", "shade",
    "shade_terms", "shading_models",
]


class SceneWarning(UserWarning):
    """A problem that does not stop rendering (no lights, an object out of view)."""


def _warn(scene):
    for diagnostic in scene.warnings:
        _warnings.warn(str(diagnostic), SceneWarning, stacklevel=3)
    return scene


def _paths(files):
    if len(files) == 1 and isinstance(files[0], (list, tuple)):
        files = files[0]
    return [os.fspath(f) for f in files]


def load(*files, max_triangles=None):
    """Reads and merges scene files (``load("a.toml")``, ``load("a.toml", "b.toml")``
    or ``load([...])``), checks them and returns the Scene. Raises SceneError listing
    every problem, IoError for a file that cannot be read. Warnings are issued as
    ``litkit.SceneWarning``."""
    paths = _paths(files)
    if max_triangles is None:
        scene = _litkit._load(paths)
    else:
        scene = _litkit._load(paths, max_triangles)
    return _warn(scene)


def loads(scene, name=None):
    """A Scene from TOML text or from Python objects: a dict shaped like a
    scene file (``{"room": {...}, "observer": {...}, "lights": [{...}]}``).
    ``name`` appears in messages; its folder resolves relative mesh paths
    (default: the current folder)."""
    if isinstance(scene, Mapping):
        text = _toml.dumps(scene)
        default_name = "<dict>"
    elif isinstance(scene, str):
        text = scene
        default_name = "<string>"
    else:
        raise TypeError(f"loads takes TOML text or a dict, not {type(scene).__name__}")
    return _warn(_litkit._loads(text, os.fspath(name) if name is not None else default_name))


def dumps(scene):
    """The TOML text of a scene given as a dict (what ``loads(dict)`` parses)."""
    return _toml.dumps(scene)


def default_scene():
    """The built-in default scene (docs/spec.md §7): a cube lit by one point light."""
    return _litkit.default_scene()


def check(*scene, max_triangles=None):
    """Checks a scene without rendering it: files (as ``load``; TOML text goes
    to ``checks``), or a Scene object after changes made in Python. Raises
    litkit.Error (SceneError with every problem, IoError) as ``litkit check``
    reports it; returns the warnings (a list of Diagnostic)."""
    if len(scene) == 1 and isinstance(scene[0], Scene):
        return _litkit._check_scene(scene[0])
    with _warnings.catch_warnings():
        _warnings.simplefilter("ignore", SceneWarning)
        try:
            return list(load(*scene, max_triangles=max_triangles).warnings)
        except IoError as error:
            looks_like_text = any(isinstance(f, str) and "\n" in f for f in _paths(scene))
            if looks_like_text and hasattr(error, "add_note"):  # Python 3.11
                error.add_note("litkit.check reads files; litkit.checks(text) checks TOML text")
            raise


def checks(scene, name=None):
    """Checks a scene given as TOML text or as a dict (as ``loads`` reads
    them) without rendering it. Raises litkit.Error (SceneError with every
    problem, IoError for a TOML syntax error) located in ``name`` (default
    ``<string>`` / ``<dict>``); returns the warnings (a list of Diagnostic)."""
    with _warnings.catch_warnings():
        _warnings.simplefilter("ignore", SceneWarning)
        return list(loads(scene, name).warnings)


def render(scene=None, *, reflection=None, shading=None, width=None, height=None,
           max_depth=None, samples=None, threads=0):
    """Renders ``scene`` (default: the built-in default scene) on the CPU and
    returns the picture as a litkit.Image, an (height, width, 3) uint8 NumPy
    array, equal to the PNG ``litkit render`` writes. ``reflection``,
    ``shading``, ``width``, ``height``, ``max_depth`` (1-16, the ray paths'
    length through glass, as ``--max-depth``) and ``samples`` (1, 4, 8 or 16
    per pixel: anti-aliasing, as ``--samples``) replace the scene's own; a scene
    without [lighting] uses phong / phong. ``threads``: 0 is one per hardware
    thread. The scene is checked first (it may have been changed in Python).
    Releases the GIL while it works."""
    if scene is None:
        scene = default_scene()
    pixels = _litkit._render(scene, reflection=reflection, shading=shading, width=width,
                             height=height, max_depth=max_depth, samples=samples,
                             threads=threads)
    return pixels.view(Image)


class Renderer:
    """A scene prepared once (meshes, vertex normals) for drawing many pictures:
    another observer, size or model costs only the rendering.

        renderer = litkit.Renderer(scene)
        scene.observer.position = (0, 2, 6)
        img = renderer.render(scene, width=400, height=300)
        renderer.mesh_builds   # still 1: the objects did not move
    """

    def __init__(self, scene=None, *, threads=0):
        self._prepared = _litkit._Renderer(default_scene() if scene is None else scene,
                                           threads=threads)

    def render(self, scene=None, *, reflection=None, shading=None, width=None, height=None,
               max_depth=None, samples=None):
        """Draws the scene given (checked, and kept for the next frames) or the
        last one; the keyword arguments apply to this picture only."""
        pixels = self._prepared.render(scene, reflection=reflection, shading=shading,
                                       width=width, height=height, max_depth=max_depth,
                                       samples=samples)
        return pixels.view(Image)

    @property
    def scene(self):
        """A copy of the scene being drawn."""
        return self._prepared.scene

    @property
    def mesh_builds(self):
        """How often the meshes were built: once, and again only when an object moved
        or changed shape."""
        return self._prepared.mesh_builds

    @property
    def triangle_count(self):
        return self._prepared.triangle_count

    @property
    def thread_count(self):
        return self._prepared.thread_count


class Explanation:
    """How one pixel of ``render`` got its value (``litkit explain --pixel X,Y``).

    ``x``, ``y``; ``hit``; ``rgb`` (the pixel); ``object`` (name, or
    ``objects[i]``), ``object_index`` and ``triangle`` of what it shows and
    ``sum``, its L before clamping (None where it shows the background);
    ``text``, what the command prints (also ``str()``); ``ray_tree``: where
    the pixel sees glass, one dict per ray, the camera's first, each after its
    parent, with the keys of ``litkit explain --json``'s "ray_tree" entries
    (``kind``, ``outcome``, ``depth``, ``parent``, ``inside``, ``object``,
    ``object_index``, ``triangle``, ``length``, ``absorption``, ``n1``,
    ``n2``, ``theta1``, ``theta2``, ``k``, ``fresnel``,
    ``total_internal_reflection``, ``weight``, ``local``, ``contribution``,
    ``radiance``, ...; docs/learning.md); the contributions add up to ``sum``.
    Empty for an opaque object. ``samples``: with several samples per pixel,
    one dict per sample (``position`` in the pixel, ``hit``, ``object_index``,
    ``light``: its L clamped to [0, 1]), whose mean after gamma is ``rgb``;
    the other fields then describe the pixel's centre. Empty with one sample.
    """

    def __init__(self, fields):
        self.__dict__.update(fields)

    def __str__(self):
        return self.text

    def __repr__(self):
        return (f"<litkit.Explanation of pixel ({self.x}, {self.y}): rgb {self.rgb}, "
                f"{len(self.ray_tree)} rays>")


def explain(scene=None, x=0, y=0, *, reflection=None, shading=None, samples=None, threads=0):
    """Explains pixel (``x``, ``y``) of ``render(scene, reflection=...,
    shading=..., samples=...)`` (default scene: the built-in one) and returns
    an Explanation. Raises ArgumentError for a pixel outside the image."""
    if scene is None:
        scene = default_scene()
    return Explanation(_litkit._explain(scene, x, y, reflection=reflection, shading=shading,
                                        samples=samples, threads=threads))


def _scene_to_dict(self):
    """The scene as Python objects, as ``tomllib`` reads ``to_toml()``; ``loads``
    takes it back."""
    import tomllib  # Python 3.11+

    return tomllib.loads(self.to_toml())


Scene.to_dict = _scene_to_dict
