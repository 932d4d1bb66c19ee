//! Parts far from the origin (1e6 and 1e8 away) keep their digits: the
//! centre-of-mass frame tensor matches the exact one to common::TOLERANCE
//! (1e-12 relative), which integrating about the origin would miss by orders
//! of magnitude.

mod common;

use common::*;
use polymass::{Body, Options};

const OFFSETS: [[f64; 3]; 4] = [
    [1e6, 1e6, 1e6],
    [-1e6, 2e6, 0.0],
    [1e8, 1e8, 1e8],
    [1e8, -1e8, 3e8],
];

fn check_far(shape: &Shape, exact: &Exact, what: &str) {
    for offset in OFFSETS {
        let p = polymass::mass_properties(
            &shape.translated(offset).surface(),
            &Options::new(),
            &Body::default(),
        )
        .unwrap();
        assert_matches(
            &p,
            &translate_exact(exact, offset),
            &format!("{what} at {offset:?}"),
        );
    }
}

#[test]
fn unit_cube_far_away() {
    check_far(
        &cuboid([0.0; 3], [1.0; 3]),
        &cuboid_exact([0.0; 3], [1.0; 3]),
        "cube",
    );
}

#[test]
fn tetrahedron_far_away() {
    let exact = corner_tetrahedron_exact(1.0, 2.0, 3.0);
    check_far(&corner_tetrahedron(1.0, 2.0, 3.0), &exact, "tetrahedron");
}

#[test]
fn prism_far_away() {
    let exact = triangular_prism_exact(3.0, 2.0, 5.0);
    check_far(&triangular_prism(3.0, 2.0, 5.0), &exact, "prism");
}

#[test]
fn cube_with_cavity_far_away() {
    let outer = cuboid_exact([0.0; 3], [2.0; 3]);
    let inner = cuboid_exact([0.25, 0.5, 0.75], [1.25, 1.0, 1.5]);
    let exact = combine(
        &outer,
        &inner,
        -1.0,
        outer.surface_area + inner.surface_area,
    );
    let shape =
        cuboid([0.0; 3], [2.0; 3]).with(&cuboid([0.25, 0.5, 0.75], [1.25, 1.0, 1.5]).reversed());
    check_far(&shape, &exact, "cube with cavity");
}

#[test]
fn inertia_about_the_origin_follows_the_parallel_axis_theorem() {
    // About the origin the tensor is dominated by m|d|²: compared relative to
    // its own size, it is as exact as the rest.
    let exact = cuboid_exact([0.0; 3], [1.0; 3]);
    let offset = [1e6, 2e6, 3e6];
    let p = polymass::mass_properties(
        &cuboid([0.0; 3], [1.0; 3]).translated(offset).surface(),
        &Options::new(),
        &Body::default(),
    )
    .unwrap();
    let com = translate_exact(&exact, offset).center_of_mass;
    let expected = add(&exact.inertia, &parallel_axis(exact.volume, &com), 1.0);
    assert_matrix_close(&p.inertia_origin, &expected, "inertia about the origin");
}
