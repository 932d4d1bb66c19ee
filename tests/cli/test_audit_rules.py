"""Tests of polymass audit's reading of MuJoCo's mass rules without MuJoCo
(tests/cli/test_audit_mujoco.py compares them with MuJoCo itself), of its
mirror pairs, of what it says about files it cannot audit as they are, and of
the Collada units note:

    POLYMASS_EXE=<polymass> POLYMASS_WORK_DIR=<scratch> python3 tests/cli/test_audit_rules.py
"""

import json
import math
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import audit_fixtures as fx
from test_audit import audit, fresh, kinds, link, run


def mjcf(worldbody, compiler="", assets=""):
    return f"""<mujoco>
  <compiler {compiler}/>
  <asset>{assets}</asset>
  <worldbody>{worldbody}</worldbody>
</mujoco>
"""


def box_inertial(mass, size, com=(0.0, 0.0, 0.0), scale=1.0):
    i = [[x * scale for x in row] for row in fx.box_inertia(mass, size)]
    return fx.urdf_inertial(mass, com, i)


def box_geometry(size):
    return f'<geometry><box size="{size[0]!r} {size[1]!r} {size[2]!r}"/></geometry>'


class Help(unittest.TestCase):
    def test_each_subcommand_prints_its_own_options(self):
        audit_help = run("audit", "--help")
        self.assertEqual(audit_help.returncode, 0)
        self.assertIn("Usage: polymass audit", audit_help.stdout)
        for option in ("--from", "--fail-on", "--fix", "--mass-from"):
            self.assertIn(option, audit_help.stdout)
        self.assertNotIn("--planarity-tolerance", audit_help.stdout)
        for command in ("check", "assembly"):
            result = run(command, "--help")
            self.assertEqual(result.returncode, 0)
            self.assertIn(f"Usage: polymass {command}", result.stdout)
            self.assertNotIn("--fail-on", result.stdout)
        top = run("--help").stdout
        self.assertIn("polymass - mass properties", top)
        self.assertNotIn("--fail-on", top)


class Refused(unittest.TestCase):
    def test_xacro_is_named_and_how_to_expand_it(self):
        directory = fresh("xacro")
        macro = """<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="leg" params="side"><link name="${side}_leg"/></xacro:macro>
  <xacro:leg side="left"/>
</robot>
"""
        for name in ("robot.urdf.xacro", "robot.urdf"):
            (directory / name).write_text(macro)
            result = run("audit", directory / name)
            self.assertEqual(result.returncode, 3, name)
            self.assertIn("a xacro file", result.stdout)
            self.assertIn(f"xacro {directory / name} > robot.urdf", result.stdout)
        # An expanded URDF that keeps the namespace declaration is a URDF.
        expanded = fx.urdf([("base", "", box_geometry(fx.SIZE))])
        expanded = expanded.replace('<robot name="test">', '<robot name="test" xmlns:xacro="x">')
        (directory / "expanded.urdf").write_text(expanded)
        result, out = audit(directory / "expanded.urdf")
        self.assertEqual([entry["name"] for entry in out["links"]], ["base"])

    def test_two_meshes_of_one_name_are_refused_as_mujoco_refuses_them(self):
        directory = fresh("duplicate_mesh")
        fx.write_obj(directory / "box.obj", fx.box_corners())
        fx.write_obj(directory / "other" / "box.obj", fx.box_corners())
        path = directory / "model.xml"
        # The second takes its name from its file: "box" again.
        assets = '<mesh name="box" file="box.obj"/><mesh file="other/box.obj"/>'
        path.write_text(mjcf('<body><geom type="mesh" mesh="box"/></body>', "", assets))
        result = run("audit", path)
        self.assertEqual(result.returncode, 3)
        self.assertIn("a second mesh named 'box'", result.stdout)


class MujocoRules(unittest.TestCase):
    def test_fromto_box_and_ellipsoid_take_size0_for_both_half_widths(self):
        path = fresh("fromto") / "model.xml"
        path.write_text(
            mjcf("""
    <body name="box"><geom type="box" size="0.02 0.015 0.08" fromto="0 0 0 0 0 0.16"/></body>
    <body name="ellipsoid">
      <geom type="ellipsoid" size="0.02 0.015 0.08" fromto="0 0 0 0.16 0 0"/>
    </body>""")
        )
        _, out = audit(path)
        self.assertAlmostEqual(
            link(out, "box")["computed"]["mass"], 1000 * 0.04 * 0.04 * 0.16, delta=1e-12
        )
        ellipsoid = link(out, "ellipsoid")["computed"]
        self.assertAlmostEqual(
            ellipsoid["mass"], 1000 * 4 / 3 * math.pi * 0.02 * 0.02 * 0.08, delta=1e-12
        )
        # Along x: the long axis, the smallest moment m (b^2 + c^2) / 5.
        moment = ellipsoid["mass"] * (0.02**2 + 0.02**2) / 5
        self.assertAlmostEqual(ellipsoid["inertia"][0][0] / moment, 1.0, delta=1e-12)

    def test_visual_geoms_weigh_and_groups_outside_the_range_do_not(self):
        path = fresh("groups") / "model.xml"
        path.write_text(
            mjcf(
                """
    <body name="b">
      <geom type="box" size="0.1 0.1 0.1" mass="2"/>
      <geom type="box" size="0.1 0.1 0.1" pos="1 0 0" mass="1" contype="0" conaffinity="0"/>
      <geom type="box" size="0.1 0.1 0.1" pos="0 1 0" mass="5" group="4"/>
    </body>""",
                'inertiagrouprange="0 3"',
            )
        )
        _, out = audit(path)
        computed = link(out, "b")["computed"]
        self.assertEqual(link(out, "b")["geometry"], "weighed")
        self.assertAlmostEqual(computed["mass"], 3.0, delta=1e-12)
        self.assertAlmostEqual(computed["center_of_mass"][0], 1 / 3, delta=1e-12)
        self.assertIn("1 geom(s) of other groups not weighed", " ".join(computed["rules"]))

    def test_fix_writes_the_geometry_not_mujocos_bounds(self):
        """boundinertia raises MuJoCo's computed moments; --fix writes the
        geometry's at the declared mass, MuJoCo bounding the file itself."""
        directory = fresh("fix_bounds")
        path = directory / "model.xml"
        body = """
    <body name="b">
      <inertial pos="0 0 0" mass="2" diaginertia="1 1 1"/>
      <geom type="box" size="0.1 0.2 0.3"/>
    </body>"""
        path.write_text(mjcf(body, 'boundinertia="5"'))
        _, out = audit(path)
        self.assertIn("boundinertia", " ".join(link(out, "b")["computed"]["rules"]))
        self.assertEqual(link(out, "b")["computed"]["principal_moments"], [5.0, 5.0, 5.0])
        run("audit", path, "--fix", directory / "fixed.xml")
        fixed = (directory / "fixed.xml").read_text()
        full = fixed.split('fullinertia="')[1].split('"')[0].split()
        expected = [
            2 * (0.4**2 + 0.6**2) / 12,
            2 * (0.2**2 + 0.6**2) / 12,
            2 * (0.2**2 + 0.4**2) / 12,
        ]
        for value, want in zip(map(float, full[:3]), expected):
            self.assertAlmostEqual(value / want, 1.0, delta=1e-12)

    def test_a_moving_body_without_mass(self):
        path = fresh("massless") / "model.xml"
        path.write_text(
            mjcf(
                """
    <body name="carried"><joint/>
      <body name="welded"><geom type="sphere" size="0.1"/></body>
    </body>
    <body name="alone"><freejoint/>
      <body name="moving_child"><joint/><geom type="sphere" size="0.1"/></body>
    </body>
    <body name="weightless"><joint/><geom type="sphere" size="0.1" density="0"/></body>
    <body name="unknown"><joint/><geom type="mesh" mesh="missing"/></body>
    <body name="field"><joint/><geom type="hfield" hfield="terrain"/></body>
    <body name="static"/>""",
                assets='<mesh name="missing" file="missing.obj"/>',
            )
        )
        result, out = audit(path)
        self.assertEqual(result.returncode, 1)
        flagged = [
            entry["name"] for entry in out["links"] if "massless_moving_body" in kinds(entry)
        ]
        # "unknown": its mesh cannot be read, so its mass is not known to be 0;
        # nor is "field"'s, whose height field MuJoCo weighs.
        self.assertEqual(flagged, ["alone", "weightless"])
        self.assertIn("unreadable_mesh", kinds(link(out, "unknown")))


class Judged(unittest.TestCase):
    def urdf(self, name, inertial, geometry):
        path = fresh(name) / "robot.urdf"
        path.write_text(fx.urdf([("base", inertial, geometry)]))
        return audit(path)[1]

    def test_placeholder_mass_on_a_primitive_is_named_so(self):
        out = self.urdf("placeholder", box_inertial(1e-5, fx.SIZE), box_geometry(fx.SIZE))
        finding = link(out, "base")["findings"][0]
        self.assertEqual(finding["kind"], "placeholder_inertial")
        self.assertIn("a placeholder", finding["message"])
        self.assertNotIn("mesh", finding["message"])

    def test_lengths_off_only_for_a_unit_factor(self):
        # Moments 0.8 times the geometry's: no unit explains it.
        out = self.urdf("factor", box_inertial(fx.MASS, fx.SIZE, scale=0.8), box_geometry(fx.SIZE))
        message = link(out, "base")["findings"][0]["message"]
        self.assertIn("every principal moment is 0.8 times the geometry's", message)
        self.assertNotIn("lengths off", message)
        # A millionth: lengths 1000 times too small, millimetres and metres.
        out = self.urdf(
            "factor_mm", box_inertial(fx.MASS, fx.SIZE, scale=1e-6), box_geometry(fx.SIZE)
        )
        self.assertIn("lengths off by a factor 0.001", link(out, "base")["findings"][0]["message"])


class MirrorPairs(unittest.TestCase):
    def write(self, directory, right_ixy_sign, names=("left_leg", "right_leg")):
        """Two links: an L prism and its mirror image across xz, each
        declaring its computed inertial, the second one's ixy times
        right_ixy_sign."""
        fx.write_l_prism(directory / "left.obj", section=fx.NOTCHED_SECTION)
        fx.write_l_prism(directory / "right.obj", mirror_y=True, section=fx.NOTCHED_SECTION)
        geometries = [
            f'<geometry><mesh filename="{side}.obj"/></geometry>' for side in ("left", "right")
        ]
        path = directory / "robot.urdf"
        path.write_text(
            fx.urdf([(name, "", geometry) for name, geometry in zip(names, geometries)])
        )
        _, out = audit(path, "--density", "1000")
        links = []
        for k, (name, geometry) in enumerate(zip(names, geometries)):
            c = link(out, name)["computed"]
            i = [row[:] for row in c["inertia"]]
            if k == 1:
                i[0][1] = i[1][0] = right_ixy_sign * i[0][1]
            links.append((name, fx.urdf_inertial(c["mass"], c["center_of_mass"], i), geometry))
        path.write_text(fx.urdf(links))
        return audit(path)[1]

    def test_a_product_of_inertia_whose_sign_breaks_the_mirror(self):
        out = self.write(fresh("mirror_wrong"), -1.0)
        self.assertEqual(kinds(link(out, "left_leg")), [])
        right = link(out, "right_leg")
        # Nothing else finds it: the moments and axes move too little.
        self.assertEqual(kinds(right), ["mirror_sign"])
        finding = right["findings"][0]
        self.assertEqual(finding["severity"], "error")
        self.assertIn("ixy", finding["message"])
        self.assertIn("'right_leg' has the sign its geometry does not", finding["message"])

    def test_mirrored_inertials_pass(self):
        out = self.write(fresh("mirror_right"), 1.0)
        for name in ("left_leg", "right_leg"):
            self.assertEqual(kinds(link(out, name)), [], name)

    def test_side_marks(self):
        paired = [
            ("l_hip", "r_hip"),
            ("hip_L", "hip_R"),
            ("FL_calf", "FR_calf"),
            ("LF_HIP", "RF_HIP"),
            ("Left-Foot", "Right-Foot"),
        ]
        for names in paired:
            out = self.write(fresh("sides"), -1.0, names)
            self.assertIn("mirror_sign", kinds(link(out, names[1])), names)
        # Names that mark no side, or the same side twice, pair nothing.
        for names in [("upper_leg", "lower_leg"), ("left_hip", "left_knee"), ("FL_hip", "FL_calf")]:
            out = self.write(fresh("sides"), -1.0, names)
            self.assertNotIn("mirror_sign", kinds(link(out, names[1])), names)


class ColladaUnits(unittest.TestCase):
    def test_one_consistent_note(self):
        """The Collada reader applies the file's <unit>: its lengths are
        metres, and no note says they are the file's units."""
        directory = fresh("collada_units")
        fx.write_dae(directory / "box.dae", fx.box_corners(), 0.001, "Z_UP")
        fx.write_stl(directory / "box.stl", fx.box_corners())
        alone = run(directory / "box.dae", "--json")
        self.assertIn("lengths in metres (the file's unit: u, 0.001 m)", alone.stderr)
        self.assertNotIn("not converted to metres", alone.stderr)
        self.assertIn("m^3", run(directory / "box.dae").stdout)
        mixed = run(directory / "box.dae", directory / "box.stl", "--json")
        self.assertIn("not converted to metres", mixed.stderr)
        self.assertIn("files that declare their unit (3MF, Collada) excepted", mixed.stderr)
        dae, stl = json.loads(mixed.stdout)["files"]
        self.assertEqual(dae["length_unit"], "m")
        self.assertNotIn("length_unit", stl)

    def test_units_do_not_scale_a_collada_file_twice(self):
        """--units is for files without a unit: a Collada file in millimetres
        keeps its <unit> (a note says --units was not applied), an STL beside
        it is converted."""
        directory = fresh("collada_and_units")
        fx.write_dae(directory / "box.dae", fx.box_corners(unit=0.001), 0.001, "Z_UP")
        fx.write_stl(directory / "box.stl", fx.box_corners())
        volume = math.prod(fx.SIZE)
        result = run("--units", "in", directory / "box.dae", directory / "box.stl", "--json")
        self.assertEqual(result.returncode, 0, result.stderr)
        dae, stl = json.loads(result.stdout)["files"]
        # Collada is read in single precision: 2^-24 of each coordinate.
        self.assertLessEqual(abs(dae["volume"] - volume), 1e-6 * volume)
        self.assertIn("--units not applied: the file declares its unit", dae["notes"])
        self.assertIn("--units not applied", result.stderr)
        self.assertLessEqual(abs(stl["volume"] - volume * 0.0254**3), 1e-6 * volume * 0.0254**3)
        self.assertNotIn("notes", stl)
        self.assertEqual([dae["length_unit"], stl["length_unit"]], ["m", "m"])


if __name__ == "__main__":
    unittest.main(verbosity=1)
