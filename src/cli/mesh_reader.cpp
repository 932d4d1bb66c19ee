#include "mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <sstream>

#include "format_readers.hpp"
#include "isolated_reader.hpp"

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

std::string read_bytes(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ReadError("cannot open the file");
    std::ostringstream contents;
    contents << file.rdbuf();
    if (file.bad()) throw ReadError("cannot read the file");
    std::string bytes = contents.str();
    if (bytes.empty()) throw ReadError("the file is empty");
    return bytes;
}

}  // namespace

const char* supported_formats() { return "obj, stl, ply, off, gltf, glb, 3mf"; }

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
    } else if (name == "gltf" || name == "glb" || name == "3mf") {
        read_bytes(path);  // the same "cannot open" and "empty" errors as the other formats
        model = read_isolated([&] { return read_with_assimp(path, name); });
    } else if (name.empty()) {
        throw ReadError(std::string("no file extension to tell the format by: name it "
                                    "with one, or give --format (") +
                        supported_formats() + ")");
    } else {
        throw ReadError("unknown format '" + name + "' (known: " + supported_formats() + ")");
    }
    model.format = name;
    model.parts.erase(std::remove_if(model.parts.begin(), model.parts.end(),
                                     [](const Part& part) { return part.face_sizes.empty(); }),
                      model.parts.end());
    if (model.parts.empty()) throw ReadError("the file holds no faces");
    return model;
}

}  // namespace polymass_cli
