// The audit's rules. Thresholds (the README lists them):
// - principal moments: the largest difference over the largest computed
//   moment, a warning above 5 %, an error above 25 %;
// - principal axes: the angle between a declared and a computed axis, for
//   axes whose moments stand apart by more than 5 % in both, a warning above
//   5 degrees, an error above 20;
// - centre of mass: the distance over the diagonal of the geometry's
//   bounding box, a warning above 5 %, an error above 20 %; an error when it
//   lies outside that box;
// - implied density (declared mass / computed volume): outside 100 to
//   25,000 kg/m^3 a warning, an error when a unit mix-up explains it; below
//   it with a mass of at most 1 g, a placeholder (a warning);
// - a tensor whose principal moments are all k times the geometry's: lengths
//   off by sqrt(k) said only when that is a ratio of length units.
#include "audit/judge.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>

#include "reports/number_format.hpp"
#include "text_streams.hpp"

namespace polymass_cli::audit {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMomentWarning = 0.05, kMomentError = 0.25;
constexpr double kAxisWarningDegrees = 5.0, kAxisErrorDegrees = 20.0;
constexpr double kDistinctMoments = 0.05;
constexpr double kComWarning = 0.05, kComError = 0.20;
constexpr double kLightest = 100.0, kHeaviest = 25000.0;  // kg/m^3
// A declared mass this small on a part that is not that light is a stand-in
// (exporters write 1e-4 to 1e-8 kg for "no inertial").
constexpr double kPlaceholderMass = 1e-3;  // kg
// Ratios of the length units descriptions mix up: metre, centimetre,
// millimetre, inch.
constexpr double kUnitRatios[] = {10.0, 100.0, 1000.0, 2.54, 25.4, 1.0 / 0.0254};
// Below this relative margin (a + b - c) / c the triangle inequality fails:
// rounding of a tensor on the boundary (a thin plate) stays above it.
constexpr double kTriangleTolerance = 1e-9;

std::string triple(const Eigen::Vector3d& v) {
    return readable_number(v[0]) + " " + readable_number(v[1]) + " " + readable_number(v[2]);
}

Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(const Eigen::Matrix3d& inertia) {
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia);
}

// The largest difference of principal moments over the largest computed one.
double moment_difference(const Eigen::Vector3d& declared, const Eigen::Vector3d& computed) {
    return (declared - computed).cwiseAbs().maxCoeff() / computed.maxCoeff();
}

// Whether moment i stands apart from the other two.
bool distinct(const Eigen::Vector3d& moments, int i) {
    const double scale = moments.cwiseAbs().maxCoeff();
    for (int j = 0; j < 3; ++j) {
        if (j != i && std::abs(moments[i] - moments[j]) <= kDistinctMoments * scale) return false;
    }
    return true;
}

// The largest angle (degrees) between matching principal axes that both
// tensors determine; 0 when none does.
double axes_angle(const Eigen::Vector3d& declared_moments, const Eigen::Matrix3d& declared_axes,
                  const Eigen::Vector3d& computed_moments, const Eigen::Matrix3d& computed_axes) {
    double largest = 0.0;
    for (int i = 0; i < 3; ++i) {
        if (!distinct(declared_moments, i) || !distinct(computed_moments, i)) continue;
        const double cosine =
            std::min(1.0, std::abs(declared_axes.col(i).dot(computed_axes.col(i))));
        largest = std::max(largest, std::acos(cosine) * 180.0 / kPi);
    }
    return largest;
}

// What explains an inertia that differs, when something simple does.
std::string inertia_hint(const Inertial& declared, const Eigen::Vector3d& declared_moments,
                         const Computed& computed) {
    const double norm = computed.inertia.norm();
    if ((declared.inertia - computed.inertia_origin).norm() <= 0.02 * norm &&
        (computed.inertia_origin - computed.inertia).norm() > 0.05 * norm) {
        return "; it is the inertia about the link origin: the shift to the centre of mass "
               "(parallel axes) is missing, as for a tensor taken in the CAD frame";
    }
    static const std::array<std::array<int, 2>, 3> kPairs{{{0, 1}, {0, 2}, {1, 2}}};
    static const char* const kNames[] = {"ixx", "iyy", "izz"};
    for (const auto& pair : kPairs) {
        Eigen::Matrix3d swapped = declared.inertia;
        swapped.row(pair[0]).swap(swapped.row(pair[1]));
        swapped.col(pair[0]).swap(swapped.col(pair[1]));
        if ((swapped - computed.inertia).norm() <= 0.02 * norm) {
            return std::string("; it is the computed tensor with ") + kNames[pair[0]] + " and " +
                   kNames[pair[1]] + " swapped";
        }
    }
    if (moment_difference(declared_moments, computed.principal_moments) <= 0.02) {
        return "; the principal moments agree: the tensor is about other axes (another frame, "
               "or entries swapped)";
    }
    const Eigen::Vector3d ratios = declared_moments.cwiseQuotient(computed.principal_moments);
    const double factor = ratios.mean();
    if ((ratios.array() - factor).abs().maxCoeff() > 0.02 * factor) return "";
    const std::string same =
        "; every principal moment is " + readable_number(factor) + " times the geometry's";
    const double length = std::sqrt(factor);
    for (const double unit : kUnitRatios) {
        for (const double ratio : {unit, 1.0 / unit}) {
            if (std::abs(std::log(length / ratio)) <= 0.02) {
                return same + ": lengths off by a factor " + readable_number(length) +
                       " (a mesh scale not applied, or a unit mix-up)";
            }
        }
    }
    return same;
}

// The unit mix-up that brings density into the plausible range, or "";
// those of a mesh's units only when there is a mesh.
std::string density_hint(double density, bool has_mesh) {
    struct Explanation {
        double factor;  // the density it would have without the mix-up
        const char* text;
    };
    const double inch = 0.0254;
    const Explanation explanations[] = {
        {1e-3, "the mass looks like grams written as kilograms"},
        {1e9, "the mesh looks like millimetres read as metres (a scale 0.001 missing)"},
        {1e6, "the mesh looks like centimetres read as metres (a scale 0.01 missing)"},
        {1.0 / (inch * inch * inch), "the mesh looks like inches read as metres"},
        {1e-9, "the mesh looks like metres scaled as millimetres (a scale 0.001 too many)"}};
    const char* best = nullptr;
    double best_distance = 0.0;
    for (const Explanation& explanation : explanations) {
        if (!has_mesh && explanation.factor != 1e-3) continue;
        const double corrected = density * explanation.factor;
        if (corrected < kLightest || corrected > kHeaviest) continue;
        // Nearest, on a log scale, to 2000 kg/m^3 (plastics to aluminium).
        const double distance = std::abs(std::log(corrected / 2000.0));
        if (best == nullptr || distance < best_distance) {
            best = explanation.text;
            best_distance = distance;
        }
    }
    return best == nullptr ? "" : best;
}

}  // namespace

std::string percent(double fraction) {
    const double value = 100.0 * fraction;
    OutputText text;
    if (std::abs(value) >= 100.0)
        text << std::fixed << std::setprecision(0);
    else
        text << std::setprecision(3);
    text << value << " %";
    return text.str();
}

std::vector<Finding> judge_declared(const Inertial& declared) {
    std::vector<Finding> findings;
    if (declared.mass == 0.0 && declared.inertia.isZero(0.0)) {
        findings.push_back({"massless", Severity::kInfo,
                            "mass and inertia zero: a static (fixed) or massless link, as Bullet "
                            "and Gazebo read it; not compared with its geometry"});
        return findings;
    }
    if (!(std::isfinite(declared.mass) && declared.mass > 0.0)) {
        findings.push_back(
            {"tensor_not_physical", Severity::kError,
             "the declared mass " + readable_number(declared.mass) + " is not positive"});
    }
    const Eigen::Vector3d moments = principal(declared.inertia).eigenvalues();
    if (!(moments[0] > 0.0) || !moments.allFinite()) {
        findings.push_back({"tensor_not_physical", Severity::kError,
                            "the declared inertia is not positive definite: principal moments " +
                                triple(moments)});
        return findings;
    }
    // Ascending: only a + b >= c can fail.
    const double margin = (moments[0] + moments[1] - moments[2]) / moments[2];
    if (margin < -kTriangleTolerance) {
        findings.push_back(
            {"tensor_not_physical", Severity::kError,
             "the declared inertia breaks the triangle inequality: principal moments " +
                 triple(moments) + ", (a+b-c)/c = " + readable_number(margin) + " (" +
                 percent(-margin) + " short); simulators reject it or go unstable"});
    }
    return findings;
}

std::vector<Finding> judge_against_geometry(const Inertial& declared, const Computed& computed,
                                            bool has_mesh) {
    std::vector<Finding> findings;
    if (computed.density < kLightest && declared.mass <= kPlaceholderMass) {
        findings.push_back(
            {"placeholder_inertial", Severity::kWarning,
             "declared mass " + readable_number(declared.mass) + " kg on a geometry of volume " +
                 readable_number(computed.volume) + " (implied density " +
                 readable_number(computed.density) +
                 " kg/m^3): a placeholder, not the part's mass; simulators use it as it is "
                 "(--fix --mass-from geometry writes the geometry's)"});
    } else if (computed.density < kLightest || computed.density > kHeaviest) {
        const std::string hint = density_hint(computed.density, has_mesh);
        findings.push_back(
            {"density_implausible", hint.empty() ? Severity::kWarning : Severity::kError,
             "implied density " + readable_number(computed.density) + " kg/m^3 (declared mass " +
                 readable_number(declared.mass) + " / volume " + readable_number(computed.volume) +
                 "), outside 100 to 25000" +
                 (hint.empty() ? ": a hollow part, or a unit mix-up" : ": " + hint)});
    }
    const auto eigen = principal(declared.inertia);
    const Eigen::Vector3d& moments = eigen.eigenvalues();
    if (moments.allFinite() && moments[0] > 0.0) {
        const double difference = moment_difference(moments, computed.principal_moments);
        const double angle = axes_angle(moments, eigen.eigenvectors(), computed.principal_moments,
                                        computed.principal_axes);
        if (difference > kMomentWarning || angle > kAxisWarningDegrees) {
            const bool error = difference > kMomentError || angle > kAxisErrorDegrees;
            OutputText message;
            message << std::setprecision(3);
            if (difference > kMomentWarning) {
                message << "principal moments differ by up to " << percent(difference);
                if (angle > kAxisWarningDegrees)
                    message << ", principal axes by " << angle << " degrees";
            } else {
                message << "principal axes differ by " << angle << " degrees";
            }
            message << " (principal moments declared " << triple(moments) << ", computed "
                    << triple(computed.principal_moments) << ")";
            message << inertia_hint(declared, moments, computed);
            findings.push_back(
                {"inertia_differs", error ? Severity::kError : Severity::kWarning, message.str()});
        }
    }
    const double size = (computed.box_max - computed.box_min).norm();
    const double offset = (declared.center_of_mass - computed.center_of_mass).norm() / size;
    if (offset > kComWarning) {
        findings.push_back({"com_differs",
                            offset > kComError ? Severity::kError : Severity::kWarning,
                            "centre of mass " + percent(offset) +
                                " of the link's size from the geometry's (declared " +
                                triple(declared.center_of_mass) + ", computed " +
                                triple(computed.center_of_mass) + ")"});
    }
    const Eigen::Vector3d slack = Eigen::Vector3d::Constant(1e-9 * size);
    if ((declared.center_of_mass.array() < (computed.box_min - slack).array()).any() ||
        (declared.center_of_mass.array() > (computed.box_max + slack).array()).any()) {
        findings.push_back({"com_outside_geometry", Severity::kError,
                            "the declared centre of mass " + triple(declared.center_of_mass) +
                                " lies outside the geometry's bounding box (" +
                                triple(computed.box_min) + " to " + triple(computed.box_max) +
                                ")"});
    }
    return findings;
}

}  // namespace polymass_cli::audit
