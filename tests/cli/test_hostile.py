"""Hostile inputs to the polymass tool, run by ctest:

    POLYMASS_EXE=<polymass> POLYMASS_SOURCE_DIR=<repo> POLYMASS_WORK_DIR=<scratch> \
        python3 tests/cli/test_hostile.py

Files that lie about their size (a header claiming more than the file holds),
that expand without bound (a zip bomb, an include of itself), that nest
without end, or that are not files at all (/dev/zero): each must give its
error category, within a memory and a time limit. The tool runs under an
address-space limit (RLIMIT_AS) where the build allows it (not under
AddressSanitizer, whose shadow memory needs terabytes of address space), and
its peak resident memory (ru_maxrss, with the reader processes it waits for)
is compared with the tool's own on a tiny valid file. Big inputs are
generated here, streamed to disk in chunks, never held whole in memory.
"""

import json
import os
import resource
import struct
import subprocess
import sys
import tempfile
import threading
import time
import unittest
import zipfile
import zlib
from pathlib import Path

import fixtures

EXE = os.environ["POLYMASS_EXE"]
WORK = Path(os.environ["POLYMASS_WORK_DIR"])
SOURCE = Path(os.environ["POLYMASS_SOURCE_DIR"])

EXIT_INVALID_MESH, EXIT_UNREADABLE = 1, 3
MIB = 1 << 20
# What a hostile file may cost beyond the tool's footprint on a tiny file.
EXTRA_MEMORY = 64 * MIB
SECONDS = 60  # a debug build on a shared machine; the fixed readers take well under one


def sanitized():
    """Whether the tool is built with AddressSanitizer (linked to libasan)."""
    libraries = subprocess.run(["ldd", EXE], capture_output=True, text=True, check=False).stdout
    return "libasan" in libraries


SANITIZED = sanitized()


class Outcome:
    def __init__(self, returncode, stdout, stderr, peak_bytes, seconds):
        self.returncode = returncode
        self.stdout = stdout
        self.stderr = stderr
        self.peak_bytes = peak_bytes
        self.seconds = seconds


def run_bounded(args, address_space=None):
    """Runs the tool with args under RLIMIT_AS = address_space (bytes, when the
    build allows it) and a time limit; returns its Outcome with its peak
    resident memory."""

    def limit():
        if address_space is not None and not SANITIZED:
            resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))

    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        start = time.monotonic()
        process = subprocess.Popen([EXE, *map(str, args)], stdout=out, stderr=err, preexec_fn=limit)
        timer = threading.Timer(SECONDS, process.kill)
        timer.start()
        _, status, usage = os.wait4(process.pid, 0)
        timer.cancel()
        seconds = time.monotonic() - start
        process.returncode = os.waitstatus_to_exitcode(status)  # reaped above
        out.seek(0)
        err.seek(0)
        return Outcome(
            process.returncode,
            out.read().decode(errors="replace"),
            err.read().decode(errors="replace"),
            usage.ru_maxrss * 1024,
            seconds,
        )


class Hostile(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.vertices, cls.faces = fixtures.bracket()
        tiny = WORK / "tiny.stl"
        fixtures.write_binary_stl(tiny, cls.vertices, cls.faces)
        # The tool's own footprint: its libraries, a context, a tiny mesh.
        footprint = run_bounded(["--json", tiny])
        assert footprint.returncode == 0, footprint.stderr
        cls.footprint = footprint.peak_bytes
        # Its address space on that file, measured by the limit it runs under.
        cls.address_space = cls.footprint + 4096 * MIB

    def bounded(self, args, extra_memory=EXTRA_MEMORY):
        outcome = run_bounded(args, self.address_space)
        # The figures, for the record (unittest shows them with -v).
        print(
            f"\n  {Path(str(args[-1])).name}: {outcome.peak_bytes / MIB:.0f} MiB peak "
            f"({self.footprint / MIB:.0f} on a tiny file), {outcome.seconds:.2f} s",
            file=sys.stderr,
        )
        self.assertGreaterEqual(outcome.returncode, 0, f"crashed: {outcome.stderr}")
        self.assertNotIn("Sanitizer", outcome.stderr)
        self.assertLess(outcome.seconds, SECONDS, f"{args}: out of time")
        self.assertLessEqual(
            outcome.peak_bytes - self.footprint,
            extra_memory,
            f"{args}: {outcome.peak_bytes / MIB:.0f} MiB at its peak, "
            f"{self.footprint / MIB:.0f} MiB on a tiny file",
        )
        return outcome

    def expect_unreadable(self, path, message_part, extra_memory=EXTRA_MEMORY):
        outcome = self.bounded(["--json", path], extra_memory)
        self.assertEqual(outcome.returncode, EXIT_UNREADABLE, outcome.stderr)
        error = json.loads(outcome.stdout)["error"]
        self.assertEqual(error["category"], "unreadable", error)
        self.assertIn(message_part, error["message"])
        return error

    def write(self, name, data):
        path = WORK / name
        path.write_bytes(data if isinstance(data, bytes) else data.encode())
        return path

    # -- mesh files whose headers lie ---------------------------------------

    def test_binary_stl_claiming_four_billion_triangles(self):
        body = fixtures.binary_stl_bytes(self.vertices, self.faces)[84:]
        path = self.write("claims_4e9.stl", b"\0" * 80 + struct.pack("<I", 4_000_000_000) + body)
        self.expect_unreadable(path, "header says 4000000000 triangles")

    def test_ply_declaring_a_trillion_vertices(self):
        header = (
            "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
            "property float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
        )
        path = self.write("trillion.ply", header.encode() + b"\0" * 4096)
        self.expect_unreadable(path, "impossible element count 1000000000000")

    def test_off_declaring_more_vertices_than_its_bytes_hold(self):
        path = self.write("many.off", "OFF\n100000000 1 0\n" + "0 0 0\n" * 1000)
        self.expect_unreadable(path, "impossible vertex count 100000000")

    def test_msh_claiming_the_largest_counts(self):
        # Every count 2^31 - 1 over a real bracket's bytes: refused by its length.
        body = fixtures.msh_bytes(self.vertices, self.faces)[16:]
        path = self.write("claims_2e9.msh", struct.pack("<4i", *[2**31 - 1] * 4) + body)
        self.expect_unreadable(path, "make 94489280484 bytes, but the file has 400")

    def test_obj_face_of_a_hundred_million_corners_on_one_line(self):
        # f 1 2 3 1 2 3 ...: one polygon of 10^8 corners naming 3 vertices, a
        # 200 MB line written in chunks. The rest of the file has room for 3
        # vertices: the face is refused once past 2^16 corners, as it is read.
        path = WORK / "long_line.obj"
        corners = 100_000_000
        chunk = b" 1 2 3" * 100_000
        with path.open("wb") as out:
            out.write(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf")
            for _ in range(corners // 300_000):
                out.write(chunk)
            out.write(b" 1 2 3" * (corners % 300_000 // 3) + b" 1\n")
        try:
            # The line is scanned to its end (its pages mapped) to find it.
            size = path.stat().st_size
            self.expect_unreadable(path, "a face of more than 65536 corners", size + EXTRA_MEMORY)
        finally:
            path.unlink()

    # -- glTF ---------------------------------------------------------------

    def gltf_parts(self):
        document, buffer = fixtures.gltf_document(self.vertices, self.faces, uri=False)
        return document, bytearray(buffer)

    def test_gltf_accessors_past_their_buffers(self):
        for name, change in (
            ("count", lambda d: d["accessors"][0].update(count=4_000_000_000)),
            ("offset", lambda d: d["accessors"][1].update(byteOffset=2**62)),
            ("view", lambda d: d["bufferViews"][0].update(byteLength=2**40)),
        ):
            with self.subTest(name):
                document, buffer = self.gltf_parts()
                change(document)
                path = WORK / f"past_buffer_{name}.gltf"
                fixtures.write_gltf_document(path, document, bytes(buffer))
                self.expect_unreadable(path, "")

    def test_gltf_primitive_naming_an_accessor_that_does_not_exist(self):
        # A fuzzer's find (tests/fuzz/gltf/regressions/): the reader looked
        # the POSITION accessor up with vector::at, whose std::out_of_range
        # escaped as "the reader failed (exit status 2)".
        document, buffer = self.gltf_parts()
        document["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 5
        path = WORK / "no_such_accessor.gltf"
        fixtures.write_gltf_document(path, document, bytes(buffer))
        self.expect_unreadable(path, "accessor 5 does not exist")

    def test_gltf_buffer_that_is_not_a_file(self):
        # A fuzzer's find (tests/fuzz/gltf/regressions/): a buffer's URI naming
        # a directory made tinygltf ask for 2^63 bytes; a pipe would have kept
        # it waiting for a writer forever.
        directory = WORK / "buffer_directory"
        directory.mkdir(exist_ok=True)
        pipe = WORK / "buffer_pipe"
        if not pipe.exists():
            os.mkfifo(pipe)
        device = WORK / "buffer_device"  # a URI is relative: a link to /dev/zero
        if not device.is_symlink():
            device.symlink_to("/dev/zero")
        for name, uri, message in (
            ("directory", directory.name, "it is a directory, not a file"),
            # The fuzzer's URI: it decodes to a NUL byte, the glTF's own directory.
            ("undecodable", "%%%%", "it is a directory, not a file"),
            ("pipe", pipe.name, "not a regular file"),
            ("device", device.name, "not a regular file"),
        ):
            with self.subTest(name):
                document, _ = self.gltf_parts()
                document["buffers"][0]["uri"] = uri
                path = WORK / f"buffer_{name}.gltf"
                path.write_text(json.dumps(document))
                self.expect_unreadable(path, message)

    def test_gltf_nodes_nested_deeply(self):
        document, buffer = self.gltf_parts()
        depth = 10_000  # ten times the deepest tree the reader follows
        document["nodes"] = [{"children": [k + 1]} for k in range(depth)] + [{"mesh": 0}]
        document["scenes"] = [{"nodes": [0]}]
        path = WORK / "deep.gltf"
        fixtures.write_gltf_document(path, document, bytes(buffer))
        self.expect_unreadable(path, "too deep")

    # -- 3MF ----------------------------------------------------------------

    def test_3mf_zip_bomb(self):
        # The model's vertices inflate to 1 GiB (38 million of them) from
        # 1 MiB: a deflate block of 1 MiB of vertices, flushed so that it
        # stands alone, repeated inside the model's <vertices>.
        path = WORK / "bomb.3mf"
        fixtures.write_3mf(path, self.vertices, self.faces)
        with zipfile.ZipFile(path) as package:
            parts = {name: package.read(name) for name in package.namelist()}
        model_name = next(name for name in parts if name.endswith(".model"))
        model = parts.pop(model_name)
        split = model.index(b"<vertices>") + len(b"<vertices>")
        vertex = b'<vertex x="0" y="0" z="0"/>'
        vertices = vertex * (MIB // len(vertex))
        repeats = 1024
        compressor = zlib.compressobj(9, zlib.DEFLATED, -15)
        head = compressor.compress(model[:split]) + compressor.flush(zlib.Z_FULL_FLUSH)
        block = compressor.compress(vertices) + compressor.flush(zlib.Z_FULL_FLUSH)
        tail = compressor.compress(model[split:]) + compressor.flush()
        crc = zlib.crc32(model[:split])
        for _ in range(repeats):
            crc = zlib.crc32(vertices, crc)
        crc = zlib.crc32(model[split:], crc)
        size = len(model) + repeats * len(vertices)
        with zipfile.ZipFile(path, "w") as package:
            for name, data in parts.items():
                package.writestr(name, data)
        self.append_deflated(path, model_name, head, block, repeats, tail, crc, size)
        self.expect_unreadable(path, "inflate to more than")

    def test_3mf_part_declaring_more_than_a_size_can_hold(self):
        # A part that declares 2^64 - 1 bytes (zip64) beside the model's:
        # summed without saturating, the declared sizes wrap past zero to
        # less than the model alone.
        path = WORK / "declares_2_64.3mf"
        fixtures.write_3mf(path, self.vertices, self.faces)
        compressor = zlib.compressobj(9, zlib.DEFLATED, -15)
        data = compressor.compress(b"x") + compressor.flush()
        self.append_deflated(
            path, "Metadata/huge.bin", data, b"", 0, b"", zlib.crc32(b"x"), 2**64 - 1
        )
        self.expect_unreadable(path, "inflate to more than")

    # -- Collada ------------------------------------------------------------

    @unittest.skipIf(
        SANITIZED,
        "AddressSanitizer's operator new ends the process when memory runs out, where the "
        "reader's budget relies on std::bad_alloc",
    )
    def test_collada_accessor_without_count(self):
        # A fuzzer's find (tests/fuzz/dae/open/): a box whose <accessor> has
        # no count, from which assimp allocates and fills 2.2 GB. The reader's
        # memory is bounded by the file's size (256 MiB and 64 bytes a byte
        # of it), where it stops.
        path = SOURCE / "tests/fuzz/dae/open/found_accessor_without_count_2GB.dae"
        self.expect_unreadable(path, "ran out of its memory", extra_memory=320 * MIB)

    # -- robot descriptions -------------------------------------------------

    def audit(self, path):
        outcome = self.bounded(["audit", "--json", path])
        return outcome, json.loads(outcome.stdout) if outcome.stdout else None

    def test_urdf_mesh_at_dev_zero_or_itself(self):
        directory = WORK / "robot"
        directory.mkdir(exist_ok=True)
        zero = directory / "zero.stl"
        if not zero.is_symlink():
            zero.symlink_to("/dev/zero")
        links = "".join(
            f'<link name="{name}"><collision><geometry><mesh filename="{uri}"/></geometry>'
            "</collision></link>"
            for name, uri in (("device", "/dev/zero"), ("link", "zero.stl"), ("self", "robot.urdf"))
        )
        path = directory / "robot.urdf"
        path.write_text(f'<robot name="hostile">{links}</robot>')
        outcome, out = self.audit(path)
        self.assertEqual(outcome.returncode, 1, outcome.stderr)
        for entry in out["links"]:
            kinds = [finding["kind"] for finding in entry["findings"]]
            self.assertIn("unreadable_mesh", kinds, entry)
        # A mesh file that is a device is refused by the reader itself too.
        self.expect_unreadable(zero, "not a regular file")

    def test_files_that_are_pipes(self):
        # Opening a pipe for reading waits for a writer: the tool must refuse
        # it at once, as a mesh file, a robot description and an assembly.
        for name, command in (
            ("mesh.stl", []),
            ("robot.urdf", ["audit"]),
            ("parts.json", ["assembly"]),
        ):
            with self.subTest(name):
                path = WORK / f"pipe_{name}"
                if not path.exists():
                    os.mkfifo(path)
                outcome = self.bounded([*command, "--json", path])
                self.assertEqual(outcome.returncode, EXIT_UNREADABLE, outcome.stderr)
                self.assertIn("not a regular file", outcome.stdout)

    def test_description_that_is_dev_zero(self):
        path = WORK / "zero.urdf"
        if not path.is_symlink():
            path.symlink_to("/dev/zero")
        outcome = self.bounded(["audit", "--json", path])
        self.assertEqual(outcome.returncode, EXIT_UNREADABLE, outcome.stderr)
        self.assertIn("not a regular file", json.loads(outcome.stdout)["error"])

    def test_assembly_file_that_is_dev_zero(self):
        # Read to its end, /dev/zero would fill the memory.
        path = WORK / "zero.json"
        if not path.is_symlink():
            path.symlink_to("/dev/zero")
        outcome = self.bounded(["assembly", "--json", path])
        self.assertEqual(outcome.returncode, EXIT_UNREADABLE, outcome.stderr)
        error = json.loads(outcome.stdout)["error"]
        self.assertEqual(error["category"], "unreadable", error)
        self.assertIn("not a regular file", error["message"])

    def test_mjcf_that_includes_itself(self):
        directory = WORK / "mjcf"
        directory.mkdir(exist_ok=True)
        path = directory / "robot.xml"
        # Twice: without a cycle check, 2^depth files would be loaded.
        path.write_text(
            '<mujoco><include file="robot.xml"/><include file="robot.xml"/>'
            '<worldbody><body name="b"/></worldbody></mujoco>'
        )
        outcome = self.bounded(["audit", "--json", path])
        self.assertEqual(outcome.returncode, EXIT_UNREADABLE, outcome.stderr)
        self.assertIn("includes a file that includes it", json.loads(outcome.stdout)["error"])

    # -- helpers ------------------------------------------------------------

    @staticmethod
    def append_deflated(path, name, head, block, repeats, tail, crc, size):
        """Appends to the zip at path a deflated entry made of head, block
        repeated, and tail, written in pieces rather than inflated here."""
        with zipfile.ZipFile(path, "a") as package:
            info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            compressed = len(head) + repeats * len(block) + len(tail)
            info.file_size = size
            info.compress_size = compressed
            info.CRC = crc
            package.fp.seek(package.start_dir)
            info.header_offset = package.fp.tell()
            info.flag_bits = 0
            package.fp.write(info.FileHeader(None))  # zip64 when a size needs it
            package.fp.write(head)
            for _ in range(repeats):
                package.fp.write(block)
            package.fp.write(tail)
            package.start_dir = package.fp.tell()
            package.filelist.append(info)
            package.NameToInfo[name] = info
            package._didModify = True


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"], exit=True)
