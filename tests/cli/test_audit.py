"""Tests of polymass audit, run by ctest:

    POLYMASS_EXE=<polymass> POLYMASS_WORK_DIR=<scratch> python3 tests/cli/test_audit.py

Each description (audit_fixtures.py) holds boxes of exact properties and one
planted error, and the finding it should raise is asserted; the JSON output is
parsed, never matched as text.
"""

import json
import os
import shutil
import subprocess
import sys
import unittest
from pathlib import Path

import audit_fixtures as fx

EXE = os.environ["POLYMASS_EXE"]
WORK = Path(os.environ["POLYMASS_WORK_DIR"]) / "audit"
RTOL = 1e-12


def run(*args, env=None):
    result = subprocess.run(
        [EXE, *map(str, args)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
        env={**os.environ, **(env or {})},
    )
    assert result.returncode >= 0, f"polymass {args} crashed\n{result.stderr}"
    assert "Sanitizer" not in result.stderr and "runtime error" not in result.stderr, result.stderr
    return result


def audit(path, *args, env=None):
    result = run("audit", "--json", path, *args, env=env)
    return result, json.loads(result.stdout)


def link(document, name):
    return next(entry for entry in document["links"] if entry["name"] == name)


def kinds(entry):
    return [finding["kind"] for finding in entry["findings"]]


def fresh(name):
    directory = WORK / name
    shutil.rmtree(directory, ignore_errors=True)
    directory.mkdir(parents=True)
    return directory


class AuditCase(unittest.TestCase):
    def assert_close(self, actual, expected, scale, what):
        self.assertLessEqual(
            abs(actual - expected), RTOL * scale, f"{what}: {actual} != {expected}"
        )

    def assert_computed(self, computed, mass, com, inertia):
        self.assert_close(computed["mass"], mass, mass, "mass")
        for i in range(3):
            self.assert_close(computed["center_of_mass"][i], com[i], 1.0, f"com[{i}]")
            for j in range(3):
                self.assert_close(
                    computed["inertia"][i][j], inertia[i][j], inertia[2][2], f"inertia[{i}][{j}]"
                )

    def box_urdf(self, name, inertial, mesh="box.obj", geometry=None, writer=fx.write_obj):
        directory = fresh(name)
        writer(directory / mesh, fx.box_corners())
        geometry = geometry or f'<geometry><mesh filename="{mesh}"/></geometry>'
        path = directory / "robot.urdf"
        path.write_text(fx.urdf([("base", inertial, geometry)]))
        return path

    def correct_inertial(self):
        return fx.urdf_inertial(fx.MASS, fx.centre(), fx.box_inertia(fx.MASS))


class Declared(AuditCase):
    def test_correct_inertial_has_no_finding_and_exact_computed(self):
        result, out = audit(self.box_urdf("correct", self.correct_inertial()))
        self.assertEqual(result.returncode, 0, result.stdout)
        entry = link(out, "base")
        rules = ["collision geometry at a uniform density: the declared mass"]
        self.assertEqual(entry["computed"]["rules"], rules)
        self.assertEqual(entry["findings"], [])
        self.assertEqual(entry["geometry"], "collision")
        self.assert_computed(entry["computed"], fx.MASS, fx.centre(), fx.box_inertia(fx.MASS))
        self.assert_close(entry["computed"]["volume"], 0.25 * 0.125 * 0.5, 1.0, "volume")

    def test_swapped_ixx_izz(self):
        inertia = fx.box_inertia(fx.MASS)
        inertia[0][0], inertia[2][2] = inertia[2][2], inertia[0][0]
        result, out = audit(
            self.box_urdf("swapped", fx.urdf_inertial(fx.MASS, fx.centre(), inertia))
        )
        self.assertEqual(result.returncode, 1)
        finding = link(out, "base")["findings"][0]
        self.assertEqual(finding["kind"], "inertia_differs")
        self.assertEqual(finding["severity"], "error")
        self.assertIn("ixx and izz swapped", finding["message"])

    def test_tensor_in_the_cad_frame(self):
        about_origin = fx.about_point(fx.box_inertia(fx.MASS), fx.MASS, fx.centre(), [0, 0, 0])
        _, out = audit(self.box_urdf("cad", fx.urdf_inertial(fx.MASS, fx.centre(), about_origin)))
        finding = link(out, "base")["findings"][0]
        self.assertEqual(finding["kind"], "inertia_differs")
        self.assertIn("about the link origin", finding["message"])

    def test_triangle_inequality_violated_by_3_percent(self):
        # Positive definite, yet izz = (ixx + iyy) / 0.97: (a+b-c)/c = -0.03.
        a, b = 0.0625, 0.078125
        inertia = [[a, 0, 0], [0, b, 0], [0, 0, (a + b) / 0.97]]
        result, out = audit(
            self.box_urdf("triangle", fx.urdf_inertial(fx.MASS, fx.centre(), inertia))
        )
        self.assertEqual(result.returncode, 1)
        finding = link(out, "base")["findings"][0]
        self.assertEqual(finding["kind"], "tensor_not_physical")
        self.assertIn("(a+b-c)/c = -0.03", finding["message"])

    def test_massless_static_link(self):
        zero = [[0, 0, 0], [0, 0, 0], [0, 0, 0]]
        result, out = audit(self.box_urdf("massless", fx.urdf_inertial(0.0, [0, 0, 0], zero)))
        self.assertEqual(result.returncode, 0)
        self.assertEqual(kinds(link(out, "base")), ["massless"])

    def test_not_positive_definite(self):
        inertia = [[1, 0, 0], [0, 1, 0], [0, 0, -1]]
        _, out = audit(self.box_urdf("indefinite", fx.urdf_inertial(fx.MASS, fx.centre(), inertia)))
        self.assertIn("tensor_not_physical", kinds(link(out, "base")))

    def test_mass_in_grams(self):
        grams = fx.MASS * 1000
        inertial = fx.urdf_inertial(grams, fx.centre(), fx.box_inertia(grams))
        _, out = audit(self.box_urdf("grams", inertial))
        entry = link(out, "base")
        self.assertEqual(kinds(entry), ["density_implausible"])
        self.assertIn("grams", entry["findings"][0]["message"])

    def test_centre_of_mass_off_and_outside(self):
        com = fx.centre()
        inertial = fx.urdf_inertial(
            fx.MASS, [com[0], com[1], com[2] + 0.25], fx.box_inertia(fx.MASS)
        )
        _, out = audit(self.box_urdf("com", inertial))
        entry = link(out, "base")
        self.assertIn("com_differs", kinds(entry))
        inertial = fx.urdf_inertial(fx.MASS, [0, 0, 0], fx.box_inertia(fx.MASS))
        _, out = audit(self.box_urdf("com_outside", inertial))
        self.assertIn("com_outside_geometry", kinds(link(out, "base")))

    def test_rotated_inertial_frame_is_read(self):
        # The box tensor given in a frame turned 90 degrees about z: ixx and
        # iyy exchange, and rpy turns them back.
        i = fx.box_inertia(fx.MASS)
        turned = [[i[1][1], 0, 0], [0, i[0][0], 0], [0, 0, i[2][2]]]
        inertial = fx.urdf_inertial(fx.MASS, fx.centre(), turned, rpy="0 0 1.5707963267948966")
        result, out = audit(self.box_urdf("rpy", inertial))
        self.assertEqual(link(out, "base")["findings"], [], result.stdout)


class Geometry(AuditCase):
    def test_mesh_scale_applied_and_ignored(self):
        directory = fresh("scale")
        fx.write_stl(directory / "box_mm.stl", fx.box_corners(unit=0.001))
        geometry = '<geometry><mesh filename="box_mm.stl" scale="0.001 0.001 0.001"/></geometry>'
        path = directory / "robot.urdf"
        path.write_text(fx.urdf([("base", self.correct_inertial(), geometry)]))
        _, out = audit(path)
        self.assertEqual(link(out, "base")["findings"], [])
        # The planted error: the inertia worked out on the mesh in millimetres.
        wrong = fx.box_inertia(fx.MASS, [s * 1000 for s in fx.SIZE])
        com = [c * 1000 for c in fx.centre()]
        path.write_text(fx.urdf([("base", fx.urdf_inertial(fx.MASS, com, wrong), geometry)]))
        _, out = audit(path)
        entry = link(out, "base")
        self.assertIn("inertia_differs", kinds(entry))
        message = next(f for f in entry["findings"] if f["kind"] == "inertia_differs")["message"]
        self.assertIn("lengths off by a factor 1000", message)

    def test_scales_out_of_range_are_findings(self):
        directory = fresh("scale_range")
        fx.write_stl(directory / "box.stl", fx.box_corners())
        for scale in ("1e-300 1e-300 1e-300", "1e300 1e300 1e300", "0 1 1"):
            geometry = f'<geometry><mesh filename="box.stl" scale="{scale}"/></geometry>'
            path = directory / "robot.urdf"
            path.write_text(fx.urdf([("base", self.correct_inertial(), geometry)]))
            result, out = audit(path)
            self.assertEqual(result.returncode, 1, scale)
            self.assertEqual(kinds(link(out, "base")), ["bad_geometry"], scale)

    def test_mesh_in_millimetres_read_as_metres(self):
        directory = fresh("mm")
        fx.write_stl(directory / "box_mm.stl", fx.box_corners(unit=0.001))
        path = directory / "robot.urdf"
        geometry = '<geometry><mesh filename="box_mm.stl"/></geometry>'
        path.write_text(fx.urdf([("base", self.correct_inertial(), geometry)]))
        _, out = audit(path)
        finding = next(
            f for f in link(out, "base")["findings"] if f["kind"] == "density_implausible"
        )
        self.assertIn("millimetres read as metres", finding["message"])

    def test_primitives_and_several_geometries(self):
        # A box primitive and a cylinder, side by side along x; the inertial
        # is exact for the pair (volumes weigh the mass).
        directory = fresh("primitives")
        path = directory / "robot.urdf"
        geometry = (
            '<geometry><box size="0.25 0.125 0.5"/></geometry>\n    </collision>\n'
            '    <collision>\n      <origin xyz="1 0 0" rpy="0 1.5707963267948966 0"/>\n'
            '      <geometry><cylinder radius="0.125" length="0.5"/></geometry>'
        )
        import math

        v_box = 0.25 * 0.125 * 0.5
        v_cyl = math.pi * 0.125**2 * 0.5
        mass = 30.0
        density = mass / (v_box + v_cyl)
        m_box, m_cyl = density * v_box, density * v_cyl
        com = [m_cyl * 1.0 / mass, 0.0, 0.0]
        box = fx.about_point(fx.box_inertia(m_box), m_box, [0, 0, 0], com)
        # The cylinder's axis is turned from z to x.
        r, h = 0.125, 0.5
        axial, transverse = m_cyl * r * r / 2, m_cyl * (3 * r * r + h * h) / 12
        cyl = fx.about_point(
            [[axial, 0, 0], [0, transverse, 0], [0, 0, transverse]], m_cyl, [1, 0, 0], com
        )
        total = [[box[i][j] + cyl[i][j] for j in range(3)] for i in range(3)]
        path.write_text(fx.urdf([("base", fx.urdf_inertial(mass, com, total), geometry)]))
        result, out = audit(path)
        entry = link(out, "base")
        self.assertEqual(entry["findings"], [], result.stdout)
        self.assert_computed(entry["computed"], mass, com, total)

    def test_visual_geometry_on_request_and_as_fallback(self):
        directory = fresh("visual")
        fx.write_obj(directory / "box.obj", fx.box_corners())
        text = fx.urdf([("base", self.correct_inertial(), "")]).replace(
            "  </link>",
            '    <visual><geometry><mesh filename="box.obj"/></geometry></visual>\n  </link>',
        )
        path = directory / "robot.urdf"
        path.write_text(text)
        _, out = audit(path)
        entry = link(out, "base")
        self.assertEqual(entry["geometry"], "visual")
        self.assertEqual(kinds(entry), ["geometry_source"])
        _, out = audit(path, "--from", "visual")
        self.assertEqual(link(out, "base")["findings"], [])

    def test_package_uri_upward_and_through_ros_package_path(self):
        root = fresh("package")
        package = root / "src" / "my_robot"
        package.mkdir(parents=True)
        (package / "package.xml").write_text(
            "<package format='3'><name>my_robot</name></package>\n"
        )
        fx.write_stl(package / "meshes" / "box.stl", fx.box_corners())
        geometry = '<geometry><mesh filename="package://my_robot/meshes/box.stl"/></geometry>'
        (package / "urdf").mkdir()
        path = package / "urdf" / "robot.urdf"
        path.write_text(fx.urdf([("base", self.correct_inertial(), geometry)]))
        _, out = audit(path)
        self.assertEqual(link(out, "base")["findings"], [])
        # Elsewhere, the package is found only through ROS_PACKAGE_PATH.
        elsewhere = fresh("package_elsewhere") / "robot.urdf"
        elsewhere.write_text(path.read_text())
        _, out = audit(elsewhere, env={"ROS_PACKAGE_PATH": str(root / "src")})
        self.assertEqual(link(out, "base")["findings"], [])
        result, out = audit(elsewhere, env={"ROS_PACKAGE_PATH": ""})
        self.assertEqual(result.returncode, 1)
        finding = link(out, "base")["findings"][0]
        self.assertEqual(finding["kind"], "unreadable_mesh")
        self.assertIn("package 'my_robot'", finding["message"])

    def test_collada_mesh_with_units_and_up_axis(self):
        directory = fresh("collada")
        # Millimetres, Y up: the file's y is the robot's z.
        corners = [(x * 1000, z * 1000, -y * 1000) for x, y, z in fx.box_corners()]
        fx.write_dae(directory / "box.dae", corners, 0.001, "Y_UP")
        geometry = '<geometry><mesh filename="box.dae"/></geometry>'
        path = directory / "robot.urdf"
        path.write_text(fx.urdf([("base", self.correct_inertial(), geometry)]))
        result, out = audit(path)
        entry = link(out, "base")
        self.assertEqual(entry["findings"], [], result.stdout)
        self.assert_computed(entry["computed"], fx.MASS, fx.centre(), fx.box_inertia(fx.MASS))
        # And the tool reads it as any mesh.
        plain = json.loads(run("--json", directory / "box.dae").stdout)
        self.assert_close(plain["volume"], 0.25 * 0.125 * 0.5, 1.0, "volume")

    def test_unreadable_and_open_meshes(self):
        directory = fresh("broken")
        fx.write_obj(directory / "open.obj", fx.box_corners(), fx.QUADS[:-1])
        fx.write_obj(directory / "flat.obj", fx.box_corners(), fx.QUADS[:1])
        path = directory / "robot.urdf"
        path.write_text(
            fx.urdf(
                [
                    (
                        "missing",
                        self.correct_inertial(),
                        '<geometry><mesh filename="no.stl"/></geometry>',
                    ),
                    (
                        "open",
                        self.correct_inertial(),
                        '<geometry><mesh filename="open.obj"/></geometry>',
                    ),
                    (
                        "flat",
                        self.correct_inertial(),
                        '<geometry><mesh filename="flat.obj"/></geometry>',
                    ),
                    ("bare", "", '<geometry><box size="1 1 1"/></geometry>'),
                    ("massonly", self.correct_inertial(), ""),
                ]
            )
        )
        result, out = audit(path)
        self.assertEqual(result.returncode, 1)
        self.assertEqual(kinds(link(out, "missing")), ["unreadable_mesh"])
        # The open box (its last quad missing) is measured repaired, its hole
        # capped by the missing quad exactly; the finding says so, with the
        # bound, and the declared inertial (correct) matches.
        open_link = link(out, "open")
        self.assertEqual(kinds(open_link), ["approximated_geometry"])
        self.assertIn("open", open_link["findings"][0]["message"])
        self.assertIn("measured as repaired: 1 holes capped", open_link["findings"][0]["message"])
        self.assertIn("off by at most", open_link["findings"][0]["message"])
        self.assertEqual(open_link["findings"][0]["severity"], "warning")
        self.assert_computed(open_link["computed"], fx.MASS, fx.centre(), fx.box_inertia(fx.MASS))
        # A single quad has no volume to repair nor a hull: not a solid.
        self.assertEqual(kinds(link(out, "flat")), ["not_a_solid"])
        self.assertIn("not measured: solid:", link(out, "flat")["findings"][0]["message"])
        self.assertIsNone(link(out, "flat")["computed"])
        self.assertEqual(kinds(link(out, "bare")), ["no_inertial"])
        self.assertEqual(link(out, "bare")["computed"]["density"], 1000)
        self.assertEqual(kinds(link(out, "massonly")), ["no_geometry"])
        self.assertEqual(run("audit", path, "--fail-on", "warning").returncode, 1)
        self.assertEqual(run("audit", directory / "none.urdf").returncode, 3)
        self.assertEqual(run("audit", path, "--fail-on", "fatal").returncode, 2)
        self.assertEqual(run("audit", path, "--density", "steel=7850").returncode, 2)

    def test_a_mesh_of_parts_resting_on_each_other_is_measured_exactly(self):
        # The box as two OBJ objects, its lower and upper halves, resting on
        # each other: measured as `polymass FILE` answers it, the exact sum of
        # the halves (welded together, their shared edges would be used by
        # four faces, and the mesh only approximated by a repair or a hull).
        directory = fresh("halves")
        size, low = fx.SIZE, fx.LOW
        half = (size[0], size[1], size[2] / 2)
        lines = []
        for k in range(2):
            lines.append(f"o half{k}")
            corners = fx.box_corners(half, (low[0], low[1], low[2] + k * half[2]))
            lines += [f"v {x!r} {y!r} {z!r}" for x, y, z in corners]
            lines += ["f " + " ".join(str(1 + 8 * k + i) for i in f) for f in fx.QUADS]
        (directory / "halves.obj").write_text("\n".join(lines) + "\n")
        path = directory / "robot.urdf"
        geometry = '<geometry><mesh filename="halves.obj"/></geometry>'
        path.write_text(fx.urdf([("base", self.correct_inertial(), geometry)]))
        result, out = audit(path)
        self.assertEqual(result.returncode, 0, result.stderr)
        base = link(out, "base")
        self.assertEqual(kinds(base), [])
        self.assert_computed(base["computed"], fx.MASS, fx.centre(), fx.box_inertia(fx.MASS))


class Sdf(AuditCase):
    def test_model_uri_and_a_centre_of_mass_off(self):
        root = fresh("sdf")
        model = root / "models" / "crate"
        fx.write_stl(model / "meshes" / "box.stl", fx.box_corners())
        com = fx.centre()
        i = fx.box_inertia(fx.MASS)
        (model / "model.sdf").write_text(f"""<?xml version="1.0"?>
<sdf version="1.9">
  <model name="crate">
    <link name="body">
      <inertial>
        <pose>{com[0]} {com[1]} {com[2] + 0.125} 0 0 0</pose>
        <mass>{fx.MASS}</mass>
        <inertia><ixx>{i[0][0]!r}</ixx><iyy>{i[1][1]!r}</iyy><izz>{i[2][2]!r}</izz>
          <ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia>
      </inertial>
      <collision name="c">
        <geometry><mesh><uri>model://crate/meshes/box.stl</uri></mesh></geometry>
      </collision>
    </link>
  </model>
</sdf>
""")
        _, out = audit(model / "model.sdf")
        entry = link(out, "body")
        self.assertEqual(out["format"], "sdf")
        self.assertEqual(kinds(entry), ["com_differs"])
        self.assert_computed(entry["computed"], fx.MASS, com, i)
        elsewhere = fresh("sdf_elsewhere") / "model.sdf"
        elsewhere.write_text((model / "model.sdf").read_text())
        _, out = audit(elsewhere, env={"GZ_SIM_RESOURCE_PATH": str(root / "models")})
        self.assertEqual(kinds(link(out, "body")), ["com_differs"])

    def test_capsule_and_ellipsoid_in_closed_form(self):
        import math

        directory = fresh("sdf_shapes")
        r, h, m = 0.25, 1.0, 500.0
        v_cyl, v_sph = math.pi * r * r * h, 4 / 3 * math.pi * r**3
        # Capsule: cylinder plus two hemispheres about the centre.
        rho = m / (v_cyl + v_sph)
        izz = rho * (v_cyl * r * r / 2 + v_sph * 2 * r * r / 5)
        ixx = rho * (
            v_cyl * (r * r / 4 + h * h / 12)
            + v_sph * r * r / 5
            + math.pi * r**3 * h * h / 3
            + math.pi * r**4 * h / 2
            + 4 / 15 * math.pi * r**5
        )
        a, b, c = 0.5, 0.25, 0.125
        ellipsoid = [m * (b * b + c * c) / 5, m * (a * a + c * c) / 5, m * (a * a + b * b) / 5]
        links = ""
        for name, shape, moments in [
            (
                "capsule",
                f"<capsule><radius>{r}</radius><length>{h}</length></capsule>",
                [ixx, ixx, izz],
            ),
            ("ellipsoid", f"<ellipsoid><radii>{a} {b} {c}</radii></ellipsoid>", ellipsoid),
        ]:
            links += f"""
    <link name="{name}">
      <inertial><mass>{m}</mass><inertia><ixx>{moments[0]!r}</ixx><iyy>{moments[1]!r}</iyy>
        <izz>{moments[2]!r}</izz></inertia></inertial>
      <collision name="c"><geometry>{shape}</geometry></collision>
    </link>"""
        path = directory / "shapes.sdf"
        path.write_text(f'<sdf version="1.9"><model name="m">{links}\n  </model></sdf>\n')
        _, out = audit(path)
        for name, moments in [("capsule", [ixx, ixx, izz]), ("ellipsoid", ellipsoid)]:
            entry = link(out, name)
            self.assertEqual(entry["findings"], [], name)
            diagonal = [[moments[i] if i == j else 0 for j in range(3)] for i in range(3)]
            self.assert_computed(entry["computed"], m, [0, 0, 0], diagonal)


def write_mjcf_model(directory, declared_quat):
    """A body with a mesh geom placed by its class (a nested default chosen by
    the body's childclass): euler 90 0 0 in degrees turns the box's y onto z,
    pos moves it 0.125 along x. The mesh is under meshdir at half size, and
    its asset's class scales it by 2."""
    fx.write_obj(directory / "assets" / "box.obj", fx.box_corners(unit=2.0))
    i = fx.box_inertia(fx.MASS)
    # The box turned by +90 degrees about x: y -> z, z -> -y.
    c = fx.centre()
    com = [c[0] + 0.125, -c[2], c[1]]
    diag = f"{i[0][0]!r} {i[2][2]!r} {i[1][1]!r}"
    body = f"""    <body name="arm" childclass="part">
      <!-- the inertial the test plants an error in -->
      <inertial pos="{com[0]!r} {com[1]!r} {com[2]!r}" mass="{fx.MASS}" diaginertia="{diag}"
                quat="{declared_quat}"/>
      <geom mesh="box"/>
    </body>"""
    path = directory / "robot.xml"
    path.write_text(fx.mjcf('angle="degree"', 'euler="90 0 0" pos="0.125 0 0"', body))
    return path, com


class Mjcf(AuditCase):
    def test_default_classes_meshdir_and_scale(self):
        directory = fresh("mjcf")
        path, com = write_mjcf_model(directory, "1 0 0 0")
        result, out = audit(path)
        entry = link(out, "arm")
        self.assertEqual(out["format"], "mjcf")
        self.assertEqual(entry["findings"], [], result.stdout)
        # Computed as MuJoCo infers it: the geom at its density (1000).
        mass = 1000 * fx.SIZE[0] * fx.SIZE[1] * fx.SIZE[2]
        i = fx.box_inertia(mass)
        turned = [[i[0][0], 0, 0], [0, i[2][2], 0], [0, 0, i[1][1]]]
        self.assert_computed(entry["computed"], mass, com, turned)
        self.assertEqual(entry["mujoco_uses"], "declared")
        self.assertEqual(len(entry["computed"]["rules"]), 1)
        self.assertIn("mesh inertia legacy", entry["computed"]["rules"][0])

    def test_inertial_quat_turning_the_axes(self):
        directory = fresh("mjcf_quat")
        # 45 degrees about z: the x and y principal axes are off by 45.
        path, _ = write_mjcf_model(directory, "0.9238795325112867 0 0 0.3826834323650898")
        _, out = audit(path)
        finding = link(out, "arm")["findings"][0]
        self.assertEqual(finding["kind"], "inertia_differs")
        self.assertIn("principal axes differ by 45 degrees", finding["message"])

    def test_an_unreadable_inertial_is_a_finding_of_its_body(self):
        directory = fresh("mjcf_invalid")
        path, _ = write_mjcf_model(directory, "1 0 0 0")
        text = path.read_text()
        start = text.index('diaginertia="') + len('diaginertia="')
        path.write_text(text[:start] + text[text.index('"', start) :])
        result, out = audit(path)
        self.assertEqual(result.returncode, 1)
        entry = link(out, "arm")
        self.assertEqual(kinds(entry), ["invalid_element"])
        self.assertIn("diaginertia", entry["findings"][0]["message"])
        self.assertIsNone(entry["declared"])
        self.assertIsNotNone(entry["computed"])

    def test_sdf_inertia_entry_not_a_number_is_refused_not_a_crash(self):
        # Found by fuzz_audit: the entry threw inside Eigen's comma
        # initializer, which aborted (assertions on) as it unwound.
        path = fresh("sdf_bad_inertia") / "model.sdf"
        path.write_text(
            '<sdf version="1.9"><model name="m"><link name="l"><inertial><mass>1</mass>'
            "<inertia><ixx>1</ixx><iyy>one</iyy><izz>1</izz></inertia></inertial>"
            "</link></model></sdf>\n"
        )
        result = run("audit", "--json", path)
        self.assertIn(result.returncode, (1, 3))
        self.assertIn("iyy", result.stdout + result.stderr)

    def test_include_and_fix_leaves_an_included_inertial(self):
        directory = fresh("mjcf_include")
        path, _ = write_mjcf_model(directory, "1 0 0 0")
        text = path.read_text()
        start, end = text.index("    <body"), text.index("</body>") + len("</body>")
        (directory / "arm.xml").write_text(f"<mujoco>\n{text[start:end]}\n</mujoco>\n")
        path.write_text(text[:start] + '    <include file="arm.xml"/>' + text[end:])
        _, out = audit(path)
        self.assertEqual(link(out, "arm")["findings"], [])
        result = run("audit", path, "--fix", directory / "fixed.xml")
        self.assertIn("0 inertial(s) replaced", result.stderr)
        self.assertIn("arm: its <inertial> is not in this file", result.stderr)
        self.assertEqual((directory / "fixed.xml").read_text(), path.read_text())


class Fix(AuditCase):
    def check_fixed(self, path, fixed, *args):
        before = path.read_text()
        result = run("audit", path, "--fix", fixed, *args)
        self.assertIn("replaced", result.stderr)
        text = fixed.read_text()
        # Every byte outside the inertial elements kept.
        for keep in ("<!-- a comment --fix must keep -->", "<collision>"):
            self.assertEqual(before.count(keep), text.count(keep))
        self.assertEqual(before[: before.index("<inertial")], text[: text.index("<inertial")])
        start = before.index("<inertial")
        end = (
            before.index("</inertial>", start) + 11
            if "</inertial>" in before
            else before.index("/>", start) + 2
        )
        tail = before[end:]
        self.assertTrue(text.endswith(tail))
        result, out = audit(fixed)
        mismatch = {"inertia_differs", "com_differs", "com_outside_geometry", "tensor_not_physical"}
        for entry in out["links"]:
            self.assertFalse(mismatch & set(kinds(entry)), entry)
        return out

    def test_fix_urdf_keeps_mass_and_every_other_byte(self):
        inertia = fx.box_inertia(fx.MASS)
        inertia[0][0], inertia[2][2] = inertia[2][2], inertia[0][0]
        path = self.box_urdf("fix_urdf", fx.urdf_inertial(fx.MASS, [0, 0, 0], inertia))
        out = self.check_fixed(path, path.with_name("fixed.urdf"))
        entry = link(out, "base")
        self.assertEqual(entry["findings"], [])
        self.assertEqual(entry["declared"]["mass"], fx.MASS)
        self.assert_computed(entry["computed"], fx.MASS, fx.centre(), fx.box_inertia(fx.MASS))

    def test_fix_after_a_byte_order_mark(self):
        inertial = fx.urdf_inertial(fx.MASS, [0, 0, 0], fx.box_inertia(fx.MASS))
        path = self.box_urdf("fix_bom", inertial)
        path.write_bytes(b"\xef\xbb\xbf" + path.read_bytes())
        self.check_fixed(path, path.with_name("fixed.urdf"))
        self.assertTrue(path.with_name("fixed.urdf").read_bytes().startswith(b"\xef\xbb\xbf"))

    def test_fix_with_a_density(self):
        path = self.box_urdf("fix_density", self.correct_inertial())
        out = self.check_fixed(path, path.with_name("fixed.urdf"), "--density", "2000")
        mass = 2000 * 0.25 * 0.125 * 0.5
        self.assert_close(link(out, "base")["declared"]["mass"], mass, mass, "mass")

    def test_fix_mjcf(self):
        directory = fresh("fix_mjcf")
        path, _ = write_mjcf_model(directory, "0.5 0.5 0.5 0.5")
        out = self.check_fixed(path, directory / "fixed.xml")
        self.assertEqual(link(out, "arm")["findings"], [])

    def test_fix_refuses_several_files(self):
        result = run("audit", "a.urdf", "b.urdf", "--fix", "out.urdf")
        self.assertEqual(result.returncode, 2)


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).parent))
    unittest.main(verbosity=1)
