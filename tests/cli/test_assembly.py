"""Tests of `polymass assembly FILE.json` and of per-part materials
(`--density NAME=D`, `--mass NAME=M`) of a file with several parts, run by
ctest with the environment of test_cli.py.

Every expected value is exact: boxes with integer sides placed by rotations
whose matrices are exact (or exact to rounding), composed here in rational
arithmetic with the parallel-axis theorem.
"""

import json
import math
import unittest
from fractions import Fraction
from xml.etree import ElementTree

import test_cli
from test_cli import EXIT_INVALID_MESH, EXIT_OK, EXIT_UNREADABLE, EXIT_USAGE, SOURCE, WORK, run

import fixtures

ASSEMBLIES = WORK / "assemblies"
SIDES = (1, 2, 3)  # the box [0, 1] x [0, 2] x [0, 3]


def box_vertices(sides):
    a, b, c = sides
    return [(x * a, y * b, z * c) for x, y, z in fixtures.cube()[0]]


def box_body(mass, rotation, translation, sides=SIDES):
    """Mass, centre of mass and inertia about it (Fractions) of the box moved
    by x -> R x + t."""
    a, b, c = (Fraction(s) for s in sides)
    centre = [a / 2, b / 2, c / 2]
    diagonal = [
        mass * (b * b + c * c) / 12,
        mass * (a * a + c * c) / 12,
        mass * (a * a + b * b) / 12,
    ]
    moved = [sum(rotation[i][k] * centre[k] for k in range(3)) + translation[i] for i in range(3)]
    inertia = [
        [sum(rotation[i][k] * diagonal[k] * rotation[j][k] for k in range(3)) for j in range(3)]
        for i in range(3)
    ]
    return mass, moved, inertia


def whole(bodies):
    """The bodies as one: the parallel-axis theorem, exactly."""
    mass = sum(m for m, _, _ in bodies)
    centre = [sum(m * c[i] for m, c, _ in bodies) / mass for i in range(3)]
    inertia = [[Fraction(0)] * 3 for _ in range(3)]
    for m, c, own in bodies:
        d = [c[i] - centre[i] for i in range(3)]
        d2 = sum(x * x for x in d)
        for i in range(3):
            for j in range(3):
                inertia[i][j] += own[i][j] + m * ((d2 if i == j else 0) - d[i] * d[j])
    return mass, centre, inertia


IDENTITY = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
CYCLE = [[0, 0, 1], [1, 0, 0], [0, 1, 0]]  # 120 degrees about (1, 1, 1): q = (1/2, 1/2, 1/2, 1/2)
QUARTER_Z = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]  # 90 degrees about z
HALF = math.sqrt(0.5)


def write_assembly(name, document):
    ASSEMBLIES.mkdir(parents=True, exist_ok=True)
    path = ASSEMBLIES / name
    path.write_text(document if isinstance(document, str) else json.dumps(document))
    return path


class Case(test_cli.Case):
    def assert_body(self, out, body, what):
        mass, centre, inertia = body
        self.assert_close(out["mass"], float(mass), float(mass), what + " mass")
        size = max(abs(float(c)) for c in centre) + 3
        for k in range(3):
            self.assert_close(out["center_of_mass"][k], float(centre[k]), size, what + " com")
        self.assert_matrix(out["inertia"], [[float(x) for x in row] for row in inertia], what)


class Assembly(Case):
    @classmethod
    def setUpClass(cls):
        ASSEMBLIES.mkdir(parents=True, exist_ok=True)
        (ASSEMBLIES / "meshes").mkdir(exist_ok=True)
        fixtures.write_obj(
            ASSEMBLIES / "meshes" / "box.obj", box_vertices(SIDES), fixtures.cube()[1]
        )
        fixtures.write_obj(ASSEMBLIES / "cube.obj", *fixtures.cube())

    def three_boxes(self):
        """A box at the origin by its density; one turned by a quaternion
        [w, x, y, z] by its mass; one a million units away, turned by an
        [x, y, z, w] quaternion, by its density."""
        return {
            "parts": [
                {"name": "plain", "mesh": "meshes/box.obj", "density": 2},
                {
                    "name": "turned",
                    "mesh": "meshes/box.obj",
                    "mass": 5,
                    "translation": [1, -2, 0.5],
                    "rotation": {"quaternion_wxyz": [0.5, 0.5, 0.5, 0.5]},
                },
                {
                    "name": "far",
                    "mesh": "meshes/box.obj",
                    "density": 0.25,
                    "translation": [1e6, 1e6, 1e6],
                    "rotation": {"quaternion_xyzw": [0, 0, HALF, HALF]},
                },
            ]
        }

    def test_three_parts_give_the_exact_whole(self):
        path = write_assembly("three.json", self.three_boxes())
        result, out = test_cli.run_json("assembly", path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["format"], "assembly")
        self.assertEqual([p["name"] for p in out["parts"]], ["plain", "turned", "far"])
        volume = Fraction(6)
        bodies = [
            box_body(2 * volume, IDENTITY, [0, 0, 0]),
            box_body(Fraction(5), CYCLE, [1, -2, Fraction(1, 2)]),
            box_body(volume / 4, QUARTER_Z, [10**6] * 3),
        ]
        for part, body in zip(out["parts"], bodies):
            self.assert_body(part, body, part["name"])
            self.assertEqual(part["volume"], 6.0)
            self.assertEqual(part["surface_area"], 22.0)
        # The far part keeps its own inertia's digits: 1e6 away, not 1e-4 of them.
        self.assertEqual(out["parts"][1]["density"], 5 / 6)
        self.assert_body(out, whole(bodies), "whole")
        self.assertEqual(out["volume"], 18.0)
        self.assertEqual(out["surface_area"], 66.0)
        self.assertIn("not checked against each other", " ".join(out["notes"]))

    def test_about_a_point_and_the_outputs(self):
        path = write_assembly("three.json", self.three_boxes())
        _, out = test_cli.run_json("assembly", "--about", "1,2,3", path)
        mass, centre, inertia = whole(
            [
                box_body(Fraction(12), IDENTITY, [0, 0, 0]),
                box_body(Fraction(5), CYCLE, [1, -2, Fraction(1, 2)]),
                box_body(Fraction(3, 2), QUARTER_Z, [10**6] * 3),
            ]
        )
        d = [centre[i] - (i + 1) for i in range(3)]
        about = [
            [
                inertia[i][j] + mass * ((sum(x * x for x in d) if i == j else 0) - d[i] * d[j])
                for j in range(3)
            ]
            for i in range(3)
        ]
        self.assert_matrix(out["inertia_point"], [[float(x) for x in r] for r in about], "point")
        urdf = ElementTree.fromstring(f"<robot>{run('assembly', '--urdf', path).stdout}</robot>")
        self.assertEqual(len(urdf.findall("inertial")), 1)
        self.assertEqual(float(urdf.find("inertial/mass").get("value")), float(mass))
        table = run("assembly", path)
        self.assertEqual(table.returncode, EXIT_OK, table.stderr)
        self.assertIn("part 'far'", table.stdout)

    def test_units_convert_each_part_to_metres(self):
        document = {
            "parts": [
                {"mesh": "meshes/box.obj", "units": "mm", "density": 8000},
                {"mesh": "meshes/box.obj", "units": "cm", "mass": 2, "translation": [0, 0, 1]},
            ]
        }
        result, out = test_cli.run_json("assembly", write_assembly("units.json", document))
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["length_unit"], "m")
        self.assertEqual([p["name"] for p in out["parts"]], ["meshes/box.obj"] * 2)
        self.assert_close(out["parts"][0]["volume"], 6e-9, 6e-9, "mm volume")
        self.assert_close(out["parts"][0]["mass"], 4.8e-5, 4.8e-5, "mm mass")
        self.assert_close(out["parts"][1]["volume"], 6e-6, 6e-6, "cm volume")
        self.assert_close(out["parts"][1]["mass"], 2.0, 2.0, "cm mass")
        self.assert_close(out["parts"][1]["center_of_mass"][2], 1.015, 1, "cm com")
        self.assert_close(out["parts"][1]["surface_area"], 22e-4, 22e-4, "cm area")
        body = box_body(Fraction(2), IDENTITY, [0, 0, 1], sides=[Fraction(s, 100) for s in SIDES])
        self.assert_body(out["parts"][1], body, "cm part")

    def test_a_mesh_that_declares_its_unit(self):
        # A 3MF in millimetres is read in metres: alone, the assembly is in
        # metres without "units"; with "units" its own unit wins (never
        # scaled twice), the note says so; beside a mesh without a unit and
        # no "units", the lengths could not be added: an error naming both.
        fixtures.write_3mf(ASSEMBLIES / "box_mm.3mf", box_vertices(SIDES), fixtures.cube()[1])
        alone = {"parts": [{"mesh": "box_mm.3mf", "mass": 2, "translation": [0, 0, 1]}]}
        result, out = test_cli.run_json("assembly", write_assembly("3mf.json", alone))
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["length_unit"], "m")
        self.assert_close(out["volume"], 6e-9, 6e-9, "mm volume")
        body = box_body(Fraction(2), IDENTITY, [0, 0, 1], sides=[Fraction(s, 1000) for s in SIDES])
        self.assert_body(out, body, "3mf part")
        self.assertIn(
            'parts[0] "box_mm.3mf": lengths in metres (the file\'s unit: millimeter)',
            out["notes"],
        )
        both = {
            "parts": [
                {"mesh": "box_mm.3mf", "units": "in", "density": 8000},
                {"mesh": "meshes/box.obj", "units": "cm", "density": 8000},
            ]
        }
        result, out = test_cli.run_json("assembly", write_assembly("3mf_units.json", both))
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["length_unit"], "m")
        self.assert_close(out["parts"][0]["volume"], 6e-9, 6e-9, "3mf volume")
        self.assert_close(out["parts"][1]["volume"], 6e-6, 6e-6, "cm volume")
        self.assertIn(
            'parts[0] "box_mm.3mf": "units" not applied: the mesh declares its unit', out["notes"]
        )
        mixed = {
            "parts": [
                {"mesh": "meshes/box.obj", "density": 1},
                {"mesh": "box_mm.3mf", "density": 1},
            ]
        }
        result, out = test_cli.run_json("assembly", write_assembly("3mf_mixed.json", mixed))
        self.assertEqual(result.returncode, EXIT_UNREADABLE, result.stdout)
        self.assertIn(
            'parts[1] "box_mm.3mf": its mesh declares its unit (its lengths are metres) where '
            'parts[0] "meshes/box.obj"\'s does not',
            out["error"]["message"],
        )

    def test_a_mirror_only_when_stated(self):
        mirror = {"matrix": [[-1, 0, 0], [0, 1, 0], [0, 0, 1]]}
        part = {"mesh": "cube.obj", "density": 1, "rotation": mirror, "mirror": True}
        result, out = test_cli.run_json(
            "assembly", write_assembly("mirror.json", {"parts": [part]})
        )
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["volume"], 1.0)
        self.assertEqual(out["center_of_mass"], [-0.5, 0.5, 0.5])
        self.assertNotIn("parts", out)  # one part is the whole

    def test_the_bundled_example(self):
        path = SOURCE / "examples" / "data" / "arm_assembly.json"
        result, out = test_cli.run_json("assembly", path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        expected = json.loads((SOURCE / "examples" / "data" / "expected.json").read_text())
        plate = expected["plate_with_hole.obj"]
        self.assert_close(out["parts"][0]["mass"], plate["volume"] * 1e-9 * 2700, 1, "plate")
        self.assertEqual(out["parts"][2]["mass"], 0.35)
        self.assertEqual(out["mass"], sum(p["mass"] for p in out["parts"]))

    def test_a_part_that_is_not_a_solid(self):
        vertices, faces = fixtures.cube()
        fixtures.write_obj(ASSEMBLIES / "open.obj", vertices, faces[1:])
        document = {"parts": [{"mesh": "cube.obj", "density": 1}, {"mesh": "open.obj", "mass": 1}]}
        result, out = test_cli.run_json("assembly", write_assembly("open.json", document))
        self.assertEqual(result.returncode, EXIT_INVALID_MESH)
        self.assertEqual(out["error"]["category"], "open")
        self.assertIn('parts[1] "open.obj"', out["error"]["message"])
        self.assertEqual(out["parts"][0]["volume"], 1.0)
        self.assertIn("edge", out["parts"][1]["error"]["message"])

    def test_a_mesh_of_parts_resting_on_each_other(self):
        # The box as two OBJ objects, [0, 1] x [0, 2] x [0, 1] under
        # [0, 1] x [0, 2] x [1, 3], resting on each other: judged as
        # `polymass FILE` judges them (never welded together, whose shared
        # edges would be used by four faces), the part is the whole box,
        # exactly, turned and moved like any.
        lines = []
        for k, (z0, z1) in enumerate(((0, 1), (1, 3))):
            lines.append(f"o half{k}")
            lines += [f"v {x} {2 * y} {z1 if z else z0}" for x, y, z in fixtures.cube()[0]]
            base = 1 + 8 * k
            lines += ["f " + " ".join(str(base + i) for i in f) for f in fixtures.cube()[1]]
        (ASSEMBLIES / "meshes" / "halves.obj").write_text("\n".join(lines) + "\n")
        document = {
            "parts": [
                {
                    "name": "halves",
                    "mesh": "meshes/halves.obj",
                    "mass": 5,
                    "translation": [1, -2, 0.5],
                    "rotation": {"quaternion_wxyz": [0.5, 0.5, 0.5, 0.5]},
                }
            ]
        }
        result, out = test_cli.run_json("assembly", write_assembly("halves.json", document))
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        # One part: the assembly is that part.
        self.assert_body(out, box_body(Fraction(5), CYCLE, [1, -2, Fraction(1, 2)]), "halves")
        self.assertEqual(out["volume"], 6.0)
        # The halves' 10 + 16, as `polymass FILE` adds its parts' areas.
        self.assertEqual(out["surface_area"], 26.0)
        self.assertIn("touching_faces", out["warnings"])


# (case, the assembly file, what its message says)
BAD_FIELDS = [
    ("not json", "{", "not valid JSON"),
    ("not an object", "[]", "an object {...} is expected"),
    (
        "unknown top key",
        {"parts": [], "part": []},
        'part: unknown key; an assembly file has "parts"',
    ),
    ("no parts", {}, "parts: a non-empty array"),
    ("empty parts", {"parts": []}, "parts: a non-empty array"),
    ("part not an object", {"parts": [3]}, "parts[0]: an object"),
    ("no mesh", {"parts": [{"density": 1}]}, 'parts[0]: the part has no "mesh"'),
    ("mesh not text", {"parts": [{"mesh": 1, "density": 1}]}, "parts[0]: mesh: a string"),
    (
        "typo",
        {"parts": [{"mesh": "cube.obj", "densty": 2}]},
        'parts[0] "cube.obj": give exactly one of "density", "material" and "mass"',
    ),
    (
        "unknown key",
        {"parts": [{"mesh": "cube.obj", "density": 2, "densty": 2}]},
        'parts[0] "cube.obj": densty: unknown key',
    ),
    (
        "both",
        {"parts": [{"mesh": "cube.obj", "density": 2, "mass": 1}]},
        'exactly one of "density", "material" and "mass"',
    ),
    ("negative", {"parts": [{"mesh": "cube.obj", "mass": -1}]}, "mass: a positive number"),
    ("text density", {"parts": [{"mesh": "cube.obj", "density": "2"}]}, "density: a number"),
    ("units", {"parts": [{"mesh": "cube.obj", "density": 1, "units": "km"}]}, '"km" is not one'),
    (
        "mixed units",
        {
            "parts": [
                {"mesh": "cube.obj", "density": 1, "units": "mm"},
                {"name": "b", "mesh": "cube.obj", "density": 1},
            ]
        },
        'parts[1] "b": no "units", where other parts give theirs',
    ),
    (
        "short translation",
        {"parts": [{"mesh": "cube.obj", "density": 1, "translation": [1, 2]}]},
        "translation: an array of 3 numbers",
    ),
    (
        "two rotations",
        {
            "parts": [
                {
                    "mesh": "cube.obj",
                    "density": 1,
                    "rotation": {"quaternion_wxyz": [1, 0, 0, 0], "quaternion_xyzw": [0, 0, 0, 1]},
                }
            ]
        },
        "rotation: give exactly one of",
    ),
    (
        "quaternion without its order",
        {"parts": [{"mesh": "cube.obj", "density": 1, "rotation": {"quaternion": [1, 0, 0, 0]}}]},
        "rotation.quaternion: unknown key",
    ),
    (
        "not a unit quaternion",
        {
            "parts": [
                {"mesh": "cube.obj", "density": 1, "rotation": {"quaternion_xyzw": [0, 0, 1, 1]}}
            ]
        },
        "rotation.quaternion_xyzw: not a unit quaternion: its length is 1.41",
    ),
    (
        "quaternion element",
        {
            "parts": [
                {"mesh": "cube.obj", "density": 1, "rotation": {"quaternion_wxyz": [1, 0, None, 0]}}
            ]
        },
        "rotation.quaternion_wxyz[2]: a number is expected",
    ),
    (
        "matrix shape",
        {
            "parts": [
                {"mesh": "cube.obj", "density": 1, "rotation": {"matrix": [[1, 0, 0], [0, 1, 0]]}}
            ]
        },
        "rotation.matrix: 3 rows of 3",
    ),
    (
        "matrix row",
        {
            "parts": [
                {
                    "mesh": "cube.obj",
                    "density": 1,
                    "rotation": {"matrix": [[1, 0, 0], [0, 1], [0, 0, 1]]},
                }
            ]
        },
        "rotation.matrix[1]: an array of 3 numbers",
    ),
    (
        "not orthonormal",
        {
            "parts": [
                {
                    "mesh": "cube.obj",
                    "density": 1,
                    "rotation": {"matrix": [[0.7071, -0.7071, 0], [0.7071, 0.7071, 0], [0, 0, 1]]},
                }
            ]
        },
        "rotation.matrix: not orthonormal",
    ),
    (
        "unstated mirror",
        {
            "parts": [
                {
                    "mesh": "cube.obj",
                    "density": 1,
                    "rotation": {"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, -1]]},
                }
            ]
        },
        'a mirror (determinant -1), not a rotation: add "mirror": true',
    ),
    (
        "mirror of a rotation",
        {
            "parts": [
                {"mesh": "cube.obj", "density": 1, "mirror": True, "rotation": {"matrix": IDENTITY}}
            ]
        },
        'a rotation (determinant +1), but the part says "mirror": true',
    ),
    (
        "mirrored quaternion",
        {
            "parts": [
                {
                    "mesh": "cube.obj",
                    "density": 1,
                    "mirror": True,
                    "rotation": {"quaternion_wxyz": [1, 0, 0, 0]},
                }
            ]
        },
        "rotation: a quaternion cannot mirror",
    ),
    (
        "mirror alone",
        {"parts": [{"mesh": "cube.obj", "density": 1, "mirror": True}]},
        "mirror: a mirror needs",
    ),
    (
        "mirror text",
        {"parts": [{"mesh": "cube.obj", "density": 1, "mirror": "yes"}]},
        "mirror: true or false",
    ),
    (
        "repeated key",
        '{"parts": [{"mesh": "cube.obj", "density": 1, "density": 2}]}',
        'the key "density" is given twice',
    ),
    ("missing mesh", {"parts": [{"mesh": "none.obj", "density": 1}]}, 'parts[0] "none.obj": '),
    ("infinite", '{"parts": [{"mesh": "cube.obj", "density": 1e999}]}', "number overflow"),
]


class AssemblyErrors(test_cli.Case):
    """Every bad field: exit 3 with the part and the JSON path in the message."""

    def test_every_bad_field_is_named(self):
        for name, document, message in BAD_FIELDS:
            with self.subTest(case=name):
                path = write_assembly(name.replace(" ", "_") + ".json", document)
                result, out = test_cli.run_json("assembly", path)
                self.assertEqual(result.returncode, EXIT_UNREADABLE, result.stdout)
                self.assertEqual(out["error"]["category"], "unreadable")
                self.assertIn(message, out["error"]["message"])
                self.assertTrue(out["error"]["message"].startswith(str(path)))
                self.assertIn(message, run("assembly", path).stdout)  # the table says it too

    def test_usage_errors(self):
        path = write_assembly("ok.json", {"parts": [{"mesh": "cube.obj", "density": 1}]})
        for arguments, message in [
            ((path, path), "reads one assembly file"),
            (("--density", "2", path), "--density is given per part"),
            (("--units", "mm", path), "--units is given per part"),
            (("--scale", "2", path), "--scale is given per part"),
        ]:
            with self.subTest(arguments=arguments):
                result = run("assembly", *arguments)
                self.assertEqual(result.returncode, EXIT_USAGE)
                self.assertIn(message, result.stderr)


class PartMaterials(Case):
    """--density NAME=D and --mass NAME=M on a file with several parts, whose
    parts are each integrated once and whose whole is their moments' sum."""

    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        vertices, faces = fixtures.cube()
        far = [(x + 1e6, y + 2, z) for x, y, z in box_vertices(SIDES)]
        lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in vertices + far]
        lines += ["o cube"] + ["f " + " ".join(str(i + 1) for i in f) for f in faces]
        lines += ["o box"] + ["f " + " ".join(str(i + 9) for i in f) for f in faces]
        cls.path = WORK / "cube_and_box.obj"
        cls.path.write_text("\n".join(lines) + "\n")
        # The same faces as one part.
        cls.single = WORK / "cube_and_box_one_part.obj"
        cls.single.write_text("\n".join(line for line in lines if not line.startswith("o ")) + "\n")

    def bodies(self, cube_mass, box_mass):
        return [
            box_body(Fraction(cube_mass), IDENTITY, [0, 0, 0], sides=(1, 1, 1)),
            box_body(Fraction(box_mass), IDENTITY, [10**6, 2, 0]),
        ]

    def test_density_per_part(self):
        result, out = test_cli.run_json("--density", "cube=2", "--density", "box=0.5", self.path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        cube, box = self.bodies(2, 3)
        self.assert_body(out["parts"][0], cube, "cube")
        self.assert_body(out["parts"][1], box, "box")
        self.assertEqual(out["parts"][1]["density"], 0.5)
        self.assert_body(out, whole([cube, box]), "whole")
        self.assertEqual(out["volume"], 7.0)

    def test_mass_per_part_and_a_default_density(self):
        result, out = test_cli.run_json("--density", "3", "--mass", "box=12", self.path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        cube, box = self.bodies(3, 12)
        self.assertEqual(out["parts"][1]["mass"], 12.0)
        self.assertEqual(out["parts"][1]["density"], 2.0)
        self.assert_body(out, whole([cube, box]), "whole")

    def test_the_whole_is_the_sum_of_the_parts(self):
        # Integrated once per part and added, the whole is the one-part file's to rounding.
        _, parts = test_cli.run_json("--mass", "7", self.path)
        _, single = test_cli.run_json("--mass", "7", self.single)
        self.assertEqual(parts["mass"], 7.0)
        for key in ("volume", "density", "surface_area"):
            self.assert_close(parts[key], single[key], single[key], key)
        self.assert_matrix(parts["inertia"], single["inertia"], "inertia")
        self.assertEqual([p["density"] for p in parts["parts"]], [1.0, 1.0])
        self.assert_body(parts, whole(self.bodies(1, 6)), "whole")

    def assert_names_error(self, arguments, message):
        result = run(*arguments)
        self.assertEqual(result.returncode, EXIT_USAGE, result.stdout)
        self.assertIn(message, result.stderr)

    def test_unknown_names_and_bad_values(self):
        self.assert_names_error(
            ("--density", "bolt=2", self.path),
            "--density bolt=...: "
            + str(self.path)
            + " has no part named 'bolt'; its parts are 'cube', 'box'",
        )
        self.assert_names_error(("--mass", "7", "--density", "box=2", self.path), "not both")
        self.assert_names_error(("--density", "box=2", "--mass", "box=2", self.path), "given twice")
        self.assert_names_error(
            ("--density", "box=heavy", self.path), "--density box= wants a positive"
        )
        self.assert_names_error(("--density", "=2", self.path), "wants a part's name")
        self.assert_names_error(
            ("--density", "1", "--density", "2", self.path), "--density is given twice"
        )

    def test_parts_that_close_only_together(self):
        # A cube split into two groups of faces: neither is a solid, the whole is.
        vertices, faces = fixtures.cube()
        lines = [f"v {x} {y} {z}" for x, y, z in vertices]
        lines += ["o lower"] + ["f " + " ".join(str(i + 1) for i in f) for f in faces[:3]]
        lines += ["o upper"] + ["f " + " ".join(str(i + 1) for i in f) for f in faces[3:]]
        path = WORK / "split_cube.obj"
        path.write_text("\n".join(lines) + "\n")
        result, out = test_cli.run_json("--density", "2", path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["mass"], 2.0)
        self.assertEqual([p["error"]["category"] for p in out["parts"]], ["open", "open"])
        result, out = test_cli.run_json("--density", "lower=2", path)
        self.assertEqual(result.returncode, EXIT_INVALID_MESH)
        self.assertIn("part 'lower' is not a solid by itself", out["error"]["message"])

    def test_a_cavity_as_a_part_of_its_own(self):
        # A box [0, 4]^3 and, as its own part, a unit cube inside it facing
        # inward: the cavity, inside out by itself, even when inverted
        # solids are accepted and turned.
        vertices, faces = fixtures.cube()
        outer = [(4 * x, 4 * y, 4 * z) for x, y, z in vertices]
        inner = [(x + 1, y + 1, z + 1) for x, y, z in vertices]
        lines = [f"v {x} {y} {z}" for x, y, z in outer + inner]
        lines += ["o block"] + ["f " + " ".join(str(i + 1) for i in f) for f in faces]
        lines += ["o cavity"] + ["f " + " ".join(str(i + 9) for i in reversed(f)) for f in faces]
        path = WORK / "cavity_part.obj"
        path.write_text("\n".join(lines) + "\n")
        for arguments in ((), ("--accept-inverted",), ("--no-intersection-check",)):
            with self.subTest(arguments=arguments):
                result, out = test_cli.run_json(*arguments, path)
                self.assertEqual(result.returncode, EXIT_OK, result.stderr)
                self.assertEqual(out["volume"], 63.0)
        _, out = test_cli.run_json("--accept-inverted", path)
        self.assertEqual(out["parts"][1]["warnings"], ["inverted"])
        result, out = test_cli.run_json("--accept-inverted", "--density", "block=2", path)
        self.assertEqual(result.returncode, EXIT_INVALID_MESH)
        self.assertIn("part 'cavity' is not a solid by itself", out["error"]["message"])

    def test_parts_crossing_each_other_are_still_refused(self):
        vertices, faces = fixtures.cube()
        moved = [(x + 0.5, y + 0.5, z + 0.5) for x, y, z in vertices]
        lines = [f"v {x} {y} {z}" for x, y, z in vertices + moved]
        lines += ["o a"] + ["f " + " ".join(str(i + 1) for i in f) for f in faces]
        lines += ["o b"] + ["f " + " ".join(str(i + 9) for i in f) for f in faces]
        path = WORK / "crossing_parts.obj"
        path.write_text("\n".join(lines) + "\n")
        result, out = test_cli.run_json(path)
        self.assertEqual(result.returncode, EXIT_INVALID_MESH)
        self.assertEqual(out["error"]["category"], "intersecting")
        self.assertEqual([p["volume"] for p in out["parts"]], [1.0, 1.0])
        result, out = test_cli.run_json("--no-intersection-check", path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["volume"], 2.0)
        # A chain beyond the solid mode answers the whole by itself: the two
        # cubes' hull is the unit cube swept along v = (0.5, 0.5, 0.5), of
        # volume 1 + |v| * (the cube's shadow along v, sqrt(3)) = 2.5; each
        # part is still an exact solid.
        result, out = test_cli.run_json("--fallback", "repair,hull", path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["provenance"]["mode"], "hull")
        self.assertAlmostEqual(out["volume"], 2.5, places=12)
        self.assertEqual([p["provenance"]["mode"] for p in out["parts"]], ["solid", "solid"])
        self.assertEqual([p["volume"] for p in out["parts"]], [1.0, 1.0])


if __name__ == "__main__":
    unittest.main()
