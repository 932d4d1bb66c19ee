// 3MF through the 3MF Consortium's lib3mf (its version 1 C interface, as
// Debian ships it), which opens the package, parses the model and checks it
// against the specification (an index out of range, a malformed number or a
// missing object is its error, passed on with its message). Each build item
// is a part: its object's meshes, through components to any depth, placed by
// the item's and the components' transforms composed in double precision; a
// mirroring placement has its triangles' corners reversed so the solid stays
// outside-out.
//
// lib3mf 1.x keeps coordinates and transforms as 32-bit floats: a 3MF
// coordinate is exact here when it is a float (as those of CAD exports in
// micrometre steps of a few millimetres are not). The README says so.
#include <Model/COM/NMR_DLLInterfaces.h>
#include <zip.h>

#include <algorithm>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "readers/format_readers.hpp"
#include "readers/isolated_reader.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/transform.hpp"

namespace polymass_cli {
namespace {

// A lib3mf instance (its interface's handle), released when it goes out of
// scope.
using Instance = NMR::PLib3MFBase*;
struct Release {
    void operator()(Instance instance) const { NMR::lib3mf_release(instance); }
};
using Handle = std::unique_ptr<NMR::PLib3MFBase, Release>;

// Throws the instance's last error when result is a failure.
void check(LIB3MFRESULT result, Instance instance, const char* doing) {
    if (result == LIB3MF_OK) return;
    DWORD code = 0;
    LPCSTR message = nullptr;
    std::string text = doing;
    if (instance != nullptr && NMR::lib3mf_getlasterror(instance, &code, &message) == LIB3MF_OK &&
        message != nullptr) {
        text += ": ";
        text += message;
    }
    throw ReadError(text + " (lib3mf error " + std::to_string(result) + ")");
}

Transform transform_of(const NMR::MODELTRANSFORM& m) {
    Transform t{};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 4; ++column) t[4 * row + column] = m.m_fFields[row][column];
    }
    return t;
}

std::string object_name(Instance object) {
    ULONG needed = 0;
    if (NMR::lib3mf_object_getnameutf8(object, nullptr, 0, &needed) != LIB3MF_OK || needed == 0) {
        return "";
    }
    std::vector<char> name(needed + 1, '\0');
    check(NMR::lib3mf_object_getnameutf8(object, name.data(), needed + 1, &needed), object,
          "reading an object's name");
    return std::string(name.data());
}

void add_mesh(Model& model, Part& part, Instance mesh, const Transform& transform) {
    DWORD vertex_count = 0, triangle_count = 0;
    check(NMR::lib3mf_meshobject_getvertexcount(mesh, &vertex_count), mesh, "counting vertices");
    check(NMR::lib3mf_meshobject_gettrianglecount(mesh, &triangle_count), mesh,
          "counting triangles");
    std::vector<NMR::MODELMESHVERTEX> vertices(vertex_count);
    std::vector<NMR::MODELMESHTRIANGLE> triangles(triangle_count);
    if (vertex_count > 0) {
        check(NMR::lib3mf_meshobject_getvertices(mesh, vertices.data(), vertex_count, nullptr),
              mesh, "reading vertices");
    }
    if (triangle_count > 0) {
        check(NMR::lib3mf_meshobject_gettriangleindices(mesh, triangles.data(), triangle_count,
                                                        nullptr),
              mesh, "reading triangles");
    }
    const uint64_t first_vertex = model.vertex_count();
    for (const NMR::MODELMESHVERTEX& v : vertices) {
        append_transformed(model.positions, transform, v.m_fPosition[0], v.m_fPosition[1],
                           v.m_fPosition[2]);
    }
    if (model.vertex_count() >= kIndexOutOfRange) throw ReadError("more than 4294967294 vertices");
    const bool mirrored = determinant(transform) < 0;
    for (const NMR::MODELMESHTRIANGLE& triangle : triangles) {
        for (int corner = 0; corner < 3; ++corner) {
            const DWORD index = triangle.m_nIndices[mirrored ? 2 - corner : corner];
            part.indices.push_back(index < vertex_count
                                       ? static_cast<uint32_t>(first_vertex + index)
                                       : kIndexOutOfRange);
        }
        part.face_sizes.push_back(3);
    }
}

void add_object(Model& model, Part& part, Instance object, const Transform& transform,
                unsigned depth) {
    // lib3mf refuses circular references; this bounds a deep but finite tree.
    constexpr unsigned kDeepest = 1000;
    if (depth > kDeepest) throw ReadError("the 3MF components are nested too deep");
    BOOL is_mesh = false, is_components = false;
    check(NMR::lib3mf_object_ismeshobject(object, &is_mesh), object, "reading an object");
    check(NMR::lib3mf_object_iscomponentsobject(object, &is_components), object,
          "reading an object");
    if (is_mesh) {
        add_mesh(model, part, object, transform);
        return;
    }
    if (!is_components) return;
    DWORD count = 0;
    check(NMR::lib3mf_componentsobject_getcomponentcount(object, &count), object,
          "counting components");
    for (DWORD i = 0; i < count; ++i) {
        Instance raw = nullptr;
        check(NMR::lib3mf_componentsobject_getcomponent(object, i, &raw), object,
              "reading a component");
        const Handle component(raw);
        NMR::MODELTRANSFORM placement{};
        check(NMR::lib3mf_component_gettransform(component.get(), &placement), component.get(),
              "reading a component's transform");
        check(NMR::lib3mf_component_getobjectresource(component.get(), &raw), component.get(),
              "reading a component's object");
        const Handle child(raw);
        add_object(model, part, child.get(), compose(transform, transform_of(placement)),
                   depth + 1);
    }
}

// A zip bomb is refused before lib3mf inflates it: the sizes the package's
// central directory declares for its parts add up to no more than its
// reader's memory budget (the same bound read_isolated sets). They are read
// by libzip, the zip library lib3mf reads the package with, from the same
// bytes, so the check and the reading cannot see two different packages.
// Reading the directory inflates nothing. A package that declares less than
// it holds fails its sizes and checksums in lib3mf, within that budget. A
// package libzip cannot open is left to lib3mf's error, unless memory ran out
// (std::bad_alloc: the check must not be skipped for want of memory).
void check_declared_sizes(std::string_view package) {
    // Fails only when it cannot allocate (the bytes are never NULL).
    zip_source_t* source = zip_source_buffer_create(package.data(), package.size(), 0, nullptr);
    if (source == nullptr) throw std::bad_alloc();
    zip_error_t error;
    zip_error_init(&error);
    zip_t* archive = zip_open_from_source(source, ZIP_RDONLY, &error);
    const bool out_of_memory = zip_error_code_zip(&error) == ZIP_ER_MEMORY;
    zip_error_fini(&error);
    if (archive == nullptr) {
        zip_source_free(source);
        if (out_of_memory) throw std::bad_alloc();
        return;
    }
    const uint64_t most = reader_memory_budget(package.size());
    uint64_t declared = 0;
    const zip_int64_t entries = zip_get_num_entries(archive, 0);
    for (zip_int64_t i = 0; i < entries && declared <= most; ++i) {
        zip_stat_t part;
        // The name as stored (ZIP_FL_ENC_RAW): converting it would allocate,
        // and only the size is wanted.
        if (zip_stat_index(archive, static_cast<zip_uint64_t>(i), ZIP_FL_ENC_RAW, &part) == 0 &&
            (part.valid & ZIP_STAT_SIZE) != 0) {
            // Saturates: two parts declaring 2^63 bytes each do not wrap.
            declared += std::min<uint64_t>(part.size, most + 1);
        }
    }
    zip_discard(archive);  // frees the source too; the bytes are the caller's
    if (declared > most) {
        throw ReadError("not a readable 3MF file: its parts inflate to more than " +
                        std::to_string(most >> 20) + " MiB from " + std::to_string(package.size()) +
                        " bytes, more than a mesh of that size can hold (a zip bomb?)");
    }
}

}  // namespace

Model read_3mf(std::string_view package) {
    check_declared_sizes(package);
    Instance raw = nullptr;
    check(NMR::lib3mf_createmodel(&raw), nullptr, "creating a 3MF model");
    const Handle model3mf(raw);
    check(NMR::lib3mf_model_queryreader(model3mf.get(), "3mf", &raw), model3mf.get(),
          "creating a 3MF reader");
    const Handle reader(raw);
    // lib3mf only reads the buffer (its interface predates const).
    BYTE* const bytes = reinterpret_cast<BYTE*>(const_cast<char*>(package.data()));
    check(NMR::lib3mf_reader_readfrombuffer(reader.get(), bytes, package.size()), reader.get(),
          "not a readable 3MF file");

    Model model;
    model.notes.emplace_back(
        "lib3mf reads 3MF coordinates as 32-bit floats: each is rounded to about 6e-8 of its "
        "value, and so may be the results");
    DWORD unit = 0;
    check(NMR::lib3mf_model_getunit(model3mf.get(), &unit), model3mf.get(), "reading the unit");
    static const char* const kUnits[] = {"micron", "millimeter", "centimeter",
                                         "inch",   "foot",       "meter"};
    if (unit < 6) model.notes.push_back(std::string("the file declares its unit: ") + kUnits[unit]);
    check(NMR::lib3mf_model_getbuilditems(model3mf.get(), &raw), model3mf.get(),
          "reading the build items");
    const Handle items(raw);
    BOOL more = false;
    check(NMR::lib3mf_builditemiterator_movenext(items.get(), &more), items.get(),
          "reading the build items");
    for (; more; check(NMR::lib3mf_builditemiterator_movenext(items.get(), &more), items.get(),
                       "reading the build items")) {
        check(NMR::lib3mf_builditemiterator_getcurrent(items.get(), &raw), items.get(),
              "reading a build item");
        const Handle item(raw);
        NMR::MODELTRANSFORM placement{};
        check(NMR::lib3mf_builditem_getobjecttransform(item.get(), &placement), item.get(),
              "reading a build item's transform");
        check(NMR::lib3mf_builditem_getobjectresource(item.get(), &raw), item.get(),
              "reading a build item's object");
        const Handle object(raw);
        Part part;
        part.name = object_name(object.get());
        if (part.name.empty()) part.name = "item " + std::to_string(model.parts.size() + 1);
        add_object(model, part, object.get(), transform_of(placement), 0);
        if (!part.face_sizes.empty()) model.parts.push_back(std::move(part));
    }
    return model;
}

}  // namespace polymass_cli
