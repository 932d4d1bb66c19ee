#include "audit/mujoco_inertia.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "audit/judge.hpp"
#include "reports/number_format.hpp"

namespace polymass_cli::audit {
namespace {

// MuJoCo's thresholds: a geom lighter than kGeomEpsilon is left out (and a
// geom mass on a volume no larger is ignored); a moving body needs a mass and
// principal moments of at least kSmallest.
constexpr double kGeomEpsilon = 1e-14;
constexpr double kSmallest = 1e-15;
// The legacy figure differs from the exact one beyond rounding above this
// (relative); a warning above kLegacyWarning in mass or moments.
constexpr double kSameFigure = 1e-9;
constexpr double kLegacyWarning = 0.05;

// The mass and principal moments MuJoCo ends with for the link (before
// settotalmass, which scales them all alike).
struct BodyMass {
    double mass = 0.0;
    Eigen::Vector3d moments = Eigen::Vector3d::Zero();
};

BodyMass body_mass(const MujocoCompiler& compiler, const LinkAudit& link) {
    const std::string uses = mujoco_uses(compiler, link);
    BodyMass body;
    if (uses == "computed") {
        if (!link.computed) return body;  // not measured: unknown
        const Computed& used = link.mujoco_legacy ? *link.mujoco_legacy : *link.computed;
        body.mass = used.mass;
        body.moments = used.principal_moments;
        return body;
    }
    if (uses == "declared") {
        body.mass = link.declared->mass;
        body.moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(link.declared->inertia,
                                                                      Eigen::EigenvaluesOnly)
                           .eigenvalues();
    }
    body.mass = std::max(body.mass, compiler.boundmass);
    body.moments = body.moments.cwiseMax(compiler.boundinertia);
    return body;
}

bool has_mass(const BodyMass& body) {
    return body.mass >= kSmallest && body.moments.minCoeff() >= kSmallest;
}

// Whether MuJoCo would find the link's mass positive; so assumed when the
// link's geometry could not be measured (nothing is known then).
bool weighs(const MujocoCompiler& compiler, const LinkAudit& link) {
    return (link.unmeasured && std::string(mujoco_uses(compiler, link)) != "declared") ||
           has_mass(body_mass(compiler, link));
}

using Children = std::vector<std::vector<std::size_t>>;

// MuJoCo's test of a moving body: its own mass, or that of a body fixed to
// it (a child without a joint, or one fixed to that, ...). Each fixed body
// is looked at for its nearest moving ancestor only.
bool carries_mass(const MujocoCompiler& compiler, const FileAudit& audit, const Children& children,
                  const std::vector<Link>& links, std::size_t index) {
    if (weighs(compiler, audit.links[index])) return true;
    for (const std::size_t child : children[index]) {
        if (!links[child].moving && carries_mass(compiler, audit, children, links, child)) {
            return true;
        }
    }
    return false;
}

void scale(Computed& computed, double factor) {
    computed.mass *= factor;
    computed.density *= factor;
    set_inertia(computed, factor * computed.inertia);
}

}  // namespace

bool weighed_by_mujoco(const Weighing& weighing, const MujocoCompiler& compiler) {
    return weighing.group >= compiler.group_low && weighing.group <= compiler.group_high;
}

double mujoco_geom_mass(const Weighing& weighing, double amount) {
    double mass = 0.0;
    if (weighing.mass) {
        if (amount > kGeomEpsilon) mass = *weighing.mass;
    } else {
        mass = weighing.density * amount;
    }
    return mass > kGeomEpsilon ? mass : 0.0;
}

void set_inertia(Computed& computed, const Eigen::Matrix3d& inertia) {
    computed.inertia = inertia;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
    computed.principal_moments = eigen.eigenvalues();
    computed.principal_axes = eigen.eigenvectors();
    if (computed.principal_axes.determinant() < 0) computed.principal_axes.col(2) *= -1.0;
    const Eigen::Vector3d& c = computed.center_of_mass;
    computed.inertia_origin =
        inertia +
        computed.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
}

void apply_body_rules(const MujocoCompiler& compiler, Computed& computed) {
    if (computed.mass < compiler.boundmass) {
        computed.rules.push_back("boundmass " + readable_number(compiler.boundmass) +
                                 ": the mass raised from " + readable_number(computed.mass));
        computed.density *= compiler.boundmass / computed.mass;
        computed.mass = compiler.boundmass;
    }
    Eigen::Vector3d moments = computed.principal_moments;
    if (moments.minCoeff() < compiler.boundinertia) {
        computed.rules.push_back("boundinertia " + readable_number(compiler.boundinertia) +
                                 ": principal moments raised to it");
        moments = moments.cwiseMax(compiler.boundinertia);
    }
    // Ascending: only a + b >= c can fail.
    if (compiler.balanceinertia && moments[0] + moments[1] < moments[2]) {
        computed.rules.push_back(
            "balanceinertia: A + B < C, each principal moment set to "
            "their mean");
        moments.setConstant(moments.mean());
    }
    if (moments != computed.principal_moments) {
        const Eigen::Matrix3d& axes = computed.principal_axes;
        set_inertia(computed, axes * moments.asDiagonal() * axes.transpose());
    }
}

std::optional<Finding> judge_legacy(const Computed& exact, const Computed& legacy) {
    const double mass = std::abs(legacy.mass - exact.mass) / exact.mass;
    const double moments =
        (legacy.principal_moments - exact.principal_moments).cwiseAbs().maxCoeff() /
        exact.principal_moments.maxCoeff();
    const double size = (exact.box_max - exact.box_min).norm();
    const double offset = (legacy.center_of_mass - exact.center_of_mass).norm() / size;
    if (std::max({mass, moments, offset}) <= kSameFigure) return std::nullopt;
    return Finding{"legacy_mesh_inertia",
                   std::max(mass, moments) > kLegacyWarning ? Severity::kWarning : Severity::kInfo,
                   "MuJoCo's default mesh inertia (legacy) is not this exact figure: mass " +
                       readable_number(legacy.mass) + " (" + percent(mass) +
                       " off), principal "
                       "moments up to " +
                       percent(moments) + " off, centre of mass " + percent(offset) +
                       " of the link's size away; inertia=\"exact\" on the "
                       "<mesh> gives the exact one"};
}

const char* mujoco_uses(const MujocoCompiler& compiler, const LinkAudit& link) {
    using FromGeom = MujocoCompiler::FromGeom;
    const bool from_geom = compiler.inertia_from_geom == FromGeom::kTrue ||
                           (compiler.inertia_from_geom == FromGeom::kAuto && !link.declared);
    // With nothing weighed, MuJoCo keeps the declared inertial, if any.
    if (from_geom && (link.computed || link.unmeasured)) return "computed";
    return link.declared ? "declared" : "none";
}

void apply_model_rules(const Description& description, FileAudit& audit) {
    const MujocoCompiler& compiler = description.compiler;
    for (LinkAudit& link : audit.links) {
        link.mujoco_uses = mujoco_uses(compiler, link);
        if (link.declared && std::string(link.mujoco_uses) == "computed") {
            link.findings.push_back({"inertial_ignored", Severity::kInfo,
                                     "inertiafromgeom=\"true\": MuJoCo ignores this <inertial> "
                                     "and uses the one computed from the geoms"});
        }
    }
    if (compiler.settotalmass > 0) {
        double total = 0.0;
        for (const LinkAudit& link : audit.links) total += body_mass(compiler, link).mass;
        const double factor =
            std::max(kSmallest, compiler.settotalmass / std::max(kSmallest, total));
        for (LinkAudit& link : audit.links) {
            const std::string uses = mujoco_uses(compiler, link);
            if (uses == "computed") {
                for (std::optional<Computed>* figure : {&link.computed, &link.mujoco_legacy}) {
                    if (!*figure) continue;
                    scale(**figure, factor);
                    (*figure)->rules.push_back(
                        "settotalmass " + readable_number(compiler.settotalmass) +
                        ": every body's mass and inertia scaled by " + readable_number(factor));
                }
            } else if (uses == "declared" && factor != 1.0) {
                link.findings.push_back({"scaled_by_settotalmass", Severity::kInfo,
                                         "settotalmass " + readable_number(compiler.settotalmass) +
                                             ": MuJoCo scales this declared mass and inertia by " +
                                             readable_number(factor)});
            }
        }
    }
    Children children(description.links.size());
    for (std::size_t i = 0; i < description.links.size(); ++i) {
        if (description.links[i].parent >= 0) children[description.links[i].parent].push_back(i);
    }
    for (std::size_t i = 0; i < audit.links.size(); ++i) {
        if (description.links[i].moving &&
            !carries_mass(compiler, audit, children, description.links, i)) {
            audit.links[i].findings.push_back(
                {"massless_moving_body", Severity::kError,
                 "a moving body (it has a joint) with no mass and no massive body fixed to it: "
                 "MuJoCo refuses the model (mass and inertia of moving bodies must be larger "
                 "than mjMINVAL); give it an <inertial> or a geom that weighs"});
        }
    }
}

}  // namespace polymass_cli::audit
