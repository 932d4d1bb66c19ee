// The ten volume integrals of a solid and the surface sums they come from.
//
// The divergence theorem turns each volume integral into a sum over faces of
// "flux" integrals n_axis * integral over the face of a polynomial (docs/integrals.md,
// section 1). Both face paths — the closed-form triangle and the projected
// polygon — produce these same ten face sums, and this file alone turns them
// into volume integrals.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace polymass::core {

// Sums over faces of n_axis * integral_face(P) dS, with n the unit outward
// normal, for the polynomials the divergence theorem needs:
//   x                                   -> volume
//   x², y², z²  (n_x, n_y, n_z)         -> first moments
//   x³, y³, z³  (n_x, n_y, n_z)         -> second moments
//   x²y, y²z, z²x (n_x, n_y, n_z)       -> products xy, yz, zx
struct FaceSums {
    double x = 0.0;
    Eigen::Vector3d squares = Eigen::Vector3d::Zero();
    Eigen::Vector3d cubes = Eigen::Vector3d::Zero();
    Eigen::Vector3d mixed = Eigen::Vector3d::Zero();

    FaceSums& operator+=(const FaceSums& other) {
        x += other.x;
        squares += other.squares;
        cubes += other.cubes;
        mixed += other.mixed;
        return *this;
    }
};

// Integrals over the solid of 1, x, y, z, x², y², z², xy, yz, zx, in the frame
// in which the faces were given (for this library: relative to a reference point).
struct VolumeIntegrals {
    double volume = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();     // ∫x, ∫y, ∫z
    Eigen::Vector3d second = Eigen::Vector3d::Zero();    // ∫x², ∫y², ∫z²
    Eigen::Vector3d products = Eigen::Vector3d::Zero();  // ∫xy, ∫yz, ∫zx

    VolumeIntegrals negated() const { return {-volume, -first, -second, -products}; }

    // The integrals of the solid measured in `unit` (a power of two; dimensions
    // L³, L⁴, L⁵) in the caller's unit.
    VolumeIntegrals scaled(double unit) const;
};

// Absolute bounds on the rounding errors of a VolumeIntegrals (docs/error_bound.md):
// of its volume, of each first moment, of each second moment and product.
struct IntegralBounds {
    double volume = 0.0;
    double first = 0.0;
    double second = 0.0;

    // The bounds of VolumeIntegrals::scaled(unit) (exact powers of two).
    IntegralBounds scaled(double unit) const;
};

// A power of two near `length`: coordinates divided by it keep every bit and
// are of order one, so no intermediate product (up to the sixth power of a
// coordinate) overflows or underflows for any mesh whose results fit. Never
// below the smallest normal power of two, 2^-1022: callers multiply by the
// inverse, and that of a subnormal unit overflows to infinity (NaN boxes in
// the intersection check, a tiny mesh's integrals taken as overflowing).
// Coordinates of a subnormal mesh are then far below one in units, which
// loses nothing: no result of such a mesh fits a double anyway.
inline double unit_length_near(double length) {
    if (!(length > 0) || !std::isfinite(length)) return 1.0;
    return std::ldexp(1.0,
                      std::max(std::ilogb(length), std::numeric_limits<double>::min_exponent - 1));
}

// value · unit^power for a power-of-two unit, exactly and with no
// intermediate overflow (unit^5 alone may not fit where the product does).
inline double times_unit_power(double value, double unit, int power) {
    return std::ldexp(value, power * std::ilogb(unit));
}

inline VolumeIntegrals VolumeIntegrals::scaled(double unit) const {
    auto times = [unit](int power) {
        return [unit, power](double value) { return times_unit_power(value, unit, power); };
    };
    return {times_unit_power(volume, unit, 3), first.unaryExpr(times(4)),
            second.unaryExpr(times(5)), products.unaryExpr(times(5))};
}

inline IntegralBounds IntegralBounds::scaled(double unit) const {
    return {times_unit_power(volume, unit, 3), times_unit_power(first, unit, 4),
            times_unit_power(second, unit, 5)};
}

// Divergence theorem with F = (x, 0, 0), (x²/2, 0, 0), (x³/3, 0, 0), (x²y/2, 0, 0)
// and their cyclic counterparts.
inline VolumeIntegrals volume_integrals_from(const FaceSums& sums) {
    return {sums.x, sums.squares / 2.0, sums.cubes / 3.0, sums.mixed / 2.0};
}

}  // namespace polymass::core

namespace polymass::core {

// A face whose area is at rounding level for its extent has no orientation to
// speak of: it is reported as degenerate, and its terms are at rounding level.
// twice_area is |E1 × E2| (or the Newell vector's length); extent_squared
// bounds |E1|·|E2| from above. (The triangle batch applies the same ratio a
// lane group at a time.)
constexpr double degenerate_area_ratio = 32.0 * 2.220446049250313e-16;

inline bool is_degenerate_face(double twice_area, double extent_squared) {
    return twice_area <= degenerate_area_ratio * extent_squared;
}

}  // namespace polymass::core
