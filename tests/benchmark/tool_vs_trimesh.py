"""The polymass tool end to end against trimesh on a closed sphere as binary
STL: a measurement, never a test (it needs trimesh from PyPI).

    python -m venv /tmp/v && /tmp/v/bin/pip install trimesh numpy
    /tmp/v/bin/python tests/benchmark/tool_vs_trimesh.py build/release/src/cli/polymass \
        [triangles, default 1e6] [rounds, default 3]

Each round runs, one after the other, `polymass FILE --json` (default
options: every check, every core) and a fresh python that loads the file
with trimesh and asks for its mass_properties; each process's wall time and
peak resident memory are its own (wait4). Prints the medians over the rounds,
trimesh's time over polymass's (issue 27 asks for at least 10) and polymass's
peak memory over the file's size (at most 2), and checks that both give the
same volume. The machine's load is printed with them: on a shared machine
only the ratios of one run compare.
"""

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

TRIMESH = """
import sys
import trimesh
mesh = trimesh.load(sys.argv[1])
print(mesh.mass_properties["volume"])
"""


def write_sphere(path, triangles):
    """A closed UV sphere of about `triangles` triangles, float32 corners
    shared exactly, written as binary STL."""
    lon = max(3, round(float(np.sqrt(triangles))))
    lat = max(2, round(triangles / (2 * lon)) + 1)
    theta = np.linspace(0, np.pi, lat + 1)[1:-1]
    phi = np.arange(lon) * 2 * np.pi / lon
    rings = np.stack(
        [
            np.outer(np.sin(theta), np.cos(phi)),
            np.outer(np.sin(theta), np.sin(phi)),
            np.outer(np.cos(theta), np.ones(lon)),
        ],
        axis=-1,
    ).astype(np.float32)
    j = np.arange(lon)
    k = (j + 1) % lon
    north = np.broadcast_to(np.float32([0, 0, 1]), (lon, 3))
    south = np.broadcast_to(np.float32([0, 0, -1]), (lon, 3))
    # Counter-clockwise seen from outside.
    parts = [np.stack([north, rings[0, j], rings[0, k]], axis=1)]
    for i in range(lat - 2):
        a, b, c, d = rings[i, j], rings[i, k], rings[i + 1, j], rings[i + 1, k]
        parts += [np.stack([a, c, d], axis=1), np.stack([a, d, b], axis=1)]
    parts.append(np.stack([south, rings[-1, k], rings[-1, j]], axis=1))
    corners = np.concatenate(parts)
    records = np.zeros(len(corners), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    records["v"] = corners
    with open(path, "wb") as f:
        f.write(b"\0" * 80)
        f.write(np.uint32(len(corners)).tobytes())
        f.write(records.tobytes())
    return len(corners)


def measure(command):
    """Wall seconds, peak resident MiB and standard output of one process."""
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    output = process.stdout.read()
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        sys.exit(f"{command[0]} failed ({process.returncode})")
    return seconds, usage.ru_maxrss / 1024, output


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    polymass = sys.argv[1]
    triangles = int(float(sys.argv[2])) if len(sys.argv) > 2 else 1_000_000
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    with tempfile.TemporaryDirectory() as directory:
        path = os.path.join(directory, "sphere.stl")
        count = write_sphere(path, triangles)
        file_mib = os.path.getsize(path) / 2**20
        runs = {"polymass": [], "trimesh": []}
        volumes = {}
        for _ in range(rounds):
            seconds, mib, output = measure([polymass, path, "--json"])
            runs["polymass"].append((seconds, mib))
            volumes["polymass"] = json.loads(output)["volume"]
            seconds, mib, output = measure([sys.executable, "-c", TRIMESH, path])
            runs["trimesh"].append((seconds, mib))
            volumes["trimesh"] = float(output)
    load = os.getloadavg()
    print(
        f"closed sphere, {count} triangles, binary STL of {file_mib:.1f} MiB; "
        f"median of {rounds} interleaved rounds; load {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}"
    )
    medians = {}
    for name, figures in runs.items():
        seconds = statistics.median(s for s, _ in figures)
        mib = statistics.median(m for _, m in figures)
        medians[name] = seconds, mib
        every = ", ".join(f"{s:.2f}" for s, _ in figures)
        print(f"  {name:9} {seconds:6.3f} s ({every})  peak {mib:6.1f} MiB")
    ratio = medians["trimesh"][0] / medians["polymass"][0]
    memory = medians["polymass"][1] / file_mib
    print(f"  trimesh / polymass time  {ratio:5.2f}x  (goal: at least 10)")
    print(f"  polymass peak / file     {memory:5.2f}x  (goal: at most 2)")
    difference = abs(volumes["polymass"] - volumes["trimesh"]) / abs(volumes["trimesh"])
    both = f"{volumes['polymass']:.15g} and {volumes['trimesh']:.15g}"
    print(f"  volumes {both}: {difference:.1e} apart")
    if difference > 1e-9:
        sys.exit("the volumes differ")


if __name__ == "__main__":
    main()
