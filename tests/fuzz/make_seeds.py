#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets of the tool (tests/fuzz/<name>/
corpus/ for obj, stl, ply, off, msh, gltf, glb, 3mf, 3mf_model, dae, audit,
arguments) and of fuzz_moments.c, from the solids of tests/cli/fixtures.py (a
cube and the L-bracket, also as triangles).

The output is deterministic and committed; run this again only after changing
it (the mesh target's own seeds are make_corpus.py's):

    python3 tests/fuzz/make_seeds.py
"""

import math
import pathlib
import struct
import sys
import zipfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "cli"))
import fixtures  # noqa: E402

SOLIDS = {"cube": fixtures.cube(), "bracket": fixtures.bracket()}


def corpus(name):
    path = HERE / name / "corpus"
    path.mkdir(parents=True, exist_ok=True)
    return path


def write_meshes():
    writers = {
        "obj": [("", fixtures.write_obj)],
        "stl": [("_ascii", fixtures.write_ascii_stl), ("_binary", fixtures.write_binary_stl)],
        "ply": [("_ascii", fixtures.write_ascii_ply), ("_binary", fixtures.write_binary_ply)],
        "off": [("", fixtures.write_off)],
        "msh": [("", fixtures.write_msh)],
        "gltf": [("", fixtures.write_gltf)],
        "glb": [("", fixtures.write_glb)],
        "3mf": [("", fixtures.write_3mf)],
    }
    for fmt, kinds in writers.items():
        for solid, (vertices, faces) in SOLIDS.items():
            for suffix, write in kinds:
                write(corpus(fmt) / f"{solid}{suffix}.{fmt}", vertices, faces)
    # 3MF with a component and a build item transform; glTF with two copies.
    vertices, faces = SOLIDS["cube"]
    fixtures.write_3mf(
        corpus("3mf") / "cube_component.3mf",
        vertices,
        faces,
        component="1 0 0 0 1 0 0 0 1 2 3 4",
        item="0 1 0 -1 0 0 0 0 1 0 0 0",
    )
    fixtures.write_gltf(
        corpus("gltf") / "cube_copies.gltf", vertices, faces, copy_shifts=[(3, 0, 0)]
    )
    # fuzz_3mf_model's seeds: the model part of each 3MF seed.
    for package in sorted(corpus("3mf").glob("*.3mf")):
        with zipfile.ZipFile(package) as archive:
            model = archive.read("3D/3dmodel.model")
        (corpus("3mf_model") / f"{package.stem}.model").write_bytes(model)
    # OBJ with negative indices, texture and normal references, two objects.
    (corpus("obj") / "cube_relative.obj").write_text(
        "o a\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "vt 0 0\nvn 0 0 1\nf -8/1/1 -5/1/1 -6/1/1 -7/1/1\nf -4//1 -3//1 -2//1 -1//1\n"
        "o b\ng side\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
    )
    # Collada: the audit fixture's box in centimetres, Y up.
    corners = [(x, y, z) for x in (0.0, 2.0) for y in (0.0, 1.0) for z in (0.0, 0.5)]
    corners = [corners[i] for i in (0, 4, 6, 2, 1, 5, 7, 3)]
    fixtures_audit().write_dae(corpus("dae") / "box_cm_y_up.dae", corners, 0.01, "Y_UP")
    fixtures_audit().write_dae(corpus("dae") / "box_m_z_up.dae", corners, 1.0, "Z_UP")


def fixtures_audit():
    import audit_fixtures

    return audit_fixtures


INERTIAL = (
    '<inertial><origin xyz="0.5 0.5 0.5" rpy="0 0 0"/><mass value="1000"/>'
    '<inertia ixx="166.7" ixy="0" ixz="0" iyy="166.7" iyz="0" izz="166.7"/></inertial>'
)


def write_descriptions():
    out = corpus("audit")
    (out / "urdf_stl.urdf").write_text(
        '<?xml version="1.0"?>\n<robot name="r"><link name="base">'
        + INERTIAL
        + '<collision><origin xyz="0 0 0" rpy="0 0 0"/><geometry>'
        '<mesh filename="meshes/cube.stl" scale="1 1 1"/></geometry></collision></link>'
        '<link name="arm"><visual><geometry><box size="1 2 3"/></geometry></visual>'
        '<collision><geometry><mesh filename="package://robot/meshes/cube.stl"/>'
        "</geometry></collision></link>"
        '<joint name="j" type="fixed"><parent link="base"/><child link="arm"/></joint></robot>\n'
    )
    (out / "urdf_primitives.urdf").write_text(
        '<robot name="r"><link name="a"><collision><geometry><cylinder radius="0.5" '
        'length="2"/></geometry></collision></link><link name="b"><collision><geometry>'
        '<sphere radius="1"/></geometry></collision></link></robot>\n'
    )
    (out / "sdf_obj.sdf").write_text(
        '<?xml version="1.0"?>\n<sdf version="1.9"><model name="m"><link name="l">'
        "<pose>1 2 3 0 0 0.5</pose><inertial><mass>1000</mass><inertia><ixx>166.7</ixx>"
        "<iyy>166.7</iyy><izz>166.7</izz></inertia></inertial>"
        "<collision name='c'><geometry><mesh><uri>meshes/cube.obj</uri><scale>1 1 1</scale>"
        "</mesh></geometry></collision></link></model></sdf>\n"
    )
    (out / "mjcf_mesh.xml").write_text(
        '<mujoco model="m"><compiler meshdir="meshes"/><asset><mesh name="c" '
        'file="cube.stl" scale="2 2 2"/></asset><worldbody><body name="b" pos="0 0 1">'
        '<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/><geom type="mesh" mesh="c"/>'
        '<body name="c"><geom type="box" size="1 1 1" density="500"/></body></body>'
        "</worldbody></mujoco>\n"
    )


def write_arguments():
    out = corpus("arguments")
    lines = {
        "properties": ["part.stl"],
        "density_json": ["--density", "7850", "--json", "--units", "mm", "part.obj"],
        "check": ["check", "--no-intersection-check", "a.ply", "b.off"],
        "urdf_about": ["--urdf", "--about", "1,2,3", "--mass", "2.5", "--scale", "0.001", "x.glb"],
        "parts": ["--density", "base=1000", "--mass", "arm=2", "--repair", "--fallback", "a.3mf"],
        "assembly": ["assembly", "robot.json", "--json"],
        "audit": ["audit", "--from", "visual", "--fail-on", "warning", "--fix", "o.urdf", "r.urdf"],
        "help": ["--help"],
    }
    for name, words in lines.items():
        (out / name).write_text("\n".join(words))


def write_moments():
    """Programs of fuzz_moments.c: a cube made, moved, scaled, weighted,
    added and subtracted, and its mass properties taken."""
    out = corpus("moments")
    d = lambda *values: struct.pack(f"<{len(values)}d", *values)  # noqa: E731
    c, s = math.cos(0.5), math.sin(0.5)
    compute = bytes([0 | 1 << 3]) + d(2, 3, 4, 1e6, -1e6, 5)
    transform = bytes([4 | 1 << 3]) + d(c, -s, 0, s, c, 0, 0, 0, 1, 1, 2, 3)
    scale = bytes([5 | 1 << 3]) + d(1e-3, 1e-3, 1e-3)
    weight = bytes([6 | 1 << 3, 0]) + d(7850)
    add = bytes([2 | 1 << 3 | 2 << 5])
    subtract = bytes([3 | 1 << 3 | 2 << 5])
    properties = bytes([7 | 1 << 3, 1]) + d(3, 0, 0, 0)
    (out / "compute_properties").write_bytes(compute + properties)
    (out / "transform_scale").write_bytes(compute + transform + scale + properties)
    (out / "weight_add_subtract").write_bytes(weight + add + subtract + properties)
    raw = bytes([1 | 2 << 3]) + d(0, 0, 0, 1, 1, 0, 0, 0, 1 / 12, 1 / 12, 1 / 12, 0, 0, 0)
    raw += d(0, 0, 0, 0, 0) + bytes([1])
    (out / "raw_partial").write_bytes(raw + bytes([2 | 2 << 3]) + bytes([7 | 2 << 3 | 0x80]))


def main():
    write_meshes()
    write_descriptions()
    write_arguments()
    write_moments()


if __name__ == "__main__":
    main()
