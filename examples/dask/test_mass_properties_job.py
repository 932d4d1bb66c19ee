"""The Dask job on a distributed.LocalCluster over a generated corpus: a row per file,
the right category for each broken one, exact volumes for the good ones, a second
run that computes only what is new, and the packed call's rows the single calls'.

    pytest examples/dask   (with dask[distributed], pyarrow and polymass installed)
"""

from __future__ import annotations

import importlib.util
import struct
from pathlib import Path

import pyarrow.parquet as pq
import pytest

distributed = pytest.importorskip("distributed")

_spec = importlib.util.spec_from_file_location(
    "mass_properties_job", Path(__file__).with_name("mass_properties_job.py")
)
job = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(job)

# Six faces of the box [0, a] x [0, b] x [0, c] moved by d, counter-clockwise from outside.
QUADS = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def box(size, shift):
    return [
        tuple(shift[k] + size[k] * ((corner >> k) & 1) for k in range(3)) for corner in range(8)
    ]


def triangles(faces):
    return [[f[0], f[k], f[k + 1]] for f in faces for k in range(1, len(f) - 1)]


def binary_stl(vertices, faces):
    tris = triangles(faces)
    data = b"polymass test corpus".ljust(80, b" ") + struct.pack("<I", len(tris))
    for tri in tris:
        data += struct.pack("<3f", 0, 0, 0)
        for i in tri:
            data += struct.pack("<3f", *vertices[i])
        data += b"\0\0"
    return data


def ascii_stl(vertices, faces):
    lines = ["solid box"]
    for tri in triangles(faces):
        lines += ["facet normal 0 0 0", "outer loop"]
        lines += ["vertex {!r} {!r} {!r}".format(*vertices[i]) for i in tri]
        lines += ["endloop", "endfacet"]
    return ("\n".join(lines + ["endsolid box"]) + "\n").encode()


def obj(vertices, faces):
    lines = ["v {!r} {!r} {!r}".format(*v) for v in vertices]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return ("\n".join(lines) + "\n").encode()


WRITERS = {".stl": binary_stl, ".obj": obj}


def make_corpus(root: Path, count: int, first: int = 0) -> dict[str, tuple[str, float]]:
    """count files under root (in nested directories): for each, the category
    expected and, for a valid solid, its exact volume. Every 10th file is broken."""
    expected = {}
    broken = ["unreadable", "open", "index_out_of_range", "non_finite", "inverted"]
    broken += ["intersecting", "empty"]
    for k in range(first, first + count):
        # Dyadic sizes and shifts: exact in float32 (binary STL) and in the integration.
        size = (1 + k % 7, 0.5 + (k % 5) / 4, 2 + (k % 3) / 8)
        shift = (k * 16.0, -(k % 11) * 0.25, 1000.0 + k)
        vertices, faces = box(size, shift), [list(f) for f in QUADS]
        kind = broken[(k // 10) % len(broken)] if k % 10 == 9 else "ok"
        # An STL has no indices to get wrong: that one is an OBJ.
        extension = ".obj" if kind == "index_out_of_range" else [".stl", ".obj", ".stl"][k % 3]
        relative = f"set{k % 4}/part{k // 50}/mesh_{k:04d}{extension}"
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        if kind == "open":
            faces = faces[:-1]
        elif kind == "index_out_of_range":
            faces[0] = [0, 2, 3, 99]
        elif kind == "non_finite":
            vertices[5] = (float("nan"), 0.0, 0.0)
        elif kind == "inverted":
            faces = [list(reversed(f)) for f in faces]
        elif kind == "intersecting":  # a copy moved by half its size: overlapping parts
            vertices += box(size, [s + d / 2 for s, d in zip(shift, size)])
            faces += [[i + 8 for i in f] for f in faces]
        if k % 3 == 2 and kind == "ok":
            data = ascii_stl(vertices, faces)
        else:
            data = WRITERS[extension](vertices, faces)
        if kind == "unreadable":
            data = data[: len(data) // 2] if extension == ".stl" else b"f 1 x 3\n"
        elif kind == "empty":
            data, kind = b"", "unreadable"
        path.write_bytes(data)
        expected[relative] = (kind, size[0] * size[1] * size[2])
    return expected


@pytest.fixture(scope="module")
def client():
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as dask_client,
    ):
        yield dask_client


def test_job_rows_categories_volumes_and_rerun(tmp_path, client):
    root, out = tmp_path / "corpus", tmp_path / "rows"
    expected = make_corpus(root, 300)
    (root / "notes.txt").write_text("not a mesh: not discovered")

    counts = job.run(root, out, client, batch_files=16)
    assert counts == {"found": 300, "skipped": 0, "computed": 300, "batches": 19}
    rows = pq.read_table(out).to_pylist()
    assert sorted(row["path"] for row in rows) == sorted(expected)
    for row in rows:
        category, volume = expected[row["path"]]
        assert row["category"] == category, row
        if category == "ok":
            assert row["status"] == "ok"
            assert row["volume"] == volume  # exact: dyadic boxes
            assert row["mass"] == volume
            assert row["warnings"] == []
        else:
            assert row["status"] == "failed"
            assert row["message"], row
            assert row["volume"] is None
    by_category = {}
    for row in rows:
        by_category[row["category"]] = by_category.get(row["category"], 0) + 1
    assert by_category == {
        "ok": 270,
        "unreadable": 9,
        "open": 5,
        "index_out_of_range": 4,
        "non_finite": 4,
        "inverted": 4,
        "intersecting": 4,
    }

    # Run again: nothing to do; add files: only they are computed.
    assert job.run(root, out, client, batch_files=16)["computed"] == 0
    expected.update(make_corpus(root, 20, first=300))
    again = job.run(root, out, client, batch_files=16)
    assert again == {"found": 320, "skipped": 300, "computed": 20, "batches": 2}
    paths = pq.read_table(out, columns=["path"]).column("path").to_pylist()
    assert sorted(paths) == sorted(expected)


def test_serial_run_gives_the_same_rows(tmp_path, client):
    root = tmp_path / "corpus"
    make_corpus(root, 40)
    job.run(root, tmp_path / "dask", client, batch_files=8)
    job.run(root, tmp_path / "serial", None, batch_files=8)

    def table(directory):
        rows = pq.read_table(directory).drop_columns(["seconds"]).to_pylist()
        return sorted(rows, key=lambda row: row["path"])

    assert table(tmp_path / "dask") == table(tmp_path / "serial")


# An L-shaped prism, volume 3 and area 14, whose two caps are single non-convex
# hexagons: a fan of triangles from the first corner of each would leave the L and
# overlap itself (area 16, and faces that touch).
L_PRISM = obj(
    [(x, y, z) for z in (0, 1) for x, y in [(2, 1), (1, 1), (1, 2), (0, 2), (0, 0), (2, 0)]],
    [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11]]
    + [[k, (k + 1) % 6, (k + 1) % 6 + 6, k + 6] for k in range(6)],
)


def test_packed_rows_are_the_single_calls(tmp_path):
    root = tmp_path / "corpus"
    expected = make_corpus(root, 40)  # every STL packed, the OBJs' quads one at a time
    tetrahedron = [(0, 0, 0), (6, 0, 0), (0, 6, 0), (0, 0, 1)]
    triangles = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    negative = obj(tetrahedron, triangles).replace(b"f 2 3 4", b"f 2 3 -9")
    assert negative != obj(tetrahedron, triangles)
    files = {
        "triangles.obj": (obj(tetrahedron, triangles), "ok"),  # packed
        # Past its own vertices: the packed call's error for this mesh alone.
        "past.obj": (obj(tetrahedron, triangles[:3] + [[1, 2, 4]]), "index_out_of_range"),
        # Negative: one at a time (the packed call would refuse the whole batch).
        "negative.obj": (negative, "index_out_of_range"),
        "l_prism.obj": (L_PRISM, "ok"),  # polygons: one at a time, not triangulated
    }
    for name, (data, category) in files.items():
        (root / name).write_bytes(data)
        expected[name] = (category, None)
    paths = list(job.discover(root))

    def rows(packed):
        table = job.process_batch(str(root), paths, 2.0, packed=packed)
        return table.drop_columns(["seconds"]).to_pylist()

    packed, single = rows(True), rows(False)
    assert packed == single
    assert [row["path"] for row in packed] == paths
    assert {row["path"]: row["category"] for row in packed} == {
        path: category for path, (category, _) in expected.items()
    }
    by_path = {row["path"]: row for row in packed}
    l_prism = by_path["l_prism.obj"]
    assert (l_prism["faces"], l_prism["volume"], l_prism["mass"]) == (8, 3.0, 6.0)
    assert (l_prism["surface_area"], l_prism["warnings"]) == (14.0, [])
    assert by_path["triangles.obj"]["mass"] == 12.0
