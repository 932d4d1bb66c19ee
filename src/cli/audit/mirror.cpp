#include "audit/mirror.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <vector>

#include "reports/number_format.hpp"

namespace polymass_cli::audit {
namespace {

// Geometries are mirror images when the reflected inertial matches to this
// (relative to the tensor's and the link's size, and to the mass).
constexpr double kMirrorTolerance = 1e-3;
// A declared product counts when it is at least this fraction of the
// largest moment; it breaks the mirror when it is the mirrored one's
// negative to within kSameSize of its size.
constexpr double kSignificant = 1e-3;
constexpr double kSameSize = 0.1;

const char* const kProductNames[] = {"ixy", "ixz", "iyz"};
const std::array<std::array<int, 2>, 3> kProducts{{{0, 1}, {0, 2}, {1, 2}}};

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// The side a token marks, and the token with it taken out.
std::optional<Sided> sided_token(const std::string& token) {
    const std::string word = lower(token);
    if (word == "left" || word == "l") return Sided{"{side}", 'L'};
    if (word == "right" || word == "r") return Sided{"{side}", 'R'};
    const bool upper = token.size() == 2 && std::isupper(static_cast<unsigned char>(token[0])) &&
                       std::isupper(static_cast<unsigned char>(token[1]));
    if (!upper) return std::nullopt;
    // LF, RH, ...: side, then front / hind / middle / back.
    if ((token[0] == 'L' || token[0] == 'R') &&
        std::string("FHMB").find(token[1]) != std::string::npos) {
        return Sided{std::string("{side}") + token[1], token[0]};
    }
    // FL, RR, ...: front / rear / hind / middle / back, then side.
    if ((token[1] == 'L' || token[1] == 'R') &&
        std::string("FRHMB").find(token[0]) != std::string::npos) {
        return Sided{token.substr(0, 1) + "{side}", token[1]};
    }
    return std::nullopt;
}

Eigen::Matrix3d reflection(int axis) {
    Eigen::Matrix3d s = Eigen::Matrix3d::Identity();
    s(axis, axis) = -1.0;
    return s;
}

// The axes whose reflection maps the left link's computed inertial onto the
// right one's.
std::vector<int> mirror_axes(const Computed& left, const Computed& right) {
    std::vector<int> axes;
    const double size = std::max((left.box_max - left.box_min).norm(), 1e-300);
    if (std::abs(left.mass - right.mass) > kMirrorTolerance * right.mass) return axes;
    for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Matrix3d s = reflection(axis);
        if ((s * left.inertia * s - right.inertia).norm() <=
                kMirrorTolerance * right.inertia.norm() &&
            (s * left.center_of_mass - right.center_of_mass).norm() <= kMirrorTolerance * size) {
            axes.push_back(axis);
        }
    }
    return axes;
}

double product(const Eigen::Matrix3d& tensor, int p) {
    return tensor(kProducts[p][0], kProducts[p][1]);
}

// The link of the pair whose declared product has the sign its own
// geometry's does not (nullptr: neither, or both).
LinkAudit* culprit(LinkAudit& left, LinkAudit& right, int p) {
    const auto wrong = [p](const LinkAudit& link) {
        const double declared = product(link.declared->inertia, p);
        const double computed = product(link.computed->inertia, p);
        return declared * computed < 0.0;
    };
    if (wrong(left) != wrong(right)) return wrong(left) ? &left : &right;
    return nullptr;
}

void judge_pair(LinkAudit& left, LinkAudit& right) {
    if (!left.declared || !right.declared || !left.computed || !right.computed) return;
    const std::vector<int> axes = mirror_axes(*left.computed, *right.computed);
    if (axes.empty()) return;
    const double scale = std::max(left.declared->inertia.diagonal().cwiseAbs().maxCoeff(),
                                  right.declared->inertia.diagonal().cwiseAbs().maxCoeff());
    for (int p = 0; p < 3; ++p) {
        // The sign the mirror gives the product, if every matching
        // reflection gives the same one.
        double mirrored = 0.0;
        bool determined = true;
        for (const int axis : axes) {
            const Eigen::Matrix3d s = reflection(axis);
            const double value = product(s * left.declared->inertia * s, p);
            if (mirrored != 0.0 && value * mirrored < 0.0) determined = false;
            mirrored = value;
        }
        const double declared = product(right.declared->inertia, p);
        if (!determined || std::abs(mirrored) < kSignificant * scale ||
            std::abs(declared + mirrored) > kSameSize * std::abs(declared)) {
            continue;
        }
        LinkAudit* wrong = culprit(left, right, p);
        const std::string message =
            std::string(kProductNames[p]) + " of '" + left.name + "' (" +
            readable_number(product(left.declared->inertia, p)) + ") and '" + right.name + "' (" +
            readable_number(declared) +
            ") have the signs of one link twice, though their geometries are mirror images "
            "(reflected across the link frame's " +
            std::string(1, "xyz"[axes.front()]) + " axis)" +
            (wrong != nullptr ? ": '" + wrong->name + "' has the sign its geometry does not" : "");
        LinkAudit& target = wrong != nullptr ? *wrong : right;
        target.findings.push_back(
            {"mirror_sign", wrong != nullptr ? Severity::kError : Severity::kWarning, message});
    }
}

}  // namespace

std::optional<Sided> sided_name(const std::string& name) {
    std::optional<Sided> found;
    std::string key;
    std::string::size_type start = 0;
    while (start <= name.size()) {
        const std::string::size_type end = std::min(name.find_first_of("_-. ", start), name.size());
        const std::string token = name.substr(start, end - start);
        if (const std::optional<Sided> sided = sided_token(token)) {
            if (found) return std::nullopt;  // two sides: no pair
            found = Sided{"", sided->side};
            key += sided->key;
        } else {
            key += token;
        }
        if (end < name.size()) key += name[end];
        start = end + 1;
    }
    if (found) found->key = key;
    return found;
}

void judge_mirror_pairs(FileAudit& audit) {
    std::map<std::string, std::array<std::vector<LinkAudit*>, 2>> sides;
    for (LinkAudit& link : audit.links) {
        if (const std::optional<Sided> sided = sided_name(link.name)) {
            sides[sided->key][sided->side == 'L' ? 0 : 1].push_back(&link);
        }
    }
    for (auto& [key, pair] : sides) {
        if (pair[0].size() == 1 && pair[1].size() == 1) judge_pair(*pair[0][0], *pair[1][0]);
    }
}

}  // namespace polymass_cli::audit
