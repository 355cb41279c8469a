# SPDX-License-Identifier: MIT
"""litkit as a Python package (pyproject.toml, setup.py): installed by pip
into a virtual environment, offline and without build isolation, as Debian
12's own tools do it, and made into a wheel by `python3 -m build`. Both reuse
the build tree's extension (LITKIT_CMAKE_BUILD_DIR: setup.py builds and
installs from it), so that each takes seconds, not a build from nothing.
Also the type stubs: they name every public name of the module and its
classes."""

import ast
import email
import os
import pathlib
import shutil
import subprocess
import sys
import zipfile

import pytest
from conftest import SOURCE_DIR

import litkit

BUILD_DIR = pathlib.Path(os.environ.get("LITKIT_BUILD_DIR", SOURCE_DIR / "build"))
VERSION = next(line.split()[2] for line in (SOURCE_DIR / "CMakeLists.txt").read_text().splitlines()
               if line.startswith("project(litkit VERSION"))


def source_copy(destination):
    """What the sdist holds (MANIFEST.in), copied: pip and build write their
    build folders and metadata into the tree they build."""
    def ignore(folder, names):
        return [n for n in names if n.startswith("build") or n in ("__pycache__", ".git")]
    destination.mkdir()
    for name in ("CMakeLists.txt", "LICENSE", "README.md", "setup.py", "pyproject.toml",
                 "MANIFEST.in"):
        shutil.copy2(SOURCE_DIR / name, destination / name)
    for folder in ("apps", "cmake", "docs", "examples", "include", "python", "src"):
        shutil.copytree(SOURCE_DIR / folder, destination / folder, ignore=ignore)
    return destination


def environment():
    """Without the build tree's package on PYTHONPATH; setup.py builds in BUILD_DIR."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["LITKIT_CMAKE_BUILD_DIR"] = str(BUILD_DIR)
    env["PIP_NO_INPUT"] = "1"
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    return env


def test_pip_installs_the_package_into_a_virtual_environment_offline(tmp_path):
    source = source_copy(tmp_path / "source")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)],
                   check=True, capture_output=True)
    python = venv / "bin" / "python"
    result = subprocess.run([str(venv / "bin" / "pip"), "install", "--no-build-isolation",
                             "--no-index", str(source)], env=environment(), capture_output=True,
                            text=True, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    program = """
import importlib.metadata as metadata, pathlib, litkit
print(litkit.__file__)
print(litkit.__version__, metadata.version("litkit"))
meta = metadata.metadata("litkit")
print(meta["License"], "License :: OSI Approved :: MIT License" in meta.get_all("Classifier"))
files = [str(f) for f in metadata.files("litkit")]
print(any(f.endswith("LICENSE") for f in files), "litkit/py.typed" in files,
      "litkit/__init__.pyi" in files)
print(litkit.render(litkit.default_scene(), width=40, height=30).shape)
"""
    shown = subprocess.run([str(python), "-c", program], env=environment(), check=True,
                           capture_output=True, text=True, cwd=tmp_path).stdout.splitlines()
    where = pathlib.Path(shown[0])
    assert where.is_relative_to(venv), where  # not the build tree's, nor the source copy's
    assert shown[1:] == [f"{VERSION} {VERSION}", "MIT True", "True True True", "(30, 40, 3)"]


def test_build_makes_a_source_distribution_and_a_wheel(tmp_path):
    pytest.importorskip("build", reason="python3-build (scripts/install-deps.sh installs it)")
    source = source_copy(tmp_path / "source")
    out = tmp_path / "dist"
    result = subprocess.run([sys.executable, "-m", "build", "--no-isolation", "--outdir",
                             str(out), str(source)], env=environment(), capture_output=True,
                            text=True, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert (out / f"litkit-{VERSION}.tar.gz").is_file()
    wheels = list(out.glob(f"litkit-{VERSION}-cp3*-linux_*.whl"))
    assert len(wheels) == 1, list(out.iterdir())
    with zipfile.ZipFile(wheels[0]) as wheel:
        names = set(wheel.namelist())
        for wanted in ("litkit/__init__.py", "litkit/_image.py", "litkit/_toml.py",
                       "litkit/__init__.pyi", "litkit/py.typed",
                       f"litkit-{VERSION}.dist-info/LICENSE"):
            assert wanted in names, sorted(names)
        assert any(n.startswith("litkit/_litkit.") and n.endswith(".so") for n in names)
        meta = email.message_from_bytes(wheel.read(f"litkit-{VERSION}.dist-info/METADATA"))
        assert meta["License"] == "MIT"
        assert wheel.read(f"litkit-{VERSION}.dist-info/LICENSE") == \
            (SOURCE_DIR / "LICENSE").read_bytes()


def test_the_version_is_the_librarys():
    assert litkit.__version__ == VERSION


def stub_names(node, classes=None):
    """The names a stub's module or class body defines (with its bases' in the stub)."""
    names = set()
    for base in getattr(node, "bases", []):
        if isinstance(base, ast.Name) and classes and base.id in classes:
            names.update(stub_names(classes[base.id], classes))
    for item in node.body:
        if isinstance(item, (ast.FunctionDef, ast.ClassDef)):
            names.add(item.name)
        elif isinstance(item, ast.AnnAssign):
            names.add(item.target.id)
        elif isinstance(item, ast.Assign):
            names.update(t.id for t in item.targets)
    return names


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_the_stubs_name_every_public_name_and_nothing_else():
    stubs = pathlib.Path(litkit.__file__).with_name("__init__.pyi")
    assert stubs.with_name("py.typed").is_file()
    tree = ast.parse(stubs.read_text())
    classes = {node.name: node for node in tree.body if isinstance(node, ast.ClassDef)}
    assert set(litkit.__all__) <= stub_names(tree)
    assert "__version__" in stub_names(tree)
    for name in litkit.__all__:
        value = getattr(litkit, name)
        if not isinstance(value, type):
            continue
        own = set()
        for klass in value.__mro__:
            if klass.__module__.startswith("litkit"):
                own.update(vars(klass))
        if issubclass(value, litkit.Error):
            own.update({"file", "line", "column", "message", "diagnostics", "warnings"})
        if name == "Explanation":  # its attributes are the fields it is made with
            own.update(vars(litkit.explain(litkit.default_scene(), 1, 1)))
        assert public(stub_names(classes[name], classes)) == public(own), name
