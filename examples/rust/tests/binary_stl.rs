//! The examples' binary STL reader: what it reads, what it refuses, and the
//! carried data/l_bracket.stl against the bracket's exact mass properties.

use polymass::{Body, Options, Surface};
use polymass_examples::binary_stl::{self, StlError};

/// A binary STL of the given triangles (zero normals, as many exporters write).
fn stl_bytes(triangles: &[[[f32; 3]; 3]]) -> Vec<u8> {
    let mut bytes = vec![b' '; 80];
    bytes.extend((triangles.len() as u32).to_le_bytes());
    for triangle in triangles {
        bytes.extend([0u8; 12]);
        for coordinate in triangle.iter().flatten() {
            bytes.extend(coordinate.to_le_bytes());
        }
        bytes.extend([0u8; 2]);
    }
    bytes
}

const TETRAHEDRON: [[[f32; 3]; 3]; 4] = [
    [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
    [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
    [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
];

#[test]
fn reads_every_vertex_in_file_order() {
    let soup = binary_stl::parse(&stl_bytes(&TETRAHEDRON)).unwrap();
    let expected: Vec<[f32; 3]> = TETRAHEDRON.iter().flatten().copied().collect();
    assert_eq!(soup.positions, expected);
    assert_eq!(
        soup.triangles,
        vec![[0, 1, 2], [3, 4, 5], [6, 7, 8], [9, 10, 11]]
    );
}

#[test]
fn a_welded_soup_is_the_solid() {
    let soup = binary_stl::parse(&stl_bytes(&TETRAHEDRON)).unwrap();
    let surface = Surface::triangles(&soup.positions, &soup.triangles);
    let welding = Options::new().weld_vertices(true);
    let p = polymass::mass_properties(&surface, &welding, &Body::default()).unwrap();
    assert!((p.volume - 1.0 / 6.0).abs() <= 1e-15);
}

#[test]
fn refuses_short_ascii_and_truncated_files() {
    assert_eq!(binary_stl::parse(&[0; 83]), Err(StlError::TooShort(83)));
    let ascii =
        b"solid cube\n  facet normal 0 0 -1\n    outer loop\n      vertex 0 0 0\n".repeat(3);
    assert!(matches!(
        binary_stl::parse(&ascii),
        Err(StlError::SizeMismatch { .. })
    ));
    let mut truncated = stl_bytes(&TETRAHEDRON);
    truncated.pop();
    let error = binary_stl::parse(&truncated).unwrap_err();
    assert_eq!(
        error,
        StlError::SizeMismatch {
            declared: 4,
            bytes: 283
        }
    );
    assert!(
        error.to_string().contains("4 triangles take 284"),
        "{error}"
    );
}

#[test]
fn the_bundled_robot_link_has_its_exact_properties() {
    let bytes = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../data/robot_link.stl"
    ))
    .unwrap();
    let soup = binary_stl::parse(&bytes).unwrap();
    assert_eq!(soup.triangles.len(), 28);
    let surface = Surface::triangles(&soup.positions, &soup.triangles);
    let welding = Options::new().weld_vertices(true);
    let p = polymass::mass_properties(&surface, &welding, &Body::default()).unwrap();
    // Exact values from examples/data/generate.py (rational arithmetic), in mm.
    let volume = 143360.0;
    let centre = [80.0, 0.0, 20.0];
    let inertia = [
        [39649280.0, 0.0, -229376000.0 / 3.0],
        [0.0, 335216640.0, 0.0],
        [-229376000.0 / 3.0, 0.0, 948305920.0 / 3.0],
    ];
    assert!((p.volume - volume).abs() <= 1e-12 * volume);
    for (actual, expected) in p.center_of_mass.iter().zip(centre) {
        assert!(
            (actual - expected).abs() <= 1e-12 * 160.0,
            "{actual} vs {expected}"
        );
    }
    for (row, expected_row) in p.inertia.iter().zip(inertia) {
        for (actual, expected) in row.iter().zip(expected_row) {
            assert!(
                (actual - expected).abs() <= 1e-12 * 335216640.0,
                "{actual} vs {expected}"
            );
        }
    }
}
