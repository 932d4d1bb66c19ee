"""Mass properties of every mesh under a directory tree, on a Dask cluster, to Parquet.

    python examples/dask/mass_properties_job.py ROOT OUT [--scheduler ADDRESS | --workers N]
                                                 [--density D] [--batch-files K] [--serial]
                                                 [--skip-intersection-check]

Finds the binary/ASCII STL and OBJ files under ROOT, leaves out those OUT already has
a row for (so a run that was stopped, or a new day's files, only computes what is
missing), cuts the rest into batches of files, and computes each batch on a worker
with the polymass Python binding: the batch's triangle meshes (every STL, an OBJ
of triangles) in one packed call, ``polymass.packed_mass_properties``, the others
(an OBJ with polygon faces) one at a time by ``polymass.mass_properties``. Every
file gives one row - path, status ("ok" or "failed"), category, message, and for a
valid solid its volume, mass, centre of mass, inertia and surface area - written as
one Parquet file per batch under OUT; a mesh's row is the same bits by either call.
A file that cannot be read or is not a valid solid is a row with its category (the
tool's: "unreadable", "open", "non_manifold", "index_out_of_range", "non_finite",
...), never an exception that stops the job.

The meshes are read here with numpy alone: a binary STL is one ``np.frombuffer`` with
a structured dtype, ASCII STL and OBJ are a few lines of text parsing. A dataset job
keeps its workers' dependencies to what it uses (numpy and polymass), and reading in
the worker's own process costs nothing beyond the bytes, where starting the
``polymass`` tool per file would cost a process each. Lengths are the files' own;
give --density in matching units. Every check is on unless
--skip-intersection-check, for files known not to hold overlapping parts, skips the
one that refuses them (most of the time of a small mesh; its rows then carry the
warning "intersections_unchecked").

Without --scheduler, a distributed.LocalCluster of --workers processes runs the job;
--serial runs it in this process (for comparison, or for debugging). Its speed:
bench_mass_properties_job.py beside it.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import re
import sys
import tempfile
import time
import uuid
from collections.abc import Iterable, Iterator
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

import polymass

EXTENSIONS = {".stl", ".obj"}

# One column per field; a failed file has nulls in the numbers.
SCHEMA = pa.schema(
    [
        ("path", pa.string()),  # relative to ROOT, so a moved corpus keeps its rows
        ("status", pa.string()),  # "ok" or "failed"
        ("category", pa.string()),  # "ok", or what failed
        ("message", pa.string()),
        ("faces", pa.int64()),
        ("volume", pa.float64()),
        ("mass", pa.float64()),
        ("center_of_mass", pa.list_(pa.float64(), 3)),
        ("inertia", pa.list_(pa.float64(), 9)),  # about the centre of mass, row-major
        ("surface_area", pa.float64()),
        ("warnings", pa.list_(pa.string())),
        # Reading this file and computing it: the single call's time, or the file's share
        # (by triangles) of its batch's packed call.
        ("seconds", pa.float64()),
    ]
)

# The categories the polymass tool prints, by the binding's exception class.
CATEGORIES = {
    polymass.OpenSurfaceError: "open",
    polymass.NonManifoldError: "non_manifold",
    polymass.InconsistentOrientationError: "inconsistent_orientation",
    polymass.InvertedError: "inverted",
    polymass.NonFiniteError: "non_finite",
    polymass.IndexOutOfRangeError: "index_out_of_range",
    polymass.FaceTooSmallError: "face_too_small",
    polymass.NonPlanarFaceError: "non_planar_face",
    polymass.IntersectingSurfaceError: "intersecting",
    polymass.ZeroVolumeError: "zero_volume",
    polymass.ResultOutOfRangeError: "overflow",
    polymass.OutOfMemoryError: "out_of_memory",
    polymass.InvalidArgumentError: "invalid_argument",
}

BINARY_STL = np.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])


class UnreadableError(Exception):
    """A file that is not a mesh this job reads (its row's category: "unreadable")."""


def read_stl(data: bytes) -> tuple[np.ndarray, list | np.ndarray]:
    """Vertices and triangles of a binary or ASCII STL (every triangle its own corners)."""
    if len(data) >= 84:
        count = int(np.frombuffer(data, "<u4", 1, 80)[0])
        if len(data) == 84 + 50 * count:
            corners = np.frombuffer(data, BINARY_STL, count, 84)["corners"]
            return corners.reshape(-1, 3).astype(np.float64), np.arange(3 * count).reshape(-1, 3)
    text = data.decode("ascii", errors="strict") if data.lstrip().startswith(b"solid") else ""
    if not text:
        raise UnreadableError("neither a binary STL (its size does not match) nor an ASCII one")
    numbers = re.findall(r"^\s*vertex\s+(\S+)\s+(\S+)\s+(\S+)\s*$", text, re.MULTILINE)
    if not numbers or len(numbers) % 3:
        raise UnreadableError(f"an ASCII STL with {len(numbers)} vertices, not triangles")
    try:
        vertices = np.array(numbers, dtype=np.float64)
    except ValueError as error:
        raise UnreadableError(f"a vertex that is not three numbers: {error}") from None
    return vertices, np.arange(len(vertices)).reshape(-1, 3)


def read_obj(data: bytes) -> tuple[np.ndarray, list]:
    """Vertices and polygon faces of an OBJ (v and f lines; negative indices count back)."""
    vertices: list[list[float]] = []
    faces: list[list[int]] = []
    for number, line in enumerate(data.decode("utf-8", errors="replace").splitlines(), 1):
        words = line.split("#", 1)[0].split()
        try:
            if words and words[0] == "v":
                vertices.append([float(x) for x in words[1:4]])
            elif words and words[0] == "f":
                indices = [int(word.split("/", 1)[0]) for word in words[1:]]
                # 1-based; a negative index counts back from the last vertex read.
                faces.append([i - 1 if i > 0 else len(vertices) + i for i in indices])
        except ValueError as error:
            raise UnreadableError(f"line {number}: {error}") from None
    if not faces:
        raise UnreadableError("no faces")
    if any(len(v) != 3 for v in vertices):
        raise UnreadableError("a vertex without three coordinates")
    return np.array(vertices, dtype=np.float64).reshape(-1, 3), faces


def read_mesh(path: Path) -> tuple[np.ndarray, list | np.ndarray]:
    data = path.read_bytes()
    if not data:
        raise UnreadableError("the file is empty")
    return (read_stl if path.suffix.lower() == ".stl" else read_obj)(data)


# STL is a triangle soup and OBJ exporters repeat positions: exactly equal positions
# are welded into one vertex. Every check is on.
OPTIONS = polymass.Options(weld=True)

# The packed call reads indices as uint32: a negative index, or one past that, in any
# mesh would refuse the whole call (naming the face by its place in the batch).
LARGEST_PACKED_INDEX = np.iinfo(np.uint32).max


def failed_row(path: str, error: Exception, seconds: float) -> dict:
    """A file's failure as its row: the category and the message."""
    if isinstance(error, (UnreadableError, OSError)):
        category, message = "unreadable", str(error)
    elif isinstance(error, polymass.Error):
        category, message = CATEGORIES.get(type(error), "internal"), error.message
    else:  # a bug here or below: a row, not a lost batch
        category, message = "internal", repr(error)
    return {"path": path, "status": "failed", "category": category, "message": message,
            "seconds": seconds}  # fmt: skip


def warning_names(bits: int) -> list[str]:
    """The names of the warnings' bits (most rows have none: then no walk of the enum)."""
    return [w.name.lower() for w in polymass.Warnings if w & bits and w.name] if bits else []


def solid_row(path: str, faces: int, numbers: dict, warnings: int, seconds: float) -> dict:
    """A valid solid's row: numbers holds volume, mass, center_of_mass, inertia (3x3)
    and surface_area, from the single call or from a row of the packed one."""
    return {
        "path": path,
        "status": "ok",
        "category": "ok",
        "message": "",
        "faces": faces,
        "volume": float(numbers["volume"]),
        "mass": float(numbers["mass"]),
        "center_of_mass": np.asarray(numbers["center_of_mass"], dtype=float).tolist(),
        "inertia": np.asarray(numbers["inertia"], dtype=float).ravel().tolist(),
        "surface_area": float(numbers["surface_area"]),
        "warnings": warning_names(warnings),
        "seconds": seconds,
    }


QUANTITIES = ("volume", "mass", "center_of_mass", "inertia", "surface_area")


def single_row(path: str, vertices, faces, density: float, options, start: float) -> dict:
    """A mesh's row by the single call, polygon faces taken whole (start: when its
    reading began)."""
    try:
        p = polymass.mass_properties(vertices, faces, density=density, options=options)
    except Exception as error:
        return failed_row(path, error, time.perf_counter() - start)
    numbers = {name: getattr(p, name) for name in QUANTITIES}
    return solid_row(path, len(faces), numbers, p.warnings, time.perf_counter() - start)


def packable(faces: list | np.ndarray) -> np.ndarray | None:
    """The faces as an (f, 3) index array when the packed call takes them, else None.

    It takes triangles only. A polygon face goes to the single call, which takes it
    whole: a fan of triangles over a non-convex face could overlap itself (its area
    counted twice, its triangles touching or crossing, which the intersection check
    flags or refuses). An index the packed call cannot read (see LARGEST_PACKED_INDEX)
    goes there too, so that its error is this file's alone."""
    if not isinstance(faces, np.ndarray) and any(len(face) != 3 for face in faces):
        return None
    try:
        triangles = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    except OverflowError:  # an index past 64 bits
        return None
    if triangles.size and not 0 <= triangles.min() <= triangles.max() <= LARGEST_PACKED_INDEX:
        return None
    return triangles


def packed_rows(meshes: list, density: float, options) -> list[dict]:
    """The rows of (path, vertices, triangles, seconds reading) meshes, by one packed
    call; each file's seconds are its reading and its share, by triangles, of the
    call."""
    vertex_counts = [len(vertices) for _, vertices, _, _ in meshes]
    face_counts = [len(triangles) for _, _, triangles, _ in meshes]
    start = time.perf_counter()
    try:
        result = polymass.packed_mass_properties(
            np.concatenate([vertices for _, vertices, _, _ in meshes]),
            np.concatenate([triangles for _, _, triangles, _ in meshes]),
            np.cumsum([0, *vertex_counts]),
            np.cumsum([0, *face_counts]),
            density=density,
            options=options,
        )
    except Exception as error:  # the call as a whole refused: every file of it says why
        seconds = time.perf_counter() - start
        return [
            failed_row(path, error, read + seconds / len(meshes)) for path, _, _, read in meshes
        ]
    seconds_per_face = (time.perf_counter() - start) / max(sum(face_counts), 1)
    rows = []
    for i, (path, _, triangles, read) in enumerate(meshes):
        seconds = read + seconds_per_face * len(triangles)
        error = result.error(i)
        if error is not None:
            rows.append(failed_row(path, error, seconds))
            continue
        numbers = {name: getattr(result, name)[i] for name in QUANTITIES}
        rows.append(solid_row(path, len(triangles), numbers, int(result.warnings[i]), seconds))
    return rows


def process_batch(
    root: str, batch: list[str], density: float, options=OPTIONS, packed: bool = True
) -> pa.Table:
    """The rows of a batch of files (what a worker runs), in the batch's order: the
    triangle meshes by one packed call, the others one at a time (every file one at
    a time when not packed: the path before the packed call, for comparison)."""
    rows: dict[str, dict] = {}
    meshes = []  # (path, vertices, triangles, seconds reading) for the packed call
    for path in batch:
        start = time.perf_counter()
        try:
            vertices, faces = read_mesh(Path(root) / path)
        except Exception as error:
            rows[path] = failed_row(path, error, time.perf_counter() - start)
            continue
        triangles = packable(faces) if packed else None
        if triangles is None:
            rows[path] = single_row(path, vertices, faces, density, options, start)
        else:
            meshes.append((path, vertices, triangles, time.perf_counter() - start))
    if meshes:
        rows.update((row["path"], row) for row in packed_rows(meshes, density, options))
    return pa.Table.from_pylist([rows[path] for path in batch], SCHEMA)


def discover(root: Path) -> Iterator[str]:
    """The mesh files under root, relative to it, in a stable order."""
    for directory, subdirectories, files in os.walk(root):
        subdirectories.sort()
        for name in sorted(files):
            if Path(name).suffix.lower() in EXTENSIONS:
                yield str((Path(directory) / name).relative_to(root))


def done_paths(out: Path) -> set[str]:
    """The files OUT already has a row for."""
    if not any(out.glob("*.parquet")):
        return set()
    return set(pq.read_table(out, columns=["path"]).column("path").to_pylist())


def batches(paths: Iterable[str], root: Path, batch_files: int, batch_bytes: int) -> list:
    """Consecutive files, up to batch_files of them or batch_bytes in all."""
    result: list[list[str]] = [[]]
    size = 0
    for path in paths:
        file_size = (root / path).stat().st_size
        if result[-1] and (len(result[-1]) >= batch_files or size + file_size > batch_bytes):
            result.append([])
            size = 0
        result[-1].append(path)
        size += file_size
    return [batch for batch in result if batch]


def write_part(out: Path, table: pa.Table) -> None:
    """One Parquet file, renamed into place whole, so a stopped run leaves no torn file."""
    name = f"part-{uuid.uuid4().hex}.parquet"
    with tempfile.NamedTemporaryFile(dir=out, suffix=".tmp", delete=False) as temporary:
        pq.write_table(table, temporary.name)
    os.replace(temporary.name, out / name)


def run(
    root: Path,
    out: Path,
    client=None,
    density: float = 1.0,
    batch_files: int = 64,
    batch_bytes: int = 64 << 20,
    options: polymass.Options = OPTIONS,
) -> dict:
    """Computes what OUT lacks; returns counts: files found, skipped, computed, batches."""
    out.mkdir(parents=True, exist_ok=True)
    found = list(discover(root))
    done = done_paths(out)
    todo = [path for path in found if path not in done]
    work = batches(todo, root, batch_files, batch_bytes)
    if client is None:
        for batch in work:
            write_part(out, process_batch(str(root), batch, density, options))
    else:
        from distributed import as_completed

        futures = client.map(
            process_batch, [str(root)] * len(work), work, density=density, options=options
        )
        for future in as_completed(futures):
            write_part(out, future.result())
            future.release()
    return {"found": len(found), "skipped": len(found) - len(todo), "computed": len(todo),
            "batches": len(work)}  # fmt: skip


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", type=Path, help="directory tree of STL/OBJ files")
    parser.add_argument("out", type=Path, help="directory of Parquet files (created)")
    parser.add_argument("--scheduler", help="address of a Dask scheduler, e.g. tcp://host:8786")
    parser.add_argument("--workers", type=int, default=os.cpu_count(), help="LocalCluster size")
    parser.add_argument("--serial", action="store_true", help="no Dask: this process only")
    parser.add_argument("--density", type=float, default=1.0, help="in the files' units")
    parser.add_argument("--batch-files", type=int, default=64, help="files per task at most")
    parser.add_argument(
        "--skip-intersection-check",
        action="store_true",
        help="for files known to hold no overlapping parts: their rows warn it was skipped",
    )
    arguments = parser.parse_args()
    options = dataclasses.replace(
        OPTIONS, skip_intersection_check=arguments.skip_intersection_check
    )

    def run_with(client) -> dict:
        return run(
            arguments.root,
            arguments.out,
            client,
            arguments.density,
            arguments.batch_files,
            options=options,
        )

    start = time.perf_counter()
    if arguments.serial:
        counts = run_with(None)
    else:
        from distributed import Client, LocalCluster

        if arguments.scheduler:
            client = Client(arguments.scheduler)
        else:
            cluster = LocalCluster(n_workers=arguments.workers, threads_per_worker=1)
            client = Client(cluster)
        with client:
            counts = run_with(client)
    seconds = time.perf_counter() - start
    rate = counts["computed"] / seconds if seconds > 0 else 0.0
    print(
        f"{counts['found']} files, {counts['skipped']} already done, {counts['computed']} "
        f"computed in {counts['batches']} batches: {seconds:.2f} s, {rate:.0f} files/s"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
