# SPDX-License-Identifier: MIT
# Type stubs of the package litkit (PEP 561; py.typed marks the package as
# typed). tests/python/test_package.py checks that they name every public
# name of the module and of its classes, and nothing else.
import os
from collections.abc import Mapping, Sequence
from typing import Any, Optional, Union

import numpy as np
import numpy.typing as npt

__version__: str
__all__: list[str]

Vec3 = Union[tuple[float, float, float], Sequence[float], npt.NDArray[Any]]
PathLike = Union[str, os.PathLike[str]]

class Error(Exception):
    file: Optional[str]
    line: Optional[int]
    column: Optional[int]
    message: str
    diagnostics: list[Diagnostic]
    warnings: list[Diagnostic]

class SceneError(Error): ...
class IoError(Error): ...
class ArgumentError(Error): ...
class SceneWarning(UserWarning): ...

class Diagnostic:
    @property
    def file(self) -> Optional[str]: ...
    @property
    def line(self) -> Optional[int]: ...
    @property
    def column(self) -> Optional[int]: ...
    @property
    def severity(self) -> str: ...
    @property
    def message(self) -> str: ...

class Room:
    width: float
    height: float
    depth: float
    ior: float

class Observer:
    position: tuple[float, float, float]
    look_at: tuple[float, float, float]
    up: tuple[float, float, float]
    fov: float
    near: float
    far: float

class Output:
    width: int
    height: int
    background: tuple[float, float, float]
    gamma: float
    samples: int

class Material:
    color: tuple[float, float, float]
    ka: float
    kd: float
    ks: float
    shininess: float
    sigma: float
    roughness: float
    f0: float
    bands: float
    minnaert_k: float
    transmission: float
    ior: float
    absorption_color: tuple[float, float, float]
    absorption_distance: float
    def __init__(self, *, color: Vec3 = ..., ka: float = ..., kd: float = ..., ks: float = ...,
                 shininess: float = ..., sigma: float = ..., roughness: float = ...,
                 f0: float = ..., bands: float = ..., minnaert_k: float = ...,
                 transmission: float = ..., ior: float = ..., absorption_color: Vec3 = ...,
                 absorption_distance: float = ...) -> None: ...

class Light:
    @property
    def type(self) -> str: ...
    color: tuple[float, float, float]
    intensity: float
    def __init__(self, type: str, *, position: Optional[Vec3] = None,
                 direction: Optional[Vec3] = None, color: Vec3 = (1.0, 1.0, 1.0),
                 intensity: float = 1.0, attenuation: Optional[Vec3] = None,
                 cutoff: Optional[float] = None, exponent: Optional[float] = None,
                 penumbra: Optional[float] = None) -> None: ...

class Scene:
    room: Room
    observer: Observer
    output: Output
    reflection: Optional[str]
    shading: Optional[str]
    normals: Optional[str]
    crease_angle: float
    max_depth: int
    @property
    def light_count(self) -> int: ...
    @property
    def object_count(self) -> int: ...
    @property
    def warnings(self) -> list[Diagnostic]: ...
    def to_toml(self, written_as: str = "") -> str: ...
    def to_dict(self) -> dict[str, Any]: ...
    def copy(self) -> Scene: ...
    def __getstate__(self) -> tuple[str]: ...  # pickles as its TOML text
    def __setstate__(self, state: tuple[str]) -> None: ...
    def add_mesh(self, vertices: npt.ArrayLike, faces: npt.ArrayLike, *, name: str = "",
                 position: Vec3 = (0.0, 0.0, 0.0), rotation: Vec3 = (0.0, 0.0, 0.0),
                 scale: float = 1.0, material: Optional[Material] = None) -> int: ...

class Image(np.ndarray[Any, np.dtype[np.uint8]]):
    def to_png(self) -> bytes: ...
    def save(self, path: PathLike) -> None: ...

class Renderer:
    def __init__(self, scene: Optional[Scene] = None, *, threads: int = 0) -> None: ...
    def render(self, scene: Optional[Scene] = None, *, reflection: Optional[str] = None,
               shading: Optional[str] = None, width: Optional[int] = None,
               height: Optional[int] = None, max_depth: Optional[int] = None,
               samples: Optional[int] = None) -> Image: ...
    @property
    def scene(self) -> Scene: ...
    @property
    def mesh_builds(self) -> int: ...
    @property
    def triangle_count(self) -> int: ...
    @property
    def thread_count(self) -> int: ...

class Explanation:
    x: int
    y: int
    hit: bool
    rgb: tuple[int, int, int]
    object: Optional[str]
    object_index: Optional[int]
    triangle: Optional[int]
    sum: Optional[tuple[float, float, float]]
    text: str
    ray_tree: list[dict[str, Any]]
    samples: list[dict[str, Any]]
    def __init__(self, fields: Mapping[str, Any]) -> None: ...

def load(*files: Union[PathLike, Sequence[PathLike]],
         max_triangles: Optional[int] = None) -> Scene: ...
def loads(scene: Union[str, Mapping[str, Any]], name: Optional[PathLike] = None) -> Scene: ...
def dumps(scene: Mapping[str, Any]) -> str: ...
def default_scene() -> Scene: ...
def default_scene_toml() -> str: ...
def check(*scene: Union[Scene, PathLike, Sequence[PathLike]],
          max_triangles: Optional[int] = None) -> list[Diagnostic]: ...
def checks(scene: Union[str, Mapping[str, Any]],
           name: Optional[PathLike] = None) -> list[Diagnostic]: ...
def render(scene: Optional[Scene] = None, *, reflection: Optional[str] = None,
           shading: Optional[str] = None, width: Optional[int] = None,
           height: Optional[int] = None, max_depth: Optional[int] = None,
           samples: Optional[int] = None, threads: int = 0) -> Image: ...
def explain(scene: Optional[Scene] = None, x: int = 0, y: int = 0, *,
            reflection: Optional[str] = None, shading: Optional[str] = None,
            samples: Optional[int] = None, threads: int = 0) -> Explanation: ...
def shade(reflection: str, material: Material, lights: Sequence[Light], position: Vec3,
          normal: Vec3, eye: Vec3) -> tuple[float, float, float]: ...
def shade_terms(reflection: str, material: Material, lights: Sequence[Light], position: Vec3,
                normal: Vec3, eye: Vec3) -> dict[str, Any]: ...
def encode_png(pixels: npt.NDArray[np.uint8]) -> bytes: ...
def reflection_models() -> list[str]: ...
def shading_models() -> list[str]: ...
def normals_weightings() -> list[str]: ...
def light_types() -> list[str]: ...
