# SPDX-License-Identifier: MIT
"""`cmake --install` puts the package beside the library, and it imports from
there (with only the install prefix's folder on PYTHONPATH)."""

import os
import pathlib
import subprocess
import sys

from conftest import SOURCE_DIR

# ctest names both; by hand, the build tree `build` and its configured folder.
BUILD_DIR = pathlib.Path(os.environ.get("LITKIT_BUILD_DIR", SOURCE_DIR / "build"))


def install_dir():
    if "LITKIT_PYTHON_INSTALL_DIR" in os.environ:
        return os.environ["LITKIT_PYTHON_INSTALL_DIR"]
    for line in (BUILD_DIR / "CMakeCache.txt").read_text().splitlines():
        if line.startswith("LITKIT_PYTHON_INSTALL_DIR:"):
            return line.split("=", 1)[1]
    raise AssertionError(f"{BUILD_DIR} is not configured with LITKIT_PYTHON")


def test_installed_package_imports_and_renders(tmp_path):
    site = install_dir()
    prefix = tmp_path / "prefix"
    cmake = os.environ.get("LITKIT_CMAKE", "cmake")
    subprocess.run([cmake, "--install", str(BUILD_DIR), "--prefix", str(prefix),
                    "--component", "python"], check=True, capture_output=True)
    package = prefix / site / "litkit"
    assert (package / "__init__.py").is_file()
    environment = dict(os.environ, PYTHONPATH=str(prefix / site))
    program = ("import litkit; print(litkit.__file__); "
               "print(litkit.render(litkit.default_scene()).shape)")
    result = subprocess.run([sys.executable, "-c", program], check=True, capture_output=True,
                            text=True, env=environment, cwd=tmp_path)
    where, shape = result.stdout.splitlines()
    assert pathlib.Path(where).parent == package
    assert shape == "(600, 800, 3)"
