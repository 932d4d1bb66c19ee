"""Random closed surfaces for the tests, each with its faces counter-clockwise from outside.

- star-shaped polyhedra: a sphere triangulation with each vertex moved along
  its ray by a random factor (non-convex; scaling along rays keeps every
  triangle's orientation, as det(ra a, rb b, rc c) = ra rb rc det(a, b, c));
- convex hulls of random points;
- extrusions of random simple (star-shaped, non-convex) polygons: polygon caps
  and quadrilateral sides, exercising the polygon-face path.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import ConvexHull


def _outward(vertices: np.ndarray, triangles: np.ndarray, inside: np.ndarray) -> np.ndarray:
    """Triangles of a convex-hull-like surface turned to face away from ``inside``."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    flip = np.einsum("ij,ij->i", normals, a - inside) < 0
    oriented = triangles.copy()
    oriented[flip] = oriented[flip][:, ::-1]
    return oriented


def sphere_triangulation(count: int) -> tuple[np.ndarray, np.ndarray]:
    """Fibonacci points on the unit sphere and their hull's triangles, outward."""
    index = np.arange(count) + 0.5
    polar = np.arccos(1 - 2 * index / count)
    azimuth = np.pi * (1 + 5**0.5) * index
    points = np.column_stack(
        [np.cos(azimuth) * np.sin(polar), np.sin(azimuth) * np.sin(polar), np.cos(polar)]
    )
    return points, _outward(points, ConvexHull(points).simplices, np.zeros(3))


def star_polyhedron(rng: np.random.Generator, count: int = 60):
    points, triangles = sphere_triangulation(count)
    radii = rng.uniform(0.4, 1.6, size=(count, 1))
    return points * radii, triangles


def convex_hull(rng: np.random.Generator, count: int = 40):
    points = rng.normal(size=(count, 3)) * rng.uniform(0.5, 2.0, size=3)
    hull = ConvexHull(points)
    used = np.unique(hull.simplices)
    remap = np.full(count, -1)
    remap[used] = np.arange(used.size)
    vertices = points[used]
    return vertices, _outward(vertices, remap[hull.simplices], vertices.mean(axis=0))


def random_simple_polygon(rng: np.random.Generator, count: int) -> np.ndarray:
    """A star-shaped (so simple) and usually non-convex polygon, counter-clockwise."""
    angles = np.sort(rng.uniform(0, 2 * np.pi, size=count))
    radii = rng.uniform(0.3, 1.0, size=count)
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])


def extrusion(rng: np.random.Generator, count: int = 9):
    """A prism over a random simple polygon: caps of ``count`` vertices, quad sides."""
    outline = random_simple_polygon(rng, count)
    height = rng.uniform(0.2, 2.0)
    vertices = np.vstack(
        [
            np.column_stack([outline, np.zeros(count)]),
            np.column_stack([outline, np.full(count, height)]),
        ]
    )
    bottom = list(range(count - 1, -1, -1))  # seen from below: counter-clockwise
    top = list(range(count, 2 * count))
    sides = [[i, (i + 1) % count, count + (i + 1) % count, count + i] for i in range(count)]
    return vertices, [bottom, top, *sides]


SHAPES = {"star": star_polyhedron, "hull": convex_hull, "extrusion": extrusion}


def soup(vertices: np.ndarray, faces) -> tuple[np.ndarray, np.ndarray]:
    """Each face with its own vertices, as an STL file stores its triangles."""
    faces = np.asarray(faces)
    return vertices[faces.reshape(-1)], np.arange(faces.size).reshape(faces.shape)


def random_rotation(rng: np.random.Generator) -> np.ndarray:
    """A uniformly random proper rotation (QR of a Gaussian matrix, det fixed to +1)."""
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    if np.linalg.det(q) < 0:
        q[:, 0] = -q[:, 0]
    return q


def torus(major: float, minor: float, rings: int, sides: int):
    """A closed torus of ``2 * rings * sides`` triangles, outward."""
    u = np.linspace(0, 2 * np.pi, rings, endpoint=False)[:, None]
    v = np.linspace(0, 2 * np.pi, sides, endpoint=False)[None, :]
    x = (major + minor * np.cos(v)) * np.cos(u)
    y = (major + minor * np.cos(v)) * np.sin(u)
    z = minor * np.sin(v) * np.ones_like(u)
    vertices = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
    i, j = np.meshgrid(np.arange(rings), np.arange(sides), indexing="ij")
    a = i * sides + j
    b = ((i + 1) % rings) * sides + j
    c = ((i + 1) % rings) * sides + (j + 1) % sides
    d = i * sides + (j + 1) % sides
    triangles = np.concatenate(
        [np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)]
    )
    return vertices, triangles.astype(np.uint32)


def axis_rotation(rng: np.random.Generator) -> np.ndarray:
    """A random rotation that maps axes to axes: exact in floating point.

    A general rotation rounds the vertices of a planar polygon face off its
    plane, and a non-planar face has no exact answer to compare with (the
    library and a fan triangulation then differ by about the non-planarity).
    """
    rotation = np.eye(3)[rng.permutation(3)] * rng.choice([-1.0, 1.0], size=3)
    if np.linalg.det(rotation) < 0:
        rotation[2] = -rotation[2]
    return rotation


# Polygon faces stay exactly planar only under rotations that are exact.
ROTATIONS = {"star": random_rotation, "hull": random_rotation, "extrusion": axis_rotation}
