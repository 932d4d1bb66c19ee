"""Shared settings: hypothesis is derandomized and keeps no example database, so that
every run (CI included) tests the same examples and leaves nothing behind."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

settings.register_profile(
    "polymass",
    max_examples=100,
    derandomize=True,
    database=None,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.load_profile("polymass")


@pytest.fixture
def tetrahedron():
    """The unit corner tetrahedron: volume 1/6, centre of mass (1/4, 1/4, 1/4)."""
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.uint32)
    return vertices, faces


@pytest.fixture
def cube():
    """The unit cube [0, 1]^3 as six quadrilaterals, counter-clockwise from outside."""
    vertices = np.array(
        [[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=np.float64
    )
    faces = [
        [0, 2, 3, 1],  # z = 0
        [4, 5, 7, 6],  # z = 1
        [0, 1, 5, 4],  # y = 0
        [2, 6, 7, 3],  # y = 1
        [0, 4, 6, 2],  # x = 0
        [1, 3, 7, 5],  # x = 1
    ]
    return vertices, faces
