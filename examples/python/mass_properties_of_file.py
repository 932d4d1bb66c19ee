"""Mass properties of a part from a mesh file, as a robotics or CAD user would compute them.

    python examples/python/mass_properties_of_file.py [MESH] [--density KG_PER_M3] [--unit mm|m]

The mesh is read with trimesh (any format it reads: STL, OBJ, PLY, OFF, glTF, 3MF);
polymass computes. Without arguments: the aluminium robot link bundled with the
project, examples/data/robot_link.stl (millimetres). An STL is a triangle soup, every
triangle with its own vertices, so its vertices are welded for the closed-surface checks.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
import trimesh

import polymass

UNITS = {"m": 1.0, "mm": 1e-3}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "mesh", nargs="?", default=Path(__file__).parents[1] / "data" / "robot_link.stl"
    )
    parser.add_argument("--density", type=float, default=2700.0, help="kg/m^3 (aluminium)")
    parser.add_argument("--unit", choices=UNITS, default="mm", help="length unit of the file")
    arguments = parser.parse_args()

    # process=False: the coordinates exactly as stored; polymass does its own checks.
    loaded = trimesh.load(arguments.mesh, force="mesh", process=False)
    # Scale to metres so that kg/m^3 gives kg and kg*m^2.
    vertices = np.asarray(loaded.vertices) * UNITS[arguments.unit]
    faces = np.asarray(loaded.faces)

    # One analysis: every check (crossing faces of parts that overlap too), every
    # finding kept, then the properties of any density read from it.
    mesh = polymass.Mesh(vertices, faces, weld=True)
    report = mesh.diagnostics
    if not mesh.ok:
        print(f"{arguments.mesh}: not a closed solid: {mesh.message}", file=sys.stderr)
        print(
            f"  {report.open_edges} open edges, {report.non_manifold_edges} non-manifold, "
            f"{report.intersecting_face_pairs} crossing face pairs",
            file=sys.stderr,
        )
        return 1
    p = mesh.mass_properties(density=arguments.density)

    np.set_printoptions(precision=6, suppress=False)
    print(
        f"{Path(arguments.mesh).name}: {len(faces)} triangles, {report.used_vertex_count} vertices"
    )
    print(f"volume          {p.volume:.9g} m^3")
    print(f"mass            {p.mass:.9g} kg (density {p.density:g} kg/m^3)")
    print(f"surface area    {p.surface_area:.9g} m^2")
    print(f"centre of mass  {p.center_of_mass} m")
    print(
        f"inertia about the centre of mass (kg m^2; off-diagonal = negated products):\n{p.inertia}"
    )
    print(f"principal moments {p.principal_moments} kg m^2")
    print(f"principal axes (columns):\n{p.principal_axes}")
    i = p.inertia
    print(
        f'<inertial>\n  <origin xyz="{" ".join(f"{c:.9g}" for c in p.center_of_mass)}"/>\n'
        f'  <mass value="{p.mass:.9g}"/>\n'
        f'  <inertia ixx="{i[0, 0]:.9g}" ixy="{i[0, 1]:.9g}" ixz="{i[0, 2]:.9g}" '
        f'iyy="{i[1, 1]:.9g}" iyz="{i[1, 2]:.9g}" izz="{i[2, 2]:.9g}"/>\n</inertial>'
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
