//! The error bound of every result contains its actual error, against closed
//! forms, near the origin and far from it.

mod common;

use common::*;
use polymass::{Body, Options};

#[test]
fn bounds_contain_the_error() {
    let cases = [
        (
            cuboid([0.0; 3], [2.0, 1.0, 0.5]),
            cuboid_exact([0.0; 3], [2.0, 1.0, 0.5]),
        ),
        (
            corner_tetrahedron(1.0, 2.0, 0.75),
            corner_tetrahedron_exact(1.0, 2.0, 0.75),
        ),
        (
            triangular_prism(1.5, 0.75, 2.0),
            triangular_prism_exact(1.5, 0.75, 2.0),
        ),
    ];
    for (shape, exact) in &cases {
        for offset in [[0.0; 3], [1e6, -1e6, 1e6], [1e8, 1e8, -1e8]] {
            let p = polymass::mass_properties(
                &shape.translated(offset).surface(),
                &Options::new(),
                &Body::default(),
            )
            .unwrap();
            let e = translate_exact(exact, offset);
            let bound = p.error_bound;
            // The closed forms are rounded: half an ulp of slack.
            let within = |got: f64, want: f64, bound: f64| {
                (got - want).abs() <= bound + 0.5 * f64::EPSILON * want.abs()
            };
            assert!(
                within(p.volume, e.volume, bound.volume),
                "volume at {offset:?}"
            );
            for axis in 0..3 {
                assert!(
                    within(
                        p.center_of_mass[axis],
                        e.center_of_mass[axis],
                        bound.center_of_mass
                    ),
                    "centre of mass at {offset:?}"
                );
            }
            for i in 0..3 {
                for j in 0..3 {
                    assert!(
                        within(p.inertia[i][j], e.inertia[i][j], bound.inertia),
                        "inertia[{i}][{j}] at {offset:?}"
                    );
                }
            }
            assert!(bound.volume > 0.0 && bound.volume < 1e-9 * p.volume);
        }
    }
}
