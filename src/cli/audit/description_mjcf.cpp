// MJCF (MuJoCo) with MuJoCo's semantics for what the audit needs:
// - <compiler angle eulerseq meshdir assetdir> (angles in degrees unless
//   angle="radian"; eulerseq "xyz" by default; mesh files under meshdir,
//   else assetdir, else next to the model file) and its mass settings
//   (inertiafromgeom, inertiagrouprange, boundmass, boundinertia,
//   balanceinertia, settotalmass), applied by audit/mujoco_inertia;
// - <default> classes, nested (a class takes its parent's values), chosen
//   by an element's class, else the nearest enclosing body's childclass,
//   else the top class "main";
// - <asset><mesh name file scale inertia> (the name defaults to the file's
//   name without its extension; two meshes of one name are refused, as
//   MuJoCo refuses them);
// - every <body> of the <worldbody> is a link: its <inertial pos quat|euler
//   |axisangle|xyaxes|zaxis mass diaginertia|fullinertia> and its geoms
//   (type, size, pos, orientation, fromto, mesh), in the body's frame, with
//   how MuJoCo weighs them (group, density, mass, shellinertia); geoms with
//   contype and conaffinity both 0 are visual, the others collision (MuJoCo
//   weighs both); a body with a <joint> or <freejoint> moves;
// - <frame> elements (MuJoCo 3) placing the geoms and bodies in them;
// - <include file> anywhere, its file's children taking its place
//   (relative to the model file's directory); an inertial in an included file
//   is audited but not written by --fix.
// A mesh geom is where the file's vertices put it in the geom frame (MuJoCo
// re-centres the mesh internally and moves the geom frame to match).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>

#include "audit/description_parsers.hpp"
#include "audit/frames.hpp"
#include "out_of_memory.hpp"

namespace polymass_cli::audit {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kDeepestInclude = 20;
// Files loaded by <include>, counting each time one is met: a file including
// another twice, which includes another twice, ... doubles at each level.
constexpr std::size_t kMostIncludes = 4096;
constexpr int kDeepestBody = 1000;  // bodies in bodies, beyond any robot's chain

using Attributes = std::map<std::string, std::string>;

std::string directory_of(const std::string& path) {
    const std::string::size_type slash = path.find_last_of('/');
    return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

bool is_absolute(const std::string& path) { return !path.empty() && path[0] == '/'; }

// dir/path, dir ending in '/' or empty.
std::string joined(const std::string& dir, const std::string& path) {
    if (is_absolute(path) || dir.empty()) return path;
    return dir.back() == '/' ? dir + path : dir + "/" + path;
}

class MjcfParser {
public:
    explicit MjcfParser(const XmlFile& main)
        : main_(main), model_dir_(directory_of(main.path)), include_chain_{same_file(main.path)} {}

    Description parse() {
        description_.format = Format::kMjcf;
        classes_["main"];
        const pugi::xml_node root = main_.document.document_element();
        for_each_child(root, main_, 0, [&](const pugi::xml_node& node, const XmlFile&) {
            const std::string name = node.name();
            if (name == "compiler") read_compiler(node);
        });
        for_each_child(root, main_, 0, [&](const pugi::xml_node& node, const XmlFile& source) {
            const std::string name = node.name();
            if (name == "default") read_default(node, source, "", 0);
        });
        for_each_child(root, main_, 0, [&](const pugi::xml_node& node, const XmlFile& source) {
            if (std::string(node.name()) == "asset") {
                for_each_child(node, source, 0, [&](const pugi::xml_node& asset, const XmlFile&) {
                    if (std::string(asset.name()) == "mesh") read_mesh(asset);
                });
            }
        });
        for_each_child(root, main_, 0, [&](const pugi::xml_node& node, const XmlFile& source) {
            if (std::string(node.name()) == "worldbody")
                read_bodies(node, source, "main", 0, Pose{}, -1);
        });
        return std::move(description_);
    }

private:
    using Visit = std::function<void(const pugi::xml_node&, const XmlFile&)>;

    // The children of node, each <include> replaced by its file's children.
    void for_each_child(const pugi::xml_node& node, const XmlFile& source, int depth,
                        const Visit& visit) {
        for (const pugi::xml_node child : node.children()) {
            if (child.type() != pugi::node_element) continue;
            if (std::string(child.name()) != "include") {
                visit(child, source);
                continue;
            }
            if (depth >= kDeepestInclude) {
                throw DescriptionError(main_.path + ": <include> nested more than " +
                                       std::to_string(kDeepestInclude) + " deep");
            }
            const std::string path = joined(model_dir_, child.attribute("file").value());
            const std::string identity = same_file(path);
            if (std::find(include_chain_.begin(), include_chain_.end(), identity) !=
                include_chain_.end()) {
                throw DescriptionError(source.path + ": <include file='" +
                                       child.attribute("file").value() +
                                       "'> includes a file that includes it (" + path + ")");
            }
            if (included_.size() >= kMostIncludes) {
                throw DescriptionError(main_.path + ": more than " + std::to_string(kMostIncludes) +
                                       " <include>s");
            }
            auto included = std::make_unique<XmlFile>();
            load_xml(*included, path);
            const XmlFile& file = *included;
            included_.push_back(std::move(included));
            include_chain_.push_back(identity);
            for_each_child(file.document.document_element(), file, depth + 1, visit);
            include_chain_.pop_back();
        }
    }

    // One name for a file however a path reaches it (links, "..").
    static std::string same_file(const std::string& path) {
        std::error_code error;
        const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
        throw_if_out_of_memory(error);
        return error ? path : canonical.string();
    }

    void read_compiler(const pugi::xml_node& node) {
        if (const pugi::xml_attribute angle = node.attribute("angle")) {
            const std::string unit = angle.value();
            if (unit != "degree" && unit != "radian") {
                throw DescriptionError(main_.path + ": <compiler angle='" + unit +
                                       "'> is neither degree nor radian");
            }
            degrees_ = unit == "degree";
        }
        if (const pugi::xml_attribute sequence = node.attribute("eulerseq")) {
            eulerseq_ = sequence.value();
        }
        if (const pugi::xml_attribute dir = node.attribute("meshdir")) meshdir_ = dir.value();
        if (const pugi::xml_attribute dir = node.attribute("assetdir")) assetdir_ = dir.value();
        read_mass_settings(node, main_.path + ": <compiler>", description_.compiler);
    }

    static bool boolean(const std::string& text, const std::string& what) {
        if (text != "true" && text != "false") {
            throw DescriptionError(what + ": '" + text + "' is neither true nor false");
        }
        return text == "true";
    }

    static int integer(double value, const std::string& what) {
        if (value != std::floor(value) || std::abs(value) > 1e9) {
            throw DescriptionError(what + ": " + std::to_string(value) + " is not an integer");
        }
        return static_cast<int>(value);
    }

    static void read_mass_settings(const pugi::xml_node& node, const std::string& what,
                                   MujocoCompiler& compiler) {
        if (const pugi::xml_attribute from = node.attribute("inertiafromgeom")) {
            const std::string value = from.value();
            if (value == "auto") {
                compiler.inertia_from_geom = MujocoCompiler::FromGeom::kAuto;
            } else {
                compiler.inertia_from_geom = boolean(value, what + " inertiafromgeom")
                                                 ? MujocoCompiler::FromGeom::kTrue
                                                 : MujocoCompiler::FromGeom::kFalse;
            }
        }
        if (const pugi::xml_attribute range = node.attribute("inertiagrouprange")) {
            const std::vector<double> v =
                parse_numbers(range.value(), 2, what + " inertiagrouprange");
            compiler.group_low = integer(v[0], what + " inertiagrouprange");
            compiler.group_high = integer(v[1], what + " inertiagrouprange");
        }
        const auto number = [&](const char* name, double& value) {
            if (const pugi::xml_attribute a = node.attribute(name)) {
                value = parse_number(a.value(), what + " " + name);
            }
        };
        number("settotalmass", compiler.settotalmass);
        number("boundmass", compiler.boundmass);
        number("boundinertia", compiler.boundinertia);
        if (const pugi::xml_attribute balance = node.attribute("balanceinertia")) {
            compiler.balanceinertia = boolean(balance.value(), what + " balanceinertia");
        }
    }

    // A <default>: its class (the top one is "main") takes its parent's
    // values, then its own elements' attributes.
    void read_default(const pugi::xml_node& node, const XmlFile& source, const std::string& parent,
                      int depth) {
        const std::string name = node.attribute("class") ? node.attribute("class").value() : "main";
        if (!parent.empty()) classes_[name] = classes_[parent];
        std::map<std::string, Attributes>& elements = classes_[name];
        for_each_child(node, source, depth, [&](const pugi::xml_node& child, const XmlFile& in) {
            if (std::string(child.name()) == "default") {
                read_default(child, in, name, depth + 1);
                return;
            }
            Attributes& attributes = elements[child.name()];
            for (const pugi::xml_attribute attribute : child.attributes()) {
                attributes[attribute.name()] = attribute.value();
            }
        });
    }

    // An attribute of element, or its default class's value, or "".
    std::string lookup(const pugi::xml_node& element, const char* name,
                       const std::string& active_class) const {
        if (const pugi::xml_attribute attribute = element.attribute(name)) return attribute.value();
        const std::string cls =
            element.attribute("class") ? element.attribute("class").value() : active_class;
        const auto found_class = classes_.find(cls);
        if (found_class == classes_.end()) {
            throw DescriptionError(main_.path + ": " + describe(element) + " uses class '" + cls +
                                   "', which no <default> defines");
        }
        const auto found_element = found_class->second.find(element.name());
        if (found_element == found_class->second.end()) return "";
        const auto found = found_element->second.find(name);
        return found == found_element->second.end() ? "" : found->second;
    }

    // Three numbers (DescriptionError naming what otherwise, an empty text
    // included).
    static Eigen::Vector3d required_vector(const std::string& text, const std::string& what) {
        const std::vector<double> v = parse_numbers(text, 3, what);
        return {v[0], v[1], v[2]};
    }

    // Three numbers, or fallback for an empty text.
    static Eigen::Vector3d vector(const std::string& text, const Eigen::Vector3d& fallback,
                                  const std::string& what) {
        return text.empty() ? fallback : required_vector(text, what);
    }

    double angle(double value) const { return degrees_ ? value * kPi / 180.0 : value; }

    // The orientation of element from whichever of quat, axisangle, xyaxes,
    // zaxis, euler it (or its class) gives; identity when none.
    Eigen::Matrix3d orientation(const pugi::xml_node& element, const std::string& cls,
                                const std::string& what) const {
        if (const std::string q = lookup(element, "quat", cls); !q.empty()) {
            const std::vector<double> v = parse_numbers(q, 4, what + " quat");
            return rotation_from_quaternion(v[0], v[1], v[2], v[3], what + " quat");
        }
        if (const std::string a = lookup(element, "axisangle", cls); !a.empty()) {
            const std::vector<double> v = parse_numbers(a, 4, what + " axisangle");
            return rotation_from_axis_angle({v[0], v[1], v[2]}, angle(v[3]), what + " axisangle");
        }
        if (const std::string xy = lookup(element, "xyaxes", cls); !xy.empty()) {
            const std::vector<double> v = parse_numbers(xy, 6, what + " xyaxes");
            return rotation_from_xy_axes({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, what + " xyaxes");
        }
        if (const std::string z = lookup(element, "zaxis", cls); !z.empty()) {
            return rotation_from_z_axis(required_vector(z, what + " zaxis"), what + " zaxis");
        }
        if (const std::string e = lookup(element, "euler", cls); !e.empty()) {
            const Eigen::Vector3d v = required_vector(e, what + " euler");
            return rotation_from_euler({angle(v[0]), angle(v[1]), angle(v[2])}, eulerseq_,
                                       what + " euler");
        }
        return Eigen::Matrix3d::Identity();
    }

    void read_mesh(const pugi::xml_node& node) {
        const std::string what = main_.path + ": " + describe(node);
        const std::string file = lookup(node, "file", "main");
        std::string name = node.attribute("name").value();
        if (name.empty()) {
            const std::string base = file.substr(file.find_last_of('/') + 1);
            name = base.substr(0, base.find_last_of('.'));
        }
        Mesh mesh;
        if (!file.empty()) {
            const std::string dir = !meshdir_.empty() ? meshdir_ : assetdir_;
            mesh.path = joined(dir, file);
        }
        mesh.scale =
            vector(lookup(node, "scale", "main"), Eigen::Vector3d::Ones(), what + " scale");
        const std::string inertia = lookup(node, "inertia", "main");
        if (inertia == "exact") {
            mesh.inertia = MeshInertia::kExact;
        } else if (inertia == "convex") {
            mesh.inertia = MeshInertia::kConvex;
        } else if (inertia == "shell") {
            mesh.inertia = MeshInertia::kShell;
        } else if (!inertia.empty() && inertia != "legacy") {
            throw DescriptionError(what + " inertia: '" + inertia +
                                   "' is none of legacy, exact, convex, shell");
        }
        if (!meshes_.emplace(name, mesh).second) {
            throw DescriptionError(what + ": a second mesh named '" + name +
                                   "' (MuJoCo refuses the model: names must be unique)");
        }
    }

    // The bodies in parent (a body, a frame or the worldbody), whose body
    // is links[parent_link] (-1: the world); frame: the parent's frame in the
    // world's, at zero joint positions (empty when a pos or orientation above
    // cannot be read).
    void read_bodies(const pugi::xml_node& parent, const XmlFile& source, const std::string& cls,
                     int depth, const std::optional<Pose>& frame, int parent_link) {
        for_each_child(parent, source, depth, [&](const pugi::xml_node& node, const XmlFile& in) {
            const std::string name = node.name();
            if (name != "body" && name != "frame") return;
            const std::string child_class =
                node.attribute("childclass") ? node.attribute("childclass").value() : cls;
            if (++body_depth_ > kDeepestBody) {
                throw DescriptionError(main_.path + ": bodies and frames nested more than " +
                                       std::to_string(kDeepestBody) + " deep");
            }
            const std::optional<Pose> placed = placed_in(node, frame, child_class);
            int link = parent_link;
            if (name == "body") {
                read_body(node, in, child_class, depth, placed, parent_link);
                link = static_cast<int>(description_.links.size()) - 1;
            }
            read_bodies(node, in, child_class, depth, placed, link);
            --body_depth_;
        });
    }

    // A body's or frame's placement in frame by its pos and orientation.
    std::optional<Pose> placed_in(const pugi::xml_node& node, const std::optional<Pose>& frame,
                                  const std::string& cls) const {
        if (!frame) return std::nullopt;
        Pose pose;
        try {
            pose.rotation = orientation(node, cls, describe(node));
            pose.position =
                vector(lookup(node, "pos", cls), Eigen::Vector3d::Zero(), describe(node) + " pos");
        } catch (const DescriptionError&) {
            return std::nullopt;  // the audit reads no body placement: the page draws it unplaced
        }
        return compose(*frame, pose);
    }

    void read_body(const pugi::xml_node& node, const XmlFile& source, const std::string& cls,
                   int depth, const std::optional<Pose>& frame, int parent_link) {
        Link link;
        link.frame = frame;
        link.parent = parent_link;
        link.name = node.attribute("name").value();
        if (link.name.empty()) link.name = "body " + std::to_string(++unnamed_);
        const std::string what = "body '" + link.name + "'";
        for_each_child(node, source, depth, [&](const pugi::xml_node& child, const XmlFile& in) {
            const std::string name = child.name();
            if (name == "joint" || name == "freejoint") link.moving = true;
            if (name != "inertial") return;
            try {
                link.inertial = read_inertial(child, in, what + " <inertial>");
            } catch (const DescriptionError& error) {
                link.invalid_inertial = error.what();
            }
        });
        read_geoms(node, source, cls, depth, Pose{}, what, link);
        description_.links.push_back(std::move(link));
    }

    // The geoms of a body, and of the <frame>s in it (MuJoCo 3: a frame
    // places its children, and its childclass is theirs), each placed by
    // frame in the body.
    void read_geoms(const pugi::xml_node& node, const XmlFile& source, const std::string& cls,
                    int depth, const Pose& frame, const std::string& what, Link& link) {
        for_each_child(node, source, depth, [&](const pugi::xml_node& child, const XmlFile& in) {
            const std::string name = child.name();
            if (name == "geom") {
                try {
                    read_geom(child, cls, frame, what + " " + describe(child), link);
                } catch (const DescriptionError& error) {
                    Geometry geometry;
                    geometry.invalid = error.what();
                    link.collision.push_back(std::move(geometry));
                }
            } else if (name == "frame") {
                const std::string where = what + " " + describe(child);
                const std::string child_class =
                    child.attribute("childclass") ? child.attribute("childclass").value() : cls;
                if (++body_depth_ > kDeepestBody) {
                    throw DescriptionError(main_.path + ": frames nested more than " +
                                           std::to_string(kDeepestBody) + " deep");
                }
                Pose inner;
                try {
                    inner.rotation = frame.rotation * orientation(child, cls, where);
                    inner.position = frame.rotation * vector(lookup(child, "pos", cls),
                                                             Eigen::Vector3d::Zero(), where) +
                                     frame.position;
                } catch (const DescriptionError& error) {
                    Geometry geometry;
                    geometry.invalid = error.what();
                    link.collision.push_back(std::move(geometry));
                    --body_depth_;
                    return;
                }
                read_geoms(child, in, child_class, depth, inner, what, link);
                --body_depth_;
            }
        });
    }

    Inertial read_inertial(const pugi::xml_node& node, const XmlFile& source,
                           const std::string& what) const {
        Inertial inertial;
        const std::string pos = node.attribute("pos").value();
        if (pos.empty()) throw DescriptionError(what + ": no pos");
        inertial.center_of_mass = required_vector(pos, what + " pos");
        const std::string mass = node.attribute("mass").value();
        if (mass.empty()) throw DescriptionError(what + ": no mass");
        inertial.mass = parse_number(mass, what + " mass");
        Eigen::Matrix3d in_frame;
        if (const pugi::xml_attribute full = node.attribute("fullinertia")) {
            const std::vector<double> v = parse_numbers(full.value(), 6, what + " fullinertia");
            in_frame << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
        } else if (const pugi::xml_attribute diagonal = node.attribute("diaginertia")) {
            in_frame = required_vector(diagonal.value(), what + " diaginertia").asDiagonal();
        } else {
            throw DescriptionError(what + ": neither diaginertia nor fullinertia");
        }
        const Eigen::Matrix3d rotation = orientation(node, "main", what);
        inertial.inertia = rotation * in_frame * rotation.transpose();
        if (&source == &main_) inertial.text = element_range(main_, node);
        return inertial;
    }

    void read_geom(const pugi::xml_node& node, const std::string& cls, const Pose& frame,
                   const std::string& what, Link& link) const {
        const std::string mesh_name = lookup(node, "mesh", cls);
        std::string type = lookup(node, "type", cls);
        if (type.empty()) type = mesh_name.empty() ? "sphere" : "mesh";
        const std::vector<double> size =
            parse_numbers(lookup(node, "size", cls), 0, what + " size");
        const auto half = [&](std::size_t i) {
            if (i >= size.size()) throw DescriptionError(what + ": size has too few numbers");
            return size[i];
        };
        Geometry geometry;
        geometry.pose.position = vector(lookup(node, "pos", cls), Eigen::Vector3d::Zero(), what);
        geometry.pose.rotation = orientation(node, cls, what);
        const std::string fromto = lookup(node, "fromto", cls);
        double half_length = 0.0;
        if (!fromto.empty() && type != "mesh" && type != "sphere") {
            const std::vector<double> v = parse_numbers(fromto, 6, what + " fromto");
            const Eigen::Vector3d from(v[0], v[1], v[2]), to(v[3], v[4], v[5]);
            geometry.pose.position = (from + to) / 2;
            geometry.pose.rotation = rotation_from_z_axis(to - from, what + " fromto");
            half_length = (to - from).norm() / 2;
        }
        // MuJoCo gives a box or an ellipsoid along a fromto segment size[0]
        // for both its half-widths.
        const auto width = [&](std::size_t i) { return fromto.empty() ? half(i) : half(0); };
        if (type == "mesh") {
            const auto found = meshes_.find(mesh_name);
            if (found == meshes_.end()) {
                throw DescriptionError(what + ": mesh '" + mesh_name + "' is no <mesh> asset");
            }
            if (found->second.path.empty()) {
                link.unsupported.push_back(what + ": mesh '" + mesh_name + "' has no file");
                link.weighs_unmeasured = true;
                return;
            }
            geometry.shape = Shape::kMesh;
            geometry.uri = found->second.path;
            geometry.scale = found->second.scale;
            geometry.weighing.mesh_inertia = found->second.inertia;
        } else if (!mesh_name.empty()) {
            link.unsupported.push_back(what + ": a " + type + " fitted to mesh '" + mesh_name +
                                       "' (MuJoCo's fitting is not one the audit reproduces)");
            link.weighs_unmeasured = true;
            return;
        } else if (type == "box") {
            geometry.shape = Shape::kBox;
            geometry.size =
                2 * Eigen::Vector3d(width(0), width(1), fromto.empty() ? half(2) : half_length);
        } else if (type == "cylinder" || type == "capsule") {
            geometry.shape = type == "cylinder" ? Shape::kCylinder : Shape::kCapsule;
            geometry.size = {half(0), 2 * (fromto.empty() ? half(1) : half_length), 0.0};
        } else if (type == "sphere") {
            geometry.shape = Shape::kSphere;
            geometry.size = {half(0), 0.0, 0.0};
        } else if (type == "ellipsoid") {
            geometry.shape = Shape::kEllipsoid;
            geometry.size = {width(0), width(1), fromto.empty() ? half(2) : half_length};
        } else {
            link.unsupported.push_back(what + ": type '" + type +
                                       "' is not a shape the audit measures");
            // MuJoCo gives a plane no volume; a height field or an SDF weighs.
            link.weighs_unmeasured = link.weighs_unmeasured || type != "plane";
            return;
        }
        geometry.pose.position = frame.rotation * geometry.pose.position + frame.position;
        geometry.pose.rotation = frame.rotation * geometry.pose.rotation;
        read_weighing(node, cls, what, type == "mesh", geometry.weighing);
        const bool visual =
            lookup(node, "contype", cls) == "0" && lookup(node, "conaffinity", cls) == "0";
        (visual ? link.visual : link.collision).push_back(std::move(geometry));
    }

    // The geom's group, density, mass and shellinertia (its class's, else
    // MuJoCo's defaults).
    void read_weighing(const pugi::xml_node& node, const std::string& cls, const std::string& what,
                       bool mesh, Weighing& weighing) const {
        if (const std::string group = lookup(node, "group", cls); !group.empty()) {
            weighing.group = integer(parse_number(group, what + " group"), what + " group");
        }
        if (const std::string density = lookup(node, "density", cls); !density.empty()) {
            weighing.density = parse_number(density, what + " density");
        }
        if (const std::string mass = lookup(node, "mass", cls); !mass.empty()) {
            weighing.mass = parse_number(mass, what + " mass");
        }
        if (weighing.density < 0.0 || (weighing.mass && *weighing.mass < 0.0)) {
            throw DescriptionError(what + ": a negative density or mass (MuJoCo refuses it)");
        }
        if (const std::string shell = lookup(node, "shellinertia", cls); !shell.empty()) {
            weighing.shell = boolean(shell, what + " shellinertia");
        }
        if (weighing.shell && mesh) {
            throw DescriptionError(what +
                                   ": shellinertia on a mesh geom (MuJoCo wants "
                                   "<mesh inertia=\"shell\"> instead)");
        }
    }

    struct Mesh {
        std::string path;  // relative to the model file's directory, or absolute
        Eigen::Vector3d scale = Eigen::Vector3d::Ones();
        MeshInertia inertia = MeshInertia::kLegacy;
    };

    const XmlFile& main_;
    std::string model_dir_;
    std::vector<std::unique_ptr<XmlFile>> included_;
    // The files whose <include> is being expanded, the model file first.
    std::vector<std::string> include_chain_;
    bool degrees_ = true;
    std::string eulerseq_ = "xyz";
    std::string meshdir_, assetdir_;
    std::map<std::string, std::map<std::string, Attributes>> classes_;
    std::map<std::string, Mesh> meshes_;
    Description description_;
    int unnamed_ = 0;
    int body_depth_ = 0;
};

}  // namespace

Description parse_mjcf(const XmlFile& file) { return MjcfParser(file).parse(); }

}  // namespace polymass_cli::audit
