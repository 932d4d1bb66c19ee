//! Every supported element type (f64/f32 positions, u32/u16 indices,
//! triangles and polygon faces) reads the same solid to the same result, and
//! positions interleaved with other vertex attributes at any stride read as
//! their packed copy, bit for bit.

mod common;

use common::*;
use polymass::{Body, ErrorKind, MassProperties, Mesh, Options, Positions, Surface};

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
        let p = polymass::mass_properties(&surface, &Options::new(), &Body::default()).unwrap();
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
        let p = polymass::mass_properties(&surface, &Options::new(), &Body::default()).unwrap();
        assert_matches(&p, &exact, what);
    }
}

#[test]
fn a_surface_borrows_vectors_and_arrays_alike() {
    let shape = corner_tetrahedron(1.0, 1.0, 1.0);
    let array: [[f64; 3]; 4] = shape.positions.clone().try_into().unwrap();
    let from_array = Surface::polygons(&array, &shape.indices, &shape.face_sizes);
    let from_vec = shape.surface();
    let a = polymass::mass_properties(&from_array, &Options::new(), &Body::default()).unwrap();
    let b = polymass::mass_properties(&from_vec, &Options::new(), &Body::default()).unwrap();
    assert_eq!(a, b);
}

/// The solid, through the one call and through a mesh (both must agree),
/// with its report and weld, for comparing two ways of reading positions.
fn read_through_every_door(
    positions: Positions<'_>,
    shape: &Shape,
) -> (MassProperties, polymass::Diagnostics, polymass::Weld) {
    let surface = Surface::polygons(positions, &shape.indices, &shape.face_sizes);
    let body = Body::density(2.5);
    let p = polymass::mass_properties(&surface, &Options::new(), &body).unwrap();
    let mesh = Mesh::new(&surface, &Options::new()).unwrap();
    assert_eq!(mesh.mass_properties(&body).unwrap(), p);
    let weld = polymass::weld_positions(positions, 1e-9).unwrap();
    (p, mesh.diagnostics().unwrap(), weld)
}

/// A box turned and moved off the origin: no coordinate is a round number.
fn oblique_box() -> Shape {
    cuboid([0.0; 3], [1.0, 2.0, 3.0])
        .rotated(&oblique_rotation())
        .translated([1e3, -2e3, 5e2])
}

#[test]
fn an_interleaved_f32_vertex_buffer_reads_as_its_packed_copy() {
    let shape = oblique_box();
    let packed = to_f32(&shape.positions);
    // An engine's vertex: normal, position, texture coordinates: 8 f32, 32
    // bytes. The normals are NaN: read, they would refuse the surface.
    let vertices: Vec<[f32; 8]> = packed
        .iter()
        .map(|&[x, y, z]| [f32::NAN, f32::NAN, f32::NAN, x, y, z, 0.25, 0.75])
        .collect();
    let floats = vertices.as_flattened();
    // The same bytes one past an aligned address: positions at odd addresses.
    let mut bytes = vec![0u8];
    bytes.extend(floats.iter().flat_map(|x| x.to_ne_bytes()));

    let expected = read_through_every_door(Positions::packed(&packed), &shape);
    let interleaved = Positions::interleaved(&floats[3..], 8).unwrap();
    let from_bytes = Positions::from_bytes::<f32>(&bytes[1 + 12..], 32, packed.len()).unwrap();
    for (what, positions) in [("interleaved", interleaved), ("bytes", from_bytes)] {
        assert_eq!(positions.len(), packed.len(), "{what}");
        let (p, report, weld) = read_through_every_door(positions, &shape);
        assert_eq!(p, expected.0, "{what}: the mass properties, bit for bit");
        assert_eq!(report, expected.1, "{what}: the report");
        assert_eq!(weld, expected.2, "{what}: the weld");
    }
    // And what it reads is the box, to single precision.
    let exact = rotate_exact(
        &cuboid_exact([0.0; 3], [1.0, 2.0, 3.0]),
        &oblique_rotation(),
    );
    assert!((expected.0.volume - exact.volume).abs() < 1e-4 * exact.volume);
}

#[test]
fn interleaved_f64_positions_read_as_their_packed_copy() {
    let shape = oblique_box();
    // x y z as f64, then an RGBA colour and a u32 id: 32 bytes, then padded
    // to 40 in the buffer.
    let mut bytes = Vec::new();
    for position in &shape.positions {
        bytes.extend(position.iter().flat_map(|x| x.to_ne_bytes()));
        bytes.extend([255u8, 128, 0, 255]);
        bytes.extend(7u32.to_ne_bytes());
        bytes.extend([0u8; 8]);
    }
    let positions = Positions::from_bytes::<f64>(&bytes, 40, shape.positions.len()).unwrap();
    let expected = read_through_every_door(Positions::packed(&shape.positions), &shape);
    assert_eq!(read_through_every_door(positions, &shape), expected);
}

#[test]
fn positions_past_their_data_are_refused_before_the_library_reads_them() {
    let floats = [0.0f32; 16];
    let bytes = [0u8; 64];
    let refused = [
        Positions::interleaved(&floats, 2).unwrap_err(),
        Positions::interleaved(&floats, 0).unwrap_err(),
        // 16 = 7 + 7 + 2: the third vertex lacks its z.
        Positions::interleaved(&floats, 7).unwrap_err(),
        Positions::from_bytes::<f32>(&bytes, 8, 2).unwrap_err(),
        Positions::from_bytes::<f64>(&bytes, 24, 3).unwrap_err(),
        Positions::from_bytes::<f32>(&bytes, usize::MAX, 2).unwrap_err(),
    ];
    for error in refused {
        assert_eq!(error.kind(), ErrorKind::InvalidArgument, "{error}");
        assert!(!error.message().is_empty());
    }
    // Exactly enough: the last vertex needs only its own coordinates.
    assert_eq!(
        Positions::from_bytes::<f64>(&bytes, 40, 2).unwrap().len(),
        2
    );
    assert!(Positions::from_bytes::<f64>(&bytes[..63], 40, 2).is_err());
    assert_eq!(
        Positions::from_bytes::<f64>(&bytes[..63], 39, 2)
            .unwrap()
            .len(),
        2
    );
    assert!(Positions::from_bytes::<f32>(&[], 12, 0).unwrap().is_empty());
    assert_eq!(Positions::interleaved(&floats[..13], 5).unwrap().len(), 3);
    // A face naming a vertex past the positions described is the library's
    // error, as with a packed slice.
    let positions = Positions::interleaved(&floats[..9], 3).unwrap();
    let surface = Surface::triangles(positions, &[[0u32, 1, 3]]);
    let error = polymass::mass_properties(&surface, &Options::new(), &Body::default()).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::IndexOutOfRange, "{error}");
}
