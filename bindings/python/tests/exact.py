"""The exact reference: mass properties in rational arithmetic over signed tetrahedra.

Every double is a rational number, so converting the input with Fraction and
summing the origin-apex tetrahedra of a fan triangulation of each face gives the
exact properties of exactly the solid the library was given. Fans of planar
non-convex polygons are fine: their signed triangles add up to the polygon.
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal, localcontext
from fractions import Fraction

import numpy as np


@dataclass
class ExactSolid:
    volume: Fraction
    center_of_mass: list[Fraction]
    inertia_origin: list[list[Fraction]]  # about (0, 0, 0), negated products off the diagonal
    inertia: list[list[Fraction]]  # about the centre of mass
    surface_area: Decimal  # to 40 digits: the square roots are not rational


def _determinant(a, b, c) -> Fraction:
    return (
        a[0] * (b[1] * c[2] - b[2] * c[1])
        - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
    )


def _norm(vector) -> Decimal:
    """The Euclidean norm of a rational vector, to 40 significant digits."""
    squared = sum(x * x for x in vector)
    with localcontext() as decimal_context:
        decimal_context.prec = 40
        return (Decimal(squared.numerator) / Decimal(squared.denominator)).sqrt()


def _inertia_from_second_moments(second):
    """I = trace(S) Identity - S for S the second moments integral of x x^T."""
    trace = second[0][0] + second[1][1] + second[2][2]
    return [[(trace if i == j else 0) - second[i][j] for j in range(3)] for i in range(3)]


def exact_solid(vertices: np.ndarray, faces) -> ExactSolid:
    """Exact volume, centre of mass and inertia (unit density) of a closed surface."""
    points = [[Fraction(float(x)) for x in row] for row in np.asarray(vertices, dtype=np.float64)]
    six_volume = Fraction(0)
    twenty_four_first = [Fraction(0)] * 3
    # 120 * integral of x_i x_j over the solid.
    hundred_twenty_second = [[Fraction(0)] * 3 for _ in range(3)]
    surface_area = Decimal(0)
    for face in faces:
        face = [int(i) for i in face]
        twice_vector_area = [Fraction(0)] * 3
        for k in range(1, len(face) - 1):
            a, b, c = points[face[0]], points[face[k]], points[face[k + 1]]
            ab = [b[i] - a[i] for i in range(3)]
            ac = [c[i] - a[i] for i in range(3)]
            twice_vector_area[0] += ab[1] * ac[2] - ab[2] * ac[1]
            twice_vector_area[1] += ab[2] * ac[0] - ab[0] * ac[2]
            twice_vector_area[2] += ab[0] * ac[1] - ab[1] * ac[0]
            det = _determinant(a, b, c)  # 6 * the signed volume of (0, a, b, c)
            six_volume += det
            total = [a[i] + b[i] + c[i] for i in range(3)]
            for i in range(3):
                twenty_four_first[i] += det * total[i]
                for j in range(3):
                    # integral x_i x_j over a tetrahedron = V/20 (sum p p^T + (sum p)(sum p)^T).
                    products = a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + total[i] * total[j]
                    hundred_twenty_second[i][j] += det * products
        surface_area += _norm(twice_vector_area) / 2
    volume = six_volume / 6
    center = [twenty_four_first[i] / 24 / volume for i in range(3)]
    second_origin = [[hundred_twenty_second[i][j] / 120 for j in range(3)] for i in range(3)]
    second_center = [
        [second_origin[i][j] - volume * center[i] * center[j] for j in range(3)] for i in range(3)
    ]
    return ExactSolid(
        volume=volume,
        center_of_mass=center,
        inertia_origin=_inertia_from_second_moments(second_origin),
        inertia=_inertia_from_second_moments(second_center),
        surface_area=surface_area,
    )


@dataclass
class ExactPolygon:
    area: Fraction  # signed: positive counter-clockwise
    centroid: list[Fraction]
    second_moments_origin: list[Fraction]  # Ixx = int y^2, Iyy = int x^2, Ixy = int x y
    second_moments: list[Fraction]  # about the centroid


def exact_polygon(points: np.ndarray) -> ExactPolygon:
    """Exact area, centroid and second moments of area by the shoelace sums."""
    xy = [[Fraction(float(x)) for x in row] for row in np.asarray(points, dtype=np.float64)]
    two_area = Fraction(0)
    six_first = [Fraction(0), Fraction(0)]
    twelve_xx = twelve_yy = twenty_four_xy = Fraction(0)
    for k in range(len(xy)):
        (x0, y0), (x1, y1) = xy[k], xy[(k + 1) % len(xy)]
        cross = x0 * y1 - x1 * y0
        two_area += cross
        six_first[0] += cross * (x0 + x1)
        six_first[1] += cross * (y0 + y1)
        twelve_xx += cross * (y0 * y0 + y0 * y1 + y1 * y1)
        twelve_yy += cross * (x0 * x0 + x0 * x1 + x1 * x1)
        twenty_four_xy += cross * (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0)
    area = two_area / 2
    centroid = [six_first[0] / 6 / area, six_first[1] / 6 / area]
    sign = 1 if area > 0 else -1
    origin = [sign * twelve_xx / 12, sign * twelve_yy / 12, sign * twenty_four_xy / 24]
    magnitude = sign * area
    about_centroid = [
        origin[0] - magnitude * centroid[1] ** 2,
        origin[1] - magnitude * centroid[0] ** 2,
        origin[2] - magnitude * centroid[0] * centroid[1],
    ]
    return ExactPolygon(area, centroid, origin, about_centroid)


def assert_close(actual, exact, rel: float, what: str) -> None:
    """|actual - exact| <= rel * max|exact| over the whole vector or tensor.

    One scale for all components: an off-diagonal product of inertia near zero
    is judged against the tensor's size, as its rounding is.
    """
    expected = np.vectorize(float)(np.array(exact, dtype=object)).astype(np.float64)
    actual = np.asarray(actual, dtype=np.float64)
    scale = float(np.max(np.abs(expected)))
    error = float(np.max(np.abs(actual - expected)))
    assert error <= rel * scale, f"{what}: error {error:.3e} > {rel:g} * {scale:.3e}"
