// libFuzzer target: arbitrary bytes as a mesh file of one format, read by the
// tool's reader of that format (src/cli/readers). Built once per format, the
// format named by POLYMASS_FUZZ_FORMAT ("obj", "stl", "ply", "off", "msh",
// "gltf", "glb", "3mf", "3mf_model", "dae").
//
// A 3MF package is a zip whose checksums keep a byte-level mutation from ever
// changing the model the reader parses: "3mf" fuzzes the package (libzip's
// reading, the declared sizes, the relationships), and "3mf_model" takes the
// bytes as the model part (3D/3dmodel.model), stored in a package beside
// the two parts every 3MF has, which reaches the model's parsing (pugixml)
// and the reader's objects, components and transforms.
//
// The tool's own readers and the 3MF and Collada readers take the bytes;
// glTF/GLB is read by tinygltf from a file, written at each execution into a
// sandbox directory of this process (external glTF buffers resolve there). The libraries' readers
// are called directly, not in the child process the tool runs them in (readers/isolated_reader), so
// that the fuzzer sees their coverage and their crashes.
//
// A reader either throws ReadError or returns a Model the rest of the tool
// relies on: every part's face sizes add up to its indices, and there are
// whole vertices (x, y, z). A violation
// prints what failed and traps; any other exception escapes (and aborts).
#include <unistd.h>
#include <zip.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <utility>

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

// A package of model and the parts every 3MF has, its entries stored.
std::string package_of(const std::string& model) {
    static const std::string kContentTypes =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Types "
        "xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\"><Default "
        "Extension=\"rels\" "
        "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/><Default "
        "Extension=\"model\" "
        "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/></Types>";
    static const std::string kRelationships =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships "
        "xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\"><Relationship "
        "Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
        "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>";
    zip_source_t* out = zip_source_buffer_create(nullptr, 0, 0, nullptr);
    if (out == nullptr) fail("libzip: no buffer for the package");
    zip_source_keep(out);  // outlives the archive, to be read back
    zip_t* archive = zip_open_from_source(out, ZIP_TRUNCATE, nullptr);
    if (archive == nullptr) fail("libzip: cannot write the package");
    for (const auto& [name, data] :
         {std::pair<const char*, const std::string*>{"[Content_Types].xml", &kContentTypes},
          {"_rels/.rels", &kRelationships},
          {"3D/3dmodel.model", &model}}) {
        zip_source_t* part = zip_source_buffer(archive, data->data(), data->size(), 0);
        const zip_int64_t at = part == nullptr ? -1 : zip_file_add(archive, name, part, 0);
        if (at < 0 || zip_set_file_compression(archive, zip_uint64_t(at), ZIP_CM_STORE, 0) != 0)
            fail("libzip: cannot add a part to the package");
    }
    if (zip_close(archive) != 0) fail("libzip: cannot write the package");
    std::string package;
    zip_stat_t written;
    if (zip_source_stat(out, &written) != 0 || zip_source_open(out) != 0)
        fail("libzip: cannot read the package back");
    package.resize(written.size);
    if (zip_source_read(out, package.data(), package.size()) != zip_int64_t(package.size()))
        fail("libzip: cannot read the package back");
    zip_source_close(out);
    zip_source_free(out);
    return package;
}

Model read(const std::string& bytes) {
    const std::string format = POLYMASS_FUZZ_FORMAT;
    if (format == "obj") return polymass_cli::read_obj(bytes);
    if (format == "stl") return polymass_cli::read_stl(bytes);
    if (format == "ply") return polymass_cli::read_ply(bytes);
    if (format == "off") return polymass_cli::read_off(bytes);
    if (format == "msh") return polymass_cli::read_msh(bytes);
    if (format == "3mf") return polymass_cli::read_3mf(bytes);
    if (format == "3mf_model") return polymass_cli::read_3mf(package_of(bytes));
    if (format == "dae") return polymass_cli::read_collada(bytes);
    {
        std::ofstream file(sandbox_file(), std::ios::binary | std::ios::trunc);
        file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!file) std::abort();
    }
    if (format == "gltf" || format == "glb") return polymass_cli::read_gltf(sandbox_file());
    fail("unknown POLYMASS_FUZZ_FORMAT");
}

// model by value: its coordinates are counted as doubles.
void check(Model model) {
    if (model.positions.as_doubles().size() % 3 != 0) fail("positions are not whole vertices");
    for (const polymass_cli::Part& part : model.parts) {
        std::uint64_t corners = 0;
        for (std::uint64_t face = 0; face < part.face_count(); ++face)
            corners += part.face_size(face);
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
