"""polymass audit --fix read back by real consumers: yourdfpy (URDF) and
MuJoCo (MJCF), from PyPI in the Python test venv (scripts/test-python.sh):

    POLYMASS_EXE=<polymass> python -m pytest tests/cli/test_audit_consumers.py

The fixed inertial each consumer reads must be the computed one; and MuJoCo,
inferring a body's inertia from its geoms (default classes, meshdir, mesh
scale, euler in degrees), must agree with the audit's geometry.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

import mujoco
import numpy as np
import yourdfpy

sys.path.insert(0, str(Path(__file__).parent))
import audit_fixtures as fx
from mujoco_body import body_inertial

EXE = os.environ["POLYMASS_EXE"]


def audit(*args):
    result = subprocess.run(
        [EXE, "audit", *map(str, args)], capture_output=True, text=True, timeout=120, check=False
    )
    assert result.returncode >= 0, result.stderr
    return result


def computed_of(path, name):
    out = json.loads(audit("--json", path).stdout)
    return next(link for link in out["links"] if link["name"] == name)["computed"]


def assert_inertial(mass, com, inertia, computed):
    np.testing.assert_allclose(mass, computed["mass"], rtol=1e-12)
    np.testing.assert_allclose(com, computed["center_of_mass"], rtol=0, atol=1e-12)
    scale = max(abs(x) for row in computed["inertia"] for x in row)
    np.testing.assert_allclose(inertia, computed["inertia"], rtol=0, atol=1e-9 * scale)


def test_yourdfpy_reads_the_fixed_urdf(tmp_path):
    fx.write_stl(tmp_path / "box.stl", fx.box_corners())
    inertia = fx.box_inertia(fx.MASS)
    inertia[0][0], inertia[2][2] = inertia[2][2], inertia[0][0]
    geometry = '<geometry><mesh filename="box.stl"/></geometry>'
    path = tmp_path / "robot.urdf"
    path.write_text(fx.urdf([("base", fx.urdf_inertial(fx.MASS, [0, 0, 0], inertia), geometry)]))
    fixed = tmp_path / "fixed.urdf"
    assert "1 inertial(s) replaced" in audit(path, "--fix", fixed).stderr
    robot = yourdfpy.URDF.load(str(fixed), load_meshes=False, build_scene_graph=False)
    inertial = robot.link_map["base"].inertial
    origin = np.asarray(inertial.origin)
    np.testing.assert_array_equal(origin[:3, :3], np.eye(3))
    computed = computed_of(path, "base")
    assert_inertial(inertial.mass, origin[:3, 3], inertial.inertia, computed)
    np.testing.assert_allclose(computed["inertia"], fx.box_inertia(fx.MASS), rtol=1e-12)


# Bodies of the class "part": the mesh turned by euler 30 90 0 (degrees, in
# the sequence zyx of the moving frame) and moved; a box turned by a
# quaternion, a capsule along a fromto segment in a <frame>.
MJCF = fx.mjcf(
    'angle="degree" eulerseq="zyx"',
    'euler="30 90 0" pos="0.125 0 0.5" density="1000"',
    """    <body name="declared" childclass="part">
      <inertial pos="0 0 0" mass="3" diaginertia="1 1 1"/>
      <geom mesh="box"/>
      <geom type="box" size="0.125 0.25 0.5" pos="1 0 0" quat="0 0 0 1"/>
    </body>
    <body name="inferred" pos="5 0 0" childclass="part">
      <geom mesh="box"/>
      <frame pos="0 0.25 0" euler="0 0 30">
        <geom class="robot" type="capsule" fromto="1 0 0 1 0.5 0.5" size="0.125"/>
      </frame>
    </body>""",
)


def test_mujoco_reads_the_fixed_mjcf_and_agrees_on_geometry(tmp_path):
    fx.write_obj(tmp_path / "assets" / "box.obj", fx.box_corners(unit=2.0))
    path = tmp_path / "robot.xml"
    path.write_text(MJCF)
    # MuJoCo's own inertia of a body from its geoms (density 1000), against
    # the audit's geometry at that density.
    mass, com, inertia = body_inertial(mujoco.MjModel.from_xml_path(str(path)), "inferred")
    assert_inertial(mass, com, inertia, computed_of(path, "inferred"))
    fixed = tmp_path / "fixed.xml"
    assert "1 inertial(s) replaced" in audit(path, "--fix", fixed).stderr
    # The fixed inertial keeps the declared mass: the computed one (the geoms
    # at their density) brought to it.
    mass, com, inertia = body_inertial(mujoco.MjModel.from_xml_path(str(fixed)), "declared")
    computed = computed_of(path, "declared")
    ratio = 3.0 / computed["mass"]
    computed["inertia"] = [[x * ratio for x in row] for row in computed["inertia"]]
    computed["mass"] = 3.0
    assert_inertial(mass, com, inertia, computed)
