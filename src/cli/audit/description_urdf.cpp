// URDF (the ROS robot description format, as urdfdom reads it): each <link>
// with its <inertial> (<origin xyz rpy>, <mass value>, <inertia ixx ...>,
// the tensor in the origin's rotated frame) and its <collision> and <visual>
// elements (<origin>, <geometry> with one <mesh filename scale>, <box size>,
// <cylinder radius length>, <sphere radius>, or <capsule radius length>,
// which some simulators read).
#include "audit/description_parsers.hpp"
#include "audit/frames.hpp"

#include <map>
#include <set>
#include <utility>

namespace polymass_cli::audit {
namespace {

Eigen::Vector3d vector_attribute(const pugi::xml_node& element, const char* name,
                                 const Eigen::Vector3d& fallback, const std::string& what) {
    const pugi::xml_attribute attribute = element.attribute(name);
    if (!attribute) return fallback;
    const std::vector<double> v = parse_numbers(attribute.value(), 3, what + " " + name);
    return {v[0], v[1], v[2]};
}

double number_attribute(const pugi::xml_node& element, const char* name, const std::string& what) {
    const pugi::xml_attribute attribute = element.attribute(name);
    if (!attribute) throw DescriptionError(what + ": no " + name + " attribute");
    return parse_number(attribute.value(), what + " " + name);
}

Pose origin_of(const pugi::xml_node& parent, const std::string& what) {
    Pose pose;
    const pugi::xml_node origin = parent.child("origin");
    if (!origin) return pose;
    pose.position = vector_attribute(origin, "xyz", Eigen::Vector3d::Zero(), what + " <origin>");
    const Eigen::Vector3d rpy =
        vector_attribute(origin, "rpy", Eigen::Vector3d::Zero(), what + " <origin>");
    pose.rotation = rotation_from_rpy(rpy[0], rpy[1], rpy[2]);
    return pose;
}

Inertial inertial_of(const XmlFile& file, const pugi::xml_node& element, const std::string& what) {
    Inertial inertial;
    const Pose frame = origin_of(element, what);
    const pugi::xml_node mass = element.child("mass");
    if (!mass) throw DescriptionError(what + ": no <mass>");
    inertial.mass = number_attribute(mass, "value", what + " <mass>");
    const pugi::xml_node tensor = element.child("inertia");
    if (!tensor) throw DescriptionError(what + ": no <inertia>");
    const std::string where = what + " <inertia>";
    const double ixx = number_attribute(tensor, "ixx", where);
    const double iyy = number_attribute(tensor, "iyy", where);
    const double izz = number_attribute(tensor, "izz", where);
    const double ixy = number_attribute(tensor, "ixy", where);
    const double ixz = number_attribute(tensor, "ixz", where);
    const double iyz = number_attribute(tensor, "iyz", where);
    Eigen::Matrix3d in_frame;
    in_frame << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
    inertial.center_of_mass = frame.position;
    inertial.inertia = frame.rotation * in_frame * frame.rotation.transpose();
    inertial.text = element_range(file, element);
    return inertial;
}

// The geometry of a <collision> or <visual>; false (and a line in
// unsupported) for a shape the audit cannot measure.
bool geometry_of(const pugi::xml_node& element, const std::string& what, Geometry& geometry,
                 std::vector<std::string>& unsupported) {
    geometry.pose = origin_of(element, what);
    const pugi::xml_node shape = element.child("geometry").first_child();
    if (!shape) throw DescriptionError(what + ": no <geometry>");
    const std::string kind = shape.name();
    const std::string where = what + " <" + kind + ">";
    if (kind == "mesh") {
        geometry.shape = Shape::kMesh;
        geometry.uri = shape.attribute("filename").value();
        if (geometry.uri.empty()) throw DescriptionError(where + ": no filename");
        const pugi::xml_attribute scale = shape.attribute("scale");
        if (scale) {
            const std::vector<double> s = parse_numbers(scale.value(), 0, where + " scale");
            if (s.size() == 1) {
                geometry.scale.setConstant(s[0]);
            } else if (s.size() == 3) {
                geometry.scale = {s[0], s[1], s[2]};
            } else {
                throw DescriptionError(where + " scale: wants 1 or 3 numbers");
            }
        }
    } else if (kind == "box") {
        geometry.shape = Shape::kBox;
        geometry.size = vector_attribute(shape, "size", Eigen::Vector3d::Zero(), where);
    } else if (kind == "cylinder" || kind == "capsule") {
        geometry.shape = kind == "cylinder" ? Shape::kCylinder : Shape::kCapsule;
        geometry.size = {number_attribute(shape, "radius", where),
                         number_attribute(shape, "length", where), 0.0};
    } else if (kind == "sphere") {
        geometry.shape = Shape::kSphere;
        geometry.size = {number_attribute(shape, "radius", where), 0.0, 0.0};
    } else {
        unsupported.push_back(where + ": not a shape the audit measures");
        return false;
    }
    return true;
}

// Each link's frame with every joint at zero: the joints' origins composed
// from the root (a link no joint names as a child). A link reached twice, or
// by no chain from a root, keeps no frame.
void place_links(const pugi::xml_node& robot, Description& description) {
    std::map<std::string, std::vector<std::pair<std::string, Pose>>> children;
    std::set<std::string> child_links;
    for (const pugi::xml_node joint : robot.children("joint")) {
        const std::string parent = joint.child("parent").attribute("link").value();
        const std::string child = joint.child("child").attribute("link").value();
        Pose origin;
        try {
            origin = origin_of(joint, "joint");
        } catch (const DescriptionError&) {
            continue;  // the audit does not read joints: a bad one leaves its child unplaced
        }
        if (!child_links.insert(child).second) continue;
        children[parent].emplace_back(child, origin);
    }
    std::map<std::string, Pose> frames;
    std::vector<std::string> pending;
    for (const Link& link : description.links) {
        if (child_links.count(link.name) == 0 && frames.emplace(link.name, Pose{}).second)
            pending.push_back(link.name);
    }
    while (!pending.empty()) {
        const std::string parent = pending.back();
        pending.pop_back();
        for (const auto& [child, origin] : children[parent]) {
            if (frames.emplace(child, compose(frames[parent], origin)).second)
                pending.push_back(child);
        }
    }
    for (Link& link : description.links) {
        const auto found = frames.find(link.name);
        if (found != frames.end()) link.frame = found->second;
    }
}

}  // namespace

Description parse_urdf(const XmlFile& file) {
    Description description;
    description.format = Format::kUrdf;
    for (const pugi::xml_node element : file.document.document_element().children("link")) {
        Link link;
        link.name = element.attribute("name").value();
        read_link_children(
            element,
            [&](const pugi::xml_node& inertial, const std::string& what) {
                return inertial_of(file, inertial, what);
            },
            geometry_of, link);
        description.links.push_back(std::move(link));
    }
    place_links(file.document.document_element(), description);
    return description;
}

}  // namespace polymass_cli::audit
