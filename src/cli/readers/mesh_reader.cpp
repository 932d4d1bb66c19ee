#include "readers/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>

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

std::ifstream open_file(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ReadError("cannot open the file");
    return file;
}

std::string read_bytes(const std::string& path) {
    std::ifstream file = open_file(path);
    // Copied through iterators, not `stream << file.rdbuf()`, which turns a
    // failed allocation into a stream error: out of memory must stay
    // std::bad_alloc (the tool's out-of-memory ending), not "cannot read".
    std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    if (file.bad()) throw ReadError("cannot read the file");
    if (bytes.empty()) throw ReadError("the file is empty");
    return bytes;
}

// The same errors as read_bytes, for a file another library reads: looking
// at its first byte tells an empty file without loading a large one.
void check_not_empty(const std::string& path) {
    std::ifstream file = open_file(path);
    if (file.peek() == std::ifstream::traits_type::eof()) {
        throw ReadError(file.bad() ? "cannot read the file" : "the file is empty");
    }
}

// Every reader records, per part, the size of each face and then all their
// corners: if these disagree, a reader has a bug, and the file is refused
// here rather than indexed past the end of its corners later.
void check_faces_match_indices(const Model& model) {
    for (size_t p = 0; p < model.parts.size(); ++p) {
        const Part& part = model.parts[p];
        uint64_t corners = 0;
        for (const uint32_t size : part.face_sizes) corners += size;
        if (corners != part.indices.size()) {
            throw ReadError("internal error in the " + model.format + " reader: part " +
                            std::to_string(p) + "'s face sizes add up to " +
                            std::to_string(corners) + " corners but it has " +
                            std::to_string(part.indices.size()));
        }
    }
}

}  // namespace

const char* supported_formats() { return "obj, stl, ply, off, gltf, glb, 3mf, dae"; }

Model read_mesh_file(const std::string& path, const std::string& format) {
    const std::string name = format.empty() ? format_from_extension(path) : lowercase(format);
    Model model;
    if (name == "obj") {
        model = read_obj(read_bytes(path));
    } else if (name == "stl") {
        model = read_stl(read_bytes(path));
    } else if (name == "ply") {
        model = read_ply(read_bytes(path));
    } else if (name == "off") {
        model = read_off(read_bytes(path));
    } else if (name == "gltf" || name == "glb") {
        check_not_empty(path);
        model = read_isolated([&] { return read_gltf(path); });
    } else if (name == "3mf") {
        check_not_empty(path);
        model = read_isolated([&] { return read_3mf(path); });
    } else if (name == "dae") {
        check_not_empty(path);
        model = read_isolated([&] { return read_collada(path); });
    } else if (name.empty()) {
        throw ReadError(std::string("no file extension to tell the format by: name it "
                                    "with one, or give --format (") +
                        supported_formats() + ")");
    } else {
        throw ReadError("unknown format '" + name + "' (known: " + supported_formats() + ")");
    }
    model.format = name;
    check_faces_match_indices(model);
    model.parts.erase(std::remove_if(model.parts.begin(), model.parts.end(),
                                     [](const Part& part) { return part.face_sizes.empty(); }),
                      model.parts.end());
    if (model.parts.empty()) throw ReadError("the file holds no faces");
    return model;
}

}  // namespace polymass_cli
