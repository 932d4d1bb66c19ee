#include "readers/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

#include "readers/file_bytes.hpp"
#include "readers/format_readers.hpp"
#include "readers/isolated_reader.hpp"

namespace polymass_cli {
namespace {

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::string format_from_extension(const std::string& path) {
    const std::string::size_type dot = path.find_last_of('.');
    const std::string::size_type slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return lowercase(path.substr(dot + 1));
}

// Every reader records, per part, the size of each face and then all their
// corners: if these disagree, a reader has a bug, and the file is refused
// here rather than indexed past the end of its corners later.
void check_faces_match_indices(const Model& model) {
    for (size_t p = 0; p < model.parts.size(); ++p) {
        const Part& part = model.parts[p];
        uint64_t corners = 0;
        for (uint64_t face = 0; face < part.face_count(); ++face) corners += part.face_size(face);
        if (corners != part.indices.size()) {
            throw ReadError("internal error in the " + model.format + " reader: part " +
                            std::to_string(p) + "'s face sizes add up to " +
                            std::to_string(corners) + " corners but it has " +
                            std::to_string(part.indices.size()));
        }
    }
}

// Faces past most_face_corners, in any format.
void check_face_sizes(const Model& model) {
    const uint64_t most = most_face_corners(model.vertex_count());
    for (size_t p = 0; p < model.parts.size(); ++p) {
        const std::vector<uint32_t>& sizes = model.parts[p].face_sizes;
        const auto large =
            std::find_if(sizes.begin(), sizes.end(), [&](uint32_t size) { return size > most; });
        if (large != sizes.end()) {
            throw ReadError("face " + std::to_string(large - sizes.begin()) +
                            (model.parts.size() > 1 ? " of part " + std::to_string(p) : "") +
                            " has " + std::to_string(*large) + " corners, but the file has " +
                            std::to_string(model.vertex_count()) +
                            " vertices: a polygon passes through a vertex at most twice");
        }
    }
}

}  // namespace

uint64_t most_face_corners(uint64_t vertex_count) {
    return std::max(uint64_t(1) << 16, 2 * vertex_count);
}

const char* supported_formats() { return "obj, stl, ply, off, msh, gltf, glb, 3mf, dae"; }

Model read_mesh_file(const std::string& path, const std::string& format) {
    const std::string name = format.empty() ? format_from_extension(path) : lowercase(format);
    Model model;
    if (name == "obj") {
        model = read_obj(FileBytes(path).view());
    } else if (name == "stl") {
        model = read_stl(FileBytes(path));
    } else if (name == "ply") {
        model = read_ply(FileBytes(path).view());
    } else if (name == "off") {
        model = read_off(FileBytes(path).view());
    } else if (name == "msh") {
        model = read_msh(FileBytes(path).view());
    } else if (name == "gltf" || name == "glb") {
        regular_file_size(path);  // a device, a pipe or an empty file is refused here
        model = read_isolated([&] { return read_gltf(path); });
    } else if (name == "3mf") {
        const FileBytes package(path);
        model = read_isolated([&] { return read_3mf(package.view()); }, package.view().size());
    } else if (name == "dae") {
        // assimp trusts a Collada accessor's count (or fills gigabytes when it
        // is missing): its memory is bounded as a 3MF's.
        const FileBytes document(path);
        model =
            read_isolated([&] { return read_collada(document.view()); }, document.view().size());
    } else if (name.empty()) {
        throw ReadError(std::string("no file extension to tell the format by: name it "
                                    "with one, or give --format (") +
                        supported_formats() + ")");
    } else {
        throw ReadError("unknown format '" + name + "' (known: " + supported_formats() + ")");
    }
    model.format = name;
    // One note for every format that declares its unit, first among them.
    if (!model.declared_unit.empty())
        model.notes.insert(model.notes.begin(),
                           "lengths in metres (the file's unit: " + model.declared_unit + ")");
    check_faces_match_indices(model);
    check_face_sizes(model);
    model.parts.erase(std::remove_if(model.parts.begin(), model.parts.end(),
                                     [](const Part& part) { return part.face_count() == 0; }),
                      model.parts.end());
    if (model.parts.empty()) throw ReadError("the file holds no faces");
    for (Part& part : model.parts) part.drop_triangle_sizes();
    return model;
}

}  // namespace polymass_cli
