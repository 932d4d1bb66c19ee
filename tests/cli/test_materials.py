"""Tests of materials by name (`--material NAME`, `--material PART=NAME`, an
assembly part's "material"), run by ctest with the environment of
test_cli.py.

The table the tool holds is read back against docs/materials.md, its
documentation: every name there gives its density, and the outputs (table,
JSON, XML, USD) name the material used.
"""

import json
import re
import unittest
from xml.etree import ElementTree

import test_cli
from test_cli import EXIT_OK, EXIT_UNREADABLE, EXIT_USAGE, SOURCE, WORK, run

import fixtures


def documented_materials():
    """{name: density in kg/m^3} from the table of docs/materials.md."""
    rows = re.findall(
        r"^\| `([a-z0-9-]+)` \| ([0-9]+) \|", (SOURCE / "docs" / "materials.md").read_text(), re.M
    )
    return {name: float(density) for name, density in rows}


class Materials(test_cli.Case):
    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        vertices, faces = fixtures.cube()
        cls.cube = WORK / "material_cube.obj"
        fixtures.write_obj(cls.cube, vertices, faces)
        far = [(x + 3, y, z) for x, y, z in vertices]
        lines = [f"v {x} {y} {z}" for x, y, z in vertices + far]
        lines += ["o left"] + ["f " + " ".join(str(i + 1) for i in f) for f in faces]
        lines += ["o right"] + ["f " + " ".join(str(i + 9) for i in f) for f in faces]
        cls.two = WORK / "material_two.obj"
        cls.two.write_text("\n".join(lines) + "\n")

    def test_every_documented_material_gives_its_density(self):
        table = documented_materials()
        self.assertGreaterEqual(len(table), 20)
        for name, density in table.items():
            with self.subTest(material=name):
                result, out = test_cli.run_json("--units", "m", "--material", name, self.cube)
                self.assertEqual(result.returncode, EXIT_OK, result.stderr)
                self.assertEqual(out["material"], name)
                self.assertEqual(out["density"], density)
                self.assertEqual(out["mass"], density)  # a 1 m cube
        # An unknown name is a usage error that lists exactly the documented ones.
        result = run("--units", "m", "--material", "unobtainium", self.cube)
        self.assertEqual(result.returncode, EXIT_USAGE)
        listed = re.search(r"the known ones are (.*) \(docs", result.stderr).group(1).split(", ")
        self.assertEqual(sorted(listed), sorted(table))

    def test_spelling_and_units(self):
        result, out = test_cli.run_json("--units", "mm", "--material", "Aluminum-6061", self.cube)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["material"], "aluminium-6061")
        self.assert_close(out["mass"], 2700e-9, 2700e-9, "mass of a 1 mm cube")
        # Without --units the lengths have no known unit, and kg/m^3 no meaning.
        result = run("--material", "pla", self.cube)
        self.assertEqual(result.returncode, EXIT_USAGE)
        self.assertIn("give the file's length unit with --units", result.stderr)

    def test_conflicts(self):
        for arguments, message in [
            (("--material", "pla", "--density", "2"), "--density, --mass or --material once"),
            (("--material", "pla", "--mass", "2"), "--density, --mass or --material once"),
            (("--material", "pla", "--material", "abs"), "--material once"),
            (("--material", "left=pla", "--density", "left=2"), "given twice"),
            (("--material", "left=pla", "--mass", "3"), "not both"),
            (("--material", "left=unobtainium"), "'unobtainium' is not a known material"),
            (("--material", "middle=pla"), "--material middle=...: "),
        ]:
            with self.subTest(arguments=arguments):
                result = run("--units", "m", *arguments, self.two)
                self.assertEqual(result.returncode, EXIT_USAGE, result.stdout)
                self.assertIn(message, result.stderr)

    def test_parts_and_the_whole(self):
        table = documented_materials()
        arguments = ("--units", "m", "--material", "steel", "--material", "right=pla", self.two)
        result, out = test_cli.run_json(*arguments)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        left, right = out["parts"]
        self.assertEqual((left["material"], left["density"]), ("steel", table["steel"]))
        self.assertEqual((right["material"], right["density"]), ("pla", table["pla"]))
        self.assertNotIn("material", out)  # a whole of two materials has none
        self.assertEqual(out["mass"], table["steel"] + table["pla"])
        # One material for both: the whole is of it too.
        _, out = test_cli.run_json("--units", "m", "--material", "abs", self.two)
        self.assertEqual(out["material"], "abs")
        self.assertEqual([p["material"] for p in out["parts"]], ["abs", "abs"])
        # A part's number is no material.
        _, out = test_cli.run_json(
            "--units", "m", "--material", "abs", "--density", "left=5", self.two
        )
        self.assertEqual([p.get("material") for p in out["parts"]], [None, "abs"])

    def test_every_output_names_it(self):
        arguments = ("--units", "m", "--material", "ti-6al-4v", self.cube)
        table = run(*arguments).stdout
        self.assertRegex(table, r"material\s+ti-6al-4v, density 4430 kg/m\^3 \(ASM")
        for output in ("--urdf", "--sdf", "--mjcf"):
            with self.subTest(output=output):
                text = run(output, *arguments).stdout
                self.assertIn("<!-- material: ti-6al-4v, density 4430 kg/m^3", text)
                ElementTree.fromstring("<r>" + text + "</r>")
        usda = run("--usda", *arguments).stdout
        self.assertIn('string material = "ti-6al-4v"', usda)
        self.assertIn("# material: ti-6al-4v, density 4430 kg/m^3", usda)

    def write_assembly(self, name, part):
        path = WORK / name
        path.write_text(json.dumps({"parts": [{"mesh": self.cube.name, **part}]}))
        return path

    def test_assembly_parts(self):
        path = self.write_assembly(
            "material_assembly.json", {"units": "cm", "material": "copper-c11000"}
        )
        result, out = test_cli.run_json("assembly", path)
        self.assertEqual(result.returncode, EXIT_OK, result.stderr)
        self.assertEqual(out["material"], "copper-c11000")
        self.assert_close(out["mass"], 8890e-6, 8890e-6, "mass of a 1 cm copper cube")
        for part, message in [
            (
                {"material": "pla"},
                'material: a material\'s density is in kg/m^3: the part needs its "units"',
            ),
            ({"units": "m", "material": "cheese"}, 'material: "cheese" is not a known material'),
            (
                {"units": "m", "material": "pla", "density": 2},
                'exactly one of "density", "material"',
            ),
            ({"units": "m", "material": 3}, "material: a string is expected"),
        ]:
            with self.subTest(part=part):
                result, out = test_cli.run_json("assembly", self.write_assembly("bad.json", part))
                self.assertEqual(result.returncode, EXIT_UNREADABLE, result.stdout)
                self.assertIn(message, out["error"]["message"])
        result = run("assembly", "--material", "pla", path)
        self.assertEqual(result.returncode, EXIT_USAGE)
        self.assertIn("--material is given per part", result.stderr)


if __name__ == "__main__":
    unittest.main()
