# SPDX-License-Identifier: MIT
"""Builds the Python package with the project's CMake build (pyproject.toml).

The extension litkit._litkit and the package's Python files are what `cmake
--install --component python` installs; this copies them into the wheel.

Environment:
  LITKIT_CMAKE_BUILD_DIR  a CMake build tree to use: built (target
                          litkit_python) and installed from if it is already
                          configured, configured there otherwise; default: a
                          folder under setuptools' own build folder
  LITKIT_CMAKE_ARGS       more arguments for the configure step (shlex)
  CMAKE                   the cmake to run (default: cmake)
"""

import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = pathlib.Path(__file__).resolve().parent


def project_version():
    """The version of CMakeLists.txt's project(), the one version of litkit."""
    text = (HERE / "CMakeLists.txt").read_text()
    return re.search(r"project\(litkit VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    """Builds and installs CMake's `python` component in place of compiling sources."""

    def run(self):
        cmake = os.environ.get("CMAKE", "cmake")
        build_dir = pathlib.Path(os.environ.get("LITKIT_CMAKE_BUILD_DIR") or
                                 pathlib.Path(self.build_temp) / "cmake").resolve()
        if not (build_dir / "CMakeCache.txt").is_file():
            build_dir.mkdir(parents=True, exist_ok=True)
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.run([cmake, "-S", str(HERE), "-B", str(build_dir), *generator,
                            "-DCMAKE_BUILD_TYPE=Release", "-DLITKIT_BUILD_TESTS=OFF",
                            "-DLITKIT_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}",
                            *shlex.split(os.environ.get("LITKIT_CMAKE_ARGS", ""))], check=True)
        jobs = ["--parallel", str(self.parallel)] if self.parallel else []
        subprocess.run([cmake, "--build", str(build_dir), "--target", "litkit_python", *jobs],
                       check=True)
        with tempfile.TemporaryDirectory() as staging:
            subprocess.run([cmake, "--install", str(build_dir), "--component", "python",
                            "--prefix", staging], check=True)
            installed = list(pathlib.Path(staging).glob("lib/python*/*-packages/litkit"))
            if len(installed) != 1:
                raise RuntimeError(f"cmake --install put no single litkit package in {staging}")
            target = pathlib.Path(self.build_lib) / "litkit"
            shutil.rmtree(target, ignore_errors=True)
            shutil.copytree(installed[0], target)
            if self.inplace:
                raise RuntimeError("litkit builds no extension in place: use PYTHONPATH=build/python")


# setuptools' own build folder beside a CMake tree named build/, not in it
# (egg_info wants its folder to exist).
os.makedirs(HERE / "build-python", exist_ok=True)

setup(
    version=project_version(),
    # One extension, built by CMake (CMakeBuild); the empty source list is
    # never compiled. It makes the wheel one for this platform and Python.
    ext_modules=[Extension("litkit._litkit", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-python"}, "egg_info": {"egg_base": "build-python"}},
)
