# SPDX-License-Identifier: MIT
"""litkit.shade and shade_terms against the equations of docs/spec.md §4,
computed here by hand for one point."""

import math

import numpy as np
import pytest

import litkit

POINT = (0.0, 0.0, 0.0)
UP = (0.0, 1.0, 0.0)
EYE = (0.0, 1.0, 3.0)


def bulb():
    # Two units above the point: L = (0, 1, 0), f = 1/d² = 1/4 (DD7).
    return litkit.Light("point", position=(0.0, 2.0, 0.0))


def test_lambert_by_hand():
    material = litkit.Material(color=(1.0, 0.5, 0.25), kd=0.7)
    got = litkit.shade("lambert", material, [bulb()], POINT, UP, EYE)
    # I = f · I_L · k_d · (N·L) · C = 0.25 · 0.7 · C
    assert got == pytest.approx(tuple(0.25 * 0.7 * c for c in (1.0, 0.5, 0.25)), rel=1e-6)


def test_ambient_adds_ka_c():
    material = litkit.Material(color=(1.0, 1.0, 1.0), ka=0.2, kd=0.7)
    ambient = litkit.Light("ambient", intensity=0.5)
    got = litkit.shade("lambert", material, [ambient, bulb()], POINT, UP, EYE)
    assert got == pytest.approx((0.2 * 0.5 + 0.25 * 0.7,) * 3, rel=1e-6)


@pytest.mark.parametrize("model", ["phong", "blinn-phong"])
def test_specular_models_by_hand(model):
    material = litkit.Material(color=(1.0, 1.0, 1.0), kd=0.7, ks=0.5, shininess=4)
    eye = (0.0, 1.0, 1.0)
    v = np.array(eye) / math.sqrt(2.0)
    n = np.array(UP)
    light = np.array([0.0, 1.0, 0.0])
    if model == "phong":
        r = 2.0 * n.dot(light) * n - light
        s = max(r.dot(v), 0.0) ** 4
    else:
        h = (light + v) / np.linalg.norm(light + v)
        s = max(n.dot(h), 0.0) ** 4
    expected = 0.25 * (0.7 * 1.0 + 0.5 * s)
    got = litkit.shade(model, material, [bulb()], POINT, UP, eye)
    assert got == pytest.approx((expected,) * 3, rel=1e-5)


def test_shade_terms_total_is_shade():
    material = litkit.Material(color=(0.8, 0.3, 0.2))
    lights = [litkit.Light("ambient", intensity=0.3), bulb(),
              litkit.Light("spot", position=(1.0, 3.0, 0.0), direction=(-1.0, -3.0, 0.0),
                           cutoff=40.0, penumbra=0.2),
              litkit.Light("directional", direction=(0.0, -1.0, -1.0), color=(1.0, 0.9, 0.8))]
    for model in litkit.reflection_models():
        terms = litkit.shade_terms(model, material, lights, POINT, UP, EYE)
        assert terms["total"] == litkit.shade(model, material, lights, POINT, UP, EYE)
        assert len(terms["lights"]) == 4
        assert terms["lights"][0]["ambient"] and not terms["lights"][1]["ambient"]
        summed = np.sum([t["contribution"] for t in terms["lights"]], axis=0)
        assert tuple(summed) == pytest.approx(terms["total"], rel=1e-5, abs=1e-7)
    lambert = litkit.shade_terms("lambert", material, [bulb()], POINT, UP, EYE)["lights"][0]
    assert lambert["to_light"] == pytest.approx((0.0, 1.0, 0.0))
    assert lambert["factor"] == pytest.approx(0.25)
    assert lambert["diffuse"] == pytest.approx(1.0)


def test_normal_that_is_not_unit_is_refused():
    with pytest.raises(litkit.ArgumentError) as raised:
        litkit.shade("phong", litkit.Material(), [bulb()], POINT, (0.0, 2.0, 0.0), EYE)
    assert "unit" in str(raised.value)


def test_bad_lights_and_models_are_refused():
    with pytest.raises(litkit.ArgumentError) as raised:
        litkit.Light("laser", position=(0, 0, 0))
    assert str(raised.value).endswith("expected one of: " + ", ".join(litkit.light_types()))
    with pytest.raises(litkit.ArgumentError):
        litkit.Light("point")  # no position
    with pytest.raises(litkit.ArgumentError):
        litkit.Light("ambient", direction=(0, -1, 0))
    with pytest.raises(litkit.ArgumentError):
        litkit.shade("fong", litkit.Material(), [bulb()], POINT, UP, EYE)


def test_the_lists_of_names_are_the_librarys():
    assert litkit.light_types() == ["ambient", "directional", "point", "spot"]
    assert litkit.normals_weightings() == ["mean", "area", "angle", "max", "file"]
    assert litkit.shading_models() == ["flat", "gouraud", "phong", "faceted"]
    keys = {"ambient": {}, "directional": {"direction": (0.0, -1.0, 0.0)},
            "point": {"position": (0.0, 1.0, 0.0)},
            "spot": {"position": (0.0, 1.0, 0.0), "direction": (0.0, -1.0, 0.0)}}
    for kind in litkit.light_types():
        assert litkit.Light(kind, **keys[kind]).type == kind
