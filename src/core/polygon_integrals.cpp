#include "polygon_integrals.hpp"

namespace polymass::core {

// Mirtich's face integrals: on the plane, c = −(n_a a + n_b b + w) / n_c and
// dS = da db / |n_c|. Dividing by the signed n_c (not |n_c|) also undoes the
// orientation the projection gave the polygon. Each expression is the region
// integral of the lifted polynomial, expanded (docs/integrals.md, section 2).
FaceSums lift_projection(const FacePlane& plane, int c, const ProjectionIntegrals& p) {
    const int a = (c + 1) % 3, b = (a + 1) % 3;
    const Eigen::Vector3d& n = plane.normal;
    const double na = n[a], nb = n[b], nc = n[c];
    const double w = -n.dot(plane.centroid);
    const double k1 = 1.0 / nc, k2 = k1 * k1, k3 = k2 * k1, k4 = k3 * k1;

    // ∫ of the projected linear form L = n_a a + n_b b and its powers, with w.
    const double linear = na * p.a + nb * p.b;
    const double quadratic = na * na * p.aa + 2.0 * na * nb * p.ab + nb * nb * p.bb;
    const double cubic = na * na * na * p.aaa + 3.0 * na * na * nb * p.aab +
                         3.0 * na * nb * nb * p.abb + nb * nb * nb * p.bbb;

    const double fa = k1 * p.a;
    const double fb = k1 * p.b;
    const double fc = -k2 * (linear + w * p.one);
    const double faa = k1 * p.aa;
    const double fbb = k1 * p.bb;
    const double fcc = k3 * (quadratic + w * (2.0 * linear + w * p.one));
    const double faaa = k1 * p.aaa;
    const double fbbb = k1 * p.bbb;
    const double fccc = -k4 * (cubic + 3.0 * w * quadratic + w * w * (3.0 * linear + w * p.one));
    const double faab = k1 * p.aab;
    const double fbbc = -k2 * (na * p.abb + nb * p.bbb + w * p.bb);
    const double fcca = k3 * (na * na * p.aaa + 2.0 * na * nb * p.aab + nb * nb * p.abb +
                              w * (2.0 * (na * p.aa + nb * p.ab) + w * p.a));

    FaceSums sums;
    sums.x = n.x() * (a == 0 ? fa : (b == 0 ? fb : fc));
    sums.squares[a] = na * faa;
    sums.squares[b] = nb * fbb;
    sums.squares[c] = nc * fcc;
    sums.cubes[a] = na * faaa;
    sums.cubes[b] = nb * fbbb;
    sums.cubes[c] = nc * fccc;
    sums.mixed[a] = na * faab;  // n_a ∫a²b
    sums.mixed[b] = nb * fbbc;  // n_b ∫b²c
    sums.mixed[c] = nc * fcca;  // n_c ∫c²a
    return sums;
}

}  // namespace polymass::core
