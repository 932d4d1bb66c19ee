//! Moments that compose: parts added (also 1e8 apart), a bore subtracted,
//! parts moved, weighted and split into face ranges, against closed forms.

mod common;

use common::*;
use polymass::{Body, Context, ErrorKind, Mesh, Moments, Options};

/// The moments of a shape's solid, from one analysis with the defaults.
fn moments(shape: &Shape) -> Moments {
    Mesh::new(&shape.surface(), &Options::new())
        .unwrap()
        .moments()
        .unwrap()
}

const IDENTITY: Matrix = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

fn assert_body(p: &polymass::MassProperties, exact: &Exact, what: &str) {
    assert_close(p.volume, exact.volume, &format!("{what}: volume"));
    let scale = exact
        .center_of_mass
        .iter()
        .fold(exact.size, |m, x| m.max(x.abs()));
    for axis in 0..3 {
        let error = (p.center_of_mass[axis] - exact.center_of_mass[axis]).abs();
        assert!(error <= TOLERANCE * scale, "{what}: centre of mass {axis}");
    }
    assert_matrix_close(&p.inertia, &exact.inertia, &format!("{what}: inertia"));
    assert!(p.surface_area.is_nan(), "moments keep no surface");
}

#[test]
fn parts_add_up_far_from_the_origin() {
    for offset in [[3.0, 0.0, 0.0], [1e6, 1e6, 0.0], [1e8, -1e8, 1e8]] {
        let block = cuboid([0.0; 3], [2.0, 1.0, 0.5]);
        let tetra = corner_tetrahedron(1.0, 2.0, 0.75).translated(offset);
        let sum = (moments(&block) + moments(&tetra)).unwrap();
        let exact = combine(
            &cuboid_exact([0.0; 3], [2.0, 1.0, 0.5]),
            &translate_exact(&corner_tetrahedron_exact(1.0, 2.0, 0.75), offset),
            1.0,
            f64::NAN,
        );
        assert_body(
            &sum.mass_properties(None).unwrap(),
            &exact,
            &format!("{offset:?}"),
        );
    }
}

#[test]
fn bore_removed_from_block() {
    let block = moments(&cuboid([0.0; 3], [4.0, 2.0, 2.0]));
    let bore = moments(&cuboid([1.0, 0.5, 0.0], [2.0, 1.5, 2.0]));
    let exact = combine(
        &cuboid_exact([0.0; 3], [4.0, 2.0, 2.0]),
        &cuboid_exact([1.0, 0.5, 0.0], [2.0, 1.5, 2.0]),
        -1.0,
        f64::NAN,
    );
    let p = (block - bore).unwrap().mass_properties(None).unwrap();
    assert_body(&p, &exact, "block minus bore");
    let inside_out = (bore - block).unwrap();
    assert_eq!(
        inside_out.mass_properties(None).unwrap_err().kind(),
        ErrorKind::ZeroVolume
    );
}

#[test]
fn moved_moments_are_the_moved_solid() {
    let rotation = oblique_rotation();
    let shape = triangular_prism(1.5, 0.75, 2.0);
    let exact = triangular_prism_exact(1.5, 0.75, 2.0);
    for offset in [[0.0; 3], [1e6, 0.0, -1e6], [1e8, 1e8, 1e8]] {
        let moved = moments(&shape).transformed(&rotation, offset).unwrap();
        let expected = translate_exact(&rotate_exact(&exact, &rotation), offset);
        assert_body(
            &moved.mass_properties(None).unwrap(),
            &expected,
            &format!("rotated, to {offset:?}"),
        );
    }
    let mirror = [[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mirrored = moments(&shape).transformed(&mirror, [0.0; 3]).unwrap();
    assert_body(
        &mirrored.mass_properties(None).unwrap(),
        &rotate_exact(&exact, &mirror),
        "mirrored: positive volume",
    );
    let not_a_rotation = [[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    assert!(mirrored.transformed(&not_a_rotation, [0.0; 3]).is_err());
}

#[test]
fn weighted_parts_and_sums_chain() {
    let a = moments(&cuboid([0.0; 3], [1.0; 3]));
    let b = a.transformed(&IDENTITY, [2.0, 0.0, 0.0]).unwrap();
    let c = a.transformed(&IDENTITY, [4.0, 0.0, 0.0]).unwrap();
    let total =
        (a.weighted(&Body::density(2.0)).unwrap() + b + c.weighted(&Body::mass(5.0)).unwrap())
            .unwrap();
    let p = total.mass_properties(None).unwrap();
    assert_close(p.mass, 8.0, "mass");
    assert_close(p.volume, 3.0, "volume");
    assert_close(
        p.center_of_mass[0],
        (2.0 * 0.5 + 2.5 + 5.0 * 4.5) / 8.0,
        "centre",
    );
    let uniform = total.mass_properties(Some(&Body::density(1.0))).unwrap();
    assert_close(uniform.mass, 3.0, "mean density 1");
    let doubled = total.scaled([2.0, 2.0, 2.0]).unwrap();
    assert_close(doubled.volume(), 24.0, "scaled volume");
}

#[test]
fn face_ranges_add_up() {
    let shape = corner_tetrahedron(1.0, 2.0, 0.75).translated([1e6, 0.0, 0.0]);
    let surface = shape.surface();
    let mut context = Context::new().unwrap();
    let whole = context
        .mesh(&surface, &Options::new())
        .unwrap()
        .moments()
        .unwrap();
    let at = whole.reference();
    let options = Options::new();
    let first = context
        .moments_of_faces(&surface, 0..2, at, &options)
        .unwrap();
    let rest = context
        .moments_of_faces(&surface, 2..4, at, &options)
        .unwrap();
    let sum = (first + rest).unwrap();
    assert!(sum.is_partial());
    assert!(sum.mass_properties(None).is_err());
    let p = sum.completed().mass_properties(None).unwrap();
    let q = whole.mass_properties(None).unwrap();
    assert_close(p.volume, q.volume, "volume");
    assert_matrix_close(&p.inertia, &q.inertia, "inertia");
    let elsewhere = whole.transformed(&IDENTITY, [1.0, 0.0, 0.0]).unwrap();
    assert!(
        (first + elsewhere).is_err(),
        "a range adds only to moments about its own reference point"
    );
}
