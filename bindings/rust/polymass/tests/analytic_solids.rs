//! Solids with closed-form mass properties: each quantity against its exact
//! value to common::TOLERANCE (1e-12 relative).

mod common;

use common::*;
use polymass::{Body, Options, Surface};

fn compute(shape: &Shape) -> polymass::MassProperties {
    polymass::mass_properties(&shape.surface(), &Options::new(), &Body::default())
        .expect("a valid solid")
}

#[test]
fn unit_cube_has_volume_one_and_a_sixth_on_the_diagonal() {
    let p = compute(&cuboid([0.0; 3], [1.0; 3]));
    assert_matches(&p, &cuboid_exact([0.0; 3], [1.0; 3]), "unit cube");
    assert_close(p.inertia[0][0], 1.0 / 6.0, "Ixx");
}

#[test]
fn boxes_of_unequal_sides_as_quads_and_as_triangles() {
    let (min, max) = ([-1.0, 0.5, 2.0], [2.0, 1.25, 7.0]);
    let shape = cuboid(min, max);
    let exact = cuboid_exact(min, max);
    assert_matches(&compute(&shape), &exact, "box of quads");
    let triangles = shape.triangles();
    let as_triangles = Surface::triangles(&shape.positions, &triangles);
    let p = polymass::mass_properties(&as_triangles, &Options::new(), &Body::default()).unwrap();
    assert_matches(&p, &exact, "box of triangles");
}

#[test]
fn corner_tetrahedra_of_several_proportions() {
    for [a, b, c] in [[1.0, 1.0, 1.0], [1.0, 2.0, 3.0], [0.25, 8.0, 0.5]] {
        let p = compute(&corner_tetrahedron(a, b, c));
        assert_matches(
            &p,
            &corner_tetrahedron_exact(a, b, c),
            &format!("tetrahedron {a} {b} {c}"),
        );
    }
}

#[test]
fn triangular_prisms_mix_triangle_and_quad_faces() {
    for [a, b, h] in [[1.0, 1.0, 1.0], [3.0, 2.0, 5.0], [0.5, 4.0, 0.125]] {
        let p = compute(&triangular_prism(a, b, h));
        assert_matches(
            &p,
            &triangular_prism_exact(a, b, h),
            &format!("prism {a} {b} {h}"),
        );
    }
}

#[test]
fn l_prism_with_non_convex_hexagonal_caps() {
    // The profile (0,0) (4,0) (4,1) (1,1) (1,3) (0,3) extruded to z = 2: the
    // union of two boxes.
    let profile = [
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 1.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [0.0, 3.0],
    ];
    let positions: Vec<[f64; 3]> = [0.0, 2.0]
        .iter()
        .flat_map(|&z| profile.iter().map(move |&[x, y]| [x, y, z]))
        .collect();
    let mut indices = vec![5, 4, 3, 2, 1, 0, 6, 7, 8, 9, 10, 11];
    for i in 0..6u32 {
        let j = (i + 1) % 6;
        indices.extend([i, j, j + 6, i + 6]);
    }
    let shape = Shape {
        positions,
        indices,
        face_sizes: vec![6, 6, 4, 4, 4, 4, 4, 4],
    };
    let foot = cuboid_exact([0.0, 0.0, 0.0], [4.0, 1.0, 2.0]);
    let leg = cuboid_exact([0.0, 1.0, 0.0], [1.0, 3.0, 2.0]);
    // Caps 2 x 6, sides 2 x the perimeter of 14.
    let exact = combine(&foot, &leg, 1.0, 2.0 * 6.0 + 2.0 * 14.0);
    assert_matches(&compute(&shape), &exact, "L prism");
}

#[test]
fn cube_with_a_cubic_cavity_is_the_difference_of_two_cubes() {
    let outer = cuboid([0.0; 3], [2.0; 3]);
    let inner = cuboid([0.25, 0.5, 0.75], [1.25, 1.0, 1.5]);
    let shape = outer.with(&inner.reversed());
    let inner_exact = cuboid_exact([0.25, 0.5, 0.75], [1.25, 1.0, 1.5]);
    let outer_exact = cuboid_exact([0.0; 3], [2.0; 3]);
    let area = outer_exact.surface_area + inner_exact.surface_area;
    let exact = combine(&outer_exact, &inner_exact, -1.0, area);
    assert_matches(&compute(&shape), &exact, "cube with cavity");
}

#[test]
fn two_separate_shells_add_up() {
    let one = cuboid([0.0; 3], [1.0; 3]);
    let other = corner_tetrahedron(1.0, 2.0, 3.0).translated([5.0, 0.0, 0.0]);
    let exact_other = translate_exact(&corner_tetrahedron_exact(1.0, 2.0, 3.0), [5.0, 0.0, 0.0]);
    let exact_one = cuboid_exact([0.0; 3], [1.0; 3]);
    let area = exact_one.surface_area + exact_other.surface_area;
    let exact = combine(&exact_one, &exact_other, 1.0, area);
    assert_matches(&compute(&one.with(&other)), &exact, "two shells");
}

#[test]
fn rotated_box_has_the_rotated_tensor_and_its_own_principal_moments() {
    let (min, max) = ([0.0; 3], [1.0, 2.0, 3.0]);
    let rotation = oblique_rotation();
    let p = compute(&cuboid(min, max).rotated(&rotation));
    let exact = cuboid_exact(min, max);
    assert_matches(&p, &rotate_exact(&exact, &rotation), "rotated box");
    for (i, moment) in p.principal_moments.iter().enumerate() {
        assert_close(
            *moment,
            exact.inertia[2 - i][2 - i],
            &format!("principal moment {i}"),
        );
    }
}

#[test]
fn principal_axes_are_a_rotation_that_diagonalises_the_inertia() {
    let p = compute(&corner_tetrahedron(1.0, 2.0, 3.0));
    let axes = &p.principal_axes;
    assert_close(determinant(axes), 1.0, "det R");
    assert_matrix_close(
        &multiply(&transpose(axes), axes),
        &diagonal([1.0; 3]),
        "RᵀR",
    );
    let rebuilt = multiply(
        &multiply(axes, &diagonal(p.principal_moments)),
        &transpose(axes),
    );
    assert_matrix_close(&rebuilt, &p.inertia, "R diag Rᵀ");
    assert!(p.principal_moments[0] <= p.principal_moments[1]);
    assert!(p.principal_moments[1] <= p.principal_moments[2]);
}

#[test]
fn tiny_and_huge_scales_keep_every_digit() {
    for scale in [1e-30, 1e-6, 1e6, 1e30] {
        let (min, max) = ([0.0; 3], [scale, 2.0 * scale, 3.0 * scale]);
        let p = compute(&cuboid(min, max));
        assert_matches(
            &p,
            &cuboid_exact(min, max),
            &format!("box at scale {scale:e}"),
        );
    }
}
