"""The --html report pages in a real browser (headless Chromium, WebGL on
SwiftShader), run by ctest:

    POLYMASS_EXE=<polymass> POLYMASS_SOURCE_DIR=<repo> POLYMASS_WORK_DIR=<scratch> \
        POLYMASS_CHROMIUM=<chromium> python3 tests/browser/test_html_report.py

Each page must load with no console error and no request but itself, draw
its canvas, and show what --json reports: the check page's findings table
row for row, its drawn locations where the mesh has them (a hole's edges,
found in the page's state and in the canvas's pixels); the properties page's
equivalent inertia box; the audit page's links, and the declared and
computed boxes of a link whose declared inertia is planted wrong. The
screenshots are kept in the work folder (the test's artefacts).
"""

import json
import math
import os
import subprocess
import sys
import time
import unittest
from pathlib import Path
from typing import ClassVar

from chromium import Chromium
from meshes import sphere_triangles, write_binary_stl

EXE = os.environ["POLYMASS_EXE"]
WORK = Path(os.environ["POLYMASS_WORK_DIR"])
CHROMIUM = os.environ.get("POLYMASS_CHROMIUM", "chromium")
LOAD_TIMEOUT = 60.0  # generous for a loaded 2-core machine, but bounded

BACKGROUND = (244, 246, 248)
OPEN_EDGE_RGB = (0xE6, 0x19, 0x4B)


def run(*args, expect=None):
    """polymass in the work folder, its files named from there (the pages,
    and their screenshots, show short names)."""
    names = [str(a.relative_to(WORK)) if isinstance(a, Path) else str(a) for a in args]
    result = subprocess.run(
        [EXE, *names], capture_output=True, text=True, timeout=120, check=False, cwd=WORK
    )
    assert result.returncode >= 0, f"polymass {args} crashed: {result.returncode}\n{result.stderr}"
    if expect is not None:
        assert result.returncode == expect, (
            f"polymass {args}: exit {result.returncode}\n{result.stderr}"
        )
    return result


def write_obj(path, vertices, faces):
    """faces: 0-based vertex lists, counter-clockwise seen from outside."""
    lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in vertices]
    lines += ["f " + " ".join(str(v + 1) for v in face) for face in faces]
    path.write_text("\n".join(lines) + "\n")
    return path


CUBE_FACES = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def box_vertices(low, high):
    (x0, y0, z0), (x1, y1, z1) = low, high
    return [
        (x0, y0, z0),
        (x1, y0, z0),
        (x1, y1, z0),
        (x0, y1, z0),
        (x0, y0, z1),
        (x1, y0, z1),
        (x1, y1, z1),
        (x0, y1, z1),
    ]


def boxes(*corners, flipped=()):
    """Several boxes as one mesh; the ones whose index is in flipped inside out."""
    vertices, faces = [], []
    for i, (low, high) in enumerate(corners):
        base = len(vertices)
        vertices += box_vertices(low, high)
        for face in CUBE_FACES:
            face = [base + v for v in face]
            faces.append(face[::-1] if i in flipped else face)
    return vertices, faces


def rotated(vertices, angle, axis_point=(0.0, 0.0, 0.0)):
    """Rotated by angle about z then about x (through axis_point): no axis kept."""
    c, s = math.cos(angle), math.sin(angle)
    out = []
    for x, y, z in vertices:
        x, y, z = x - axis_point[0], y - axis_point[1], z - axis_point[2]
        x, y = c * x - s * y, s * x + c * y
        y, z = c * y - s * z, s * y + c * z
        out.append((x + axis_point[0], y + axis_point[1], z + axis_point[2]))
    return out


# ---- a robot for polymass audit -------------------------------------------------

LINKS = 13
LINK_BOX = (0.1, 0.2, 0.3)  # each link's geometry: a box on its link's z axis
JOINT_XYZ = (0.1, 0.0, 0.3)
JOINT_YAW = 0.5
LINK_MASS = 2.0
WRONG_LINK = "link_7"  # its declared inertia 23 times too large
WRONG_FACTOR = 23.0


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def yaw(angle):
    c, s = math.cos(angle), math.sin(angle)
    return [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]


def link_frames():
    """Each link's rotation and position with every joint at zero."""
    frames = [([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]], [0.0, 0.0, 0.0])]
    for _ in range(LINKS - 1):
        rotation, position = frames[-1]
        step = [sum(rotation[i][k] * JOINT_XYZ[k] for k in range(3)) for i in range(3)]
        frames.append((matmul(rotation, yaw(JOINT_YAW)), [p + d for p, d in zip(position, step)]))
    return frames


def box_moments(mass, size):
    a, b, c = size
    return [mass * (b * b + c * c) / 12, mass * (a * a + c * c) / 12, mass * (a * a + b * b) / 12]


def write_robot(folder):
    """A chain of LINKS links, each a box (link_3 a mesh file), each joint
    turning the next link by JOINT_YAW; WRONG_LINK's inertia planted wrong."""
    corners = box_vertices([-s / 2 for s in LINK_BOX], [s / 2 for s in LINK_BOX])
    write_obj(folder / "link_3.obj", corners, CUBE_FACES)
    parts = ['<robot name="chain">']
    for k in range(LINKS):
        name = f"link_{k}"
        moments = box_moments(LINK_MASS, LINK_BOX)
        if name == WRONG_LINK:
            moments = [m * WRONG_FACTOR for m in moments]
        ixx, iyy, izz = moments
        shape = (
            '<mesh filename="link_3.obj"/>'
            if k == 3
            else '<box size="{} {} {}"/>'.format(*LINK_BOX)
        )
        parts.append(
            f'<link name="{name}"><inertial><origin xyz="0 0 0.15"/>'
            f'<mass value="{LINK_MASS}"/><inertia ixx="{ixx!r}" iyy="{iyy!r}" izz="{izz!r}"'
            ' ixy="0" ixz="0" iyz="0"/></inertial>'
            f'<collision><origin xyz="0 0 0.15"/><geometry>{shape}</geometry></collision>'
            "</link>"
        )
        if k:
            parts.append(
                f'<joint name="joint_{k}" type="revolute"><parent link="link_{k - 1}"/>'
                f'<child link="{name}"/><origin xyz="{JOINT_XYZ[0]} {JOINT_XYZ[1]} {JOINT_XYZ[2]}"'
                f' rpy="0 0 {JOINT_YAW}"/><axis xyz="0 0 1"/>'
                '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
            )
    parts.append("</robot>")
    path = folder / "chain.urdf"
    path.write_text("\n".join(parts) + "\n")
    return path


# JavaScript: the check page's findings table as shown (a kind's row, then
# its locations' rows) and the "... and N more" rows.
TABLE_ROWS = """[...document.querySelectorAll(
    '#findings tr.kind-row, #findings tr.location-row')].map((row) =>
  row.classList.contains('kind-row')
    ? {key: row.dataset.key, count: Number(row.cells[1].textContent)}
    : {key: row.dataset.key, location: JSON.parse(row.dataset.location),
       text: row.cells[2].textContent})"""

CANVAS_SAMPLES = """(() => {
  const canvas = document.getElementById('canvas');
  const samples = [];
  for (let i = 1; i < 24; i++) for (let j = 1; j < 24; j++)
    samples.push(window.polymass.pixelAt(canvas.clientWidth * i / 24,
                                         canvas.clientHeight * j / 24));
  return samples;
})()"""


# The canvas's colour where a point of the model falls.
PIXEL_AT_POINT = """(() => { const p = window.polymass.project(%s);
  return window.polymass.pixelAt(p.x, p.y); })()"""


def finding_rows(report):
    """What the findings table must list, from --json: each finding (a member
    with a count) and its locations, in order."""
    rows = []
    for key, value in report.items():
        if not isinstance(value, dict) or "count" not in value:
            continue
        rows.append({"key": key, "count": value["count"]})
        (locations,) = [
            value[name]
            for name in value
            if name.startswith("first_") and name != "first_pair_shells"
        ]
        rows += [{"key": key, "location": location} for location in locations]
    return rows


class ReportPages(unittest.TestCase):
    browser = None
    load_times: ClassVar[dict] = {}

    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.browser = Chromium(CHROMIUM, timeout=LOAD_TIMEOUT).__enter__()

    @classmethod
    def tearDownClass(cls):
        cls.browser.__exit__(None, None, None)
        for name, seconds in sorted(cls.load_times.items()):
            print(f"  {name}: ready in {seconds:.2f} s", file=sys.stderr)

    def load(self, page_path):
        """The page opened and ready, checked for errors and requests."""
        url = page_path.resolve().as_uri()
        start = time.monotonic()
        page = self.browser.open(url)
        self.addCleanup(page.close)
        page.wait_for("window.polymass && window.polymass.ready", timeout=LOAD_TIMEOUT)
        self.load_times[page_path.name] = time.monotonic() - start
        self.assertEqual(page.errors, [])
        # Offline: the page asks for nothing but itself.
        self.assertEqual(page.requests, [url])
        return page

    def assert_drawn(self, page):
        """The canvas is not blank: the scene covers part of it, in more than
        one shade."""
        samples = page.evaluate(CANVAS_SAMPLES)
        drawn = [
            tuple(p[:3]) for p in samples if max(abs(a - b) for a, b in zip(p[:3], BACKGROUND)) > 12
        ]
        self.assertGreater(len(drawn), len(samples) // 20, "the canvas is (nearly) blank")
        self.assertGreater(len(set(drawn)), 3, "the scene is drawn in one flat colour")

    def screenshot(self, page, name):
        page.screenshot(str(WORK / name))

    def assert_table_is_json(self, page, report):
        shown = page.evaluate(TABLE_ROWS)
        expected = finding_rows(report)
        self.assertEqual([{k: v for k, v in row.items() if k != "text"} for row in shown], expected)
        # The text says the numbers the row names.
        for row in shown:
            if "location" not in row:
                continue
            location = row["location"] if isinstance(row["location"], list) else [row["location"]]
            for number in location:
                self.assertRegex(row["text"], rf"\b{number}\b")

    # ---- polymass check --html -------------------------------------------------

    def test_check_page_draws_the_hole(self):
        # A box with its x = 0 side missing: four open edges around the hole.
        vertices, faces = boxes(((0, 0, 0), (1, 2, 3)))
        mesh = write_obj(WORK / "open_box.obj", vertices, [f for f in faces if f != [3, 0, 4, 7]])
        page_path = WORK / "check_open_box.html"
        run("check", "--html", page_path, mesh, expect=1)
        report = json.loads(run("check", "--json", mesh, expect=1).stdout)
        page = self.load(page_path)
        self.assert_drawn(page)
        self.assert_table_is_json(page, report)

        hole = {
            frozenset(map(tuple, pair))
            for pair in [
                ((0, 0, 0), (0, 2, 0)),
                ((0, 2, 0), (0, 2, 3)),
                ((0, 2, 3), (0, 0, 3)),
                ((0, 0, 3), (0, 0, 0)),
            ]
        }
        drawn = [d for d in page.evaluate("window.polymass.drawn") if d["key"] == "open_edges"]
        self.assertEqual({frozenset(map(tuple, d["points"])) for d in drawn}, hole)
        self.assertEqual(len(drawn), 4)
        # Where each hole edge's middle falls on the canvas, the canvas is
        # the open edges' colour.
        for edge in hole:
            a, b = tuple(edge)
            middle = [(p + q) / 2 for p, q in zip(a, b)]
            pixel = page.evaluate(PIXEL_AT_POINT % middle)
            self.assertLess(
                max(abs(c - e) for c, e in zip(pixel[:3], OPEN_EDGE_RGB)),
                40,
                f"edge {edge}: pixel {pixel}",
            )
        self.screenshot(page, "check_open_box.png")

        # A location's row selects it: the view turns to the edge's middle.
        page.evaluate("document.querySelector('#findings tr.location-row').click()")
        self.assertTrue(
            page.evaluate(
                "document.querySelector('#findings tr.location-row').classList.contains('selected')"
            )
        )
        first = report["open_edges"]["first_edges"][0]
        ends = [vertices[v] for v in first]
        middle = [(p + q) / 2 for p, q in zip(*ends)]
        target = page.evaluate("window.polymass.target()")
        for got, want in zip(target, middle):
            self.assertAlmostEqual(got, want, places=4)

    def test_check_page_lists_what_json_reports(self):
        # Crossing boxes and one inside out (several shells); boxes sharing
        # an edge (non-manifold); several files in one page.
        crossing = write_obj(
            WORK / "crossing.obj",
            *boxes(
                ((0, 0, 0), (1, 1, 1)),
                ((0.5, 0.5, 0.5), (1.5, 1.5, 1.5)),
                ((3, 0, 0), (4, 1, 1)),
                flipped=(2,),
            ),
        )
        touching = write_obj(
            WORK / "edge_shared.obj", *boxes(((0, 0, 0), (1, 1, 1)), ((1, 1, 0), (2, 2, 1)))
        )
        page_path = WORK / "check_findings.html"
        run("check", "--html", page_path, crossing, touching, expect=1)
        reports = json.loads(run("check", "--json", crossing, touching, expect=1).stdout)
        page = self.load(page_path)
        for index, report in enumerate(reports):
            page.evaluate(f"window.polymass.show({index})")
            self.assertEqual(page.errors, [])
            self.assert_drawn(page)
            self.assert_table_is_json(page, report)
            found = [row for row in finding_rows(report) if row.get("count")]
            self.assertTrue(found, f"{report['file']}: no finding to compare")
            # Every location of a finding that has a place is drawn.
            drawn = {
                (d["key"], json.dumps(d["location"]))
                for d in page.evaluate("window.polymass.drawn")
            }
            for row in finding_rows(report):
                if "location" in row:
                    self.assertIn((row["key"], json.dumps(row["location"])), drawn)
            self.screenshot(page, f"check_findings_{index}.png")
        self.assertGreater(reports[0]["intersecting_face_pairs"]["count"], 0)
        self.assertGreater(reports[1]["non_manifold_edges"]["count"], 0)

    def test_unwritable_page_is_an_error(self):
        vertices, faces = boxes(((0, 0, 0), (1, 1, 1)))
        mesh = write_obj(WORK / "cube.obj", vertices, faces)
        result = run("--html", WORK / "no" / "such" / "folder.html", mesh, expect=3)
        self.assertIn("cannot write", result.stderr)
        result = run("assembly", "--html", WORK / "a.html", mesh, expect=2)
        self.assertIn("writes no --html page", result.stderr)

    # ---- polymass FILE --html --------------------------------------------------

    def test_properties_page_draws_the_equivalent_box(self):
        # A 1 x 2 x 3 box turned about two axes, far from the origin: its
        # equivalent inertia box is itself.
        centre = (1000.0, -2000.0, 500.0)
        low = [c - h for c, h in zip(centre, (0.5, 1.0, 1.5))]
        high = [c + h for c, h in zip(centre, (0.5, 1.0, 1.5))]
        vertices, faces = boxes((low, high))
        mesh = write_obj(WORK / "turned_box.obj", rotated(vertices, 0.4, centre), faces)
        page_path = WORK / "properties_box.html"
        run("--html", page_path, "--density", "2", mesh, expect=0)
        report = json.loads(run("--json", "--density", "2", mesh, expect=0).stdout)
        page = self.load(page_path)
        self.assert_drawn(page)
        (box,) = page.evaluate("window.polymass.boxes")
        self.assertEqual(sorted(round(s, 9) for s in box["sides"]), [1.0, 2.0, 3.0])
        self.assertEqual(box["center"], report["center_of_mass"])
        self.assertEqual(box["axes"], report["principal_axes"])
        shown = page.evaluate("document.getElementById('details').textContent")
        self.assertIn("equivalent inertia box", shown)
        self.screenshot(page, "properties_box.png")

    def test_properties_page_of_an_open_mesh_says_why(self):
        vertices, faces = boxes(((0, 0, 0), (1, 1, 1)))
        mesh = write_obj(WORK / "open_cube.obj", vertices, faces[1:])
        page_path = WORK / "properties_open.html"
        run("--html", page_path, mesh, expect=1)
        page = self.load(page_path)
        self.assert_drawn(page)  # the mesh, with no answer to draw
        self.assertEqual(page.evaluate("window.polymass.boxes"), [])
        status = page.evaluate("document.getElementById('summary').textContent")
        self.assertIn("open: ", status)

    def test_repaired_and_hull_answers_are_drawn(self):
        # A box with a side missing: --repair caps the hole, --hull covers it.
        vertices, faces = boxes(((0, 0, 0), (1, 2, 3)))
        mesh = write_obj(WORK / "open_box_2.obj", vertices, faces[:-1])
        repaired, hull = WORK / "properties_repaired.html", WORK / "check_hull.html"
        run("--repair", "--html", repaired, mesh, expect=0)
        run("check", "--hull", "--html", hull, mesh, expect=1)
        report = json.loads(run("--repair", "--json", mesh, expect=0).stdout)
        holes = report["provenance"]["repairs"]["holes"]
        self.assertEqual(holes["count"], 1)
        page = self.load(repaired)
        legend = page.evaluate("document.getElementById('legend').textContent")
        self.assertIn("capped hole", legend)
        page = self.load(hull)
        self.assertIn("convex hull", page.evaluate("document.getElementById('legend').textContent"))
        self.assertIn("Hull", page.evaluate("document.getElementById('toolbar').textContent"))
        self.assert_drawn(page)

    def test_large_mesh_is_drawn_decimated(self):
        # A sphere of 208,656 triangles: past the 200,000 the page draws.
        triangles = sphere_triangles(323, 324)
        mesh = write_binary_stl(WORK / "sphere.stl", triangles)
        page_path = WORK / "properties_sphere.html"
        # The topology checks (slow in a Debug build) are not what is tested.
        run("--no-check", "--html", page_path, mesh, expect=0)
        page = self.load(page_path)
        self.assert_drawn(page)
        (note,) = page.evaluate("window.polymass.notes")
        self.assertIn(f"of {len(triangles):,} triangles", note)
        shown = int(note.split(" ")[2].replace(",", ""))
        self.assertLessEqual(shown, 200000)
        self.assertGreater(shown, 50000)
        self.screenshot(page, "properties_sphere.png")

    # ---- polymass audit --html ---------------------------------------------------

    def test_audit_page_shows_the_wrong_inertial(self):
        description = write_robot(WORK)
        page_path = WORK / "audit_chain.html"
        run("audit", "--html", page_path, description, expect=1)
        report = json.loads(run("audit", "--json", description, expect=1).stdout)
        page = self.load(page_path)
        self.assert_drawn(page)
        # Every link listed, each with the findings --json gives it.
        shown = page.evaluate(
            """[...document.querySelectorAll('#links tr.link-row')].map((row) => ({
                 name: row.dataset.link,
                 kinds: [...row.querySelectorAll('.finding')]
                          .map((f) => f.dataset.kind).sort()}))"""
        )
        expected = {
            link["name"]: sorted(f["kind"] for f in link["findings"]) for link in report["links"]
        }
        self.assertEqual({row["name"]: row["kinds"] for row in shown}, expected)
        self.assertEqual(len(shown), LINKS)
        # The most severe first: the planted link's errors head the list.
        self.assertEqual(shown[0]["name"], WRONG_LINK)

        boxes = {(b["link"], b["which"]): b for b in page.evaluate("window.polymass.boxes")}
        self.assertEqual(len(boxes), 2 * LINKS)
        frames = link_frames()
        for k in range(LINKS):
            name = f"link_{k}"
            declared, computed = boxes[(name, "declared")], boxes[(name, "computed")]
            factor = math.sqrt(WRONG_FACTOR) if name == WRONG_LINK else 1.0
            for d, c in zip(sorted(declared["sides"]), sorted(computed["sides"])):
                self.assertAlmostEqual(d, factor * c, delta=1e-9 * factor)
            self.assertEqual(sorted(round(s, 9) for s in computed["sides"]), sorted(LINK_BOX))
            # Both centres where the link's frame puts (0, 0, 0.15).
            rotation, position = frames[k]
            want = [position[i] + rotation[i][2] * 0.15 for i in range(3)]
            for box in (declared, computed):
                for got, expect in zip(box["center"], want):
                    self.assertAlmostEqual(got, expect, places=9)
        self.screenshot(page, "audit_chain.png")

    def test_audit_page_says_a_box_side_is_clamped(self):
        # Declared moments 0.1, 0.1, 1: 0.1 + 0.1 < 1, no box has them.
        description = WORK / "unphysical.urdf"
        description.write_text(
            '<robot name="r"><link name="base"><inertial><mass value="1"/>'
            '<inertia ixx="0.1" iyy="0.1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>'
            '<collision><geometry><box size="1 1 1"/></geometry></collision></link></robot>\n'
        )
        page_path = WORK / "audit_unphysical.html"
        run("audit", "--html", page_path, description, expect=1)
        page = self.load(page_path)
        boxes = {b["which"]: b for b in page.evaluate("window.polymass.boxes")}
        self.assertEqual(boxes["declared"]["clamped"], [False, False, True])
        self.assertEqual(boxes["declared"]["sides"][2], 0)
        self.assertEqual(boxes["computed"]["clamped"], [False, False, False])
        (note,) = page.evaluate("window.polymass.notes")
        self.assertIn("base: the declared inertia box has a side clamped to 0", note)


if __name__ == "__main__":
    unittest.main(verbosity=2)
