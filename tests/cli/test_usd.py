"""polymass --usda read back by OpenUSD itself (usd-core from PyPI, in the
Python test venv of scripts/test-python.sh):

    POLYMASS_EXE=<polymass> python -m pytest tests/cli/test_usd.py

Each prim's PhysicsMassAPI, read through pxr.UsdPhysics, must give back the
tool's own answer (polymass --json) to float precision: the mass, the centre
of mass, and the tensor about the centre of mass rebuilt from the quaternion
and the diagonal as R diag R^T, for a rotated part, a part far from the
origin, a file of several parts and an assembly; the stage's units as
--units or the file's declared unit says.
"""

import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
from pxr import Gf, Usd, UsdGeom, UsdPhysics

sys.path.insert(0, str(Path(__file__).parent))
import fixtures

EXE = os.environ["POLYMASS_EXE"]
FLOAT_EPSILON = 2.0**-23


def run(*args):
    result = subprocess.run(
        [EXE, *map(str, args)], capture_output=True, text=True, timeout=120, check=False
    )
    assert result.returncode >= 0, result.stderr
    return result


def layer(tmp_path, *args, name="out.usda"):
    """The --usda output of args, written to a file, opened by USD; and stderr."""
    result = run(*args, "--usda")
    assert result.returncode == 0, result.stderr
    path = tmp_path / name
    path.write_text(result.stdout)
    stage = Usd.Stage.Open(str(path))
    assert stage is not None
    return stage, result.stderr


def rotation_of(quaternion):
    """R of a unit quaternion (w, x, y, z), Hamilton's: v' = q v q*."""
    w, x, y, z = quaternion
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def assert_prim_is(prim, solid, origin=(0, 0, 0)):
    """The prim's mass properties equal the JSON solid's to float precision."""
    assert prim.HasAPI(UsdPhysics.RigidBodyAPI) and prim.HasAPI(UsdPhysics.MassAPI)
    mass_api = UsdPhysics.MassAPI(prim)
    mass = mass_api.GetMassAttr().Get()
    assert abs(mass - solid["mass"]) <= FLOAT_EPSILON * solid["mass"]
    com = np.array(mass_api.GetCenterOfMassAttr().Get(), dtype=float)
    expected_com = np.array(solid["center_of_mass"]) - np.array(origin)
    np.testing.assert_allclose(
        com, expected_com, rtol=0, atol=FLOAT_EPSILON * max(abs(expected_com))
    )
    quaternion = mass_api.GetPrincipalAxesAttr().Get()
    assert isinstance(quaternion, Gf.Quatf)
    q = [quaternion.GetReal(), *quaternion.GetImaginary()]
    assert abs(math.sqrt(sum(c * c for c in q)) - 1) <= 2 * FLOAT_EPSILON
    diagonal = np.array(mass_api.GetDiagonalInertiaAttr().Get(), dtype=float)
    assert all(moment > 0 for moment in diagonal)
    rotation = rotation_of(q)
    assert abs(np.linalg.det(rotation) - 1) <= 4 * FLOAT_EPSILON
    # USD's own reading of the quaternion (its matrices act on row vectors).
    usd_rotation = np.array(Gf.Matrix3d(Gf.Rotation(Gf.Quatd(*q))), dtype=float).T
    np.testing.assert_allclose(usd_rotation, rotation, rtol=0, atol=4 * FLOAT_EPSILON)
    tensor = rotation @ np.diag(diagonal) @ rotation.T
    expected = np.array(solid["inertia"])
    scale = max(solid["principal_moments"])
    np.testing.assert_allclose(tensor, expected, rtol=0, atol=8 * FLOAT_EPSILON * scale)


def turned(vertices, rotation, shift=(0, 0, 0)):
    return [tuple(float(c) for c in rotation @ np.array(v) + np.array(shift)) for v in vertices]


# A rotation with no symmetry: every principal axis off every coordinate axis.
TURN_QUATERNION = [c / np.linalg.norm([0.8, 0.2, -0.5, 0.26]) for c in (0.8, 0.2, -0.5, 0.26)]
TURN = rotation_of(TURN_QUATERNION)


def only_prim(stage):
    (prim,) = [p for p in stage.Traverse()]
    return prim


def test_the_bracket_and_the_stage_units(tmp_path):
    vertices, faces = fixtures.bracket()
    mesh = tmp_path / "bracket.obj"
    fixtures.write_obj(mesh, vertices, faces)
    solid = json.loads(run("--json", mesh, "--units", "mm", "--density", 2700).stdout)
    stage, _ = layer(tmp_path, mesh, "--units", "mm", "--density", 2700)
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert UsdPhysics.GetStageKilogramsPerUnit(stage) == 1.0
    assert stage.GetDefaultPrim().GetName() == "bracket"
    assert_prim_is(only_prim(stage), solid)
    # Without --units the lengths are the file's: the stage does not guess.
    solid = json.loads(run("--json", mesh).stdout)
    stage, stderr = layer(tmp_path, mesh, name="file_units.usda")
    assert not stage.HasAuthoredMetadata("metersPerUnit")
    assert not stage.HasAuthoredMetadata("kilogramsPerUnit")
    assert "--units" in stderr
    assert_prim_is(only_prim(stage), solid)


def test_a_file_that_declares_its_unit(tmp_path):
    # A 3MF in millimetres is read in metres: the stage says so without --units.
    vertices, faces = fixtures.bracket()
    mesh = tmp_path / "bracket.3mf"
    fixtures.write_3mf(mesh, vertices, faces)
    solid = json.loads(run("--json", mesh, "--density", 2700).stdout)
    assert solid["length_unit"] == "m"
    stage, stderr = layer(tmp_path, mesh, "--density", 2700)
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert UsdPhysics.GetStageKilogramsPerUnit(stage) == 1.0
    assert "not converted to metres" not in stderr
    assert_prim_is(only_prim(stage), solid)


def test_a_rotated_part_and_an_origin(tmp_path):
    vertices, faces = fixtures.bracket()
    mesh = tmp_path / "turned.stl"
    fixtures.write_binary_stl(mesh, turned(vertices, TURN), faces)
    solid = json.loads(run("--json", mesh, "--mass", 3).stdout)
    assert all(abs(c) > 0.05 for axis in solid["principal_axes"] for c in axis)
    stage, _ = layer(tmp_path, mesh, "--mass", 3, "--origin", "1,2,3")
    assert_prim_is(only_prim(stage), solid, origin=(1, 2, 3))


def test_a_far_part_is_a_warning(tmp_path):
    vertices, faces = fixtures.bracket()
    mesh = tmp_path / "far.stl"
    fixtures.write_binary_stl(mesh, turned(vertices, TURN, (1e4, -2e4, 5e3)), faces)
    solid = json.loads(run("--json", mesh).stdout)
    stage, stderr = layer(tmp_path, mesh)
    assert_prim_is(only_prim(stage), solid)
    assert re.search(r"far\.stl: the whole: warning: the centre of mass.*32-bit float", stderr)
    # Near the origin, the same part is no warning.
    origin = ",".join(map(repr, solid["center_of_mass"]))
    stage, stderr = layer(tmp_path, mesh, "--origin", origin, name="near.usda")
    assert "warning" not in stderr
    assert_prim_is(only_prim(stage), solid, origin=solid["center_of_mass"])


def test_parts_of_a_file_are_children_of_the_whole(tmp_path):
    vertices, faces = fixtures.cube()
    lines = [f"v {x} {y} {z}" for x, y, z in vertices]
    lines += [f"v {x + 5} {2 * y} {3 * z}" for x, y, z in turned(vertices, TURN)]
    lines += ["o left-arm"] + ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    lines += ["o 2nd-arm"] + ["f " + " ".join(str(i + 9) for i in f) for f in faces]
    mesh = tmp_path / "two parts.obj"
    mesh.write_text("\n".join(lines) + "\n")
    arguments = (mesh, "--units", "cm", "--density", "left-arm=2700", "--density", "7850")
    out = json.loads(run("--json", *arguments).stdout)
    stage, _ = layer(tmp_path, *arguments)
    whole = stage.GetDefaultPrim()
    assert whole.GetName() == "two_parts"
    assert_prim_is(whole, out)
    children = whole.GetChildren()
    assert [c.GetName() for c in children] == ["left_arm", "_2nd_arm"]
    for prim, part in zip(children, out["parts"]):
        assert prim.GetCustomDataByKey("name") == part["name"]
        assert not UsdPhysics.RigidBodyAPI(prim).GetRigidBodyEnabledAttr().Get()
        assert_prim_is(prim, part)


def test_an_assembly(tmp_path):
    vertices, faces = fixtures.bracket()
    fixtures.write_obj(tmp_path / "bracket.obj", vertices, faces)
    document = {
        "parts": [
            {"name": "base", "mesh": "bracket.obj", "units": "mm", "density": 2700},
            {
                "name": "base",
                "mesh": "bracket.obj",
                "units": "mm",
                "mass": 0.5,
                "translation": [1000, 0, 0.5],
                "rotation": {"quaternion_wxyz": [float(c) for c in TURN_QUATERNION]},
            },
        ]
    }
    assembly = tmp_path / "arm.json"
    assembly.write_text(json.dumps(document))
    out = json.loads(run("assembly", "--json", assembly).stdout)
    stage, _ = layer(tmp_path, "assembly", assembly)
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    whole = stage.GetDefaultPrim()
    assert_prim_is(whole, out)
    assert [c.GetName() for c in whole.GetChildren()] == ["base", "base_2"]
    for prim, part in zip(whole.GetChildren(), out["parts"]):
        assert_prim_is(prim, part)
