"""Robot descriptions for the tests of polymass audit, each built around
boxes whose mass properties are exact (dyadic sizes and offsets), with the
planted errors the tests expect found.

box(size, low) is the solid [low, low + size]; its reference properties at a
mass are closed forms (Ixx = m (b^2 + c^2) / 12 about the centre).
"""

import struct

# A box of 0.25 x 0.125 x 0.5 m whose lowest corner is at (0.5, 0.25, -0.125)
# in the mesh file: away from the link origin, so that frames matter.
SIZE = (0.25, 0.125, 0.5)
LOW = (0.5, 0.25, -0.125)
MASS = 3.0


def centre(size=SIZE, low=LOW):
    return [lo + s / 2 for lo, s in zip(low, size)]


def box_inertia(mass, size=SIZE):
    a, b, c = size
    return [
        [mass * (b * b + c * c) / 12, 0.0, 0.0],
        [0.0, mass * (a * a + c * c) / 12, 0.0],
        [0.0, 0.0, mass * (a * a + b * b) / 12],
    ]


def about_point(inertia, mass, com, point):
    """The parallel-axis shift of a tensor about the centre of mass to point."""
    d = [c - p for c, p in zip(com, point)]
    dd = sum(x * x for x in d)
    return [
        [inertia[i][j] + mass * ((dd if i == j else 0.0) - d[i] * d[j]) for j in range(3)]
        for i in range(3)
    ]


def box_corners(size=SIZE, low=LOW, unit=1.0):
    return [
        tuple((lo + ((k >> axis) & 1) * s) / unit for axis, (lo, s) in enumerate(zip(low, size)))
        for k in range(8)
    ]


QUADS = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def triangles():
    return [t for q in QUADS for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])]


def write_obj(path, corners, faces=QUADS):
    lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in corners]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")


# An L-shaped prism (not convex: its hull, its surface and MuJoCo's legacy
# rule each weigh it differently; not symmetric: its products of inertia
# about its centre of mass are not zero), its section counter-clockwise in
# xy. Its coordinates are dyadic: MuJoCo keeps mesh vertices in single
# precision.
L_SECTION = [(0.0, 0.0), (0.25, 0.0), (0.25, 0.125), (0.125, 0.125), (0.125, 0.25), (0.0, 0.25)]
L_HEIGHT = 0.0625
# A long bar with a corner cut away: products of inertia small beside its
# distinct moments (a wrong sign moves the principal moments and axes
# little, as on most links of a robot).
NOTCHED_SECTION = [
    (0.0, 0.0),
    (0.5, 0.0),
    (0.5, 0.09375),
    (0.4375, 0.09375),
    (0.4375, 0.125),
    (0.0, 0.125),
]
# A U: its faces' area centroid lies in its gap, outside the solid, from
# where some faces are seen from behind (MuJoCo's legacy rule counts those
# pyramids positive); cut into triangles explicitly (no corner sees them all).
U_SECTION = [
    (0.0, 0.0),
    (0.25, 0.0),
    (0.25, 0.25),
    (0.1875, 0.25),
    (0.1875, 0.0625),
    (0.0625, 0.0625),
    (0.0625, 0.25),
    (0.0, 0.25),
]
U_TRIANGLES = [(0, 1, 4), (0, 4, 5), (1, 2, 3), (1, 3, 4), (0, 5, 6), (0, 6, 7)]


def write_l_prism(
    path,
    offset=(0.03125, -0.015625, 0.0078125),
    mirror_y=False,
    section=L_SECTION,
    triangles=None,
):
    """The prism of a section (its triangles: a fan from corner 0 unless
    given), or its mirror image across the xz plane (y negated, each face
    turned so that it still faces out)."""
    n = len(section)
    triangles = triangles or [(0, k, k + 1) for k in range(1, n - 1)]
    sign = -1.0 if mirror_y else 1.0
    vertices = [
        (x + offset[0], sign * (y + offset[1]), z + offset[2])
        for z in (0.0, L_HEIGHT)
        for x, y in section
    ]
    faces = []
    for a, b, c in triangles:
        faces.append((a, c, b))  # bottom, facing -z
        faces.append((n + a, n + b, n + c))  # top, facing +z
    for k in range(n):
        a, b = k, (k + 1) % n
        faces += [(a, b, n + b), (a, n + b, n + a)]
    if mirror_y:
        faces = [(a, c, b) for a, b, c in faces]
    path.parent.mkdir(parents=True, exist_ok=True)
    write_obj(path, vertices, faces)


def write_stl(path, corners):
    path.parent.mkdir(parents=True, exist_ok=True)
    data = bytearray(80) + struct.pack("<I", 12)
    for t in triangles():
        data += struct.pack("<3f", 0, 0, 0)
        for i in t:
            data += struct.pack("<3f", *corners[i])
        data += b"\0\0"
    path.write_bytes(bytes(data))


def write_dae(path, corners, unit, up):
    pos = " ".join(f"{x!r} {y!r} {z!r}" for x, y, z in corners)
    idx = " ".join(str(i) for t in triangles() for i in t)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="u" meter="{unit}"/><up_axis>{up}</up_axis></asset>
  <library_geometries>
    <geometry id="box"><mesh>
      <source id="p"><float_array id="pa" count="24">{pos}</float_array>
        <technique_common><accessor source="#pa" count="8" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/>
          <param name="Z" type="float"/></accessor></technique_common></source>
      <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
      <triangles count="12"><input semantic="VERTEX" source="#v" offset="0"/><p>{idx}</p>
      </triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="s">
    <node id="n"><instance_geometry url="#box"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
""")


def urdf_inertial(mass, com, inertia, rpy="0 0 0"):
    i = inertia
    return f"""    <inertial>
      <origin xyz="{com[0]!r} {com[1]!r} {com[2]!r}" rpy="{rpy}"/>
      <mass value="{mass!r}"/>
      <inertia ixx="{i[0][0]!r}" ixy="{i[0][1]!r}" ixz="{i[0][2]!r}" iyy="{i[1][1]!r}"
               iyz="{i[1][2]!r}" izz="{i[2][2]!r}"/>
    </inertial>"""


def urdf(links):
    """links: (name, inertial text or '', collision geometry text or '')."""
    body = []
    for name, inertial, geometry in links:
        body.append(f'  <link name="{name}">')
        body.append("    <!-- a comment --fix must keep -->")
        if inertial:
            body.append(inertial)
        if geometry:
            body.append(f"    <collision>\n      {geometry}\n    </collision>")
        body.append("  </link>")
    return '<?xml version="1.0"?>\n<robot name="test">\n' + "\n".join(body) + "\n</robot>\n"


def mjcf(compiler, geom_defaults, worldbody):
    """An MJCF model whose mesh asset box.obj (under meshdir "assets", at half
    size) is scaled by 2 through its class "robot", and whose class "part",
    nested in it, gives geoms geom_defaults (bodies choose it by childclass)."""
    return f"""<mujoco model="test">
  <compiler meshdir="assets" {compiler}/>
  <default>
    <default class="robot">
      <mesh scale="2 2 2"/>
      <default class="part">
        <geom type="mesh" {geom_defaults}/>
      </default>
    </default>
  </default>
  <asset>
    <mesh class="robot" file="box.obj"/>
  </asset>
  <worldbody>
{worldbody}
  </worldbody>
</mujoco>
"""
