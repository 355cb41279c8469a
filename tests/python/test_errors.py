# SPDX-License-Identifier: MIT
"""Errors reach Python as litkit.Error with the message and place that
`litkit check` prints, and bad arguments raise litkit.Error, never crash."""

import re

import pytest
from conftest import EXAMPLES, run_cli

import litkit

VALID = """\
[room]
width = 10
height = 10
depth = 20

[observer]
position = [0, 1, 6]
look_at = [0, 0, 0]

[lighting]
reflection = "phong"
shading = "phong"

[output]
width = 80
height = 60

[[lights]]
type = "point"
position = [0, 3, 3]
intensity = 9

[[objects]]
type = "cube"
size = 2
"""


def line_of(text, fragment):
    """The 1-based line of `text` that holds `fragment` (once)."""
    lines = [n for n, line in enumerate(text.splitlines(), 1) if fragment in line]
    assert len(lines) == 1, (fragment, lines)
    return lines[0]


def errors_printed_by_check(path):
    """The error lines `litkit check PATH` prints (exit status 2 or 1)."""
    result = run_cli("check", path, check=False)
    assert result.returncode in (1, 2), result
    return [line for line in result.stderr.splitlines() if "error: " in line]


def write(tmp_path, text, name="scene.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_one_located_error_is_the_line_check_prints(tmp_path):
    text = VALID.replace("width = 80", "width = 0")
    line = line_of(text, "width = 0")  # the value starts at column 9
    path = write(tmp_path, text)
    with pytest.raises(litkit.SceneError) as raised:
        litkit.load(path)
    error = raised.value
    assert isinstance(error, litkit.Error)
    assert [str(error)] == errors_printed_by_check(path)
    assert (error.file, error.line, error.column) == (str(path), line, 9)
    assert "width" in error.message and "0" in error.message
    assert str(error) == f"{path}:{line}:9: error: {error.message}"
    assert len(error.diagnostics) == 1 and str(error.diagnostics[0]) == str(error)


def test_every_problem_is_listed_as_check_lists_them(tmp_path):
    text = VALID.replace("width = 80", "width = 0").replace("position = [0, 3, 3]",
                                                           "position = [0, 3, 99]")
    path = write(tmp_path, text)
    with pytest.raises(litkit.Error) as raised:
        litkit.check(path)
    printed = errors_printed_by_check(path)
    assert len(printed) == 2
    assert str(raised.value).splitlines() == printed
    assert [str(d) for d in raised.value.diagnostics] == printed
    assert [d.line for d in raised.value.diagnostics] == [line_of(text, "width = 0"),
                                                          line_of(text, "[0, 3, 99]")]


def test_a_file_that_cannot_be_read(tmp_path):
    missing = tmp_path / "missing.toml"
    with pytest.raises(litkit.IoError) as raised:
        litkit.load(missing)
    assert [str(raised.value)] == errors_printed_by_check(missing)
    assert raised.value.file == str(missing)
    assert raised.value.line is None
    assert raised.value.message.startswith(f"cannot read '{missing}'")


def test_a_toml_syntax_error_is_located(tmp_path):
    path = write(tmp_path, "[room]\nwidth = 10\n[observer\n")
    with pytest.raises(litkit.IoError) as raised:
        litkit.load(path)
    assert [str(raised.value)] == errors_printed_by_check(path)
    assert (raised.value.file, raised.value.line) == (str(path), 3)


def test_text_errors_name_the_source(tmp_path):
    text = VALID.replace("size = 2", "size = -2")
    with pytest.raises(litkit.SceneError) as raised:
        litkit.loads(text, name="mine.toml")
    assert raised.value.file == "mine.toml" and raised.value.line == line_of(text, "size = -2")
    path = write(tmp_path, VALID.replace("size = 2", "size = -2"), "mine.toml")
    assert [str(raised.value).replace("mine.toml", str(path))] == errors_printed_by_check(path)


def test_check_returns_the_warnings(tmp_path):
    path = write(tmp_path, VALID.split("[[lights]]")[0] + VALID.split("intensity = 9\n")[1])
    warnings = litkit.check(path)
    result = run_cli("check", path)
    printed = [line for line in result.stderr.splitlines() if "warning: " in line]
    assert printed and [str(w) for w in warnings] == printed
    assert all(w.severity == "warning" for w in warnings)
    with pytest.warns(litkit.SceneWarning):
        litkit.load(path)


def test_a_scene_broken_in_python_is_refused_with_checks_message(tmp_path):
    scene = litkit.loads(VALID)
    scene.observer.position = (0, 0, 0)  # inside the cube
    with pytest.raises(litkit.SceneError) as raised:
        litkit.check(scene)
    with pytest.raises(litkit.SceneError) as raised_by_render:
        litkit.render(scene)
    assert str(raised_by_render.value) == str(raised.value)
    # The same scene written out: `litkit check` says the same thing.
    path = write(tmp_path, scene.to_toml())
    printed = errors_printed_by_check(path)
    assert [re.sub(r"^.*?error: ", "", line) for line in printed] == [
        d.message for d in raised.value.diagnostics]
    with pytest.raises(litkit.SceneError):
        litkit.Renderer(scene)


@pytest.mark.parametrize("arguments", [
    {"reflection": "fong"},
    {"shading": "smooth"},
    {"width": 0},
    {"height": 0},
    {"width": -5},
    {"height": 16385},
    {"max_depth": 0},
    {"max_depth": 17},
    {"threads": -1},
    {"threads": 5000},
])
def test_bad_render_arguments_raise_litkit_error(arguments):
    with pytest.raises(litkit.ArgumentError) as raised:
        litkit.render(litkit.default_scene(), **arguments)
    assert isinstance(raised.value, litkit.Error)
    name = next(iter(arguments))
    assert name.rstrip("s") in str(raised.value)  # says which argument
    renderer = litkit.Renderer()
    if name != "threads":
        with pytest.raises(litkit.ArgumentError):
            renderer.render(**arguments)
    # The renderer is still good after refusing.
    assert renderer.render(width=8, height=6).shape == (6, 8, 3)


def test_unknown_model_names_the_known_ones():
    with pytest.raises(litkit.ArgumentError) as raised:
        litkit.render(reflection="fong")
    assert str(raised.value) == ("unknown reflection model 'fong'; expected one of: "
                                 + ", ".join(litkit.reflection_models()))
    with pytest.raises(litkit.ArgumentError):
        litkit.default_scene().shading = "smooth"


def test_wrong_types_are_type_errors_not_crashes():
    with pytest.raises(TypeError):
        litkit.render(litkit.default_scene(), width="wide")
    with pytest.raises(TypeError):
        litkit.render("not a scene")
    with pytest.raises(TypeError):
        litkit.loads(42)
    with pytest.raises(TypeError):
        litkit.loads({"room": {"width": object()}})
    with pytest.raises(TypeError):
        litkit.default_scene().observer.position = (1, 2)


def test_a_size_zero_scene_changed_in_python_is_refused():
    scene = litkit.default_scene()
    scene.output.width = 0
    with pytest.raises(litkit.SceneError) as raised:
        litkit.render(scene)
    assert "width" in raised.value.message


def test_loading_nothing_is_an_argument_error():
    with pytest.raises(litkit.ArgumentError):
        litkit.load()


def test_examples_all_check_clean():
    for path in sorted(EXAMPLES.glob("*.toml")):
        litkit.check(path)  # raises on any error


def test_the_triangle_budget_is_the_clis():
    path = EXAMPLES / "teapot.toml"
    with pytest.raises(litkit.SceneError) as raised:
        litkit.load(path, max_triangles=100)
    result = run_cli("check", path, "--max-triangles", 100, check=False)
    assert result.returncode == 2
    assert str(raised.value).splitlines() == [
        line for line in result.stderr.splitlines() if "error: " in line]
    assert "triangle" in raised.value.message


def test_checks_reads_text_and_check_reads_files(tmp_path):
    # The same broken text given as text and as a file: the same error, at
    # the same place (line 3, the unclosed table header), named after its source.
    text = "[room]\nwidth = 10\n[observer\n"
    with pytest.raises(litkit.IoError) as from_text:
        litkit.checks(text, name="mine.toml")
    assert isinstance(from_text.value, litkit.Error)
    assert (from_text.value.file, from_text.value.line) == ("mine.toml", 3)
    path = write(tmp_path, text, "mine.toml")
    with pytest.raises(litkit.IoError) as from_file:
        litkit.check(path)
    assert (from_file.value.file, from_file.value.line) == (str(path), 3)
    assert str(from_text.value).replace("mine.toml", str(path)) == str(from_file.value)
    assert [str(from_file.value)] == errors_printed_by_check(path)
    # Without a name the text is "<string>".
    with pytest.raises(litkit.IoError) as unnamed:
        litkit.checks("[room\n")
    assert (unnamed.value.file, unnamed.value.line) == ("<string>", 1)


def test_checks_lists_every_problem_and_returns_the_warnings(tmp_path):
    text = VALID.replace("width = 80", "width = 0").replace("size = 2", "size = -2")
    with pytest.raises(litkit.SceneError) as raised:
        litkit.checks(text)
    assert [(d.file, d.line) for d in raised.value.diagnostics] == [
        ("<string>", line_of(text, "width = 0")), ("<string>", line_of(text, "size = -2"))]
    assert [str(d).replace("<string>", str(tmp_path / "s.toml")) for d in raised.value.diagnostics] \
        == errors_printed_by_check(write(tmp_path, text, "s.toml"))
    no_lights = VALID.split("[[lights]]")[0] + VALID.split("intensity = 9\n")[1]
    warnings = litkit.checks(no_lights)
    assert warnings and all(w.severity == "warning" and w.file == "<string>" for w in warnings)
    # A dict is checked as loads reads it.
    with pytest.raises(litkit.SceneError) as from_dict:
        litkit.checks({"room": {"width": 10, "height": 10, "depth": -20}})
    assert from_dict.value.file == "<dict>"


def test_check_of_text_says_to_use_checks():
    with pytest.raises(litkit.IoError) as raised:
        litkit.check("[room\n")
    assert raised.value.message.startswith("cannot read '[room")  # a path, as check reads it
    notes = getattr(raised.value, "__notes__", [])
    assert any("litkit.checks" in note for note in notes) or not hasattr(raised.value, "add_note")
