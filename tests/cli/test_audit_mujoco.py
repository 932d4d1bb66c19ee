"""polymass audit's MJCF inertials against MuJoCo's own compiler (pip's
`mujoco`, in the Python test venv: scripts/test-python.sh):

    POLYMASS_EXE=<polymass> python -m pytest tests/cli/test_audit_mujoco.py

Models written here exercise every mass rule the audit reads (geom density
and mass, visual geoms in and out of inertiagrouprange, fromto boxes and
ellipsoids, shellinertia primitives, mesh inertia exact / convex / shell,
nested defaults and childclass, boundmass, boundinertia, balanceinertia,
settotalmass, inertiafromgeom); MuJoCo compiles each, and every body's mass,
centre of mass and inertia tensor must be the audit's `computed` to 1e-9
relative.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

import mujoco
import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))
import audit_fixtures as fx
from mujoco_body import body_inertial

EXE = os.environ["POLYMASS_EXE"]
RTOL = 1e-9


@pytest.fixture(autouse=True)
def in_scratch(tmp_path, monkeypatch):
    """MuJoCo writes its warnings (settotalmass is deprecated in 4.0) to
    MUJOCO_LOG.TXT in the working directory: the test's own."""
    monkeypatch.chdir(tmp_path)


def audit_json(path):
    result = subprocess.run(
        [EXE, "audit", "--json", str(path)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert result.returncode in (0, 1), result.stderr
    return {link["name"]: link for link in json.loads(result.stdout)["links"]}


def assert_agree(path, names):
    model = mujoco.MjModel.from_xml_path(str(path))
    links = audit_json(path)
    for name in names:
        mass, com, inertia = body_inertial(model, name)
        computed = links[name]["computed"]
        assert computed is not None, (name, links[name]["findings"])
        assert computed["mass"] == pytest.approx(mass, rel=RTOL), name
        size = max(np.abs(com).max(), 1e-3)
        np.testing.assert_allclose(
            computed["center_of_mass"], com, rtol=0, atol=RTOL * size, err_msg=name
        )
        scale = np.abs(inertia).max()
        np.testing.assert_allclose(
            computed["inertia"], inertia, rtol=0, atol=RTOL * scale, err_msg=name
        )
    return links


def model(compiler, defaults, worldbody, assets=""):
    return f"""<mujoco model="rules">
  <compiler {compiler}/>
  <default>{defaults}</default>
  <asset>{assets}</asset>
  <worldbody>{worldbody}</worldbody>
</mujoco>
"""


PRIMITIVES = """
    <body name="box_fromto" pos="0.5 0 0">
      <geom type="box" size="0.02 0.015 0.08" fromto="0 0 0 0.03 0.04 0.12"/>
    </body>
    <body name="ellipsoid_fromto" pos="1 0 0">
      <geom type="ellipsoid" size="0.02 0.015 0.08" fromto="0.01 0 0 0 0.05 0.1"/>
    </body>
    <body name="mixed" pos="0 1 0" euler="10 20 30">
      <geom type="sphere" size="0.05" pos="0.1 0 0" density="500"/>
      <geom type="capsule" size="0.03 0.07" pos="0 0.1 0" euler="30 0 45"/>
      <geom type="cylinder" size="0.04 0.06" pos="0 0 0.1" mass="2.5" quat="1 0.2 0.3 0.4"/>
      <geom type="ellipsoid" size="0.03 0.05 0.02" pos="-0.1 0 0" axisangle="1 1 0 40"/>
      <geom type="box" size="0.03 0.02 0.01" pos="0 -0.1 0" zaxis="1 2 3"/>
      <geom type="sphere" size="0.1" pos="0 0 -0.2" mass="0"/>
      <geom type="sphere" size="0.1" pos="0 0 -0.2" density="0"/>
    </body>
    <body name="visual_in_and_out" pos="0 2 0">
      <geom type="box" size="0.05 0.05 0.05"/>
      <geom type="sphere" size="0.04" pos="0.2 0 0" contype="0" conaffinity="0" group="2"/>
      <geom type="sphere" size="0.3" pos="0 0.2 0" contype="0" conaffinity="0" group="3"/>
    </body>
    <body name="shells" pos="0 3 0">
      <geom type="sphere" size="0.05" pos="0.1 0 0" shellinertia="true"/>
      <geom type="box" size="0.03 0.02 0.05" pos="0 0.1 0" shellinertia="true" euler="0 30 0"/>
      <geom type="cylinder" size="0.03 0.05" pos="0 0 0.1" shellinertia="true" density="3"/>
      <geom type="capsule" size="0.02 0.06" pos="-0.1 0 0" shellinertia="true" euler="90 0 0"/>
      <geom type="ellipsoid" size="0.03 0.04 0.05" pos="0 -0.1 0" shellinertia="true"/>
    </body>
    <body name="light" pos="0 4 0">
      <joint/>
      <geom type="sphere" size="0.01" mass="1e-6"/>
    </body>
    <body name="classes" pos="0 5 0" childclass="part">
      <geom size="0.04 0.02 0.03"/>
      <geom class="heavy" size="0.02" pos="0.1 0 0"/>
      <body name="child_of_classes" pos="0.3 0 0">
        <geom size="0.01 0.02 0.03" pos="0 0.05 0"/>
      </body>
    </body>"""

CLASSES = """
    <default class="base">
      <geom density="300"/>
      <default class="part">
        <geom type="box" group="1"/>
        <default class="heavy">
          <geom type="sphere" density="7800"/>
        </default>
      </default>
    </default>"""


def test_primitives_with_every_geom_rule(tmp_path):
    path = tmp_path / "primitives.xml"
    compiler = 'inertiagrouprange="0 2" boundmass="1e-3" boundinertia="1e-7" balanceinertia="true"'
    path.write_text(model(compiler, CLASSES, PRIMITIVES))
    names = [
        "box_fromto",
        "ellipsoid_fromto",
        "mixed",
        "visual_in_and_out",
        "shells",
        "light",
        "classes",
        "child_of_classes",
    ]
    links = assert_agree(path, names)
    # The fromto box: MuJoCo's 0.02 for both half-widths, along a
    # segment 0.13 long.
    assert links["box_fromto"]["computed"]["mass"] == pytest.approx(
        1000 * 0.04 * 0.04 * 0.13, rel=1e-12
    )
    assert any("boundmass" in rule for rule in links["light"]["computed"]["rules"])
    assert any(
        "inertiagrouprange" in rule for rule in links["visual_in_and_out"]["computed"]["rules"]
    )


MESHES = """
    <mesh name="exact" file="l.obj" inertia="exact" scale="1 2 0.5"/>
    <mesh name="convex" file="l.obj" inertia="convex" scale="-1 1 1"/>
    <mesh name="shell" file="l.obj" inertia="shell" scale="2 1 1"/>
    <mesh class="exactly" name="by_class" file="l.obj"/>"""

MESH_BODIES = """
    <body name="mesh_exact" pos="0 0 1">
      <geom type="mesh" mesh="exact" pos="0.1 0 0" euler="0 0 90"/>
    </body>
    <body name="mesh_convex" pos="0 0 2">
      <geom type="mesh" mesh="convex"/>
    </body>
    <body name="mesh_shell" pos="0 0 3">
      <geom type="mesh" mesh="shell" density="2"/>
      <geom type="box" size="0.01 0.01 0.01"/>
    </body>
    <body name="mesh_by_class" pos="0 0 4">
      <geom type="mesh" mesh="by_class" mass="3"/>
    </body>"""


def test_meshes_in_each_inertia_mode(tmp_path):
    fx.write_l_prism(tmp_path / "l.obj")
    path = tmp_path / "meshes.xml"
    defaults = '<default class="exactly"><mesh inertia="exact" scale="0.5 0.5 0.5"/></default>'
    path.write_text(model("", defaults, MESH_BODIES, MESHES))
    assert_agree(path, ["mesh_exact", "mesh_convex", "mesh_shell", "mesh_by_class"])


def test_settotalmass_and_inertiafromgeom(tmp_path):
    worldbody = """
    <body name="declared">
      <inertial pos="0 0 0.1" mass="2" diaginertia="0.01 0.02 0.03"/>
      <geom type="box" size="0.1 0.1 0.1"/>
    </body>
    <body name="inferred" pos="1 0 0">
      <geom type="sphere" size="0.1"/>
      <geom type="capsule" size="0.02 0.1" pos="0 0 0.2"/>
    </body>"""
    path = tmp_path / "total.xml"
    path.write_text(model('settotalmass="10"', "", worldbody))
    links = assert_agree(path, ["inferred"])
    assert links["declared"]["mujoco_uses"] == "declared"
    assert "scaled_by_settotalmass" in [f["kind"] for f in links["declared"]["findings"]]
    # inertiafromgeom="true": the geoms' inertial replaces the declared one.
    path.write_text(model('inertiafromgeom="true"', "", worldbody))
    links = assert_agree(path, ["declared", "inferred"])
    assert links["declared"]["mujoco_uses"] == "computed"


def test_a_moving_body_without_mass_is_what_mujoco_refuses(tmp_path):
    worldbody = """
    <body name="empty"><joint/>
      <body name="fixed_child"><geom type="sphere" size="0.1"/></body>
    </body>
    <body name="nothing" pos="1 0 0"><joint/></body>"""
    path = tmp_path / "massless.xml"
    path.write_text(model("", "", worldbody))
    links = audit_json(path)
    kinds = {name: [f["kind"] for f in link["findings"]] for name, link in links.items()}
    # A body fixed to it carries the mass: MuJoCo accepts "empty".
    assert "massless_moving_body" not in kinds["empty"]
    assert "massless_moving_body" in kinds["nothing"]
    with pytest.raises(ValueError, match="mass and inertia of moving bodies"):
        mujoco.MjModel.from_xml_path(str(path))


def test_legacy_mesh_inertia_is_mujocos_figure_and_the_distance_is_said(tmp_path):
    """A mesh asset without inertia="..." keeps MuJoCo's default, legacy:
    the audit's computed is the exact solid (MuJoCo's figure with
    inertia="exact"), mujoco_legacy what MuJoCo compiles by default."""
    fx.write_l_prism(tmp_path / "l.obj", section=fx.U_SECTION, triangles=fx.U_TRIANGLES)
    worldbody = """
    <body name="legacy" pos="0 0 1">
      <geom type="mesh" mesh="l" pos="0.1 0 0" euler="0 30 90"/>
      <geom type="box" size="0.01 0.02 0.03" pos="0 0.2 0"/>
    </body>"""
    paths = {}
    for name, mode in (("legacy", ""), ("exact", 'inertia="exact"')):
        paths[name] = tmp_path / f"{name}.xml"
        paths[name].write_text(
            model("", "", worldbody, f'<mesh name="l" file="l.obj" scale="1 2 1" {mode}/>')
        )
    legacy_path = paths["legacy"]
    legacy, exact = (audit_json(paths[name])["legacy"] for name in ("legacy", "exact"))
    # The exact figure is the same either way, and MuJoCo's with inertia="exact".
    assert_agree(paths["exact"], ["legacy"])
    assert legacy["computed"] == exact["computed"] | {"rules": legacy["computed"]["rules"]}
    # MuJoCo's default compile is the legacy figure.
    mass, com, inertia = body_inertial(mujoco.MjModel.from_xml_path(str(legacy_path)), "legacy")
    figure = legacy["mujoco_legacy"]
    assert figure["mass"] == pytest.approx(mass, rel=RTOL)
    np.testing.assert_allclose(figure["center_of_mass"], com, rtol=0, atol=RTOL * np.abs(com).max())
    np.testing.assert_allclose(
        figure["inertia"], inertia, rtol=0, atol=RTOL * np.abs(inertia).max()
    )
    # The legacy rule counts the pyramids over the faces seen from behind.
    assert figure["mass"] > legacy["computed"]["mass"] * 1.01
    (finding,) = [f for f in legacy["findings"] if f["kind"] == "legacy_mesh_inertia"]
    assert "% off" in finding["message"] and 'inertia="exact"' in finding["message"]
    assert "mujoco_legacy" not in exact
