"""polygon_properties against the exact shoelace sums in rational arithmetic."""

from __future__ import annotations

import numpy as np
import pytest

import polymass
from exact import assert_close, exact_polygon
from shapes import random_simple_polygon

RELATIVE = 1e-12


@pytest.mark.parametrize("offset", [0.0, 1e6, 1e8])
@pytest.mark.parametrize("scale", [1e-6, 1.0, 1e6])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_polygons_match_the_exact_reference(seed, scale, offset):
    rng = np.random.default_rng(seed)
    points = random_simple_polygon(rng, 12) * scale + offset * rng.normal(size=2)
    result = polymass.polygon_properties(points)
    exact = exact_polygon(points)
    assert result.counter_clockwise
    assert_close(result.area, exact.area, RELATIVE, "area")
    assert_close(result.centroid, exact.centroid, RELATIVE, "centroid")
    assert_close(result.second_moments, exact.second_moments, RELATIVE, "second moments")
    assert_close(
        result.second_moments_origin, exact.second_moments_origin, RELATIVE, "about the origin"
    )
    assert result.polar_moment == pytest.approx(
        result.second_moments[0] + result.second_moments[1], rel=RELATIVE
    )


def test_clockwise_polygons_give_the_same_properties():
    points = random_simple_polygon(np.random.default_rng(4), 9)
    forward = polymass.polygon_properties(points)
    backward = polymass.polygon_properties(points[::-1])
    assert not backward.counter_clockwise
    assert backward.area == pytest.approx(forward.area, rel=1e-15)
    np.testing.assert_allclose(backward.second_moments, forward.second_moments, rtol=1e-13)


def test_a_rectangle_has_its_closed_form_principal_moments_and_angle():
    width, height, angle = 4.0, 1.0, 0.3
    corners = np.array([[0, 0], [width, 0], [width, height], [0, height]]) - [width / 2, height / 2]
    rotation = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    result = polymass.polygon_properties(corners @ rotation.T)
    # About the long axis: width * height^3 / 12, smallest.
    expected = sorted([width * height**3 / 12, height * width**3 / 12])
    np.testing.assert_allclose(result.principal_moments, expected, rtol=1e-13)
    assert result.principal_angle == pytest.approx(angle, rel=1e-13)


def test_points_are_read_from_a_strided_view():
    points = random_simple_polygon(np.random.default_rng(5), 7)
    wide = np.zeros((7, 5))
    wide[:, :2] = points
    strided = polymass.polygon_properties(wide[:, :2])
    assert strided.area == polymass.polygon_properties(points).area


def test_too_few_points_are_refused():
    with pytest.raises(polymass.FaceTooSmallError):
        polymass.polygon_properties([[0.0, 0.0], [1.0, 0.0]])
