# SPDX-License-Identifier: MIT
"""Writes a scene given as Python objects (dicts, lists, numbers, strings) as
the TOML text that ``litkit.loads`` parses, so that a scene built in code goes
through the same reader and checks as a scene file.

Top-level dicts become tables (``[observer]``), lists of dicts arrays of
tables (``[[lights]]``), dicts inside those inline tables
(``material = { kd = 0.7 }``). NumPy scalars and arrays are written as their
values.
"""

import json
import math
import re
from collections.abc import Mapping

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(key):
    if not isinstance(key, str):
        raise TypeError(f"scene keys must be strings, found {key!r}")
    return key if _BARE_KEY.match(key) else json.dumps(key)


def _value(value):
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        value = value.tolist()  # NumPy scalars and arrays
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # JSON's escapes are TOML basic-string escapes
    if isinstance(value, Mapping):
        return "{ " + ", ".join(f"{_key(k)} = {_value(v)}" for k, v in value.items()) + " }"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v) for v in value) + "]"
    raise TypeError(f"cannot write {type(value).__name__} {value!r} into a scene")


def _is_table_array(value):
    return (isinstance(value, (list, tuple)) and len(value) > 0
            and all(isinstance(v, Mapping) for v in value))


def _table_body(table, lines):
    for key, value in table.items():
        lines.append(f"{_key(key)} = {_value(value)}")


def dumps(scene):
    """The TOML text of ``scene``, a mapping as a scene file's tables."""
    if not isinstance(scene, Mapping):
        raise TypeError(f"a scene is a dict of tables, found {type(scene).__name__}")
    lines = []
    for key, value in scene.items():
        if not isinstance(value, Mapping) and not _is_table_array(value):
            lines.append(f"{_key(key)} = {_value(value)}")
    for key, value in scene.items():
        if isinstance(value, Mapping):
            lines.append(f"\n[{_key(key)}]")
            _table_body(value, lines)
        elif _is_table_array(value):
            for entry in value:
                lines.append(f"\n[[{_key(key)}]]")
                _table_body(entry, lines)
    return "\n".join(lines) + "\n"
