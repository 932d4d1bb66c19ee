#include "audit/resolve.hpp"

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <regex>
#include <system_error>
#include <vector>

#include "out_of_memory.hpp"
#include "readers/file_bytes.hpp"
#include "readers/mesh_reader.hpp"
#include "text_streams.hpp"

namespace polymass_cli::audit {
namespace {

namespace fs = std::filesystem;

bool file_exists(const fs::path& path) {
    std::error_code error;
    const bool exists = fs::is_regular_file(path, error);
    throw_if_out_of_memory(error);
    return exists;
}

bool directory_exists(const fs::path& path) {
    std::error_code error;
    const bool exists = fs::is_directory(path, error);
    throw_if_out_of_memory(error);
    return exists;
}

std::vector<fs::path> search_path(const char* variable) {
    std::vector<fs::path> roots;
    const char* value = std::getenv(variable);
    if (value == nullptr) return roots;
    InputText entries(value);
    std::string entry;
    while (std::getline(entries, entry, ':')) {
        if (!entry.empty()) roots.emplace_back(entry);
    }
    return roots;
}

// The <name> a package.xml in dir declares, or "".
// (Mapped, so a package.xml that is a device or a pipe is no package.)
std::string package_name(const fs::path& dir) {
    std::string content;
    try {
        content = std::string(FileBytes(dir / "package.xml").view());
    } catch (const ReadError&) {
        return "";
    }
    static const std::regex kName(R"(<name>\s*([^<\s]+)\s*</name>)");
    std::smatch match;
    return std::regex_search(content, match, kName) ? match[1].str() : "";
}

bool is_package(const fs::path& dir, const std::string& name) {
    return directory_exists(dir) && package_name(dir) == name;
}

// The directory of package name under a ROS_PACKAGE_PATH root: the root
// itself, or a directory up to two levels below it.
std::optional<fs::path> package_under(const fs::path& root, const std::string& name) {
    if (is_package(root, name)) return root;
    if (directory_exists(root / name)) return root / name;
    std::error_code error;
    for (fs::directory_iterator level1(root, error), end; !error && level1 != end;
         level1.increment(error)) {
        if (!level1->is_directory(error)) {
            throw_if_out_of_memory(error);
            continue;
        }
        if (is_package(level1->path(), name)) return level1->path();
        for (fs::directory_iterator level2(level1->path(), error); !error && level2 != end;
             level2.increment(error)) {
            if (level2->is_directory(error) && is_package(level2->path(), name)) {
                return level2->path();
            }
        }
        throw_if_out_of_memory(error);
        error.clear();
    }
    throw_if_out_of_memory(error);
    return std::nullopt;
}

// The description's directory and every directory above it.
std::vector<fs::path> upward(const std::string& description_path) {
    std::vector<fs::path> dirs;
    std::error_code error;
    fs::path dir = fs::absolute(fs::path(description_path), error).parent_path();
    throw_if_out_of_memory(error);
    while (!dir.empty()) {
        dirs.push_back(dir);
        if (dir == dir.parent_path()) break;
        dir = dir.parent_path();
    }
    return dirs;
}

std::optional<fs::path> find_package(const std::string& name, const std::string& description) {
    for (const fs::path& root : search_path("ROS_PACKAGE_PATH")) {
        if (auto found = package_under(root, name)) return found;
    }
    for (const fs::path& dir : upward(description)) {
        if (is_package(dir, name) || dir.filename() == name) return dir;
        if (directory_exists(dir / name)) return dir / name;
    }
    return std::nullopt;
}

std::optional<fs::path> find_model(const std::string& name, const std::string& description) {
    for (const char* variable :
         {"GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH", "SDF_PATH", "GAZEBO_MODEL_PATH"}) {
        for (const fs::path& root : search_path(variable)) {
            if (directory_exists(root / name)) return root / name;
        }
    }
    for (const fs::path& dir : upward(description)) {
        if (dir.filename() == name) return dir;
        if (directory_exists(dir / name)) return dir / name;
    }
    return std::nullopt;
}

Resolved found_or_missing(const fs::path& path, const std::string& uri) {
    if (file_exists(path)) return {path.string(), ""};
    return {"", "'" + uri + "' resolves to " + path.string() + ", which is not a file"};
}

// A URI of the form scheme://NAME/PATH resolved by find (package or model).
Resolved in_named_directory(const std::string& uri, std::size_t prefix, const char* what,
                            const char* variables, const std::string& description,
                            std::optional<fs::path> (*find)(const std::string&,
                                                            const std::string&)) {
    const std::string rest = uri.substr(prefix);
    const std::string::size_type slash = rest.find('/');
    const std::string name = rest.substr(0, slash);
    if (name.empty()) return {"", "'" + uri + "' names no " + what};
    const std::optional<fs::path> dir = find(name, description);
    if (!dir) {
        return {"", std::string(what) + " '" + name + "' of '" + uri + "' not found (through " +
                        variables + ", or above the description)"};
    }
    return found_or_missing(slash == std::string::npos ? *dir : *dir / rest.substr(slash + 1), uri);
}

}  // namespace

Resolved resolve_mesh(const std::string& uri, const std::string& description_path) {
    if (uri.rfind("package://", 0) == 0) {
        return in_named_directory(uri, 10, "package", "ROS_PACKAGE_PATH", description_path,
                                  find_package);
    }
    if (uri.rfind("model://", 0) == 0) {
        return in_named_directory(uri, 8, "model",
                                  "GZ_SIM_RESOURCE_PATH, IGN_GAZEBO_RESOURCE_PATH, SDF_PATH, "
                                  "GAZEBO_MODEL_PATH",
                                  description_path, find_model);
    }
    std::string path = uri.rfind("file://", 0) == 0 ? uri.substr(7) : uri;
    if (path.find("://") != std::string::npos) {
        return {"", "'" + uri + "': a URI scheme the audit does not resolve"};
    }
    fs::path file(path);
    if (file.is_relative()) file = fs::path(description_path).parent_path() / file;
    return found_or_missing(file, uri);
}

}  // namespace polymass_cli::audit
