"""The polymass tool end to end against trimesh on a closed sphere as binary
STL: a measurement, never a test (it needs trimesh from PyPI).

    python -m venv /tmp/v && /tmp/v/bin/pip install trimesh numpy
    /tmp/v/bin/python tests/benchmark/tool_vs_trimesh.py [--triangles 1e6] [--rounds 3] \
        build/release/src/cli/polymass [another polymass, e.g. a build of main ...]

Each round runs, one after the other, `POLYMASS FILE --json` for each tool
given (default options: every check, every core) and a fresh python that
loads the file with trimesh and asks for its mass_properties; each process's
wall time and peak resident memory are its own (/usr/bin/time). Prints the medians
over the rounds, trimesh's time over each tool's (issue 27 asks for at least
10) and each tool's peak memory over the file's size (at most 2), and checks
that all give the same volume. The machine's load is printed with them: on a shared machine
only the ratios of one run compare.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

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
    """Wall seconds, peak resident MiB and standard output of one process,
    as /usr/bin/time measures them: a child forked from this python would
    count the python's pages in its peak (Linux keeps it across exec)."""
    with tempfile.NamedTemporaryFile("r") as figures:
        timed = ["/usr/bin/time", "-f", "%e %M", "-o", figures.name, *command]
        run = subprocess.run(timed, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, check=False)
        if run.returncode != 0:
            sys.exit(f"{command[0]} failed ({run.returncode})")
        seconds, kib = figures.read().split()
    return float(seconds), int(kib) / 1024, run.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("polymass", nargs="+", help="the tools to measure")
    parser.add_argument("--triangles", type=float, default=1e6)
    parser.add_argument("--rounds", type=int, default=3)
    arguments = parser.parse_args()
    tools = {f"polymass {i + 1}": tool for i, tool in enumerate(arguments.polymass)}
    runs = {name: [] for name in [*tools, "trimesh"]}
    volumes = {}
    with tempfile.TemporaryDirectory() as directory:
        path = os.path.join(directory, "sphere.stl")
        count = write_sphere(path, int(arguments.triangles))
        file_mib = os.path.getsize(path) / 2**20
        for _ in range(arguments.rounds):
            for name, tool in tools.items():
                seconds, mib, output = measure([tool, path, "--json"])
                runs[name].append((seconds, mib))
                volumes[name] = json.loads(output)["volume"]
            seconds, mib, output = measure([sys.executable, "-c", TRIMESH, path])
            runs["trimesh"].append((seconds, mib))
            volumes["trimesh"] = float(output)
    load = os.getloadavg()
    print(
        f"closed sphere, {count} triangles, binary STL of {file_mib:.1f} MiB; median of "
        f"{arguments.rounds} interleaved rounds; load {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}"
    )
    for name, tool in tools.items():
        print(f"  {name}: {tool}")
    medians = {}
    for name, figures in runs.items():
        seconds = statistics.median(s for s, _ in figures)
        mib = statistics.median(m for _, m in figures)
        medians[name] = seconds, mib
        every = ", ".join(f"{s:.2f}" for s, _ in figures)
        print(f"  {name:10} {seconds:6.3f} s ({every})  peak {mib:6.1f} MiB")
    for name in tools:
        ratio = medians["trimesh"][0] / medians[name][0]
        memory = medians[name][1] / file_mib
        print(
            f"  {name}: trimesh's time {ratio:5.2f}x its own (goal: at least 10); "
            f"its peak {memory:4.2f}x the file (goal: at most 2)"
        )
    print("  volumes: " + ", ".join(f"{name} {volume:.15g}" for name, volume in volumes.items()))
    reference = volumes["trimesh"]
    if any(abs(volume - reference) > 1e-9 * abs(reference) for volume in volumes.values()):
        sys.exit("the volumes differ")


if __name__ == "__main__":
    main()
