// polymass audit --html: the page's data is the --json document and, for
// each description, each link's frame at zero joint positions and the
// geometries the audit measured (meshes as the page draws them, shapes by
// their sizes), each placed in its link's frame.
#include <map>

#include "audit/description.hpp"
#include "audit/report.hpp"
#include "audit/resolve.hpp"
#include "readers/mesh_reader.hpp"
#include "reports/html_mesh.hpp"
#include "reports/html_page.hpp"

namespace polymass_cli::audit {
namespace {

Json pose_json(const Pose& pose) {
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rows = pose.rotation;
    Json rotation = Json::array();
    for (int row = 0; row < 3; ++row) rotation.push_back(json_numbers(rows.data() + 3 * row, 3));
    return {{"rotation", rotation}, {"position", json_numbers(pose.position.data(), 3)}};
}

const char* shape_name(Shape shape) {
    switch (shape) {
        case Shape::kMesh:
            return "mesh";
        case Shape::kBox:
            return "box";
        case Shape::kCylinder:
            return "cylinder";
        case Shape::kSphere:
            return "sphere";
        case Shape::kCapsule:
            return "capsule";
        case Shape::kEllipsoid:
            return "ellipsoid";
    }
    return "mesh";
}

// The meshes of one page, each file read once however many links use it.
class MeshCache {
public:
    explicit MeshCache(HtmlPage& page) : page_(page) {}

    // The page's mesh of the file uri names, or why there is none.
    Json mesh(const std::string& uri, const std::string& description_path) {
        const Resolved resolved = resolve_mesh(uri, description_path);
        if (resolved.path.empty()) return {{"error", resolved.error}};
        const auto found = meshes_.find(resolved.path);
        if (found != meshes_.end()) return found->second;
        Json view;
        try {
            const Model model = read_mesh_file(resolved.path, "");
            view = mesh_view(page_, model, combined_part(model), {}, Located{});
        } catch (const ReadError& error) {
            view = {{"error", error.what()}};
        }
        return meshes_.emplace(resolved.path, view).first->second;
    }

private:
    HtmlPage& page_;
    std::map<std::string, Json> meshes_;
};

Json geometry_json(const Geometry& geometry, const std::string& description_path,
                   MeshCache& meshes) {
    Json entry = Json::object();
    entry["shape"] = shape_name(geometry.shape);
    entry["pose"] = pose_json(geometry.pose);
    if (geometry.shape == Shape::kMesh) {
        entry["uri"] = geometry.uri;
        entry["scale"] = json_numbers(geometry.scale.data(), 3);
        entry["mesh"] = meshes.mesh(geometry.uri, description_path);
    } else {
        entry["size"] = json_numbers(geometry.size.data(), 3);
    }
    return entry;
}

// Each link of the description (in the audit's order): its frame and the
// geometries the audit measured.
Json robot_json(const FileAudit& file, MeshCache& meshes) {
    if (!file.error.empty()) return nullptr;
    Description description;
    try {
        description = read_description(file.path);
    } catch (const DescriptionError&) {
        return nullptr;  // changed since the audit read it: the page draws nothing
    }
    Json links = Json::array();
    for (size_t i = 0; i < description.links.size() && i < file.links.size(); ++i) {
        const Link& link = description.links[i];
        const std::string measured = file.links[i].geometry;
        Json geometries = Json::array();
        for (const Geometry& geometry : measured == "visual" ? link.visual : link.collision) {
            if (geometry.invalid.empty() && measured != "none")
                geometries.push_back(geometry_json(geometry, file.path, meshes));
        }
        links.push_back(
            {{"frame", link.frame ? pose_json(*link.frame) : Json()}, {"geometries", geometries}});
    }
    return {{"links", links}};
}

}  // namespace

ExitCode write_audit_html(const std::string& path, const std::vector<FileAudit>& files) {
    HtmlPage page("audit");
    MeshCache meshes(page);
    Json robots = Json::array();
    for (const FileAudit& file : files) robots.push_back(robot_json(file, meshes));
    page.data()["report"] = audit_json_document(files);
    page.data()["robots"] = robots;
    return page.write(path);
}

}  // namespace polymass_cli::audit
