"""Sizes and load times of --html pages (the README's figures; not a test):
a sphere of about 1e4 and of 1e6 triangles (polymass check and polymass
FILE pages) and a 13-link URDF chain whose links are 1e4-triangle meshes
(polymass audit), each page opened in headless Chromium after a warm-up,
three times, the time from navigation to the page drawn.

    python3 tests/browser/page_load_times.py POLYMASS CHROMIUM WORK_DIR
"""

import math
import subprocess
import sys
import time
from pathlib import Path

from chromium import Chromium
from meshes import sphere_triangles, write_binary_stl

DRAWN = "new Promise((done) => requestAnimationFrame(() => done(window.polymass.ready)))"


def robot(folder, links=13):
    """A chain of links, each its own 1e4-triangle sphere mesh, 0.3 apart."""
    parts = ['<robot name="chain">']
    triangles = sphere_triangles(71, 71)
    for k in range(links):
        write_binary_stl(folder / f"link{k}.stl", triangles)
        moment = 0.4 * 4.19 * 0.01
        parts.append(
            f'<link name="l{k}"><inertial><mass value="4.19"/><inertia ixx="{moment}" '
            f'iyy="{moment}" izz="{moment}" ixy="0" ixz="0" iyz="0"/></inertial><collision>'
            f'<geometry><mesh filename="link{k}.stl" scale="0.1 0.1 0.1"/></geometry>'
            "</collision></link>"
        )
        if k:
            parts.append(
                f'<joint name="j{k}" type="revolute"><parent link="l{k - 1}"/>'
                f'<child link="l{k}"/><origin xyz="0 0 0.3" rpy="0 0.2 0"/><axis xyz="0 0 1"/>'
                '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
            )
    path = folder / "chain.urdf"
    path.write_text("\n".join(parts + ["</robot>"]) + "\n")
    return path


def main():
    polymass, chromium, work = sys.argv[1], sys.argv[2], Path(sys.argv[3]).resolve()
    work.mkdir(parents=True, exist_ok=True)
    pages = []
    for count in (10_000, 1_000_000):
        side = round(math.sqrt(count / 2))
        mesh = write_binary_stl(work / f"sphere_{count}.stl", sphere_triangles(side, side + 1))
        for command in (["check"], []):
            page = work / f"{'check' if command else 'properties'}_{count}.html"
            start = time.monotonic()
            subprocess.run([polymass, *command, "--html", page, mesh], capture_output=True)
            pages.append((page, time.monotonic() - start))
    description = robot(work)
    page = work / "audit_chain.html"
    start = time.monotonic()
    subprocess.run([polymass, "audit", "--html", page, description], capture_output=True)
    pages.append((page, time.monotonic() - start))

    with Chromium(chromium, timeout=120) as browser:
        warm_up = browser.open(pages[0][0].as_uri())
        warm_up.wait_for("window.polymass && window.polymass.ready", 120)
        warm_up.close()
        print(f"{'page':28} {'size':>10} {'written':>9} {'load (3 runs)':>22}")
        for page, written in pages:
            times = []
            for _ in range(3):
                start = time.monotonic()
                tab = browser.open(page.as_uri())
                tab.wait_for("window.polymass && window.polymass.ready", 120)
                tab.evaluate(DRAWN)
                times.append(time.monotonic() - start)
                assert not tab.errors, tab.errors
                tab.close()
            size = page.stat().st_size / 1e6
            runs = " ".join(f"{t:.2f}" for t in times)
            print(f"{page.name:28} {size:8.1f} MB {written:7.1f} s {runs:>20} s")


if __name__ == "__main__":
    main()
