"""Writes one solid in every format the polymass tool reads.

The solid is an L-bracket (a non-convex hexagonal profile extruded along z)
away from the origin, whose inertia tensor has a non-zero product Ixy, so sign
conventions show. Its coordinates are dyadic, so every format stores them
exactly. Polygon formats (OBJ, PLY, OFF) keep the hexagon caps; the
triangle-only formats (STL, glTF, 3MF) get a fan of the caps, which is valid
because every fan triangle of this profile from its first corner is
counter-clockwise.
"""

import base64
import json
import struct
import zipfile

PROFILE = [(0, 0), (1, 0), (1, 0.25), (0.25, 0.25), (0.25, 0.75), (0, 0.75)]
OFFSET = (3.5, -2.0, 1.25)
DEPTH = 0.5


def cube():
    """The unit cube [0, 1]^3: vertex k has x = bit 0, y = bit 1, z = bit 2 of k,
    six quads counter-clockwise seen from outside."""
    vertices = [(k & 1, (k >> 1) & 1, (k >> 2) & 1) for k in range(8)]
    faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return vertices, faces


def bracket():
    n = len(PROFILE)
    ox, oy, oz = OFFSET
    vertices = [(x + ox, y + oy, oz) for x, y in PROFILE]
    vertices += [(x + ox, y + oy, oz + DEPTH) for x, y in PROFILE]
    # The bottom cap runs backwards from corner 0, so that its fan (below) is
    # made of the same valid triangles as the top cap's.
    faces = [[0] + list(reversed(range(1, n))), list(range(n, 2 * n))]
    faces += [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
    return vertices, faces


def triangles(faces):
    return [[f[0], f[k], f[k + 1]] for f in faces for k in range(1, len(f) - 1)]


def write_obj(path, vertices, faces):
    lines = ["o bracket"] + [f"v {x!r} {y!r} {z!r}" for x, y, z in vertices]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")


def write_ascii_stl(path, vertices, faces):
    lines = ["solid bracket"]
    for f in triangles(faces):
        lines += ["  facet normal 0 0 0", "    outer loop"]
        lines += ["      vertex {!r} {!r} {!r}".format(*vertices[i]) for i in f]
        lines += ["    endloop", "  endfacet"]
    path.write_text("\n".join(lines + ["endsolid bracket"]) + "\n")


def binary_stl_bytes(vertices, faces):
    tris = triangles(faces)
    parts = [b"binary STL".ljust(80, b"\0"), struct.pack("<I", len(tris))]
    for f in tris:
        parts.append(struct.pack("<3f", 0, 0, 0))
        for i in f:
            parts.append(struct.pack("<3f", *vertices[i]))
        parts.append(b"\0\0")
    return b"".join(parts)


def write_binary_stl(path, vertices, faces):
    path.write_bytes(binary_stl_bytes(vertices, faces))


def ply_header(encoding, vertex_count, face_count):
    return (
        f"ply\nformat {encoding} 1.0\ncomment polymass test\n"
        f"element vertex {vertex_count}\nproperty double x\nproperty double y\n"
        f"property double z\nelement face {face_count}\n"
        "property list uchar int vertex_indices\nend_header\n"
    ).encode()


def write_ascii_ply(path, vertices, faces):
    body = [" ".join(repr(c) for c in v) for v in vertices]
    body += [" ".join(str(x) for x in [len(f)] + f) for f in faces]
    path.write_bytes(
        ply_header("ascii", len(vertices), len(faces)) + ("\n".join(body) + "\n").encode()
    )


def write_binary_ply(path, vertices, faces):
    data = [ply_header("binary_big_endian", len(vertices), len(faces))]
    data += [struct.pack(">3d", *v) for v in vertices]
    data += [struct.pack(f">B{len(f)}i", len(f), *f) for f in faces]
    path.write_bytes(b"".join(data))


def write_off(path, vertices, faces):
    lines = ["OFF", f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(repr(c) for c in v) for v in vertices]
    lines += [" ".join(str(x) for x in [len(f)] + f) for f in faces]
    path.write_text("\n".join(lines) + "\n")


def msh_bytes(vertices, faces, normals=0, texcoords=0):
    """MuJoCo's binary .msh: int32 nvertex, nnormal, ntexcoord, nface, then
    float32 positions, normals, texture coordinates and int32 triangles (the
    given counts of normals and texture coordinates, zeros)."""
    triangle_list = triangles(faces)
    data = struct.pack("<4i", len(vertices), normals, texcoords, len(triangle_list))
    data += struct.pack(f"<{3 * len(vertices)}f", *[c for v in vertices for c in v])
    data += bytes(12 * normals + 8 * texcoords)
    return data + struct.pack(f"<{3 * len(triangle_list)}i", *[i for t in triangle_list for i in t])


def write_msh(path, vertices, faces):
    path.write_bytes(msh_bytes(vertices, faces, normals=len(vertices), texcoords=len(vertices)))


# The glTF scene: a parent node whose matrix (column-major, as glTF stores
# it) turns a quarter about z and scales by 2, (x, y, z) -> (-2y, 2x, 2z), and
# under it a child node translated by CHILD_SHIFT that holds the mesh. Both are
# exact in binary, as is the inverse the mesh's vertices are stored through.
PARENT_MATRIX = [0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]
CHILD_SHIFT = (1.0, 0.5, -0.25)


def parent_transform(point):
    x, y, z = point
    return (-2 * y, 2 * x, 2 * z)


def parent_inverse(point):
    x, y, z = point
    return (y / 2, -x / 2, z / 2)


def gltf_document(vertices, faces, uri, copy_shifts=()):
    """A glTF 2 document whose buffer holds float32 positions then uint32
    indices. Its scene puts the solid where vertices say through the parent's
    and the child's transforms, which the reader must compose. Each of
    copy_shifts adds a sibling of the child translated by it that uses the same
    mesh: a copy of the solid moved by parent_transform(shift - CHILD_SHIFT)."""
    tris = triangles(faces)
    local = [tuple(c - s for c, s in zip(parent_inverse(v), CHILD_SHIFT)) for v in vertices]
    positions = b"".join(struct.pack("<3f", *v) for v in local)
    indices = b"".join(struct.pack("<3I", *f) for f in tris)
    buffer = positions + indices
    lo = [min(v[k] for v in local) for k in range(3)]
    hi = [max(v[k] for v in local) for k in range(3)]
    children = [{"mesh": 0, "name": "bracket", "translation": list(CHILD_SHIFT)}]
    children += [
        {"mesh": 0, "name": f"copy {k + 1}", "translation": list(shift)}
        for k, shift in enumerate(copy_shifts)
    ]
    parent = {
        "name": "frame",
        "matrix": PARENT_MATRIX,
        "children": list(range(1, 1 + len(children))),
    }
    document = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [parent] + children,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "buffers": [{"byteLength": len(buffer)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(positions), "target": 34962},
            {
                "buffer": 0,
                "byteOffset": len(positions),
                "byteLength": len(indices),
                "target": 34963,
            },
        ],
        "accessors": [
            {
                "bufferView": 0,
                "componentType": 5126,
                "count": len(local),
                "type": "VEC3",
                "min": lo,
                "max": hi,
            },
            {"bufferView": 1, "componentType": 5125, "count": 3 * len(tris), "type": "SCALAR"},
        ],
    }
    if uri:
        document["buffers"][0]["uri"] = (
            "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()
        )
    return document, buffer


def write_gltf_document(path, document, buffer):
    """A .gltf of document with buffer (changed by a test) embedded."""
    document["buffers"][0]["uri"] = (
        "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()
    )
    document["buffers"][0]["byteLength"] = len(buffer)
    path.write_text(json.dumps(document))


def write_gltf(path, vertices, faces, copy_shifts=()):
    document, _ = gltf_document(vertices, faces, uri=True, copy_shifts=copy_shifts)
    path.write_text(json.dumps(document))


def write_glb(path, vertices, faces):
    document, buffer = gltf_document(vertices, faces, uri=False)
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    buffer += b"\0" * (-len(buffer) % 4)
    chunks = (
        struct.pack("<I4s", len(text), b"JSON")
        + text
        + struct.pack("<I4s", len(buffer), b"BIN\0")
        + buffer
    )
    path.write_bytes(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)


def write_3mf(path, vertices, faces, component=None, item=None, unit="millimeter"):
    """A 3MF of the solid: object 1 is its mesh. With component (a 3MF
    transform, "m00 m01 m02 m10 ... m32": rows of a 4x3 matrix applied to row
    vectors), object 2 holds object 1 as a component so placed and is the one
    built; item is the build item's transform. unit is the <model unit>
    (None: no unit attribute, millimetres by the specification)."""
    vertex_xml = "".join('<vertex x="{!r}" y="{!r}" z="{!r}"/>'.format(*v) for v in vertices)
    triangle_xml = "".join(
        f'<triangle v1="{a}" v2="{b}" v3="{c}"/>' for a, b, c in triangles(faces)
    )
    built = 1
    components = ""
    if component is not None:
        built = 2
        components = (
            '<object id="2" type="model" name="assembly"><components>'
            f'<component objectid="1" transform="{component}"/></components></object>'
        )
    item_transform = f' transform="{item}"' if item is not None else ""
    unit_attribute = f'unit="{unit}" ' if unit is not None else ""
    model = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        f'<model {unit_attribute}xml:lang="en-US" '
        'xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">'
        '<resources><object id="1" type="model"><mesh>'
        f"<vertices>{vertex_xml}</vertices><triangles>{triangle_xml}</triangles>"
        f"</mesh></object>{components}</resources>"
        f'<build><item objectid="{built}"{item_transform}/></build></model>'
    )
    write_3mf_package(path, model)


MODEL_RELATIONSHIP = "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"


def write_3mf_package(path, model, target="/3D/3dmodel.model", relationship=MODEL_RELATIONSHIP):
    """A 3MF package of the model part's XML text, named by the root
    relationships as target with the relationship type given."""
    content_types = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">'
        '<Default Extension="rels" '
        'ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
        '<Default Extension="model" '
        'ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>'
        "</Types>"
    )
    rels = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
        f'<Relationship Target="{target}" Id="rel0" Type="{relationship}"/></Relationships>'
    )
    with zipfile.ZipFile(path, "w") as archive:
        for name, data in (
            ("[Content_Types].xml", content_types),
            ("_rels/.rels", rels),
            ("3D/3dmodel.model", model),
        ):
            # A fixed time: the same solid gives the same bytes (committed seeds).
            archive.writestr(zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0)), data)


WRITERS = {
    "bracket.obj": write_obj,
    "bracket_ascii.stl": write_ascii_stl,
    "bracket_binary.stl": write_binary_stl,
    "bracket_ascii.ply": write_ascii_ply,
    "bracket_binary.ply": write_binary_ply,
    "bracket.off": write_off,
    "bracket.msh": write_msh,
    "bracket.gltf": write_gltf,
    "bracket.glb": write_glb,
    "bracket.3mf": write_3mf,
}
