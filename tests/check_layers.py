#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The build enforces src/'s layers (src/README.md, src/CMakeLists.txt): a
file of one layer compiles against its own folder, the folders below it and
their public headers, and an include that points up (or sideways, between
cpu/ and codegen/) does not compile.

Each probe is a one-line file compiled (-fsyntax-only) with exactly the
command that the build uses for a real source file of that layer, taken from
compile_commands.json; includes that must work are probed too, so that a
broken probe cannot pass as a refusal.

    check_layers.py BUILD_DIR/compile_commands.json
"""
import json
import os
import shlex
import subprocess
import sys
import tempfile

# (layer, include, must it compile?)
PROBES = [
    ("core", "core/files.hpp", True),
    ("core", "litkit/error.hpp", True),
    ("core", "cpu/pipeline.hpp", False),
    ("core", "litkit/scene.hpp", False),
    ("lighting", "litkit/equations.hpp", True),
    ("lighting", "geometry/convex.hpp", False),
    ("geometry", "core/parallel.hpp", True),
    ("geometry", "litkit/lighting.hpp", True),
    ("geometry", "scene/world_mesh.hpp", False),
    ("geometry", "litkit/render.hpp", False),
    ("scene", "geometry/weld.hpp", True),
    ("scene", "cpu/shade_kernel.hpp", False),
    ("scene", "litkit/glsl.hpp", False),
    ("trace", "scene/camera.hpp", True),
    ("trace", "core/parallel.hpp", True),
    ("trace", "cpu/pipeline.hpp", False),
    ("trace", "litkit/render.hpp", False),
    ("cpu", "trace/accel.hpp", True),
    ("codegen", "trace/bvh_build.hpp", True),
    ("cpu", "scene/camera.hpp", True),
    ("cpu", "litkit/render.hpp", True),
    ("cpu", "codegen/gl_scene.hpp", False),
    ("cpu", "teach/labels.hpp", False),
    ("cpu", "litkit/explain.hpp", False),
    ("codegen", "scene/world_mesh.hpp", True),
    ("codegen", "cpu/pipeline.hpp", False),
    ("codegen", "litkit/render.hpp", False),
    ("teach", "cpu/pipeline.hpp", True),
    ("teach", "codegen/glsl_expr.hpp", False),
    ("gl", "codegen/gl_scene.hpp", True),
    ("gl", "teach/labels.hpp", False),
]


def layer_command(entries, layer):
    """The compile command of one source file of LAYER, as an argument list."""
    marker = f"/src/{layer}/"
    for entry in entries:
        if marker in entry["file"] and entry["file"].endswith(".cpp") and \
                f"litkit_layer_{layer}.dir" in entry.get("output", entry["command"]):
            return shlex.split(entry["command"]), entry["directory"], entry["file"]
    sys.exit(f"FAIL: compile_commands.json has no source file of layer {layer}")


def compiles(command, directory, source, include, scratch):
    probe = os.path.join(scratch, "probe.cpp")
    with open(probe, "w") as f:
        f.write(f'#include "{include}"\n')
    args = []
    skip = False
    for i, arg in enumerate(command):
        if skip:
            skip = False
            continue
        if i == 0 and os.path.basename(arg) == "ccache":
            continue
        if arg == "-o":
            skip = True
            continue
        if arg == "-c":
            continue
        if arg == source or os.path.normpath(os.path.join(directory, arg)) == source:
            continue
        if arg.startswith("-MF") or arg in ("-MD", "-MT"):
            skip = arg in ("-MT",) or arg == "-MF"
            continue
        args.append(arg)
    args += ["-fsyntax-only", probe]
    result = subprocess.run(args, cwd=directory, capture_output=True, text=True)
    return result.returncode == 0, result.stderr


def main():
    with open(sys.argv[1]) as f:
        entries = json.load(f)
    failures = 0
    with tempfile.TemporaryDirectory() as scratch:
        for layer, include, expected in PROBES:
            command, directory, source = layer_command(entries, layer)
            ok, stderr = compiles(command, directory, source, include, scratch)
            verdict = "compiles" if ok else "refused"
            if ok != expected:
                failures += 1
                print(f"FAIL: {layer}/ including \"{include}\" {verdict}; expected "
                      f"{'to compile' if expected else 'a refusal'}\n{stderr}")
            elif not ok and "No such file" not in stderr:
                failures += 1
                print(f"FAIL: {layer}/ including \"{include}\" failed for another reason:\n{stderr}")
            else:
                print(f"ok: {layer}/ including \"{include}\" {verdict}")
    print(f"{len(PROBES) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
