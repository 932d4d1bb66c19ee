"""Surfaces that bound a region twice (faces crossing, shells nested in a solid of the
same sense, shells inside out) and those that only look alike (cavities, parts in
hollows, parts resting on each other), as the library reports them: the binding's
exception, option, report fields and shells, not a judgement of its own.

Every verdict is also checked far from the origin and at tiny and huge scales: the
library decides them with exact predicates, so they must not change.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

import polymass
from shapes import ROTATIONS, SHAPES

# (name, scale, translation): each case is also tried at x' = scale x + translation.
PLACEMENTS = [
    ("as given", 1.0, (0.0, 0.0, 0.0)),
    ("at 1e6", 1.0, (1e6, -1e6, 1e6)),
    ("at 1e8", 1.0, (1e8, 1e8, -1e8)),
    ("scaled 1e-60", 1e-60, (0.0, 0.0, 0.0)),
    ("scaled 1e60", 1e60, (0.0, 0.0, 0.0)),
]
PLACEMENT_IDS = [name for name, _, _ in PLACEMENTS]

# Faces seen from outside, counter-clockwise; corner k of a box has x from bit 0,
# y from bit 1, z from bit 2 of k.
_BOX_QUADS = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


class Surface:
    """Shells gathered into one surface: vertices and faces (lists of indices)."""

    def __init__(self) -> None:
        self.vertices: list[list[float]] = []
        self.faces: list[list[int]] = []

    def add(self, vertices, faces, *, inside_out: bool = False) -> Surface:
        base = len(self.vertices)
        self.vertices.extend([float(x) for x in vertex] for vertex in vertices)
        for face in faces:
            face = [base + int(i) for i in face]
            self.faces.append(face[::-1] if inside_out else face)
        return self

    def box(self, low, high, *, triangles: bool = False, inside_out: bool = False) -> Surface:
        corners = [[high[a] if k >> a & 1 else low[a] for a in range(3)] for k in range(8)]
        faces = _BOX_QUADS
        if triangles:
            faces = [[q[0], q[k], q[k + 1]] for q in _BOX_QUADS for k in (1, 2)]
        return self.add(corners, faces, inside_out=inside_out)

    def l_prism(self) -> Surface:
        """An L-shaped prism 0 <= z <= 1 whose notch is the square [1, 4] x [1, 4]."""
        outline = [[0, 0], [4, 0], [4, 1], [1, 1], [1, 4], [0, 4]]
        n = len(outline)
        vertices = [[x, y, 0] for x, y in outline] + [[x, y, 1] for x, y in outline]
        bottom = list(range(n - 1, -1, -1))
        top = list(range(n, 2 * n))
        sides = [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
        return self.add(vertices, [bottom, top, *sides])

    def octahedron(self, centre, radius, *, inside_out: bool = False) -> Surface:
        c, r = np.asarray(centre, dtype=float), radius
        vertices = [c + r * np.array(d) for d in np.vstack([np.eye(3), -np.eye(3)])]
        # +x, +y, +z = 0, 1, 2; -x, -y, -z = 3, 4, 5.
        faces = [[0, 1, 2], [1, 3, 2], [3, 4, 2], [4, 0, 2]]
        faces += [[1, 0, 5], [3, 1, 5], [4, 3, 5], [0, 4, 5]]
        return self.add(vertices, faces, inside_out=inside_out)

    def placed(self, scale: float, translation) -> tuple[np.ndarray, list[list[int]]]:
        return np.array(self.vertices) * scale + np.array(translation), self.faces


def overlapping_cubes(triangles: bool = False) -> Surface:
    """Two unit cubes overlapping by an eighth: 1.875 enclosed, 2 counted."""
    return (
        Surface()
        .box((0, 0, 0), (1, 1, 1), triangles=triangles)
        .box((0.5, 0.5, 0.5), (1.5, 1.5, 1.5), triangles=triangles)
    )


def solid_in_solid() -> Surface:
    return Surface().box((0, 0, 0), (4, 4, 4)).box((1, 1, 1), (2, 2, 2), triangles=True)


def cube_with_cavity() -> Surface:
    return Surface().box((0, 0, 0), (4, 4, 4)).box((1, 1, 1), (3, 3, 3), inside_out=True)


def part_in_hollow() -> Surface:
    """A hollow cube (6^3 - 4^3) and, in its hollow, a cube of 2^3."""
    return (
        Surface()
        .box((0, 0, 0), (6, 6, 6))
        .box((1, 1, 1), (5, 5, 5), triangles=True, inside_out=True)
        .box((2, 2, 2), (4, 4, 4))
    )


def inverted_apart() -> Surface:
    return Surface().box((0, 0, 0), (1, 1, 1)).box((3, 0, 0), (3.5, 0.5, 0.5), inside_out=True)


def inverted_in_the_notch() -> Surface:
    """Within the L's bounding box, outside the L: only counted nesting tells it from a cavity."""
    return Surface().l_prism().box((2.5, 2.5, 0.25), (3, 3, 0.75), triangles=True, inside_out=True)


# (case, status with the check, status without, volume when accepted with the check)
OK = 0
VERDICTS = [
    ("overlapping cubes", overlapping_cubes, polymass.IntersectingSurfaceError, OK, None),
    (
        "overlapping cubes, triangles",
        lambda: overlapping_cubes(True),
        polymass.IntersectingSurfaceError,
        OK,
        None,
    ),
    ("a solid cube in a solid cube", solid_in_solid, polymass.IntersectingSurfaceError, OK, None),
    ("a cube with a cavity", cube_with_cavity, OK, OK, 64.0 - 8.0),
    ("a part in a hollow part", part_in_hollow, OK, OK, 216.0 - 64.0 + 8.0),
    (
        "an inside-out cube apart",
        inverted_apart,
        polymass.InvertedError,
        polymass.InvertedError,
        None,
    ),
    ("an inside-out cube in an L's notch", inverted_in_the_notch, polymass.InvertedError, OK, None),
]


def _verdict(vertices, faces, check_intersections: bool):
    """The exception class raised, or the result."""
    skip = not check_intersections
    try:
        return polymass.mass_properties(vertices, faces, skip_intersection_check=skip)
    except polymass.Error as error:
        return type(error)


@pytest.mark.parametrize(("name", "scale", "translation"), PLACEMENTS, ids=PLACEMENT_IDS)
@pytest.mark.parametrize(
    ("case", "make", "checked", "unchecked", "volume"), VERDICTS, ids=[v[0] for v in VERDICTS]
)
def test_verdicts_everywhere(case, make, checked, unchecked, volume, name, scale, translation):
    vertices, faces = make().placed(scale, translation)
    with_check = _verdict(vertices, faces, True)
    without = _verdict(vertices, faces, False)
    got = [v if isinstance(v, type) else OK for v in (with_check, without)]
    assert got == [checked, unchecked], f"{case}, {name}"
    if checked is OK:
        assert with_check.volume == pytest.approx(volume * scale**3, rel=1e-12)
        assert with_check.warnings == 0
        _assert_identical(with_check, without)
        assert without.warnings == polymass.Warnings.INTERSECTIONS_UNCHECKED
    # check() says what mass_properties does, with the same keyword.
    for keyword, expected in ((True, checked), (False, unchecked)):
        report = polymass.check(vertices, faces, skip_intersection_check=not keyword)
        assert report.error is (None if expected is OK else expected), f"{case}, {name}"


def _assert_identical(one: polymass.MassProperties, other: polymass.MassProperties) -> None:
    for field in (
        "volume",
        "mass",
        "surface_area",
        "center_of_mass",
        "inertia",
        "inertia_origin",
        "principal_moments",
        "principal_axes",
    ):
        assert np.array_equal(getattr(one, field), getattr(other, field)), field


def test_every_call_refuses_overlapping_cubes_by_default():
    """Two unit cubes overlapping by an eighth: the solid is 1.875, their sum 2.0. Every
    call refuses them unless the check is skipped by name, which gives the sum."""
    vertices, faces = overlapping_cubes().placed(1.0, (0, 0, 0))
    calls = {
        "mass_properties": lambda **k: polymass.mass_properties(vertices, faces, **k).volume,
        "Mesh": lambda **k: polymass.Mesh(vertices, faces, **k).mass_properties().volume,
        "moments": lambda **k: polymass.moments(vertices, faces, **k).volume,
        "batch": lambda **k: _raised_or(polymass.batch([(vertices, faces)], **k)[0]).volume,
    }
    for name, call in calls.items():
        with pytest.raises(polymass.IntersectingSurfaceError):
            call()
        assert call(skip_intersection_check=True) == pytest.approx(2.0, rel=1e-15), name
        assert call(skip_checks=True) == pytest.approx(2.0, rel=1e-15), name
    assert polymass.check(vertices, faces).error is polymass.IntersectingSurfaceError
    assert polymass.check(vertices, faces, skip_intersection_check=True).ok


def _raised_or(outcome):
    """A batch item's result, or its error raised."""
    if isinstance(outcome, polymass.Error):
        raise outcome
    return outcome


def test_overlapping_cubes_are_refused_naming_the_faces_and_accepted_double_skipped():
    vertices, faces = overlapping_cubes().placed(1.0, (0, 0, 0))
    with pytest.raises(polymass.IntersectingSurfaceError) as raised:
        polymass.mass_properties(vertices, faces)
    error = raised.value
    assert isinstance(error, polymass.Error) and isinstance(error, ValueError)
    assert error.status == polymass.IntersectingSurfaceError.status == 24
    assert error.status_name and str(error).startswith(error.status_name)
    named = re.search(r"faces (\d+) \(shell (\d+)\) and (\d+) \(shell (\d+)\) cross", error.message)
    assert named, error.message
    first, first_shell, second, second_shell = (int(g) for g in named.groups())
    assert (first_shell, second_shell) == (0, 1) and first < 6 <= second < 12
    # The pair named is the report's first.
    report = polymass.check(vertices, faces)
    assert report.first_intersecting_face_pairs[0] == (first, second)
    assert report.message == error.message
    # A Mesh checks too: it is refused, and says why.
    refused = polymass.Mesh(vertices, faces)
    assert refused.error is polymass.IntersectingSurfaceError
    assert refused.message == error.message
    assert refused.diagnostics.first_intersecting_face_pairs[0] == (first, second)
    with pytest.raises(polymass.IntersectingSurfaceError):
        refused.mass_properties()
    # Skipped by name, the overlap is counted twice: what the library then reports.
    trusted = polymass.mass_properties(vertices, faces, skip_intersection_check=True)
    assert trusted.volume == pytest.approx(2.0, rel=1e-15)
    trusted = polymass.Mesh(vertices, faces, skip_intersection_check=True).mass_properties()
    assert trusted.volume == pytest.approx(2.0, rel=1e-15)
    # The trusted path that skips the topology checks skips this one too.
    assert polymass.mass_properties(vertices, faces, skip_checks=True).volume == pytest.approx(2.0)


def test_the_report_lists_crossing_face_pairs_lowest_first():
    vertices, faces = overlapping_cubes().placed(1.0, (0, 0, 0))
    report = polymass.check(vertices, faces)
    assert report.error is polymass.IntersectingSurfaceError and not report.ok
    assert report.shell_count == 2
    assert report.intersecting_face_pairs >= 3
    pairs = report.first_intersecting_face_pairs
    assert len(pairs) == min(report.intersecting_face_pairs, 8)
    assert all(a < 6 <= b < 12 for a, b in pairs), pairs
    assert list(pairs) == sorted(set(pairs))
    assert (report.touching_face_pairs, report.first_touching_face_pairs) == (0, ())
    assert (report.inverted_shells, report.first_inverted_shells) == (0, ())
    with pytest.raises(polymass.IntersectingSurfaceError, match="cross each other"):
        report.raise_if_error()
    # Skipped, no pair is looked for: the report is mass_properties' verdict.
    plain = polymass.check(vertices, faces, skip_intersection_check=True)
    assert plain.ok and plain.shell_count == 2
    assert (plain.intersecting_face_pairs, plain.first_intersecting_face_pairs) == (0, ())


def test_the_report_names_shells_inside_out_and_counted_twice():
    surface = cube_with_cavity().box((6, 0, 0), (7, 1, 1), inside_out=True)
    report = polymass.check(*surface.placed(1.0, (0, 0, 0)))
    assert report.error is polymass.InvertedError
    assert "shell 2" in report.message
    assert report.shell_count == 3
    assert (report.inverted_shells, report.first_inverted_shells) == (1, (2,))
    assert (report.overlapping_shells, report.first_overlapping_shells) == (0, ())

    report = polymass.check(*solid_in_solid().placed(1.0, (0, 0, 0)))
    assert report.error is polymass.IntersectingSurfaceError
    assert "shell 1" in report.message
    assert (report.overlapping_shells, report.first_overlapping_shells) == (1, (1,))
    assert report.intersecting_face_pairs == 0


def test_an_inside_out_shell_apart_is_refused_with_or_without_the_check():
    vertices, faces = inverted_apart().placed(1.0, (0, 0, 0))
    for keyword in (False, True):
        with pytest.raises(polymass.InvertedError, match="shell 1") as raised:
            polymass.mass_properties(vertices, faces, skip_intersection_check=not keyword)
        assert isinstance(raised.value, ValueError)


def _shells(vertices, faces, **options) -> list[polymass.Shell]:
    return polymass.Mesh(vertices, faces, **options).shells


@pytest.mark.parametrize(("name", "scale", "translation"), PLACEMENTS, ids=PLACEMENT_IDS)
def test_the_shells_are_described(name, scale, translation):
    s3 = scale**3
    surface = cube_with_cavity().box((6, 0, 0), (7, 1, 1), inside_out=True)
    shells = _shells(*surface.placed(scale, translation))
    assert [s.kind for s in shells] == ["solid", "cavity", "inverted"]
    assert [(s.face_count, s.first_face) for s in shells] == [(6, 0), (6, 6), (6, 12)]
    expected = [64.0 * s3, -8.0 * s3, -1.0 * s3]
    for shell, volume in zip(shells, expected):
        assert shell.signed_volume == pytest.approx(volume, rel=1e-12)

    def kinds_of(make, **keyword):
        return [s.kind for s in _shells(*make().placed(scale, translation), **keyword)]

    assert kinds_of(solid_in_solid) == ["solid", "overlapping"]
    assert kinds_of(part_in_hollow) == ["solid", "cavity", "solid"]
    assert kinds_of(inverted_in_the_notch) == ["solid", "inverted"]
    # Without the check nesting is judged by bounding boxes, as the library documents:
    # a negative shell within a solid's box is taken for a cavity.
    assert kinds_of(inverted_in_the_notch, skip_intersection_check=True) == ["solid", "cavity"]
    assert kinds_of(overlapping_cubes)[0] == "solid"


def test_shells_name_every_kind_of_the_header():
    from polymass import _header
    from polymass.diagnostics import _SHELL_KINDS

    kinds = {v for k, v in vars(_header).items() if k.startswith("POLYMASS_SHELL_")}
    assert kinds == set(_SHELL_KINDS)
    # A double-sided sheet beside a cube: a shell without volume.
    sheet = (
        Surface()
        .box((0, 0, 0), (1, 1, 1))
        .add([[3, 0, 0], [4, 0, 0], [3, 1, 0]], [[0, 1, 2], [0, 2, 1]])
    )
    shells = _shells(*sheet.placed(1.0, (0, 0, 0)))
    assert [(s.kind, s.face_count, s.signed_volume) for s in shells[1:]] == [("no_volume", 2, 0.0)]


def test_many_shells_are_listed():
    surface = Surface()
    for k in range(40):
        surface.box((3 * k, 0, 0), (3 * k + 1, 1, 1 + k))
    shells = _shells(*surface.placed(1.0, (0, 0, 0)))
    assert [s.kind for s in shells] == ["solid"] * 40
    assert [s.first_face for s in shells] == list(range(0, 240, 6))
    assert [s.signed_volume for s in shells] == pytest.approx([1.0 + k for k in range(40)])
    assert all(isinstance(s, polymass.Shell) for s in shells)


def test_shells_are_unjudged_only_when_a_check_before_them_failed(tetrahedron, cube):
    vertices, faces = tetrahedron
    open_surface = polymass.Mesh(vertices, faces[:3])
    assert open_surface.error is polymass.OpenSurfaceError
    assert "used by one face only" in open_surface.message
    assert not open_surface.diagnostics.checks & polymass.Checks.SHELLS
    [shell] = open_surface.shells
    assert (shell.kind, shell.face_count, shell.first_face) == ("unjudged", 3, 0)
    assert np.isnan(shell.signed_volume)
    # Inside out as a whole: closed, manifold and oriented, so its shell is judged
    # (signed as found) and the surface refused.
    inverted = polymass.Mesh(vertices, faces[:, ::-1])
    assert inverted.error is polymass.InvertedError
    assert inverted.diagnostics.checks & polymass.Checks.SHELLS
    [shell] = inverted.shells
    assert (shell.kind, shell.face_count) == ("inverted", 4)
    assert shell.signed_volume == pytest.approx(-1 / 6, rel=1e-15)
    turned = _shells(vertices, faces[:, ::-1], accept_inverted=True)
    assert [(s.kind, s.face_count) for s in turned] == [("solid", 4)]
    assert turned[0].signed_volume == pytest.approx(1 / 6, rel=1e-15)
    assert [s.kind for s in _shells(*cube)] == ["solid"]


@pytest.mark.parametrize(
    "shape",
    sorted(SHAPES),
)
@pytest.mark.parametrize("seed", range(4))
def test_valid_solids_give_bit_identical_results_with_the_check(shape, seed):
    """No false positive, and the check changes nothing it accepts: random solids,
    rotated and far from the origin."""
    rng = np.random.default_rng(seed)
    vertices, faces = SHAPES[shape](rng)
    vertices = np.asarray(vertices) @ ROTATIONS[shape](rng).T + rng.uniform(-1e6, 1e6, 3)
    checked = polymass.mass_properties(vertices, faces)
    unchecked = polymass.mass_properties(vertices, faces, skip_intersection_check=True)
    _assert_identical(checked, unchecked)
    assert (checked.warnings, unchecked.warnings) == (0, polymass.Warnings.INTERSECTIONS_UNCHECKED)
    report = polymass.check(vertices, faces)
    assert report.ok, report.message
    assert (report.intersecting_face_pairs, report.touching_face_pairs) == (0, 0)
    assert report.shell_count == 1


def resting_cubes() -> Surface:
    return Surface().box((0, 0, 0), (1, 1, 1)).box((1, 0, 0), (2, 1, 1))


def resting_half_on() -> Surface:
    return (
        Surface()
        .box((0, 0, 0), (1, 1, 1), triangles=True)
        .box((0.25, 0.5, 1), (1.25, 1.5, 2), triangles=True)
    )


def cavity_touching_its_wall() -> Surface:
    """An octahedral cavity whose lowest corner (2, 2, 0) is on the outer bottom face."""
    return Surface().box((0, 0, 0), (4, 4, 4)).octahedron((2, 2, 1), 1.0, inside_out=True)


TOUCHING = [
    ("two cubes resting against each other", resting_cubes, 2.0),
    ("a cube resting half on another", resting_half_on, 2.0),
    ("a cavity touching its wall in one point", cavity_touching_its_wall, 64.0 - 4.0 / 3.0),
]


@pytest.mark.parametrize(("name", "scale", "translation"), PLACEMENTS, ids=PLACEMENT_IDS)
@pytest.mark.parametrize(("case", "make", "volume"), TOUCHING, ids=[t[0] for t in TOUCHING])
def test_touching_faces_are_a_warning_with_locations(case, make, volume, name, scale, translation):
    vertices, faces = make().placed(scale, translation)
    checked = polymass.mass_properties(vertices, faces)
    assert checked.warnings == polymass.Warnings.TOUCHING_FACES, f"{case}, {name}"
    assert checked.volume == pytest.approx(volume * scale**3, rel=1e-12)
    plain = polymass.mass_properties(vertices, faces, skip_intersection_check=True)
    assert plain.warnings == polymass.Warnings.INTERSECTIONS_UNCHECKED
    assert np.array_equal(plain.inertia, checked.inertia)
    report = polymass.check(vertices, faces)
    assert report.ok and report.intersecting_face_pairs == 0
    assert report.touching_face_pairs >= 1
    assert len(report.first_touching_face_pairs) == min(report.touching_face_pairs, 8)
    assert all(a < b for a, b in report.first_touching_face_pairs)
