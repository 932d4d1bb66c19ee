// SDFormat: every <model> (in the file, in a <world>, nested in a model)
// and its <link>s, each with its <inertial> (<pose>, <mass>, <inertia>
// with <ixx>...<izz>, the tensor in the pose's frame) and its <collision>
// and <visual> elements (<pose>, <geometry> with <mesh> (<uri>, <scale>),
// <box>, <cylinder>, <sphere>, <capsule>, <ellipsoid>). Poses are "x y z
// roll pitch yaw", or in degrees (degrees="true"), or "x y z qx qy qz qw"
// (rotation_format="quat_xyzw"); a pose relative_to another frame than the
// link's is not followed (said, and that geometry left out). Links of nested
// or several models are named model::link.
#include <cmath>
#include <cstring>

#include "audit/description_parsers.hpp"
#include "audit/frames.hpp"

namespace polymass_cli::audit {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string text_of(const pugi::xml_node& element, const char* child, const std::string& what) {
    const pugi::xml_node node = element.child(child);
    if (!node) throw DescriptionError(what + ": no <" + child + ">");
    return node.text().get();
}

double number_of(const pugi::xml_node& element, const char* child, const std::string& what) {
    return parse_number(text_of(element, child, what), what + " <" + child + ">");
}

Eigen::Vector3d vector_of(const pugi::xml_node& element, const char* child,
                          const std::string& what) {
    const std::vector<double> v =
        parse_numbers(text_of(element, child, what), 3, what + " <" + child + ">");
    return {v[0], v[1], v[2]};
}

// The <pose> child of element, in the link's frame; false when it is
// relative to another frame.
bool pose_of(const pugi::xml_node& element, const std::string& link, const std::string& what,
             Pose& pose) {
    pose = Pose{};
    const pugi::xml_node node = element.child("pose");
    if (!node) return true;
    const std::string relative_to = node.attribute("relative_to").value();
    if (!relative_to.empty() && relative_to != link) return false;
    const std::string where = what + " <pose>";
    const bool quaternion =
        std::strcmp(node.attribute("rotation_format").value(), "quat_xyzw") == 0;
    const std::vector<double> v = parse_numbers(node.text().get(), quaternion ? 7 : 6, where);
    pose.position = {v[0], v[1], v[2]};
    if (quaternion) {
        pose.rotation = rotation_from_quaternion(v[6], v[3], v[4], v[5], where);
    } else {
        const double unit = node.attribute("degrees").as_bool() ? kPi / 180.0 : 1.0;
        pose.rotation = rotation_from_rpy(v[3] * unit, v[4] * unit, v[5] * unit);
    }
    return true;
}

Inertial inertial_of(const XmlFile& file, const pugi::xml_node& element, const std::string& link,
                     const std::string& what) {
    Inertial inertial;
    Pose frame;
    if (!pose_of(element, link, what, frame)) {
        throw DescriptionError(what + ": a <pose> relative to another frame than the link's");
    }
    inertial.mass = element.child("mass") ? number_of(element, "mass", what) : 1.0;
    Eigen::Matrix3d in_frame = Eigen::Matrix3d::Identity();  // SDFormat's defaults
    if (const pugi::xml_node tensor = element.child("inertia")) {
        const std::string where = what + " <inertia>";
        const auto entry = [&](const char* name, double fallback) {
            return tensor.child(name) ? number_of(tensor, name, where) : fallback;
        };
        // Every entry read before the matrix is filled: one that is not a
        // number throws, and must not leave Eigen's comma initializer half
        // done (it asserts as it unwinds).
        const double ixx = entry("ixx", 1.0), iyy = entry("iyy", 1.0), izz = entry("izz", 1.0);
        const double ixy = entry("ixy", 0.0), ixz = entry("ixz", 0.0), iyz = entry("iyz", 0.0);
        in_frame << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
    }
    inertial.center_of_mass = frame.position;
    inertial.inertia = frame.rotation * in_frame * frame.rotation.transpose();
    inertial.text = element_range(file, element);
    return inertial;
}

bool geometry_of(const pugi::xml_node& element, const std::string& link, const std::string& what,
                 Geometry& geometry, std::vector<std::string>& unsupported) {
    if (!pose_of(element, link, what, geometry.pose)) {
        unsupported.push_back(what + ": a <pose> relative to another frame than the link's");
        return false;
    }
    const pugi::xml_node shape = element.child("geometry").first_child();
    if (!shape) throw DescriptionError(what + ": no <geometry>");
    const std::string kind = shape.name();
    const std::string where = what + " <" + kind + ">";
    if (kind == "mesh") {
        geometry.shape = Shape::kMesh;
        geometry.uri = text_of(shape, "uri", where);
        if (shape.child("scale")) geometry.scale = vector_of(shape, "scale", where);
        if (shape.child("submesh")) {
            unsupported.push_back(where + ": a <submesh> (the whole mesh is measured)");
        }
    } else if (kind == "box") {
        geometry.shape = Shape::kBox;
        geometry.size = vector_of(shape, "size", where);
    } else if (kind == "cylinder" || kind == "capsule") {
        geometry.shape = kind == "cylinder" ? Shape::kCylinder : Shape::kCapsule;
        geometry.size = {number_of(shape, "radius", where), number_of(shape, "length", where), 0};
    } else if (kind == "sphere") {
        geometry.shape = Shape::kSphere;
        geometry.size = {number_of(shape, "radius", where), 0.0, 0.0};
    } else if (kind == "ellipsoid") {
        geometry.shape = Shape::kEllipsoid;
        geometry.size = vector_of(shape, "radii", where);
    } else {
        unsupported.push_back(where + ": not a shape the audit measures");
        return false;
    }
    return true;
}

// The frame of a link or model whose <pose> is in the frame placed by
// parent (its model's); empty when either is not known.
std::optional<Pose> placed(const pugi::xml_node& element, const std::optional<Pose>& parent,
                           const std::string& what) {
    Pose pose;
    try {
        if (!parent || !pose_of(element, "", what, pose)) return std::nullopt;
    } catch (const DescriptionError&) {
        return std::nullopt;  // the link's own elements say what is wrong with them
    }
    return compose(*parent, pose);
}

// placement: the model frame in the description's (empty: not known, a
// pose relative to another frame).
void parse_model(const XmlFile& file, const pugi::xml_node& model, const std::string& prefix,
                 const std::optional<Pose>& placement, Description& description) {
    for (const pugi::xml_node element : model.children("link")) {
        Link link;
        const std::string name = element.attribute("name").value();
        link.name = prefix + name;
        link.frame = placed(element, placement, prefix + name);
        read_link_children(
            element,
            [&](const pugi::xml_node& inertial, const std::string& what) {
                return inertial_of(file, inertial, name, what);
            },
            [&](const pugi::xml_node& child, const std::string& what, Geometry& geometry,
                std::vector<std::string>& unsupported) {
                return geometry_of(child, name, what, geometry, unsupported);
            },
            link);
        description.links.push_back(std::move(link));
    }
    for (const pugi::xml_node nested : model.children("model")) {
        const std::string name = nested.attribute("name").value();
        parse_model(file, nested, prefix + name + "::", placed(nested, placement, name),
                    description);
    }
}

}  // namespace

Description parse_sdf(const XmlFile& file) {
    Description description;
    description.format = Format::kSdf;
    const pugi::xml_node root = file.document.document_element();
    std::vector<pugi::xml_node> models;
    for (const pugi::xml_node model : root.children("model")) models.push_back(model);
    for (const pugi::xml_node world : root.children("world")) {
        for (const pugi::xml_node model : world.children("model")) models.push_back(model);
    }
    for (const pugi::xml_node& model : models) {
        const std::string prefix =
            models.size() > 1 ? std::string(model.attribute("name").value()) + "::" : "";
        parse_model(file, model, prefix, placed(model, Pose{}, prefix), description);
    }
    return description;
}

}  // namespace polymass_cli::audit
