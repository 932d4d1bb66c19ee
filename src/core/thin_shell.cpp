#include "thin_shell.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace polymass::core {
namespace {

constexpr double u = 0x1p-53;  // unit roundoff
constexpr double pi = 3.14159265358979323846;

// ∫ over a triangle of 1, r and r rᵀ (docs/approximations.md, "The sheet"):
//   A,  A s / 3,  A (Σ pᵢ pᵢᵀ + s sᵀ) / 12,  with s = p0 + p1 + p2,
// accumulated as weights w = 2A times 1, s and Σ pᵢ pᵢᵀ + s sᵀ; the constants
// 2, 6 and 24 are divided out once at the end.
struct SheetSums {
    double twice_area = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();     // × 6
    Eigen::Vector3d squares = Eigen::Vector3d::Zero();   // x², y², z²  × 24
    Eigen::Vector3d products = Eigen::Vector3d::Zero();  // xy, yz, zx  × 24

    void add(double w, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
             const Eigen::Vector3d& p2) {
        const Eigen::Vector3d s = p0 + p1 + p2;
        twice_area += w;
        first += w * s;
        squares += w * (p0.cwiseAbs2() + p1.cwiseAbs2() + p2.cwiseAbs2() + s.cwiseAbs2());
        auto next = [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.y(), p.z(), p.x()); };
        products += w * (p0.cwiseProduct(next(p0)) + p1.cwiseProduct(next(p1)) +
                         p2.cwiseProduct(next(p2)) + s.cwiseProduct(next(s)));
    }

    SheetSums& operator+=(const SheetSums& other) {
        twice_area += other.twice_area;
        first += other.first;
        squares += other.squares;
        products += other.products;
        return *this;
    }
};

// |δ|, also for a δ whose squares would lose digits (a sliver 1e-150 of the
// mesh's size), as in the solid path.
double length(const Eigen::Vector3d& delta) {
    const double squared = delta.squaredNorm();
    return squared < 0x1p-960 ? std::hypot(delta.x(), delta.y(), delta.z()) : std::sqrt(squared);
}

class SheetIntegrator {
public:
    SheetIntegrator(const Eigen::Vector3d& reference, double size)
        : reference_(reference),
          unit_(unit_length_near(size)),
          inverse_unit_(1.0 / unit_),
          size_(size) {}

    // A point in integration units: relative to the reference, over the unit.
    Eigen::Vector3d local(const Eigen::Vector3d& p) const {
        return (p - reference_) * inverse_unit_;
    }

    // One triangle (integration units), its weight signed by `sign`.
    void add_triangle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                      const Eigen::Vector3d& p2, double sign) {
        const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0;
        block_.add(sign * length(e1.cross(e2)), p0, p1, p2);
        extents_squared_ += std::max(e1.squaredNorm(), e2.squaredNorm());
        ++triangles_;
        if (++in_block_ == block_size) flush();
    }

    // The faces' own edges and corners (not a fan's inner diagonals), for the
    // wall bound: caller's units.
    void add_outline(double perimeter, std::size_t corners) {
        perimeter_ += perimeter;
        corners_ += corners;
    }

    ThinShell finish(double thickness) {
        flush();
        const double unit = unit_;
        VolumeIntegrals sheet;  // "volume" is the area here: ∫1 dA
        sheet.volume = total_.twice_area / 2.0;
        sheet.first = total_.first / 6.0;
        sheet.second = total_.squares / 24.0;
        sheet.products = total_.products / 24.0;
        const IntegralBounds bounds = rounding_bounds(sheet.volume);

        // Areas scale as L², first moments L³, second L⁴.
        VolumeIntegrals scaled;
        scaled.volume = times_unit_power(sheet.volume, unit, 2);
        auto times = [unit](int power) {
            return [unit, power](double v) { return times_unit_power(v, unit, power); };
        };
        scaled.first = sheet.first.unaryExpr(times(3));
        scaled.second = sheet.second.unaryExpr(times(4));
        scaled.products = sheet.products.unaryExpr(times(4));
        const IntegralBounds scaled_bounds{times_unit_power(bounds.volume, unit, 2),
                                           times_unit_power(bounds.first, unit, 3),
                                           times_unit_power(bounds.second, unit, 4)};

        ThinShell shell;
        // Area density `thickness`: the sheet's integrals are those of unit
        // density times the thickness, and its volume is its mass.
        shell.moments = Moments::of_solid(scaled, scaled_bounds, reference_, thickness);
        shell.moments.volume = shell.moments.mass.volume;
        shell.moments.volume_bound = shell.moments.mass_bounds.volume;
        shell.area = scaled.volume;
        shell.area_bound = scaled_bounds.volume;
        shell.wall_bound = wall_bound(thickness, shell.area);
        return shell;
    }

private:
    static constexpr std::size_t block_size = 64;

    void flush() {
        total_ += block_;
        block_ = SheetSums();
        in_block_ = 0;
        ++blocks_;
    }

    // docs/approximations.md, "Rounding": in units, for a sheet of area `area`.
    IntegralBounds rounding_bounds(double area) const {
        const double radius = size_ / 2.0 / unit_;
        const double depth = 32.0 + double(block_size) + double(blocks_);
        const double terms = depth * u * extents_squared_ / 2.0;
        // Moving each vertex by ε = √3 u R moves each triangle's edges by 2ε.
        const double epsilon = std::sqrt(3.0) * u * radius;
        const double n = double(triangles_);
        const double area_change =
            2.0 * epsilon * std::sqrt(n * extents_squared_) + 2.0 * n * epsilon * epsilon;
        return {terms + area_change, terms * radius + area_change * radius + area * epsilon,
                terms * radius * radius + area_change * radius * radius +
                    area * epsilon * (2.0 * radius + epsilon)};
    }

    // docs/approximations.md, "The sheet and a real wall".
    ApproximationBound wall_bound(double thickness, double area) const {
        const double h = thickness / 2.0;
        const double joints = 4.0 * pi * h * h * perimeter_ +
                              16.0 * std::sqrt(2.0) / 3.0 * pi * h * h * h * double(corners_);
        ApproximationBound bound =
            bound_of_changed_volume(joints, thickness * area, size_ + thickness);
        bound.inertia += thickness * thickness * thickness * area / 12.0;
        return bound;
    }

    const Eigen::Vector3d reference_;
    const double unit_, inverse_unit_, size_;
    SheetSums block_, total_;
    std::size_t in_block_ = 0, blocks_ = 0, triangles_ = 0, corners_ = 0;
    double extents_squared_ = 0.0;  // Σ max(|E1|², |E2|²), units²
    double perimeter_ = 0.0;        // caller's units
};

}  // namespace

template <class Scalar, class Index>
ThinShell thin_shell_moments(const MeshView<Scalar, Index>& mesh, double thickness,
                             const Eigen::Vector3d& reference, double size) {
    SheetIntegrator sheet(reference, size);
    auto corner = [&](std::size_t position) { return mesh.positions[mesh.indices[position]]; };
    for_each_face(mesh, [&](std::size_t, std::size_t first, std::size_t count) {
        double perimeter = 0.0;
        for (std::size_t i = 0; i < count; ++i)
            perimeter += (corner(first + (i + 1) % count) - corner(first + i)).norm();
        sheet.add_outline(perimeter, count);
        if (count < 3) return;
        const Eigen::Vector3d p0 = sheet.local(corner(first));
        if (count == 3) {
            sheet.add_triangle(p0, sheet.local(corner(first + 1)), sheet.local(corner(first + 2)),
                               1.0);
            return;
        }
        // The fan's triangles, each signed by its turn against the Newell
        // normal: a reflex corner's triangles cover ground outside the face
        // that others cover again, and the signs cancel it.
        Eigen::Vector3d normal = Eigen::Vector3d::Zero();
        for (std::size_t i = 1; i + 1 < count; ++i)
            normal += (sheet.local(corner(first + i)) - p0)
                          .cross(sheet.local(corner(first + i + 1)) - p0);
        for (std::size_t i = 1; i + 1 < count; ++i) {
            const Eigen::Vector3d p1 = sheet.local(corner(first + i));
            const Eigen::Vector3d p2 = sheet.local(corner(first + i + 1));
            const double turn = (p1 - p0).cross(p2 - p0).dot(normal);
            sheet.add_triangle(p0, p1, p2, turn < 0.0 ? -1.0 : 1.0);
        }
    });
    return sheet.finish(thickness);
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                      \
    template ThinShell thin_shell_moments<Scalar, Index>(const MeshView<Scalar, Index>&, double, \
                                                         const Eigen::Vector3d&, double);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
