// libFuzzer target: arbitrary bytes as a mesh file of one format, read by the
// tool's reader of that format (src/cli/readers). Built once per format, the
// format named by POLYMASS_FUZZ_FORMAT ("obj", "stl", "ply", "off", "gltf",
// "glb", "3mf", "dae").
//
// The tool's own readers and the 3MF reader take the bytes; glTF/GLB and
// Collada are read by their libraries from a file, written at each execution
// into a sandbox directory of this process (external glTF buffers resolve
// there). The libraries' readers are called directly, not in the child
// process the tool runs them in (readers/isolated_reader), so that the fuzzer
// sees their coverage and their crashes.
//
// A reader either throws ReadError or returns a Model the rest of the tool
// relies on: every part's face sizes add up to its indices, and there are
// whole vertices (x, y, z). A violation
// prints what failed and traps; any other exception escapes (and aborts).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "readers/format_readers.hpp"
#include "readers/mesh_reader.hpp"

#ifndef POLYMASS_FUZZ_FORMAT
#error "POLYMASS_FUZZ_FORMAT names the format (tests/fuzz/CMakeLists.txt)"
#endif

namespace {

using polymass_cli::Model;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "\nfuzz_reader (%s): invariant violated: %s\n", POLYMASS_FUZZ_FORMAT,
                 what);
    std::fflush(stderr);
    __builtin_trap();
}

// The file a library reads, in a directory of this process's own.
const std::string& sandbox_file() {
    static const std::string path = [] {
        char directory[] = "/tmp/polymass-fuzz-reader-XXXXXX";
        if (!mkdtemp(directory)) std::abort();
        return std::string(directory) + "/input." POLYMASS_FUZZ_FORMAT;
    }();
    return path;
}

Model read(const std::string& bytes) {
    const std::string format = POLYMASS_FUZZ_FORMAT;
    if (format == "obj") return polymass_cli::read_obj(bytes);
    if (format == "stl") return polymass_cli::read_stl(bytes);
    if (format == "ply") return polymass_cli::read_ply(bytes);
    if (format == "off") return polymass_cli::read_off(bytes);
    if (format == "3mf") return polymass_cli::read_3mf(bytes);
    {
        std::ofstream file(sandbox_file(), std::ios::binary | std::ios::trunc);
        file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!file) std::abort();
    }
    if (format == "gltf" || format == "glb") return polymass_cli::read_gltf(sandbox_file());
    if (format == "dae") return polymass_cli::read_collada(sandbox_file());
    fail("unknown POLYMASS_FUZZ_FORMAT");
}

void check(const Model& model) {
    if (model.positions.size() % 3 != 0) fail("positions are not whole vertices");
    for (const polymass_cli::Part& part : model.parts) {
        std::uint64_t corners = 0;
        for (const std::uint32_t size : part.face_sizes) corners += size;
        if (corners != part.indices.size()) fail("face sizes do not add up to the indices");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        check(read(bytes));
    } catch (const polymass_cli::ReadError&) {
        // A clear refusal: what a malformed file must give.
    }
    return 0;
}
