// --usda: a USD text layer (OpenUSD's UsdPhysics schema, openusd.org: "Usd
// Physics: Rigid Body Physics in USD"), a prim per file for the whole, with
// a child prim per part. Each prim applies PhysicsRigidBodyAPI and
// PhysicsMassAPI and authors
//  - float physics:mass;
//  - point3f physics:centerOfMass, "in the prim's local space" (the file's
//    frame moved to --origin, no rotation, as for the XML outputs);
//  - float3 physics:diagonalInertia, the principal moments;
//  - quatf physics:principalAxes, "the orientation of the inertia tensor's
//    principal axes in the prim's local space": the unit quaternion (real
//    part first) of the rotation R whose columns are the principal axes, so
//    that the tensor about the centre of mass is R diag(moments) R^T
//    (docs/usd.md has the derivation and what is checked).
// The stage's metersPerUnit and kilogramsPerUnit are 1 with --units (the
// results are in metres and kilograms); without --units the lengths are the
// file's, and the layer says so instead of guessing. The attributes are 32-bit
// floats: a comment says so, and a centre of mass far from the origin, where
// float loses more than the answer's error bound and a millionth of the
// part's size, is a warning on stderr and in the layer. A value that float
// cannot hold (overflow, or a positive mass or moment that would round to 0
// or lose digits as a subnormal) leaves the prim out, with the reason.
#include <polymass/polymass.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <set>

#include <Eigen/Geometry>

#include "library/categories.hpp"
#include "reports/number_format.hpp"
#include "reports/provenance.hpp"
#include "reports/report.hpp"
#include "reports/utf8.hpp"

namespace polymass_cli {
namespace {

// How the part's values are written: rounded to float, with the problems
// found on the way.
struct UsdValues {
    float mass = 0.0f;
    std::array<float, 3> center_of_mass{};
    std::array<float, 3> moments{};
    std::array<float, 4> quaternion{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
    std::string unrepresentable;  // why float cannot hold a value, if it cannot
    std::string far_from_origin;  // the warning, if the centre of mass is far
};

// The unit quaternion (w, x, y, z), w >= 0, of a proper rotation given
// row-major (Eigen's conversion takes the largest component from the
// diagonal, so it divides by no small number).
std::array<double, 4> rotation_quaternion(const double* r) {
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> rotation(r);
    Eigen::Quaterniond q(rotation);
    q.normalize();
    if (q.w() < 0.0) q.coeffs() *= -1.0;  // q and -q are the same rotation
    return {q.w(), q.x(), q.y(), q.z()};
}

// A positive quantity as a normal float, or why it cannot be one.
std::string positive_float(const char* what, double value, float& out) {
    out = float(value);
    if (!(value > 0.0) || !std::isfinite(out) || out < FLT_MIN)
        return std::string(what) + " " + exact_number(value) + " is not a normal 32-bit float";
    return "";
}

UsdValues usd_values(const polymass_mass_properties& p, const std::array<double, 3>& origin) {
    UsdValues values;
    std::string problem = positive_float("the mass", p.mass, values.mass);
    for (int k = 0; k < 3 && problem.empty(); ++k)
        problem = positive_float("a principal moment", p.principal_moments[k], values.moments[k]);
    double rounding = 0.0;  // of the centre of mass, the largest coordinate's
    double distance = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double coordinate = p.center_of_mass[k] - origin[k];
        values.center_of_mass[k] = float(coordinate);
        if (!std::isfinite(values.center_of_mass[k]) && problem.empty())
            problem = "the centre of mass " + exact_number(coordinate) + " is past 32-bit floats";
        rounding = std::max(rounding, std::abs(double(values.center_of_mass[k]) - coordinate));
        distance = std::max(distance, std::abs(coordinate));
    }
    values.unrepresentable = problem;
    if (!problem.empty()) return values;
    const std::array<double, 4> q = rotation_quaternion(p.principal_axes);
    for (int k = 0; k < 4; ++k) values.quaternion[k] = float(q[k]);
    // The part's size: its radius of gyration about its largest principal
    // axis. Float keeps about 6e-8 of every value; a centre of mass far
    // from the origin loses that much of its distance, which is more than
    // the part's own size can tell once the distance is some 16 sizes.
    const double size = std::sqrt(p.principal_moments[2] / p.mass);
    const double tolerated = std::max(p.error_bound_center_of_mass, 1e-6 * size);
    if (rounding > tolerated)
        values.far_from_origin =
            "the centre of mass, " + readable_number(distance) +
            " from the origin, is rounded by up to " + readable_number(rounding) +
            " in 32-bit float, more than its error bound and a "
            "millionth of the part's size (" +
            readable_number(size) + "): give a frame near it with --origin X,Y,Z";
    return values;
}

// A USD identifier ([A-Za-z_][A-Za-z0-9_]*) made from a name: every other
// byte becomes '_', a leading digit gets a '_' before it; unique among
// `taken` (its siblings) by a suffix _2, _3, ...
std::string prim_name(const std::string& name, std::set<std::string>& taken) {
    std::string identifier;
    for (const char c : name) {
        const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
        identifier += letter || (c >= '0' && c <= '9') ? c : '_';
    }
    if (identifier.empty() || (identifier[0] >= '0' && identifier[0] <= '9'))
        identifier = "_" + identifier;
    std::string unique = identifier;
    for (int n = 2; !taken.insert(unique).second; ++n)
        unique = identifier + "_" + std::to_string(n);
    return unique;
}

// A USD string literal: double quotes, with the C escapes USD reads back.
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : valid_utf8(text)) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string floats(const float* values, int count) {
    std::string text = "(";
    for (int k = 0; k < count; ++k) text += (k ? ", " : "") + float_number(values[k]);
    return text + ")";
}

class UsdWriter {
public:
    UsdWriter(std::ostream& out, std::ostream& diagnostics, const OutputSettings& settings)
        : out_(out), diagnostics_(diagnostics), settings_(settings) {}

    void comment(const std::string& indent, const std::string& text) {
        std::string line = valid_utf8(text);
        std::replace(line.begin(), line.end(), '\n', ' ');
        std::replace(line.begin(), line.end(), '\r', ' ');
        out_ << indent << "# " << line << '\n';
    }

    // The prim of the whole (depth 0) or of a part (depth 1, its rigid body
    // disabled: the file is one body, and the parent's mass properties are
    // the whole's); the part prims follow as children of the whole's.
    // Returns false when a value cannot be written in float.
    bool prim(const std::string& path, const PartReport& part, const std::string& name, int depth,
              const std::vector<PartReport>& children) {
        const std::string indent(4 * depth, ' ');
        const polymass_mass_properties& p = part.result.properties;
        const UsdValues values = usd_values(p, settings_.link_origin);
        const std::string label = depth ? "part '" + part.name + "'" : "the whole";
        if (!values.unrepresentable.empty()) {
            comment(indent, label + ": no prim: " + values.unrepresentable);
            diagnostics_ << "polymass: " << path << ": " << label
                         << ": no USD prim: " << values.unrepresentable << '\n';
            return false;
        }
        if (p.warnings) comment(indent, "warning: " + warning_text(p.warnings));
        comment(indent, "provenance: " + provenance_text(part.result.provenance));
        comment(indent, "error bound: " + error_bound_text(p));
        if (!part.material.empty()) comment(indent, "material: " + material_text(part));
        if (!values.far_from_origin.empty()) {
            comment(indent, "warning: " + values.far_from_origin);
            diagnostics_ << "polymass: " << path << ": " << label
                         << ": warning: " << values.far_from_origin << '\n';
        }
        out_ << indent << "def Xform \"" << name << "\" (\n"
             << indent << "    prepend apiSchemas = [\"PhysicsRigidBodyAPI\", \"PhysicsMassAPI\"]\n"
             << indent << "    customData = {\n";
        if (depth == 0) out_ << indent << "        string file = " << quoted(path) << '\n';
        if (depth != 0) out_ << indent << "        string name = " << quoted(part.name) << '\n';
        if (!part.material.empty())
            out_ << indent << "        string material = " << quoted(part.material) << '\n';
        out_ << indent << "        double density = " << exact_number(p.density) << '\n'
             << indent << "    }\n"
             << indent << ")\n"
             << indent << "{\n";
        const std::string inner = indent + "    ";
        if (depth) out_ << inner << "bool physics:rigidBodyEnabled = 0\n";
        out_ << inner << "float physics:mass = " << float_number(values.mass) << '\n'
             << inner
             << "point3f physics:centerOfMass = " << floats(values.center_of_mass.data(), 3) << '\n'
             << inner << "float3 physics:diagonalInertia = " << floats(values.moments.data(), 3)
             << '\n'
             << inner << "quatf physics:principalAxes = " << floats(values.quaternion.data(), 4)
             << '\n';
        bool written = true;
        std::set<std::string> taken;
        for (const PartReport& child : children) {
            out_ << '\n';
            if (!child.computed || child.result.status != POLYMASS_OK) {
                comment(inner, "part '" + child.name + "': no prim, " +
                                   (child.computed ? child.result.message : "not computed"));
                continue;
            }
            written &= prim(path, child, prim_name(child.name, taken), depth + 1, {});
        }
        out_ << indent << "}\n";
        return written;
    }

private:
    std::ostream& out_;
    std::ostream& diagnostics_;
    const OutputSettings& settings_;
};

}  // namespace

bool write_usda(std::ostream& out, std::ostream& diagnostics, const std::vector<FileReport>& files,
                const OutputSettings& settings) {
    std::set<std::string> taken;
    std::vector<std::string> names;
    for (const FileReport& file : files)
        names.push_back(prim_name(std::filesystem::path(file.path).stem().string(), taken));
    out << "#usda 1.0\n(\n";
    if (files.size() == 1) out << "    defaultPrim = \"" << names.front() << "\"\n";
    out << "    doc = \"mass properties by polymass " << polymass_version_string() << "\"\n";
    if (!settings.length_unit.empty()) out << "    kilogramsPerUnit = 1\n    metersPerUnit = 1\n";
    out << "    upAxis = \"Z\"\n)\n\n";
    UsdWriter writer(out, diagnostics, settings);
    writer.comment("",
                   "UsdPhysics mass properties: physics:mass, physics:centerOfMass, "
                   "physics:diagonalInertia and physics:principalAxes are 32-bit floats, each "
                   "our double rounded to the nearest float (about 6e-8 of its value); "
                   "the tensor about the centre of mass is R diag(physics:diagonalInertia) R^T, "
                   "R the rotation of physics:principalAxes (w, x, y, z), its columns the "
                   "principal axes");
    writer.comment("",
                   settings.length_unit.empty()
                       ? std::string(kFileUnitsNote) +
                             ": metersPerUnit and kilogramsPerUnit are left unset (give the "
                             "file's unit with --units)"
                       : "lengths in metres (--units, or the unit each file declares), masses in "
                         "kilograms");
    bool written = true;
    for (size_t k = 0; k < files.size(); ++k) {
        const FileReport& file = files[k];
        out << '\n';
        if (file.exit_code() != kExitOk) {
            writer.comment(
                "",
                file.path + ": no prim, " +
                    (file.readable ? std::string(category_of(file.solid.result.status)) + ": " +
                                         file.solid.result.message
                                   : std::string(kUnreadableCategory) + ": " + file.read_error));
            continue;
        }
        writer.comment("", file.path);
        for (const std::string& note : file.notes) writer.comment("", "note: " + note);
        written &= writer.prim(file.path, file.solid, names[k], 0, file.parts);
    }
    return written;
}

}  // namespace polymass_cli
