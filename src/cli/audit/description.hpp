// A robot description (URDF, SDFormat or MJCF) as the audit needs it: each
// link's declared inertial and the geometries it could be checked against,
// all in the link's frame. The parsers (description_urdf/_sdf/_mjcf) fill it;
// resolving mesh paths, computing and judging come afterwards.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace polymass_cli::audit {

// A rigid placement: a point p of the child frame is rotation * p + position
// in the parent frame.
struct Pose {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

// The placement of a frame placed by child in a frame placed by parent.
Pose compose(const Pose& parent, const Pose& child);

enum class Shape { kMesh, kBox, kCylinder, kSphere, kCapsule, kEllipsoid };

// How MuJoCo integrates a mesh asset (<mesh inertia>): legacy (its default:
// every tetrahedron counted positive), exact, the convex hull, or the surface.
enum class MeshInertia { kLegacy, kExact, kConvex, kShell };

// How MuJoCo weighs an MJCF geom (URDF and SDFormat geometry keeps the
// defaults, which the audit does not read for them).
struct Weighing {
    int group = 0;               // <geom group>, against inertiagrouprange
    double density = 1000.0;     // kg/m^3 (kg/m^2 for a shell)
    std::optional<double> mass;  // <geom mass>: the geom's mass, its density derived
    bool shell = false;          // <geom shellinertia>: a primitive's surface
    // The mesh asset's (MuJoCo's default is legacy; URDF and SDFormat meshes
    // are weighed exactly).
    MeshInertia mesh_inertia = MeshInertia::kExact;
};

struct Geometry {
    Shape shape = Shape::kMesh;
    Pose pose;  // in the link frame
    // box: edge lengths; cylinder and capsule: radius, length (of the
    // cylindrical part, along z), unused; sphere: radius; ellipsoid: radii.
    Eigen::Vector3d size = Eigen::Vector3d::Zero();
    std::string uri;                                  // mesh: as written
    Eigen::Vector3d scale = Eigen::Vector3d::Ones();  // mesh: applied before pose
    // Why the element cannot be read (a missing or malformed value), when it
    // cannot: the link's geometry is then unknown.
    std::string invalid;
    Weighing weighing;
};

// Where an element sits in the description's text, for --fix: the bytes
// [begin, end) of the element, the column its line is indented to.
struct TextRange {
    std::size_t begin = 0;
    std::size_t end = 0;
    std::string indent;  // the whitespace before the element on its line
};

struct Inertial {
    double mass = 0.0;
    Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();  // link frame
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the centre of mass, link axes
    std::optional<TextRange> text;  // empty: not in the file --fix writes (an MJCF include)
};

struct Link {
    std::string name;
    std::optional<Inertial> inertial;
    std::string invalid_inertial;  // why its <inertial> cannot be read, when it cannot
    std::vector<Geometry> collision;
    std::vector<Geometry> visual;
    // Geometries the description has but the audit cannot measure (an
    // MJCF plane or height field, a pose relative to another frame): said.
    std::vector<std::string> unsupported;
    // The link frame in the description's frame with every joint at zero
    // (URDF: its joints' origins from the root; SDFormat: the link's pose in
    // its model; MJCF: the bodies' pos and orientation), for the --html
    // page; empty when the description does not say (a pose relative to
    // another frame, a link no joint reaches from the root).
    std::optional<Pose> frame;
    // MJCF: one of those is a geom MuJoCo weighs (a height field, a mesh
    // without a file, a shape fitted to a mesh): the body's mass is unknown.
    bool weighs_unmeasured = false;
    // MJCF: the enclosing body's index in Description::links (-1: the
    // world), and whether the body moves (has a joint).
    int parent = -1;
    bool moving = false;
};

enum class Format { kUrdf, kSdf, kMjcf };

// MuJoCo's <compiler> settings for mass and inertia.
struct MujocoCompiler {
    enum class FromGeom { kFalse, kTrue, kAuto };
    FromGeom inertia_from_geom = FromGeom::kAuto;
    int group_low = 0, group_high = 5;  // inertiagrouprange
    double settotalmass = -1.0;         // > 0: every body's mass scaled to add up to it
    double boundmass = 0.0;             // each body's mass at least this
    double boundinertia = 0.0;          // each principal moment at least this
    bool balanceinertia = false;        // A + B < C: all three set to their mean
};

struct Description {
    Format format = Format::kUrdf;
    std::string path;
    std::string text;  // the file's bytes, which --fix edits
    std::vector<Link> links;
    MujocoCompiler compiler;  // MJCF only
};

// A description that cannot be read: missing file, not XML, not one of the
// three formats, a value that is not a number. The message says where.
class DescriptionError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

const char* format_name(Format format);

// Reads path and parses it by its root element (<robot>, <sdf>, <mujoco>).
// Throws DescriptionError.
Description read_description(const std::string& path);

}  // namespace polymass_cli::audit
