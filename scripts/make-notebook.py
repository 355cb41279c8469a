#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Makes a Jupyter notebook from a `# %%` script, so that the notebook is
never edited by hand and never drifts from the script it comes from.

    scripts/make-notebook.py                 examples/python/lighting_models.py -> .ipynb
    scripts/make-notebook.py --check         fails if the notebook differs from what it makes
    scripts/make-notebook.py SCRIPT NOTEBOOK [--check]

The script's cells: `# %%` starts a code cell, `# %% [markdown]` a Markdown
cell whose lines are comments (`# ` taken off). Lines before the first
marker (the licence line) are not part of the notebook. The notebook has no
outputs (the tests run it: tests/python/test_notebook.py) and is written the
way nbformat writes one (sorted keys, one-space indents), with cell ids
numbered in order, so that the same script always gives the same bytes.
Only the standard library: no Jupyter needed to make or check it.
"""

import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DEFAULT_SCRIPT = ROOT / "examples" / "python" / "lighting_models.py"


def cells_of(text):
    """[(kind, lines)] of the script's cells, kind "code" or "markdown"."""
    cells = []
    for line in text.splitlines():
        if line.startswith("# %%"):
            kind = "markdown" if line.strip() == "# %% [markdown]" else "code"
            cells.append((kind, []))
        elif cells:
            cells[-1][1].append(line)
    result = []
    for kind, lines in cells:
        if kind == "markdown":
            lines = [line[2:] if line.startswith("# ") else line.lstrip("#") for line in lines]
        while lines and not lines[-1].strip():
            lines.pop()
        while lines and not lines[0].strip():
            lines.pop(0)
        result.append((kind, lines))
    return result


def notebook_of(text):
    """The notebook's JSON text."""
    cells = []
    for number, (kind, lines) in enumerate(cells_of(text), start=1):
        source = [line + "\n" for line in lines]
        if source:
            source[-1] = source[-1][:-1]
        cell = {"cell_type": kind, "id": f"cell-{number:02d}", "metadata": {}, "source": source}
        if kind == "code":
            cell.update(execution_count=None, outputs=[])
        cells.append(cell)
    notebook = {
        "cells": cells,
        "metadata": {
            "kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"},
            "language_info": {"name": "python"},
        },
        "nbformat": 4,
        "nbformat_minor": 5,
    }
    return json.dumps(notebook, indent=1, sort_keys=True, ensure_ascii=False) + "\n"


def main(arguments):
    check = "--check" in arguments
    paths = [pathlib.Path(a) for a in arguments if a != "--check"]
    script = paths[0] if paths else DEFAULT_SCRIPT
    notebook = paths[1] if len(paths) > 1 else script.with_suffix(".ipynb")
    made = notebook_of(script.read_text())
    if check:
        if not notebook.is_file() or notebook.read_text() != made:
            print(f"{notebook} is not what {script} makes: run scripts/make-notebook.py",
                  file=sys.stderr)
            return 1
        return 0
    notebook.write_text(made)
    print(f"wrote {notebook}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
