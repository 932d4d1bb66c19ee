//! Every supported element type (f64/f32 positions, u32/u16 indices,
//! triangles and polygon faces) reads the same solid to the same result.

mod common;

use common::*;
use polymass::{Body, Surface};

fn to_f32(positions: &[[f64; 3]]) -> Vec<[f32; 3]> {
    positions.iter().map(|p| p.map(|x| x as f32)).collect()
}

fn to_u16<const N: usize>(items: &[[u32; N]]) -> Vec<[u16; N]> {
    items
        .iter()
        .map(|item| item.map(|i| u16::try_from(i).unwrap()))
        .collect()
}

#[test]
fn triangles_of_every_position_and_index_type() {
    // Dyadic coordinates: exact in f32 too.
    let (min, max) = ([-0.5, 1.0, 2.0], [1.5, 1.25, 6.0]);
    let shape = cuboid(min, max);
    let exact = cuboid_exact(min, max);
    let positions32 = to_f32(&shape.positions);
    let triangles = shape.triangles();
    let triangles16 = to_u16(&triangles);
    let surfaces = [
        ("f64/u32", Surface::triangles(&shape.positions, &triangles)),
        (
            "f64/u16",
            Surface::triangles(&shape.positions, &triangles16),
        ),
        ("f32/u32", Surface::triangles(&positions32, &triangles)),
        ("f32/u16", Surface::triangles(&positions32, &triangles16)),
    ];
    for (what, surface) in surfaces {
        assert_eq!(surface.face_count(), 12);
        let p = polymass::mass_properties(&surface, &Body::default()).unwrap();
        assert_matches(&p, &exact, what);
    }
}

#[test]
fn polygon_faces_of_every_position_and_index_type() {
    let shape = triangular_prism(3.0, 2.0, 5.0);
    let exact = triangular_prism_exact(3.0, 2.0, 5.0);
    let positions32 = to_f32(&shape.positions);
    let indices16: Vec<u16> = shape.indices.iter().map(|&i| i as u16).collect();
    let sizes = &shape.face_sizes;
    let surfaces = [
        (
            "f64/u32",
            Surface::polygons(&shape.positions, &shape.indices, sizes),
        ),
        (
            "f64/u16",
            Surface::polygons(&shape.positions, &indices16, sizes),
        ),
        (
            "f32/u32",
            Surface::polygons(&positions32, &shape.indices, sizes),
        ),
        (
            "f32/u16",
            Surface::polygons(&positions32, &indices16, sizes),
        ),
    ];
    for (what, surface) in surfaces {
        assert_eq!(surface.face_count(), 5);
        let p = polymass::mass_properties(&surface, &Body::default()).unwrap();
        assert_matches(&p, &exact, what);
    }
}

#[test]
fn a_surface_borrows_vectors_and_arrays_alike() {
    let shape = corner_tetrahedron(1.0, 1.0, 1.0);
    let array: [[f64; 3]; 4] = shape.positions.clone().try_into().unwrap();
    let from_array = Surface::polygons(&array, &shape.indices, &shape.face_sizes);
    let from_vec = shape.surface();
    let a = polymass::mass_properties(&from_array, &Body::default()).unwrap();
    let b = polymass::mass_properties(&from_vec, &Body::default()).unwrap();
    assert_eq!(a, b);
}
