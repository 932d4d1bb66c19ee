//! The modes through the Rust front door: repair within its bound, the hull
//! where repair gives up, a thin wall, valid solids unchanged.

use polymass::{Body, ErrorKind, Mesh, Mode, Options, Surface, Warnings};

const OCTAHEDRON: [[f64; 3]; 6] = [
    [1.0, 0.0, 0.0],
    [-1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, -1.0, 0.0],
    [0.0, 0.0, 1.0],
    [0.0, 0.0, -1.0],
];
const FACES: [[u32; 3]; 8] = [
    [0, 2, 4],
    [2, 1, 4],
    [1, 3, 4],
    [3, 0, 4],
    [2, 0, 5],
    [1, 2, 5],
    [3, 1, 5],
    [0, 3, 5],
];

#[test]
fn flipped_and_missing_faces_are_repaired_within_the_bound() {
    let exact = polymass::mass_properties(
        &Surface::triangles(&OCTAHEDRON, &FACES),
        &Options::new(),
        &Body::default(),
    )
    .unwrap();
    let mut damaged: Vec<[u32; 3]> = FACES[1..].to_vec();
    damaged[2].swap(1, 2);
    let surface = Surface::triangles(&OCTAHEDRON, &damaged);
    let mesh = Mesh::new(&surface, &Options::new().repair(true)).unwrap();
    let (p, provenance) = (
        mesh.mass_properties(&Body::density(2.0)).unwrap(),
        mesh.provenance().unwrap(),
    );
    // The one call gives the same answer.
    let one_call =
        polymass::mass_properties(&surface, &Options::new().repair(true), &Body::density(2.0));
    assert_eq!(one_call.unwrap(), p);
    // What is wrong with the surface itself, whatever answered, in words.
    let defect = mesh.diagnostics().unwrap().error.unwrap();
    assert!(!defect.message().is_empty(), "{defect}");
    assert!(mesh.status().is_ok());
    assert_eq!(provenance.mode, Mode::Repair);
    assert_eq!(provenance.holes.count, 1);
    assert_eq!(provenance.reoriented_faces.count, 1);
    assert_eq!(provenance.reoriented_faces.first, vec![2]);
    assert!(p.warnings.contains(Warnings::REPAIRED));
    // A planar cap over a missing planar face is exact.
    assert!((p.volume - exact.volume).abs() <= p.error_bound.volume);
    assert!((p.mass - 2.0 * exact.volume).abs() <= 2.0 * p.error_bound.volume);
    for axis in 0..3 {
        assert!(
            (p.center_of_mass[axis] - exact.center_of_mass[axis]).abs()
                <= p.error_bound.center_of_mass
        );
    }
}

#[test]
fn a_valid_solid_is_answered_as_without_modes() {
    let surface = Surface::triangles(&OCTAHEDRON, &FACES);
    let exact = polymass::mass_properties(&surface, &Options::new(), &Body::default()).unwrap();
    let options = Options::new().fallback(&[Mode::Repair, Mode::Hull]);
    assert_eq!(options.modes(), vec![Mode::Solid, Mode::Repair, Mode::Hull]);
    let mesh = Mesh::new(&surface, &options).unwrap();
    assert_eq!(mesh.provenance().unwrap().mode, Mode::Solid);
    assert_eq!(mesh.mass_properties(&Body::default()).unwrap(), exact);
}

#[test]
fn a_shell_is_a_thin_wall() {
    // The octahedron's surface, open at one face: area 7 (√3 / 2) · 2.
    let open = &FACES[1..];
    let mesh = Mesh::new(
        &Surface::triangles(&OCTAHEDRON, open),
        &Options::new().shell(0.01),
    )
    .unwrap();
    let (p, provenance) = (
        mesh.mass_properties(&Body::default()).unwrap(),
        mesh.provenance().unwrap(),
    );
    let area = 7.0 * 3f64.sqrt() / 2.0;
    assert_eq!(provenance.mode, Mode::Shell);
    assert!((provenance.shell_area - area).abs() < 1e-14);
    assert!((p.mass - 0.01 * area).abs() < 1e-15);
}

#[test]
fn a_shell_without_a_thickness_is_refused() {
    let surface = Surface::triangles(&OCTAHEDRON, &FACES);
    let options = Options::new().fallback(&[Mode::Shell]);
    let error = polymass::mass_properties(&surface, &options, &Body::default()).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    assert!(error.message().contains("shell_thickness"), "{error}");
    let thick = options.with_shell_thickness(0.01);
    assert!(polymass::mass_properties(&surface, &thick, &Body::default()).is_ok());
}
