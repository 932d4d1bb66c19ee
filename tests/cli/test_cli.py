"""Tests of the polymass command-line tool, run by ctest:

    POLYMASS_EXE=<polymass> POLYMASS_SOURCE_DIR=<repo> POLYMASS_WORK_DIR=<scratch> \
        python3 tests/cli/test_cli.py

Every format is generated here (fixtures.py) for one solid whose exact
properties come from rational arithmetic (examples/data/generate.py), and the
tool's outputs are parsed back with json and xml.etree, never matched as text.
"""

import importlib.util
import json
import os
import re
import struct
import subprocess
import sys
import unittest
from pathlib import Path
from xml.etree import ElementTree

import fixtures

EXE = os.environ["POLYMASS_EXE"]
SOURCE = Path(os.environ["POLYMASS_SOURCE_DIR"])
WORK = Path(os.environ["POLYMASS_WORK_DIR"])

_spec = importlib.util.spec_from_file_location(
    "generate", SOURCE / "examples" / "data" / "generate.py"
)
generate = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(generate)

EXIT_OK, EXIT_INVALID_MESH, EXIT_USAGE, EXIT_UNREADABLE = 0, 1, 2, 3
RTOL = 1e-12


def run(*args):
    result = subprocess.run(
        [EXE, *map(str, args)], capture_output=True, text=True, timeout=120, check=False
    )
    # A crash is a negative return code (a signal) or a sanitizer report.
    assert result.returncode >= 0, f"polymass {args} crashed: {result.returncode}\n{result.stderr}"
    assert "Sanitizer" not in result.stderr and "runtime error" not in result.stderr, result.stderr
    return result


def run_json(*args):
    result = run("--json", *args)
    return result, json.loads(result.stdout)


def scaled(expected, factor):
    """The exact properties of the solid with every length times factor."""
    return {
        "volume": expected["volume"] * factor**3,
        "center_of_mass": [c * factor for c in expected["center_of_mass"]],
        "inertia": [[x * factor**5 for x in row] for row in expected["inertia"]],
        "inertia_origin": [[x * factor**5 for x in row] for row in expected["inertia_origin"]],
        "surface_area": expected["surface_area"] * factor**2,
    }


def in_metres(vertices, metres_per_unit):
    """The vertices as a file that declares its unit is read: each coordinate
    the double nearest the file's one times the double nearest the unit's
    metres (one rounding, Python's as C's)."""
    return [tuple(c * metres_per_unit for c in v) for v in vertices]


class Case(unittest.TestCase):
    def assert_close(self, actual, expected, scale, what):
        self.assertLessEqual(
            abs(actual - expected), RTOL * scale, f"{what}: {actual} != {expected}"
        )

    def assert_matrix(self, actual, expected, what):
        norm = max(abs(x) for row in expected for x in row)
        for i in range(3):
            for j in range(3):
                self.assert_close(actual[i][j], expected[i][j], norm, f"{what}[{i}][{j}]")

    def assert_properties(self, out, expected, density=1.0, what=""):
        self.assertNotIn("error", out, what)
        self.assert_close(out["volume"], expected["volume"], expected["volume"], what + " volume")
        self.assert_close(
            out["mass"], density * expected["volume"], density * expected["volume"], what + " mass"
        )
        size = max(abs(c) for c in expected["center_of_mass"]) + expected["volume"] ** (1 / 3)
        for k in range(3):
            self.assert_close(
                out["center_of_mass"][k], expected["center_of_mass"][k], size, what + " com"
            )

        def dens(m):
            return [[density * x for x in row] for row in m]

        self.assert_matrix(out["inertia"], dens(expected["inertia"]), what + " inertia")
        self.assert_matrix(
            out["inertia_origin"], dens(expected["inertia_origin"]), what + " inertia_origin"
        )
        self.assert_close(
            out["surface_area"], expected["surface_area"], expected["surface_area"], what + " area"
        )


class EveryFormat(Case):
    """The same solid written in every format gives the same exact values."""

    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.vertices, cls.faces = fixtures.bracket()
        cls.expected = generate.exact_properties(cls.vertices, cls.faces)
        for name, writer in fixtures.WRITERS.items():
            writer(WORK / name, cls.vertices, cls.faces)

    def test_each_format_gives_the_exact_properties(self):
        for name in fixtures.WRITERS:
            with self.subTest(file=name):
                result, out = run_json(WORK / name)
                self.assertEqual(result.returncode, EXIT_OK, result.stderr)
                # The 3MF declares millimetres: its lengths are read in metres.
                factor = 1e-3 if name.endswith(".3mf") else 1.0
                self.assert_properties(out, scaled(self.expected, factor), what=name)
                self.assertEqual(out["warnings"], [])

    def test_audit_measures_an_msh_mesh(self):
        # MuJoCo models name .msh meshes: the audit reads them as the tool does.
        # The geom weighs as MuJoCo weighs it, by its own density (MuJoCo's
        # default 1000, not --density): 1 here, so the mass is the volume.
        model = WORK / "msh_robot.xml"
        model.write_text(
            '<mujoco><asset><mesh file="bracket.msh"/></asset><worldbody><body name="b">'
            '<geom type="mesh" mesh="bracket" density="1"/></body></worldbody></mujoco>'
        )
        result = run("audit", model, "--json")
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        (link,) = json.loads(result.stdout)["links"]
        self.assertNotIn("unreadable_mesh", [f["kind"] for f in link["findings"]], result.stdout)
        self.assert_close(
            link["computed"]["mass"], self.expected["volume"], self.expected["volume"], "mass"
        )

    def test_gltf_mirrored_node_keeps_the_solid(self):
        # A node scaled by -1 along x mirrors the mesh: glTF says its triangles
        # then wind clockwise, so the reader reverses them and the solid is
        # the mirror image, not an inverted one.
        document, buffer = fixtures.gltf_document(self.vertices, self.faces, uri=False)
        document["scenes"][0]["nodes"] = [2]
        document["nodes"].append({"name": "mirror", "scale": [-1, 1, 1], "children": [0]})
        path = WORK / "mirrored.gltf"
        fixtures.write_gltf_document(path, document, buffer)
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        mirrored = [(-x, y, z) for x, y, z in self.vertices]
        tris = [list(reversed(f)) for f in fixtures.triangles(self.faces)]
        self.assert_properties(out, generate.exact_properties(mirrored, tris), what="mirrored")

    def test_3mf_components_and_build_transforms(self):
        # Object 2 holds the bracket as a component turned a quarter about z
        # ((x, y, z) -> (-y, x, z)) and moved; the build item moves it again.
        # 3MF transforms act on row vectors: rows m0, m1, m2 then translation.
        turn = "0 1 0 -1 0 0 0 0 1 2 3 4"
        item = "1 0 0 0 1 0 0 0 1 -0.5 0.25 8"
        path = WORK / "components.3mf"
        fixtures.write_3mf(path, self.vertices, self.faces, component=turn, item=item)
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        placed = [(-y + 2 - 0.5, x + 3 + 0.25, z + 4 + 8) for x, y, z in self.vertices]
        self.assert_properties(
            out,
            scaled(generate.exact_properties(placed, fixtures.triangles(self.faces)), 1e-3),
            what="components",
        )
        self.assertEqual(out["notes"], ["lengths in metres (the file's unit: millimeter)"])

    def test_3mf_decimals_are_read_in_double_precision(self):
        # Coordinates no 32-bit float holds, a thousand units out: the volume
        # and the rest are those of the decimals as doubles (lib3mf 1.x, read
        # before, rounded each to a float: about 1e-4 of this volume).
        placed = [(x * 0.1 + 1000.3, y * 0.7 - 20.1, z * 0.3 + 5.7) for x, y, z in self.vertices]
        path = WORK / "decimals.3mf"
        fixtures.write_3mf(path, placed, self.faces)
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        metres = in_metres(placed, 1e-3)
        expected = generate.exact_properties(metres, fixtures.triangles(self.faces))
        self.assert_properties(out, expected, what="decimals")

    def test_3mf_unit_is_applied(self):
        # Every unit of the 3MF core specification, and none (millimetres by
        # the specification): the lengths in metres, each coordinate placed
        # in the file's unit, then times the unit's metres (in_metres): the
        # exact properties of those coordinates to RTOL. The bracket is turned
        # and moved far out, so a factor applied to the translation alone, or
        # twice, shows. (Against the decimal metres themselves, far out, each
        # coordinate's rounding is 2^-52 of 3 m on a body of 1 mm: 1e-12 of
        # it, the most a double of the metres can do.)
        item = "0 1 0 -1 0 0 0 0 1 1000.5 -2000.25 3000"
        placed = [(-y + 1000.5, x - 2000.25, z + 3000) for x, y, z in self.vertices]
        for unit, factor, named in (
            ("micron", 1e-6, "micron"),
            ("millimeter", 1e-3, "millimeter"),
            ("centimeter", 1e-2, "centimeter"),
            ("inch", 0.0254, "inch"),
            ("foot", 0.3048, "foot"),
            ("meter", 1.0, "meter"),
            (None, 1e-3, "millimeter, 3MF's default"),
        ):
            with self.subTest(unit=unit):
                path = WORK / f"unit_{unit}.3mf"
                fixtures.write_3mf(path, self.vertices, self.faces, item=item, unit=unit)
                result, out = run_json(path)
                self.assertEqual(result.returncode, EXIT_OK, result.stderr)
                exact = generate.exact_properties(
                    in_metres(placed, factor), fixtures.triangles(self.faces)
                )
                self.assert_properties(out, exact, what=str(unit))
                self.assertEqual(out["length_unit"], "m")
                self.assertEqual(out["notes"], [f"lengths in metres (the file's unit: {named})"])
                self.assertNotIn("not converted to metres", result.stderr)
        # The table labels metres too.
        self.assertIn("m^3", run(WORK / "unit_inch.3mf").stdout)

    def test_units_do_not_apply_to_a_file_that_declares_its_own(self):
        # --units is for the files without a unit: the 3MF keeps its
        # millimetres (never scaled twice) and says --units was not applied,
        # the OBJ beside it is read in inches.
        path = WORK / "declared_mm.3mf"
        fixtures.write_3mf(path, self.vertices, self.faces)
        result, out = run_json("--units", "in", path, WORK / "bracket.obj")
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        threemf, obj = out["files"]
        self.assert_properties(threemf, scaled(self.expected, 1e-3), what="3mf --units in")
        self.assertEqual(
            threemf["notes"],
            [
                "lengths in metres (the file's unit: millimeter)",
                "--units not applied: the file declares its unit",
            ],
        )
        self.assertIn("--units not applied", result.stderr)
        self.assert_properties(obj, scaled(self.expected, 0.0254), what="obj --units in")
        self.assertNotIn("notes", obj)
        self.assertEqual([f["length_unit"] for f in out["files"]], ["m", "m"])

    def test_a_declared_unit_beside_a_file_without_one(self):
        # Without --units the OBJ's lengths are its own and the 3MF's metres:
        # the outputs are not labelled metres, and the note says which are.
        path = WORK / "declared_mm.3mf"
        fixtures.write_3mf(path, self.vertices, self.faces)
        result, out = run_json(path, WORK / "bracket.obj")
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["files"][0]["length_unit"], "m")
        self.assertNotIn("length_unit", out["files"][1])
        self.assertIn("not converted to metres", result.stderr)
        self.assertIn("files that declare their unit (3MF, Collada) excepted", result.stderr)
        self.assert_properties(out["files"][0], scaled(self.expected, 1e-3), what="3mf")
        self.assert_properties(out["files"][1], self.expected, what="obj")
        # The table labels each file's lengths as they are.
        table = run(path, WORK / "bracket.obj").stdout
        self.assertIn("m^3", table.split("bracket.obj")[0])
        self.assertIn("(file units)", table.split("bracket.obj")[1])

    def test_error_bound_contains_the_error(self):
        result, out = run_json(WORK / "bracket.obj")
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        bound = out["error_bound"]

        def error(got, exact):  # the exact value is rounded: half an ulp of slack
            return abs(got - exact) - 0.5 * sys.float_info.epsilon * abs(exact)

        self.assertLessEqual(error(out["volume"], self.expected["volume"]), bound["volume"])
        for k in range(3):
            com = error(out["center_of_mass"][k], self.expected["center_of_mass"][k])
            self.assertLessEqual(com, bound["center_of_mass"])
            for j in range(3):
                inertia = error(out["inertia"][k][j], self.expected["inertia"][k][j])
                self.assertLessEqual(inertia, bound["inertia"])
        self.assertLess(bound["volume"], 1e-9 * out["volume"])
        self.assertLessEqual(bound["principal_axes"], 1.5707963267948966)

    def test_polygon_formats_keep_their_faces(self):
        for name in ("bracket.obj", "bracket_ascii.ply", "bracket_binary.ply", "bracket.off"):
            with self.subTest(file=name):
                _, out = run_json(WORK / name)
                self.assertEqual(out["faces"], len(self.faces))
                self.assertEqual(out["vertices"], len(self.vertices))

    def test_obj_line_continuation_and_off_count_after_its_keyword(self):
        # Both are legal and written by real exporters: a face continued after a
        # backslash (with CRLF line ends), and "OFF8 6 0" with no space.
        obj = WORK / "continued.obj"
        lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in self.vertices]
        for face in self.faces:
            corners = [str(i + 1) for i in face]
            lines.append("f " + " ".join(corners[:2]) + " \\")
            lines.append(" ".join(corners[2:]))
        obj.write_bytes(("\r\n".join(lines) + "\r\n").encode())
        _, out = run_json(obj)
        self.assert_properties(out, self.expected, what="continued.obj")
        off = (WORK / "bracket.off").read_text().split("\n", 1)
        glued = WORK / "glued.off"
        glued.write_text("  \tOFF" + off[1].lstrip())
        _, out = run_json(glued)
        self.assert_properties(out, self.expected, what="glued.off")

    def test_triangulate_and_planarity_tolerance(self):
        # The bracket with one corner of a quad lifted: not planar, refused;
        # accepted with a looser tolerance; --triangulate gives the fan's solid,
        # whose volume the exact reference gives for the same triangles.
        vertices = list(self.vertices)
        x, y, z = vertices[self.faces[-1][0]]
        vertices[self.faces[-1][0]] = (x, y, z + 0.25)
        fixtures.write_obj(WORK / "bent.obj", vertices, self.faces)
        result, out = run_json(WORK / "bent.obj")
        self.assertEqual(out["error"]["category"], "non_planar_face")
        result, out = run_json("--planarity-tolerance", "0.1", WORK / "bent.obj")
        self.assertEqual(result.returncode, EXIT_OK, out)
        _, out = run_json("--triangulate", WORK / "bent.obj")
        fanned = fixtures.triangles(self.faces)
        expected = generate.exact_properties(vertices, fanned)
        self.assert_properties(out, expected, what="bent.obj --triangulate")
        self.assertEqual(out["faces"], len(fanned))

    def test_float32_files_answer_as_their_doubles(self):
        # Binary STL and .msh positions reach the library as float32, the text
        # formats' as float64: the same coordinates give the same digits (the
        # library widens each float exactly, as the tool did), with and without
        # a scale (applied to the widened doubles), far from the origin.
        def float32(v):
            return struct.unpack("<3f", struct.pack("<3f", *v))

        vertices = [
            float32((1.1 * x + 1000.3, 0.7 * y - 250.1, 1.3 * z + 77.7))
            for x, y, z in self.vertices
        ]
        fanned = fixtures.triangles(self.faces)
        fixtures.write_obj(WORK / "float32.obj", vertices, fanned)
        fixtures.write_binary_stl(WORK / "float32.stl", vertices, fanned)
        fixtures.write_msh(WORK / "float32.msh", vertices, fanned)
        for options in ([], ["--scale", "3.3"], ["--about", "origin", "--threads", "1"]):
            answers = {}
            for name in ("float32.obj", "float32.stl", "float32.msh"):
                result, out = run_json(*options, WORK / name)
                self.assertEqual(result.returncode, EXIT_OK, result.stderr)
                answers[name] = {k: v for k, v in out.items() if k not in ("file", "format")}
            with self.subTest(options=options):
                self.assertEqual(answers["float32.stl"], answers["float32.obj"])
                self.assertEqual(answers["float32.msh"], answers["float32.obj"])

    def test_stl_soup_is_welded(self):
        _, out = run_json(WORK / "bracket_binary.stl")
        self.assertEqual(out["vertices"], len(self.vertices))
        self.assertEqual(out["faces"], len(fixtures.triangles(self.faces)))

    def test_units_and_scale(self):
        for options, factor in (
            (["--units", "mm"], 1e-3),
            (["--units", "in"], 0.0254),
            (["--scale", "4"], 4.0),
            (["--units", "cm", "--scale", "2"], 0.02),
        ):
            with self.subTest(options=options):
                _, out = run_json(*options, WORK / "bracket.obj")
                self.assert_properties(out, scaled(self.expected, factor), what=str(options))

    def test_density_and_mass(self):
        _, out = run_json("--density", "2700", WORK / "bracket.obj")
        self.assert_properties(out, self.expected, density=2700.0, what="density")
        self.assertEqual(out["density"], 2700.0)
        _, out = run_json("--mass", "3", WORK / "bracket.obj")
        density = 3.0 / self.expected["volume"]
        self.assert_properties(out, self.expected, density=density, what="mass")

    def test_about_a_point(self):
        point = (1.5, -0.5, 2.0)
        _, out = run_json("--about", ",".join(map(str, point)), WORK / "bracket.obj")
        # Parallel axes: I_P = I_C + m (|d|^2 1 - d d^T), d = C - P.
        mass = out["mass"]
        d = [c - p for c, p in zip(self.expected["center_of_mass"], point)]
        expected = [
            [
                self.expected["inertia"][i][j]
                + mass * ((sum(x * x for x in d) if i == j else 0) - d[i] * d[j])
                for j in range(3)
            ]
            for i in range(3)
        ]
        self.assert_matrix(out["inertia_point"], expected, "inertia_point")
        self.assertEqual(out["about_point"], list(point))

    def test_principal_axes_diagonalise_the_inertia(self):
        _, out = run_json(WORK / "bracket.obj")
        inertia = out["inertia"]
        norm = max(abs(x) for row in inertia for x in row)
        for moment, axis in zip(out["principal_moments"], out["principal_axes"]):
            image = [sum(inertia[i][j] * axis[j] for j in range(3)) for i in range(3)]
            for i in range(3):
                self.assert_close(image[i], moment * axis[i], norm, "I a = lambda a")

    def test_inertial_xml_of_each_format(self):
        expected = self.expected
        mass = 2.5
        inertia = [[mass / expected["volume"] * x for x in row] for row in expected["inertia"]]
        self.assertNotEqual(inertia[0][1], 0.0)  # the sign convention must show
        com = expected["center_of_mass"]

        def floats(text):
            return [float(x) for x in text.split()]

        urdf = ElementTree.fromstring(run("--urdf", "--mass", mass, WORK / "bracket.obj").stdout)
        self.assertEqual(urdf.tag, "inertial")
        origin = floats(urdf.find("origin").get("xyz"))
        self.assertEqual(floats(urdf.find("origin").get("rpy")), [0, 0, 0])
        self.assert_close(float(urdf.find("mass").get("value")), mass, mass, "urdf mass")
        element = urdf.find("inertia")
        urdf_values = {k: float(element.get(k)) for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")}

        sdf = ElementTree.fromstring(run("--sdf", "--mass", mass, WORK / "bracket.obj").stdout)
        pose = floats(sdf.find("pose").text)
        self.assertEqual(pose[3:], [0, 0, 0])
        self.assert_close(float(sdf.find("mass").text), mass, mass, "sdf mass")
        sdf_values = {k: float(sdf.find("inertia/" + k).text) for k in urdf_values}

        mjcf = ElementTree.fromstring(run("--mjcf", "--mass", mass, WORK / "bracket.obj").stdout)
        self.assert_close(float(mjcf.get("mass")), mass, mass, "mjcf mass")
        full = floats(mjcf.get("fullinertia"))
        # MuJoCo's order: M11 M22 M33 M12 M13 M23.
        mjcf_values = dict(zip(("ixx", "iyy", "izz", "ixy", "ixz", "iyz"), full))

        # Every format takes the tensor element: ixy = I[0][1] = -integral rho x y dV.
        element_of = {
            "ixx": (0, 0),
            "ixy": (0, 1),
            "ixz": (0, 2),
            "iyy": (1, 1),
            "iyz": (1, 2),
            "izz": (2, 2),
        }
        norm = max(abs(x) for row in inertia for x in row)
        for name, values in (("urdf", urdf_values), ("sdf", sdf_values), ("mjcf", mjcf_values)):
            for key, (i, j) in element_of.items():
                self.assert_close(values[key], inertia[i][j], norm, f"{name} {key}")
        for name, position in (
            ("urdf", origin),
            ("sdf", pose[:3]),
            ("mjcf", floats(mjcf.get("pos"))),
        ):
            for k in range(3):
                self.assert_close(position[k], com[k], abs(com[k]) + 1, f"{name} com")
        # ixy is the negated product of inertia: for this L the product
        # integral x' y' over the centroid is negative, so ixy is positive.
        self.assertGreater(urdf_values["ixy"], 0.0)

    def test_table_output(self):
        result = run(WORK / "bracket.obj", "--about", "origin")
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        for label in (
            "volume",
            "mass",
            "centre of mass",
            "inertia about COM",
            "inertia about origin",
            "principal moments",
            "surface area",
            "warnings",
        ):
            self.assertIn(label, result.stdout)

    def test_several_files_and_a_summary(self):
        result, out = run_json(WORK / "bracket.obj", WORK / "bracket.off", WORK / "missing.obj")
        self.assertEqual(result.returncode, EXIT_UNREADABLE)
        self.assertEqual(
            [f["file"] for f in out["files"]],
            [str(WORK / "bracket.obj"), str(WORK / "bracket.off"), str(WORK / "missing.obj")],
        )
        self.assertEqual(out["summary"]["valid"], 2)
        self.assertEqual(out["summary"]["failed"], 1)
        self.assert_close(
            out["summary"]["total_volume"],
            2 * self.expected["volume"],
            self.expected["volume"],
            "sum",
        )
        self.assertEqual(out["files"][2]["error"]["category"], "unreadable")

    def test_parts_and_combined(self):
        # Two OBJ objects: the bracket and the same bracket moved along x.
        n = len(self.vertices)
        moved = [(x + 10, y, z) for x, y, z in self.vertices]
        lines = ["o first"] + [f"v {x!r} {y!r} {z!r}" for x, y, z in self.vertices + moved]
        lines += ["f " + " ".join(str(i + 1) for i in f) for f in self.faces]
        lines += ["o second"] + ["f " + " ".join(str(i + 1 + n) for i in f) for f in self.faces]
        path = WORK / "two_parts.obj"
        path.write_text("\n".join(lines) + "\n")
        _, out = run_json(path)
        self.assertEqual([p["name"] for p in out["parts"]], ["first", "second"])
        self.assert_properties(out["parts"][0], self.expected, what="part 1")
        self.assert_close(
            out["volume"], 2 * self.expected["volume"], self.expected["volume"], "combined"
        )
        self.assert_close(
            out["center_of_mass"][0], self.expected["center_of_mass"][0] + 5, 10, "combined com"
        )

    def test_gltf_mesh_used_by_two_nodes_gives_two_parts(self):
        # The fixture's child node and a sibling under the same turned and
        # scaled parent use one mesh: the bracket, and a copy where the
        # sibling's other translation, turned and scaled, moves it.
        shift = (3.0, 0.0, 1.0)
        path = WORK / "two_nodes.gltf"
        fixtures.write_gltf(path, self.vertices, self.faces, copy_shifts=[shift])
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual([p["name"] for p in out["parts"]], ["bracket", "copy 1"])
        move = fixtures.parent_transform([a - b for a, b in zip(shift, fixtures.CHILD_SHIFT)])
        moved = [tuple(c + m for c, m in zip(v, move)) for v in self.vertices]
        tris = fixtures.triangles(self.faces)
        self.assert_properties(out["parts"][0], self.expected, what="first node")
        self.assert_properties(
            out["parts"][1], generate.exact_properties(moved, tris), what="second node"
        )
        n = len(self.vertices)
        both = generate.exact_properties(
            self.vertices + moved, tris + [[i + n for i in f] for f in tris]
        )
        self.assert_properties(out, both, what="both nodes")

    def test_ascii_stl_solids_are_parts(self):
        # Two `solid` blocks, the second the bracket moved along y: two named parts.
        moved = [(x, y + 4, z) for x, y, z in self.vertices]
        first, second = WORK / "solid_a.stl", WORK / "solid_b.stl"
        fixtures.write_ascii_stl(first, self.vertices, self.faces)
        fixtures.write_ascii_stl(second, moved, self.faces)
        text = first.read_text() + second.read_text().replace("bracket", "moved")
        path = WORK / "two_solids.stl"
        path.write_text(text)
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual([p["name"] for p in out["parts"]], ["bracket", "moved"])
        tris = fixtures.triangles(self.faces)
        self.assert_properties(out["parts"][0], self.expected, what="solid 1")
        self.assert_properties(
            out["parts"][1], generate.exact_properties(moved, tris), what="solid 2"
        )

    def test_ply_elements_without_properties_are_skipped_at_once(self):
        # 30000 declared elements of 500000 items with no properties take no
        # byte of the body: read in no time, counting through them took minutes.
        for encoding, writer in (
            ("ascii", fixtures.write_ascii_ply),
            ("binary_big_endian", fixtures.write_binary_ply),
        ):
            with self.subTest(encoding=encoding):
                path = WORK / f"empty_elements_{encoding}.ply"
                writer(path, self.vertices, self.faces)
                header, body = path.read_bytes().split(b"end_header\n", 1)
                empty = b"element nothing 500000\n" * 30000
                header = header.replace(b"element vertex", empty + b"element vertex")
                path.write_bytes(header + b"end_header\n" + body)
                result, out = run_json(path)
                self.assertEqual(result.returncode, EXIT_OK, result.stderr)
                self.assert_properties(out, self.expected, what=path.name)


class BadInput(Case):
    """Malformed files and invalid solids: a clear error and exit status."""

    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.vertices, cls.faces = fixtures.bracket()

    def expect_error(self, path, category, exit_code, message_part=""):
        result, out = run_json(path)
        self.assertEqual(result.returncode, exit_code, result.stderr)
        self.assertEqual(out["error"]["category"], category, out)
        self.assertIn(message_part, out["error"]["message"])
        self.assertIn(category, result.stderr)
        return out

    def write(self, name, data):
        path = WORK / name
        path.write_bytes(data if isinstance(data, bytes) else data.encode())
        return path

    def test_truncated_binary_stl(self):
        data = fixtures.binary_stl_bytes(self.vertices, self.faces)
        self.expect_error(
            self.write("truncated.stl", data[:-30]), "unreadable", EXIT_UNREADABLE, "truncated"
        )

    def test_binary_stl_header_and_declared_count(self):
        # The exact size decides binary: a header beginning with "solid" is
        # still binary, read as the same solid; a count one off either way is
        # refused, and with a "solid" header the file is then read as ASCII,
        # which it is not.
        data = fixtures.binary_stl_bytes(self.vertices, self.faces)
        count = len(fixtures.triangles(self.faces))
        solid_header = b"solid bracket".ljust(80, b"\0")

        def answer(name, content):
            result, out = run_json(self.write(name, content))
            self.assertEqual(result.returncode, EXIT_OK, result.stderr)
            return {k: v for k, v in out.items() if k != "file"}

        self.assertEqual(
            answer("solid_header.stl", solid_header + data[80:]), answer("plain.stl", data)
        )
        for declared, message in (
            (count + 1, "(truncated)"),
            (count - 1, "(not an STL, or corrupt)"),
        ):
            with self.subTest(declared=declared):
                lying = data[:80] + struct.pack("<I", declared) + data[84:]
                self.expect_error(
                    self.write("lying.stl", lying), "unreadable", EXIT_UNREADABLE, message
                )
                ascii_then = solid_header + lying[80:]
                self.expect_error(
                    self.write("solid_lying.stl", ascii_then), "unreadable", EXIT_UNREADABLE
                )

    def test_msh_that_is_not_one(self):
        data = fixtures.msh_bytes(self.vertices, self.faces, normals=len(self.vertices))
        for name, content, message in [
            ("truncated.msh", data[:-4], "counts (nvertex 12, nnormal 12, ntexcoord 0, nface 20)"),
            ("longer.msh", data + b"\0", "make 544 bytes, but the file has 545"),
            ("short.msh", data[:15], "four int32 counts (16 bytes), but the file has 15"),
            ("negative.msh", struct.pack("<4i", 3, -1, 0, 1) + data[16:], "negative count"),
            ("points.msh", struct.pack("<4i", 2, 0, 0, 0) + data[16:40], "no faces"),
            ("gmsh.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n", "a Gmsh mesh"),
        ]:
            with self.subTest(file=name):
                self.expect_error(self.write(name, content), "unreadable", EXIT_UNREADABLE, message)
        # A corner naming no vertex (negative, or past the last) is the library's finding.
        corners = len(data) - 12 * len(fixtures.triangles(self.faces))
        for index in (-1, 12):
            with self.subTest(index=index):
                bad = data[:corners] + struct.pack("<i", index) + data[corners + 4 :]
                self.expect_error(
                    self.write("index.msh", bad), "index_out_of_range", EXIT_INVALID_MESH
                )

    def test_garbage(self):
        garbage = bytes((i * 7919 + 13) % 256 for i in range(3000))
        for name in (
            "garbage.stl",
            "garbage.ply",
            "garbage.obj",
            "garbage.off",
            "garbage.glb",
            "garbage.3mf",
            "garbage.gltf",
        ):
            with self.subTest(file=name):
                result, out = run_json(self.write(name, garbage))
                self.assertIn(
                    result.returncode, (EXIT_UNREADABLE, EXIT_INVALID_MESH), result.stderr
                )
                self.assertIn("error", out)

    def test_empty_files(self):
        for name in ("empty.obj", "empty.stl", "empty.ply", "empty.off", "empty.glb"):
            with self.subTest(file=name):
                self.expect_error(self.write(name, b""), "unreadable", EXIT_UNREADABLE, "empty")

    def test_missing_file_and_unknown_format(self):
        self.expect_error(WORK / "does_not_exist.obj", "unreadable", EXIT_UNREADABLE, "cannot open")
        self.expect_error(
            self.write("mesh.xyz", "1 2 3\n"), "unreadable", EXIT_UNREADABLE, "unknown format"
        )

    def test_index_past_the_end(self):
        n = len(self.vertices)
        obj = "\n".join(
            [f"v {x!r} {y!r} {z!r}" for x, y, z in self.vertices]
            + ["f " + " ".join(str(i + 1) for i in f) for f in self.faces[:-1]]
            + [f"f 1 2 {n + 5}"]
        )
        self.expect_error(self.write("index.obj", obj), "index_out_of_range", EXIT_INVALID_MESH)
        off = ["OFF", f"{n} {len(self.faces)} 0"] + [" ".join(map(repr, v)) for v in self.vertices]
        off += [" ".join(map(str, [len(f)] + f)) for f in self.faces[:-1]] + [f"3 0 1 {n}"]
        self.expect_error(
            self.write("index.off", "\n".join(off)), "index_out_of_range", EXIT_INVALID_MESH
        )
        ply = fixtures.ply_header("ascii", n, 1) + b"\n".join(
            " ".join(map(repr, v)).encode() for v in self.vertices
        )
        self.expect_error(
            self.write("index.ply", ply + f"\n3 0 1 {n + 100}\n".encode()),
            "index_out_of_range",
            EXIT_INVALID_MESH,
        )

    def test_binary_ply_ending_with_its_header(self):
        # end_header is the file's last line, without its newline: no body.
        header = fixtures.ply_header("binary_little_endian", 4, 1).rstrip(b"\n")
        self.expect_error(
            self.write("header_only.ply", header), "unreadable", EXIT_UNREADABLE, "truncated"
        )

    def test_faces_without_vertices(self):
        obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\n"
        self.expect_error(
            self.write("empty_face.obj", obj), "face_too_small", EXIT_INVALID_MESH, "face 0"
        )

    def test_a_3mf_with_a_bad_checksum_is_an_unreadable_file(self):
        # A 3MF whose zip checksum no longer matches its (still valid) XML: the
        # assimp Debian ships aborted on it (the tool read it in a child
        # process, which it still does); libzip's checksum refuses it.
        path = WORK / "bad_checksum.3mf"
        fixtures.write_3mf(path, self.vertices, self.faces)
        data = bytearray(path.read_bytes())
        digit = data.index(b'<vertex x="') + len(b'<vertex x="')
        data[digit] = ord("7") if data[digit] != ord("7") else ord("6")
        path.write_bytes(bytes(data))
        self.expect_error(path, "unreadable", EXIT_UNREADABLE, "3dmodel.model: CRC error")

    def test_stl_keywords_out_of_place_in_a_facet(self):
        # Corners read before a second `outer loop` or a new `solid` belonged
        # to no face: the part's faces no longer added up to its corners.
        loop = ["facet normal 0 0 1", "outer loop", "vertex 0 0 0", "vertex 1 0 0"]
        rest = ["vertex 0 1 0", "endloop", "endfacet", "endsolid a"]
        for intruder, line, message in (
            (["outer loop"], 6, "'outer' inside a facet's loop"),
            (["solid b"], 6, "'solid' inside a facet's loop"),
            (["endsolid a"], 6, "'endsolid' inside a facet's loop"),
            (["vertex 0 0 1", "endloop", "outer loop"], 8, "a second 'outer loop' in a facet"),
            (["vertex 0 0 1", "endloop", "solid b"], 8, "'solid' inside a facet"),
            (["vertex 0 0 1", "endloop", "endsolid a"], 8, "'endsolid' inside a facet"),
        ):
            with self.subTest(intruder=intruder):
                text = "\n".join(["solid a"] + loop + intruder + rest) + "\n"
                self.expect_error(
                    self.write("intruder.stl", text),
                    "unreadable",
                    EXIT_UNREADABLE,
                    f"line {line}: {message}",
                )

    def test_underflow_is_zero_and_overflow_is_not_finite(self):
        # A magnitude below the smallest double rounds to zero (or a subnormal);
        # one above the largest is infinite, which the library refuses.
        vertices, faces = fixtures.cube()
        lines = ["v " + " ".join("1" if c else "-1e-400" for c in v) for v in vertices]
        lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
        path = self.write("underflow.obj", "\n".join(lines).replace("-1e-400 ", "1e-400 ", 3))
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assert_properties(out, generate.exact_properties(vertices, faces), what="underflow")
        result, out = run_json("--about", "3e-324,1e-400,-1e-400", path)
        self.assertEqual(out["about_point"], [5e-324, 0.0, 0.0])
        self.expect_error(
            self.write("overflow.obj", "\n".join(lines).replace("-1e-400", "1e400", 1)),
            "non_finite",
            EXIT_INVALID_MESH,
        )

    def test_usd_refuses_what_float_cannot_hold(self):
        # USD's attributes are 32-bit floats: a mass past 3.4e38 or moments
        # below float's normal range leave the prim out, with the reason; the
        # same cube in a float's range is a prim. (tests/cli/test_usd.py reads
        # the layers back with OpenUSD.)
        vertices, faces = fixtures.cube()
        path = WORK / "usd_cube.obj"
        fixtures.write_obj(path, vertices, faces)
        result = run("--usda", path, "--scale", "1e13")
        self.assertEqual(result.returncode, EXIT_INVALID_MESH, result.stderr)
        self.assertIn(
            "the whole: no USD prim: the mass 1e+39 is not a normal 32-bit float", result.stderr
        )
        self.assertNotIn("def Xform", result.stdout)
        self.assertIn("# the whole: no prim: the mass", result.stdout)
        result = run("--usda", path, "--scale", "1e-8")
        self.assertEqual(result.returncode, EXIT_INVALID_MESH, result.stderr)
        self.assertIn("a principal moment", result.stderr)
        result = run("--usda", path, "--scale", "1e6")
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertIn("float physics:mass = 1e+18", result.stdout)

    def test_xml_outputs_are_utf8_whatever_the_paths(self):
        # Several files: each element follows a comment naming its file.
        latin1 = bytes(WORK) + b"/br\xfcket.obj"
        plain = WORK / "plain.obj"
        for path in (Path(os.fsdecode(latin1)), plain):
            fixtures.write_obj(path, self.vertices, self.faces)
        for output in ("--urdf", "--sdf", "--mjcf"):
            result = subprocess.run(
                [EXE, output, latin1, bytes(plain)], capture_output=True, timeout=120
            )
            self.assertEqual(result.returncode, EXIT_OK, result.stderr)
            text = result.stdout.decode("utf-8")  # strict: raises on invalid UTF-8
            ElementTree.fromstring("<files>" + text + "</files>")

    def test_json_output_is_utf8_whatever_the_names(self):
        # Part names are the file's bytes: Latin-1, or broken UTF-8 (overlong,
        # surrogate, cut short). Valid UTF-8 is kept; each maximal ill-formed
        # subsequence is one U+FFFD (Unicode 15, 3.9): the bytes that cannot
        # start a character one each, a sequence cut short as a whole.
        names = {
            b"W\xfcrfel": "W\ufffdrfel",
            "Würfel_\U0001d11e".encode(): "Würfel_\U0001d11e",
            b"\xc0\xaf_\xed\xa0\x80_\xe2\x82": "\ufffd\ufffd_\ufffd\ufffd\ufffd_\ufffd",
        }
        vertices, faces = fixtures.cube()
        text = b""
        for k, name in enumerate(names):  # cube k at x = 2k, apart from the others
            text += (
                b"o "
                + name
                + b"\n"
                + b"".join(b"v %d %d %d\n" % (x + 2 * k, y, z) for x, y, z in vertices)
            )
            text += b"".join(
                b"f " + b" ".join(b"%d" % (i - len(vertices)) for i in f) + b"\n" for f in faces
            )
        path = self.write("names.obj", text)
        result = subprocess.run([EXE, "--json", str(path)], capture_output=True, check=False)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        out = json.loads(result.stdout.decode("utf-8"))
        self.assertEqual([p["name"] for p in out["parts"]], list(names.values()))

    def test_nan_coordinates(self):
        vertices = list(self.vertices)
        vertices[2] = (float("nan"), 0.0, 0.0)
        fixtures.write_obj(WORK / "nan.obj", vertices, self.faces)
        self.expect_error(WORK / "nan.obj", "non_finite", EXIT_INVALID_MESH)
        fixtures.write_binary_stl(WORK / "nan.stl", vertices, self.faces)
        self.expect_error(WORK / "nan.stl", "non_finite", EXIT_INVALID_MESH)
        fixtures.write_off(WORK / "nan.off", vertices, self.faces)
        self.expect_error(WORK / "nan.off", "non_finite", EXIT_INVALID_MESH)

    def test_invalid_solids(self):
        fixtures.write_obj(WORK / "open.obj", self.vertices, self.faces[:-1])
        self.expect_error(WORK / "open.obj", "open", EXIT_INVALID_MESH)
        inverted = [list(reversed(f)) for f in self.faces]
        fixtures.write_obj(WORK / "inverted.obj", self.vertices, inverted)
        self.expect_error(WORK / "inverted.obj", "inverted", EXIT_INVALID_MESH)
        flipped = self.faces[:-1] + [list(reversed(self.faces[-1]))]
        fixtures.write_obj(WORK / "flipped.obj", self.vertices, flipped)
        self.expect_error(WORK / "flipped.obj", "inconsistent_orientation", EXIT_INVALID_MESH)
        small = self.faces + [[0, 1]]
        fixtures.write_obj(WORK / "small.obj", self.vertices, small)
        self.expect_error(WORK / "small.obj", "face_too_small", EXIT_INVALID_MESH)

    def test_accept_inverted(self):
        inverted = [list(reversed(f)) for f in self.faces]
        fixtures.write_obj(WORK / "inverted.obj", self.vertices, inverted)
        result, out = run_json("--accept-inverted", WORK / "inverted.obj")
        self.assertEqual(result.returncode, EXIT_OK)
        self.assertIn("inverted", out["warnings"])
        self.assert_properties(
            out, generate.exact_properties(self.vertices, self.faces), what="turned"
        )

    def test_no_check(self):
        fixtures.write_obj(WORK / "bracket.obj", self.vertices, self.faces)
        result, out = run_json("--no-check", WORK / "bracket.obj")
        self.assertEqual(result.returncode, EXIT_OK)
        self.assertIn("unchecked", out["warnings"])
        # The intersection check goes with the topology checks, and says so.
        self.assertIn("intersections_unchecked", out["warnings"])
        result, out = run_json("--no-intersection-check", WORK / "bracket.obj")
        self.assertEqual(result.returncode, EXIT_OK)
        self.assertEqual(out["warnings"], ["intersections_unchecked"])

    def test_usage_errors(self):
        for args in (
            [],
            ["--density"],
            ["--density", "-1", "x.obj"],
            ["--mass", "1", "--density", "1", "x.obj"],
            ["--units", "furlong", "x.obj"],
            ["--about", "1,2", "x.obj"],
            ["--frobnicate", "x.obj"],
            ["--json", "--urdf", "x.obj"],
            ["--usda", "--mjcf", "x.obj"],
            ["check", "--usda", "x.obj"],
            ["--weld-tolerance", "1", "x.obj"],
        ):
            with self.subTest(args=args):
                result = run(*args)
                self.assertEqual(result.returncode, EXIT_USAGE)
                self.assertTrue(result.stderr.startswith("polymass: "), result.stderr)

    def test_help(self):
        result = run("--help")
        self.assertEqual(result.returncode, EXIT_OK)
        for word in ("Usage", "--density", "--units", "--json", "--urdf", "check", "Exit status"):
            self.assertIn(word, result.stdout)

    def gltf_parts(self):
        """The fixture's glTF document and buffer: positions, then indices."""
        document, buffer = fixtures.gltf_document(self.vertices, self.faces, uri=False)
        return document, bytearray(buffer)

    def test_gltf_accessor_past_its_buffer_view(self):
        document, buffer = self.gltf_parts()
        document["accessors"][0]["count"] += 1  # one vertex more than the view holds
        path = WORK / "accessor_past_view.gltf"
        fixtures.write_gltf_document(path, document, bytes(buffer))
        self.expect_error(path, "unreadable", EXIT_UNREADABLE, "accessor 0 (")
        document, buffer = self.gltf_parts()
        document["bufferViews"][1]["byteLength"] += 4  # the indices' view past the buffer
        path = WORK / "view_past_buffer.gltf"
        fixtures.write_gltf_document(path, document, bytes(buffer))
        self.expect_error(path, "unreadable", EXIT_UNREADABLE)

    def test_gltf_index_out_of_range_and_nan(self):
        document, buffer = self.gltf_parts()
        buffer[-4:] = struct.pack("<I", len(self.vertices) + 5)
        path = WORK / "index.gltf"
        fixtures.write_gltf_document(path, document, bytes(buffer))
        self.expect_error(path, "index_out_of_range", EXIT_INVALID_MESH)
        document, buffer = self.gltf_parts()
        buffer[8:12] = struct.pack("<f", float("nan"))  # z of the first vertex
        path = WORK / "nan.gltf"
        fixtures.write_gltf_document(path, document, bytes(buffer))
        self.expect_error(path, "non_finite", EXIT_INVALID_MESH)

    def test_gltf_node_reached_twice_is_refused(self):
        document, buffer = self.gltf_parts()
        document["scenes"][0]["nodes"] = [0, 1]  # node 1 is also node 0's child
        path = WORK / "shared_node.gltf"
        fixtures.write_gltf_document(path, document, bytes(buffer))
        self.expect_error(path, "unreadable", EXIT_UNREADABLE, "reached twice")

    def test_malformed_3mf_models(self):
        mesh = (
            '<mesh><vertices><vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/>'
            '<vertex x="0" y="1" z="0"/><vertex x="0" y="0" z="1"/></vertices><triangles>'
            '<triangle v1="0" v2="2" v3="1"/><triangle v1="0" v2="1" v3="3"/>'
            '<triangle v1="0" v2="3" v3="2"/><triangle v1="1" v2="2" v3="3"/></triangles></mesh>'
        )

        def model(resources, build='<item objectid="1"/>', unit="millimeter"):
            return (
                f'<model unit="{unit}" xmlns="http://schemas.microsoft.com/3dmanufacturing/'
                f'core/2015/02"><resources>{resources}</resources><build>{build}</build></model>'
            )

        tetrahedron = f'<object id="1">{mesh}</object>'
        path = WORK / "tetrahedron.3mf"
        fixtures.write_3mf_package(path, model(tetrahedron, unit="inch"))
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assert_close(out["volume"], 0.0254**3 / 6, 0.0254**3 / 6, "inch volume")
        self.assertEqual(out["notes"], ["lengths in metres (the file's unit: inch)"])
        component = '<object id="{}"><components><component objectid="{}"{}/></components></object>'
        for name, content, message in [
            ("cycle", model(component.format(1, 1, "")), "object 1: a component names object 1"),
            (
                "later",
                model(component.format(2, 1, "") + tetrahedron, '<item objectid="2"/>'),
                "object 2: a component names object 1, which is not defined before it",
            ),
            (
                "transform",
                model(
                    tetrahedron + component.format(2, 1, ' transform="1 0 0 0 1 0"'),
                    '<item objectid="2"/>',
                ),
                "the transform is not 12 numbers",
            ),
            (
                # A token that is no number, then more than 12 tokens in all.
                "transform token",
                model(
                    tetrahedron + component.format(2, 1, ' transform="1 x' + " 0" * 12 + '"'),
                    '<item objectid="2"/>',
                ),
                "the transform is not 12 numbers",
            ),
            ("twice", model(tetrahedron + tetrahedron), "object id 1 is used twice"),
            ("no object", model(tetrahedron, '<item objectid="7"/>'), "names object 7"),
            ("unit", model(tetrahedron, unit="furlong"), "<model unit='furlong'> is none of"),
            ("number", model(tetrahedron.replace('x="1"', 'x="1,5"')), "x is not a number"),
            ("index", model(tetrahedron.replace('v3="3"', 'v3="4"', 1)), "vertex index 4"),
            ("not xml", "<model", "not well-formed XML"),
            (
                "production",
                model(tetrahedron + component.format(2, 1, ' p:path="/3D/other.model"')),
                "3MF production extension",
            ),
        ]:
            with self.subTest(case=name):
                path = WORK / (name.replace(" ", "_") + ".3mf")
                fixtures.write_3mf_package(path, content)
                self.expect_error(path, "unreadable", EXIT_UNREADABLE, message)
        path = WORK / "no_model.3mf"
        fixtures.write_3mf_package(path, model(tetrahedron), relationship="thumbnail")
        self.expect_error(path, "unreadable", EXIT_UNREADABLE, "names no 3D model part")
        fixtures.write_3mf_package(path, model(tetrahedron), target="/3D/elsewhere.model")
        self.expect_error(path, "unreadable", EXIT_UNREADABLE, "no part 3D/elsewhere.model")

    def test_3mf_index_out_of_range_and_nan(self):
        path = WORK / "index.3mf"
        faces = self.faces[:-1] + [[0, 1, len(self.vertices) + 5]]
        fixtures.write_3mf(path, self.vertices, faces)
        out = self.expect_error(path, "unreadable", EXIT_UNREADABLE)
        self.assertIn("index", out["error"]["message"].lower())
        vertices = list(self.vertices)
        vertices[0] = (float("nan"), 0.0, 0.0)
        path = WORK / "nan.3mf"
        fixtures.write_3mf(path, vertices, self.faces)
        result, out = run_json(path)
        self.assertIn(result.returncode, (EXIT_UNREADABLE, EXIT_INVALID_MESH), result.stderr)
        self.assertIn(out["error"]["category"], ("unreadable", "non_finite"))


class Check(Case):
    """polymass check: diagnostics and their exit status."""

    def cubes(self, name, second_lo, second_hi, second_inside_out=False):
        """A unit cube and a box, two shells of one OBJ file."""
        cube_vertices, cube_faces = fixtures.cube()
        (x0, y0, z0), (x1, y1, z1) = second_lo, second_hi
        box = [(x1 if x else x0, y1 if y else y0, z1 if z else z0) for x, y, z in cube_vertices]
        n = len(cube_vertices)
        turn = reversed if second_inside_out else list
        faces = cube_faces + [[n + i for i in turn(f)] for f in cube_faces]
        path = WORK / name
        fixtures.write_obj(path, cube_vertices + box, faces)
        return path

    def test_overlapping_cubes_are_refused(self):
        # Two unit cubes overlapping by 1/8: volume 2 would count the overlap twice.
        path = self.cubes("overlapping.obj", (0.5, 0.5, 0.5), (1.5, 1.5, 1.5))
        result = run("check", "--json", path)
        self.assertEqual(result.returncode, EXIT_INVALID_MESH, result.stdout)
        report = json.loads(result.stdout)
        self.assertIs(report["valid"], False)
        self.assertEqual(report["category"], "intersecting")
        self.assertIn("cross each other", report["message"])
        pairs = report["intersecting_face_pairs"]
        self.assertGreaterEqual(pairs["count"], 3)
        for (low, high), shells in zip(pairs["first_pairs"], pairs["first_pair_shells"]):
            self.assertLess(low, 6)  # a face of the first cube
            self.assertGreaterEqual(high, 6)  # crosses one of the second
            self.assertEqual(shells, [0, 1])
        text = run("check", path).stdout
        self.assertIn("crossing face pairs", text)
        self.assertIn("(shell 0) and face", text)
        # Computing refuses it the same way, in every output.
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_INVALID_MESH, result.stdout)
        self.assertEqual(out["error"]["category"], "intersecting")
        self.assertEqual(run("--urdf", path).returncode, EXIT_INVALID_MESH)
        # Unchecked, the library cannot see it: the README says so.
        result, out = run_json("--no-intersection-check", path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["volume"], 2.0)

    def test_touching_cubes_are_a_valid_solid_with_a_warning(self):
        # Resting against the cube on a smaller face, sharing no corner (the
        # tool welds: shared corners would make its edges non-manifold).
        path = self.cubes("touching.obj", (1, 0.25, 0.25), (2, 0.75, 0.75))
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["volume"], 1.25)
        self.assertEqual(out["warnings"], ["touching_faces"])
        self.assertIn("touch", result.stderr)
        report = json.loads(run("check", "--json", path).stdout)
        self.assertIs(report["valid"], True)
        self.assertGreater(report["touching_face_pairs"]["count"], 0)
        self.assertEqual([s["kind"] for s in report["shell_list"]], ["solid", "solid"])

    def objects(self, name, *boxes):
        """Boxes (lo, hi) as OBJ objects of one file, each with its own vertices."""
        cube_vertices, cube_faces = fixtures.cube()
        lines = []
        for k, ((x0, y0, z0), (x1, y1, z1)) in enumerate(boxes):
            lines.append(f"o box{k}")
            for x, y, z in cube_vertices:
                lines.append(f"v {x1 if x else x0!r} {y1 if y else y0!r} {z1 if z else z0!r}")
            base = 1 + k * len(cube_vertices)
            lines += ["f " + " ".join(str(base + i) for i in f) for f in cube_faces]
        path = WORK / name
        path.write_text("\n".join(lines) + "\n")
        return path

    def test_parts_resting_on_each_other_are_a_whole(self):
        # Two cubes as two objects, one on the other: their touching corners
        # at the same positions. Each part is judged alone and the parts
        # against each other, never welded together: the whole is answered,
        # the sum of the parts, with the touching warning.
        path = self.objects("stacked.obj", ((0, 0, 0), (1, 1, 1)), ((0, 0, 1), (1, 1, 2)))
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["volume"], 2.0)
        self.assertEqual(out["center_of_mass"], [0.5, 0.5, 1.0])
        self.assertEqual(out["warnings"], ["touching_faces"])
        self.assertEqual([p["volume"] for p in out["parts"]], [1.0, 1.0])
        # Exact solids, each part and their sum: no approximation to bound.
        self.assertEqual(out["provenance"], {"mode": "solid"})
        self.assertEqual([p["provenance"] for p in out["parts"]], [{"mode": "solid"}] * 2)
        # Checked against each other, the parts carry no "unchecked" warning.
        self.assertEqual([p["warnings"] for p in out["parts"]], [[], []])
        # A cube resting half on the other, and three stacked: the same.
        path = self.objects("half_on.obj", ((0, 0, 0), (1, 1, 1)), ((0.5, 0, 1), (1.5, 1, 2)))
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual((out["volume"], out["warnings"]), (2.0, ["touching_faces"]))
        boxes = [((0, 0, k), (1, 1, k + 1)) for k in range(3)]
        result, out = run_json(self.objects("three.obj", *boxes))
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["volume"], 3.0)

    def test_parts_crossing_or_nested_are_refused(self):
        for name, second, volume in (
            ("crossing_parts.obj", ((0.5, 0.5, 0.5), (1.5, 1.5, 1.5)), 1.0),
            ("nested_parts.obj", ((0.25, 0.25, 0.25), (0.75, 0.75, 0.75)), 0.125),
        ):
            path = self.objects(name, ((0, 0, 0), (1, 1, 1)), second)
            result, out = run_json(path)
            self.assertEqual(result.returncode, EXIT_INVALID_MESH, name)
            self.assertEqual(out["error"]["category"], "intersecting", name)
            self.assertEqual([p["volume"] for p in out["parts"]], [1.0, volume])
            # Skipped by name, each part is still answered and the whole is their sum,
            # each saying the check did not run.
            result, out = run_json("--no-intersection-check", path)
            self.assertEqual(result.returncode, EXIT_OK, result.stderr)
            self.assertEqual(out["volume"], 1.0 + volume)
            self.assertEqual(out["warnings"], ["intersections_unchecked"])
            for part in out["parts"]:
                self.assertEqual(part["warnings"], ["intersections_unchecked"])
        # A fallback answers the crossing whole by its chain, and says so.
        path = WORK / "crossing_parts.obj"
        result, out = run_json("--fallback", "repair,hull", path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertNotEqual(out["provenance"]["mode"], "solid")

    def test_check_judges_parts_as_computing_does(self):
        # polymass check judges a file of several parts part by part, as
        # polymass FILE does: the same verdict, the same exit status.
        cases = (
            ("stacked.obj", ((0, 0, 1), (1, 1, 2)), None),
            ("half_on.obj", ((0.5, 0, 1), (1.5, 1, 2)), None),
            ("crossing_parts.obj", ((0.5, 0.5, 0.5), (1.5, 1.5, 1.5)), "intersecting"),
            ("nested_parts.obj", ((0.25, 0.25, 0.25), (0.75, 0.75, 0.75)), "intersecting"),
        )
        for name, second, category in cases:
            path = self.objects(name, ((0, 0, 0), (1, 1, 1)), second)
            computed, out = run_json(path)
            checked = run("check", "--json", path)
            self.assertEqual(checked.returncode, computed.returncode, name)
            report = json.loads(checked.stdout)
            self.assertEqual(report["valid"], category is None, name)
            self.assertEqual(report["shells"], 2, name)
            if category is None:
                self.assertEqual(out["warnings"], ["touching_faces"], name)
                self.assertGreater(report["touching_face_pairs"]["count"], 0, name)
                self.assertEqual(report["non_manifold_edges"]["count"], 0, name)
                self.assertEqual(report["answer"], {"mode": "solid"}, name)
            else:
                self.assertEqual(report["category"], out["error"]["category"], name)
        # The crossing pair is located as in the file: a face of the first
        # object (faces 0-5, shell 0) and one of the second (6-11, shell 1).
        report = json.loads(run("check", "--json", WORK / "crossing_parts.obj").stdout)
        pairs = report["intersecting_face_pairs"]
        self.assertGreater(pairs["count"], 0)
        for (low, high), shells in zip(pairs["first_pairs"], pairs["first_pair_shells"]):
            self.assertLess(low, 6)
            self.assertGreaterEqual(high, 6)
            self.assertEqual(shells, [0, 1])
        self.assertEqual(report["overlapping_shells"]["count"], 0)
        report = json.loads(run("check", "--json", WORK / "nested_parts.obj").stdout)
        self.assertEqual(report["overlapping_shells"]["first_shells"], [1])

    def test_check_judges_parts_sharing_vertices_apart(self):
        # The second object stands on the first's top corners, using the
        # file's vertices 4 to 7 as its bottom: welded as one surface those
        # edges would be used by four faces; judged apart, the second part
        # has its own copies, and the parts touch.
        cube_vertices, cube_faces = fixtures.cube()
        vertices = cube_vertices + [(x, y, z + 1) for x, y, z in cube_vertices if z]
        second = [k + 4 for k in range(8)]  # its bottom the file's 4-7, its top 8-11
        lines = [f"v {x} {y} {z}" for x, y, z in vertices] + ["o first"]
        lines += ["f " + " ".join(str(i + 1) for i in f) for f in cube_faces]
        lines.append("o second")
        lines += ["f " + " ".join(str(second[i] + 1) for i in f) for f in cube_faces]
        path = WORK / "sharing_parts.obj"
        path.write_text("\n".join(lines) + "\n")
        computed, out = run_json(path)
        self.assertEqual(computed.returncode, EXIT_OK, computed.stderr)
        self.assertEqual(out["volume"], 2.0)
        checked = run("check", "--json", path)
        self.assertEqual(checked.returncode, EXIT_OK, checked.stdout)
        report = json.loads(checked.stdout)
        self.assertEqual(report["non_manifold_edges"]["count"], 0)
        self.assertGreater(report["touching_face_pairs"]["count"], 0)
        self.assertEqual([s["kind"] for s in report["shell_list"]], ["solid", "solid"])

    def test_exact_parts_give_the_same_bits_whatever_the_fallback(self):
        # The bracket and a copy moved by (3.3, 0, 1.7): integrated as one
        # surface the whole differed from the parts' sum in its last digits.
        vertices, faces = fixtures.bracket()
        n = len(vertices)
        moved = [(x + 3.3, y, z + 1.7) for x, y, z in vertices]
        lines = ["o first"] + [f"v {x!r} {y!r} {z!r}" for x, y, z in vertices + moved]
        lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
        lines += ["o second"] + ["f " + " ".join(str(i + 1 + n) for i in f) for f in faces]
        path = WORK / "two_brackets.obj"
        path.write_text("\n".join(lines) + "\n")
        _, exact = run_json(path)
        keys = ("volume", "center_of_mass", "inertia", "principal_moments", "surface_area")
        for fallback in ("repair", "hull", "repair,hull", "repair,shell"):
            extra = ["--shell", "0.1"] if "shell" in fallback else []
            result, out = run_json("--fallback", fallback, *extra, path)
            self.assertEqual(result.returncode, EXIT_OK, result.stderr)
            for key in keys:
                self.assertEqual(out[key], exact[key], f"{fallback}: {key}")
            self.assertEqual(out["parts"], exact["parts"], fallback)

    def test_a_solid_inside_a_solid_is_counted_twice(self):
        path = self.cubes("nested.obj", (0.25, 0.25, 0.25), (0.75, 0.75, 0.75))
        report = json.loads(run("check", "--json", path).stdout)
        self.assertEqual(report["category"], "intersecting")
        self.assertEqual(report["overlapping_shells"]["count"], 1)
        self.assertEqual(report["overlapping_shells"]["first_shells"], [1])
        kinds = [s["kind"] for s in report["shell_list"]]
        self.assertEqual(kinds, ["solid", "overlapping"])
        # The same box inside out is a cavity.
        path = self.cubes("cavity.obj", (0.25, 0.25, 0.25), (0.75, 0.75, 0.75), True)
        result, out = run_json(path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["volume"], 1 - 0.125)

    def test_valid_solid_with_two_shells(self):
        result = run("check", "--json", SOURCE / "examples" / "data" / "hollow_box.obj")
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        report = json.loads(result.stdout)
        self.assertIs(report["valid"], True)
        self.assertEqual(report["shells"], 2)
        # A 40 mm cube around a 30 x 30 x 20 mm cavity.
        shells = sorted((s["kind"], s["signed_volume"]) for s in report["shell_list"])
        self.assertEqual([kind for kind, _ in shells], ["cavity", "solid"])
        # Each shell's volume is a sum over its faces, exact to rounding.
        for (_, got), expected in zip(shells, (-18000.0, 64000.0)):
            self.assertAlmostEqual(got, expected, delta=1e-12 * abs(expected))
        self.assertEqual(report["open_edges"]["count"], 0)
        self.assertEqual(report["open_edges"]["first_edges"], [])

    def test_a_disjoint_inverted_shell(self):
        # A unit cube and, apart, a half-size one inside out: the surface is
        # closed and its total volume positive (7/8), yet it is not a solid.
        cube_vertices, cube_faces = fixtures.cube()
        vertices = cube_vertices + [(x / 2 + 3, y / 2, z / 2) for x, y, z in cube_vertices]
        n = len(cube_vertices)
        faces = cube_faces + [[n + i for i in reversed(f)] for f in cube_faces]
        fixtures.write_obj(WORK / "inverted_shell.obj", vertices, faces)
        result = run("check", "--json", WORK / "inverted_shell.obj")
        self.assertEqual(result.returncode, EXIT_INVALID_MESH, result.stdout)
        report = json.loads(result.stdout)
        self.assertEqual(report["category"], "inverted")
        self.assertIn("shell 1 (6 faces, the first face 6", report["message"])
        self.assertIs(report["valid"], False)
        kinds = [s["kind"] for s in report["shell_list"]]
        self.assertEqual(kinds, ["solid", "inverted"])
        # Computing the part refuses it the same way (not a 7/8 body with a
        # negative moment), and so does the inertial for a model file.
        result, out = run_json(WORK / "inverted_shell.obj")
        self.assertEqual(result.returncode, EXIT_INVALID_MESH, result.stdout)
        self.assertEqual(out["error"]["category"], "inverted")
        self.assertEqual(run("--urdf", WORK / "inverted_shell.obj").returncode, EXIT_INVALID_MESH)

    def test_a_whole_inverted_file_accepted_has_no_inverted_shell(self):
        cube_vertices, cube_faces = fixtures.cube()
        vertices = cube_vertices + [(x + 3, y, z) for x, y, z in cube_vertices]
        n = len(cube_vertices)
        faces = [list(reversed(f)) for f in cube_faces]
        faces += [[n + i for i in reversed(f)] for f in cube_faces]
        fixtures.write_obj(WORK / "all_inverted.obj", vertices, faces)
        result, out = run_json("--accept-inverted", WORK / "all_inverted.obj")
        self.assertEqual(result.returncode, EXIT_OK, result.stdout)
        self.assertEqual(out["warnings"], ["inverted"])
        result = run("check", "--json", "--accept-inverted", WORK / "all_inverted.obj")
        self.assertEqual(result.returncode, EXIT_OK, result.stdout)
        kinds = [s["kind"] for s in json.loads(result.stdout)["shell_list"]]
        self.assertEqual(kinds, ["solid", "solid"])

    def test_open_mesh_is_located(self):
        vertices, faces = fixtures.bracket()
        fixtures.write_obj(WORK / "open.obj", vertices, faces[:-1])
        result = run("check", "--json", WORK / "open.obj")
        self.assertEqual(result.returncode, EXIT_INVALID_MESH)
        report = json.loads(result.stdout)
        self.assertEqual(report["category"], "open")
        self.assertEqual(report["open_edges"]["count"], len(faces[-1]))
        # Every edge of the missing face, each in the direction its remaining
        # neighbour traverses it: against the missing face's own.
        hole = faces[-1]
        rim = {(hole[(i + 1) % len(hole)], hole[i]) for i in range(len(hole))}
        self.assertEqual({tuple(e) for e in report["open_edges"]["first_edges"]}, rim)
        text = run("check", WORK / "open.obj")
        self.assertEqual(text.returncode, EXIT_INVALID_MESH)
        self.assertIn("NOT A VALID SOLID", text.stdout)

    def test_unreadable(self):
        result = run("check", WORK / "does_not_exist.stl")
        self.assertEqual(result.returncode, EXIT_UNREADABLE)


class Outputs(Case):
    """What the outputs say besides the numbers, and how they write them."""

    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.vertices, cls.faces = fixtures.bracket()
        cls.path = WORK / "outputs_bracket.obj"
        fixtures.write_obj(cls.path, cls.vertices, cls.faces)

    @staticmethod
    def parse_xml(text):
        """The elements and comments of an XML output, in order."""
        builder = ElementTree.TreeBuilder(insert_comments=True)
        parser = ElementTree.XMLParser(target=builder)
        parser.feed("<output>" + text + "</output>")
        return list(parser.close())

    @staticmethod
    def comments(nodes):
        return [n.text.strip() for n in nodes if n.tag is ElementTree.Comment]

    def test_warnings_reach_stderr_and_the_xml(self):
        inverted = WORK / "outputs_inverted.obj"
        fixtures.write_obj(inverted, self.vertices, [list(reversed(f)) for f in self.faces])
        for output in ("--json", "--urdf", "--sdf", "--mjcf", None):
            with self.subTest(output=output):
                args = [output] if output else []
                result = run("--accept-inverted", *args, inverted)
                self.assertEqual(result.returncode, EXIT_OK, result.stderr)
                self.assertIn("warning: inverted", result.stderr)
                if output not in (None, "--json"):
                    comments = self.comments(self.parse_xml(result.stdout))
                    self.assertTrue(any("inverted" in c for c in comments), comments)

    def test_file_units_note(self):
        result = run("--urdf", self.path)
        self.assertIn("note: lengths are in the file's units", result.stderr)
        comments = self.comments(self.parse_xml(result.stdout))
        self.assertTrue(any("file's units" in c for c in comments), comments)
        result = run("--urdf", "--units", "mm", self.path)
        self.assertNotIn("file's units", result.stderr + result.stdout)
        # A 3MF declares its unit: in metres, no note, alone; beside the OBJ,
        # only the OBJ's inertial says its lengths are the file's.
        threemf = WORK / "outputs_bracket.3mf"
        fixtures.write_3mf(threemf, self.vertices, self.faces)
        result = run("--urdf", threemf)
        self.assertNotIn("file's units", result.stderr + result.stdout)
        groups = [[]]
        for node in self.parse_xml(run("--urdf", threemf, self.path).stdout):
            groups[-1].append(node)
            if node.tag == "inertial":
                groups.append([])
        self.assertFalse(any("file's units" in c for c in self.comments(groups[0])), groups[0])
        self.assertTrue(any("file's units" in c for c in self.comments(groups[1])), groups[1])

    def test_no_negative_zero_and_symmetric_tensors(self):
        # A cube centred on the origin, and the bracket turned and far away:
        # zeros print as 0, [i][j] and [j][i] are the same double.
        cube, quads = fixtures.cube()
        centred = WORK / "outputs_centred_cube.obj"
        fixtures.write_obj(centred, [tuple(c - 0.5 for c in v) for v in cube], quads)
        far = WORK / "outputs_far.obj"
        fixtures.write_obj(
            far, [(y + 1e6, -x + 3e7, z * 3 - 2e5) for x, y, z in self.vertices], self.faces
        )
        negative_zero = re.compile(r"(?<![\d.eE])-0(\.0*)?(?![.\deE])")
        for path in (centred, far):
            for output in ("--json", "--urdf", "--sdf", "--mjcf", None):
                with self.subTest(path=path.name, output=output):
                    result = run(*([output] if output else []), "--about", "origin", path)
                    self.assertEqual(result.returncode, EXIT_OK, result.stderr)
                    self.assertIsNone(negative_zero.search(result.stdout), result.stdout)
            _, out = run_json(path)
            for key in ("inertia", "inertia_origin"):
                m = out[key]
                for i in range(3):
                    for j in range(3):
                        self.assertEqual(repr(m[i][j]), repr(m[j][i]), f"{path.name} {key}")

    def test_failed_file_comment_says_why(self):
        result = run("--sdf", self.path, WORK / "outputs_missing.obj")
        self.assertEqual(result.returncode, EXIT_UNREADABLE)
        nodes = self.parse_xml(result.stdout)
        self.assertEqual([n.tag for n in nodes if n.tag is not ElementTree.Comment], ["inertial"])
        failed = [c for c in self.comments(nodes) if "outputs_missing.obj" in c]
        self.assertEqual(len(failed), 1)
        self.assertIn("no inertial", failed[0])
        self.assertIn("cannot open", failed[0])

    def test_origin_of_the_link_frame(self):
        origin = (0.25, -1.5, 1e3)
        _, out = run_json(self.path)
        com = out["center_of_mass"]
        expected = [c - o for c, o in zip(com, origin)]
        text = ",".join(map(repr, origin))
        urdf = self.parse_xml(run("--urdf", "--origin", text, self.path).stdout)[-1]
        self.assertEqual([float(x) for x in urdf.find("origin").get("xyz").split()], expected)
        sdf = self.parse_xml(run("--sdf", "--origin", text, self.path).stdout)[-1]
        self.assertEqual([float(x) for x in sdf.find("pose").text.split()], expected + [0, 0, 0])
        mjcf = self.parse_xml(run("--mjcf", "--origin", text, self.path).stdout)[-1]
        self.assertEqual([float(x) for x in mjcf.get("pos").split()], expected)
        for args in (
            ["--origin", text],
            ["--json", "--origin", text],
            ["--urdf", "--origin", "1,2"],
        ):
            with self.subTest(args=args):
                result = run(*args, self.path)
                self.assertEqual(result.returncode, EXIT_USAGE, result.stderr)
                self.assertIn("--origin", result.stderr)


class Modes(Case):
    """--repair, --shell, --hull, --fallback: answers that say how they were reached."""

    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.vertices, cls.faces = fixtures.bracket()
        cls.expected = generate.exact_properties(cls.vertices, cls.faces)
        cls.valid = WORK / "modes_bracket.obj"
        fixtures.write_obj(cls.valid, cls.vertices, cls.faces)
        # Without its top cap (a planar face): open.
        cls.open = WORK / "modes_open.obj"
        fixtures.write_obj(cls.open, cls.vertices, cls.faces[:1] + cls.faces[2:])

    def test_a_refusal_names_the_option_that_answers(self):
        result, out = run_json(self.open)
        self.assertEqual(result.returncode, EXIT_INVALID_MESH)
        self.assertIn("--repair would give an answer", out["error"]["message"])

    def test_repair_caps_the_hole_within_its_bound(self):
        result, out = run_json("--repair", self.open)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        provenance = out["provenance"]
        self.assertEqual(provenance["mode"], "repaired")
        self.assertEqual(provenance["repairs"]["holes"]["count"], 1)
        self.assertGreater(provenance["cap_area_fraction"], 0)
        self.assertIn("repaired", out["warnings"])
        # The cap of a planar hole is the missing face: within the bound, and exact.
        self.assertLessEqual(
            abs(out["volume"] - self.expected["volume"]), out["error_bound"]["volume"]
        )
        self.assert_properties(out, self.expected, what="repaired")
        table = run("--repair", self.open).stdout
        self.assertIn("repaired: 1 holes capped", table)
        self.assertIn("error bound", table)

    def test_a_valid_solid_is_answered_as_without_modes(self):
        _, plain = run_json(self.valid)
        for args in (["--repair"], ["--fallback", "repair,hull"]):
            with self.subTest(args=args):
                result, out = run_json(*args, self.valid)
                self.assertEqual(result.returncode, EXIT_OK)
                self.assertEqual(out["provenance"], {"mode": "solid"})
                self.assertEqual(out, plain)

    def test_hull_and_shell(self):
        _, hull = run_json("--hull", self.open)
        self.assertEqual(hull["provenance"]["mode"], "hull")
        self.assertGreaterEqual(hull["volume"], self.expected["volume"])
        self.assertGreaterEqual(
            hull["error_bound"]["volume"], hull["volume"] - self.expected["volume"]
        )
        _, shell = run_json("--shell", "0.01", "--density", "2", self.open)
        self.assertEqual(shell["provenance"]["mode"], "shell")
        area = shell["provenance"]["shell_area"]
        self.assert_close(shell["mass"], 2 * 0.01 * area, shell["mass"], "shell mass")
        _, chain = run_json("--fallback", "repair,hull", self.open)
        self.assertEqual(chain["provenance"]["mode"], "repaired")

    def test_xml_says_how_the_answer_was_reached(self):
        result = run("--repair", "--urdf", self.open)
        self.assertEqual(result.returncode, EXIT_OK)
        comments = Outputs.comments(Outputs.parse_xml(result.stdout))
        self.assertTrue(any(c.startswith("provenance: repaired") for c in comments), comments)
        self.assertTrue(any(c.startswith("error bound: volume") for c in comments), comments)

    def test_check_says_which_mode_answers(self):
        result = run("check", "--json", self.open)
        self.assertEqual(result.returncode, EXIT_INVALID_MESH)
        self.assertEqual(
            json.loads(result.stdout)["answer"], {"mode": "repaired", "option": "--repair"}
        )
        self.assertEqual(
            json.loads(run("check", "--json", self.valid).stdout)["answer"], {"mode": "solid"}
        )
        self.assertIn("--repair would give an answer", run("check", self.open).stdout)
        # Answered by --repair, the one analysis still says what is wrong with the surface.
        result = run("check", "--json", "--repair", self.open)
        self.assertEqual(result.returncode, EXIT_INVALID_MESH)
        report = json.loads(result.stdout)
        self.assertEqual(report["answer"], {"mode": "repaired"})
        self.assertEqual(report["category"], "open")
        self.assertIn("used by one face only", report["message"])

    def test_mode_usage_errors(self):
        for args in (
            ["--repair", "--hull"],
            ["--fallback", "repair,bogus"],
            ["--fallback", "shell"],
            ["--shell", "0.1", "--fallback", "repair"],
            ["--shell", "-1"],
        ):
            with self.subTest(args=args):
                self.assertEqual(run(*args, self.valid).returncode, EXIT_USAGE)


class BundledMeshes(Case):
    """Every mesh of examples/data gives the properties expected.json documents."""

    def test_bundled_meshes(self):
        data = SOURCE / "examples" / "data"
        expected = json.loads((data / "expected.json").read_text())
        self.assertGreaterEqual(len(expected), 4)
        for name, values in expected.items():
            with self.subTest(mesh=name):
                result, out = run_json(data / name)
                self.assertEqual(result.returncode, EXIT_OK, result.stderr)
                self.assert_properties(out, values, what=name)
                self.assertEqual(out["faces"], values["faces"])
                self.assertEqual(out["vertices"], values["vertices"])


if __name__ == "__main__":
    unittest.main(verbosity=2)
