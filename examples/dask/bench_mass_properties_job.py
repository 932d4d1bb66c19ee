"""Meshes/s of the Dask job's tasks on a LocalCluster against the serial packed call.

    python examples/dask/bench_mass_properties_job.py [ROOT] [--files N] [--triangles T]
        [--workers W] [--batch-files K] [--rounds R]

On the STL/OBJ files under ROOT or, without ROOT, on N generated binary STLs (each
a closed torus of about T triangles at its own place: a triangle soup, as STL
files are, which the job welds), times the job's task, ``process_batch``
(reading the files, computing them, the Arrow table of their rows; not writing
Parquet), over the job's batches of at most K files:

  serial packed      every batch in this process, one packed call each: the
                     bound the cluster is measured against
  serial per file    the same, one ``polymass.mass_properties`` call a file (the
                     job before the packed call: ``packed=False``)
  cluster packed     the batches as tasks on a LocalCluster of W one-thread
  cluster per file   worker processes (the rows sent back; the cluster started
                     and warmed beforehand, outside the times)

each with the job's options, every check on (the default), and again with
``skip_intersection_check=True``: the intersection check is most of a small
mesh's time. Every time is the median of R interleaved rounds. Prints meshes/s
and the ratios; asserts nothing about speed (the rows of every path are checked
the same). Not run by the tests.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import statistics
import tempfile
import time
from pathlib import Path

import cloudpickle
import distributed
import mass_properties_job as job  # beside this file: the script's directory is on sys.path
import numpy as np
import pyarrow as pa

import polymass


def torus_soup(triangles: int, shift: float) -> np.ndarray:
    """The (f, 3, 3) corners of a closed torus (radii 2 and 0.5) of about
    ``triangles`` triangles, outward, moved by ``shift`` along x."""
    around = max(round((triangles / 2) ** 0.5 * 1.25), 3)  # the long way round
    across = max(triangles // (2 * around), 3)
    u = 2 * np.pi * np.arange(around) / around
    v = 2 * np.pi * np.arange(across) / across
    ring = 2 + 0.5 * np.cos(v)
    points = np.stack(
        [
            np.outer(np.cos(u), ring) + shift,
            np.outer(np.sin(u), ring),
            np.broadcast_to(0.5 * np.sin(v), (around, across)),
        ],
        axis=-1,
    )
    i, j = np.meshgrid(np.arange(around), np.arange(across), indexing="ij")
    a, b = points[i, j], points[(i + 1) % around, j]
    c, d = points[(i + 1) % around, (j + 1) % across], points[i, (j + 1) % across]
    quads = np.stack([a, b, c, d], axis=2).reshape(-1, 4, 3)
    return np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])


def write_corpus(root: Path, files: int, triangles: int) -> None:
    """files binary STLs of tori under root, a hundred to a directory."""
    for k in range(files):
        corners = torus_soup(triangles, 8.0 * k)
        records = np.zeros(len(corners), job.BINARY_STL)
        records["corners"] = corners
        path = root / f"set{k // 100:03d}" / f"torus_{k:05d}.stl"
        path.parent.mkdir(parents=True, exist_ok=True)
        count = np.array([len(corners)], "<u4").tobytes()
        path.write_bytes(b"bench_mass_properties_job".ljust(80) + count + records.tobytes())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", type=Path, nargs="?", help="STL/OBJ files (default: generated)")
    parser.add_argument("--files", type=int, default=2000, help="generated files")
    parser.add_argument("--triangles", type=int, default=1000, help="per generated file")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster processes")
    parser.add_argument("--batch-files", type=int, default=64, help="files per task at most")
    parser.add_argument("--rounds", type=int, default=3)
    arguments = parser.parse_args()

    with tempfile.TemporaryDirectory() as scratch:
        root = arguments.root
        if root is None:
            root = Path(scratch)
            write_corpus(root, arguments.files, arguments.triangles)
        paths = list(job.discover(root))
        work = job.batches(paths, root, arguments.batch_files, 64 << 20)
        faces = sum(len(job.read_mesh(root / path)[1]) for path in paths[:100])
        print(
            f"polymass {polymass.__version__}: {len(paths):,} files (the first 100: "
            f"{faces / min(len(paths), 100):,.0f} faces each), {len(work)} batches of at most "
            f"{arguments.batch_files}, {arguments.workers} one-thread workers, median of "
            f"{arguments.rounds} interleaved rounds; load average {os.getloadavg()[0]:.1f} "
            f"on {os.cpu_count()} cores before it (other work shares them)"
        )
        # The workers get the job's module in the pickles, as they get the job's functions.
        cloudpickle.register_pickle_by_value(job)
        with (
            distributed.LocalCluster(
                n_workers=arguments.workers, threads_per_worker=1, dashboard_address=None
            ) as cluster,
            distributed.Client(cluster) as client,
        ):
            for name, options in (
                ("every check (the default)", job.OPTIONS),
                (
                    "skip_intersection_check=True",
                    dataclasses.replace(job.OPTIONS, skip_intersection_check=True),
                ),
            ):
                measure(client, str(root), work, len(paths), name, options, arguments.rounds)


def measure(client, root: str, work: list, files: int, name: str, options, rounds: int) -> None:
    """Times the four paths with these options and prints their meshes/s."""

    def serial(packed: bool) -> list[pa.Table]:
        return [job.process_batch(root, batch, 1.0, options, packed) for batch in work]

    def cluster(packed: bool) -> list[pa.Table]:
        futures = client.map(
            job.process_batch, [root] * len(work), work, [1.0] * len(work),
            [options] * len(work), [packed] * len(work), pure=False,
        )  # fmt: skip
        return client.gather(futures)

    paths = {
        "serial packed": lambda: serial(True),
        "serial per file": lambda: serial(False),
        "cluster packed": lambda: cluster(True),
        "cluster per file": lambda: cluster(False),
    }
    cluster(True)  # the workers' first task: imports and the library loaded
    times: dict[str, list[float]] = {path: [] for path in paths}
    expected = None
    for _ in range(rounds):
        for path, call in paths.items():
            start = time.perf_counter()
            tables = call()
            times[path].append(time.perf_counter() - start)
            rows = pa.concat_tables(tables).drop_columns(["seconds"])
            if expected is None:
                expected = rows
            elif not rows.equals(expected):
                raise RuntimeError(f"{path}: other rows than serial packed")
    ok = expected.column("status").to_pylist().count("ok")
    rate = {path: files / statistics.median(values) for path, values in times.items()}
    bound = rate["serial packed"]
    print(f"  {name}: {ok:,} of {files:,} files solids")
    for path in paths:
        print(
            f"    {path:18s} {rate[path]:9.0f} meshes/s  {rate[path] / bound:5.2f} of serial packed"
        )
    gain = rate["cluster packed"] / rate["cluster per file"]
    print(f"    cluster packed / cluster per file {gain:.2f}")


if __name__ == "__main__":
    main()
