//! A mesh's diagnostics report every problem with counts and first
//! locations, and nothing for a valid solid.

mod common;

use common::*;
use polymass::{Body, Checks, Diagnostics, ErrorKind, Mesh, Occurrences, Options, Surface};

fn report(surface: &Surface<'_>) -> Diagnostics {
    Mesh::new(surface, &Options::new())
        .unwrap()
        .diagnostics()
        .unwrap()
}

#[test]
fn a_valid_solid_has_a_clean_report() {
    let shape = cuboid([0.0; 3], [1.0, 2.0, 3.0]);
    let report = report(&shape.surface());
    assert!(report.is_solid(), "{report:?}");
    let every = Checks::TOPOLOGY | Checks::SHELLS | Checks::INTERSECTIONS;
    assert_eq!(report.checks, every);
    assert_eq!(report.shell_count, 1);
    assert_eq!(
        (
            report.face_count,
            report.used_vertex_count,
            report.edge_count
        ),
        (6, 8, 12)
    );
    for none in [
        report.non_finite_vertices,
        report.out_of_range_indices,
        report.small_faces,
        report.degenerate_faces,
        report.non_planar_faces,
    ] {
        assert_eq!(none, Occurrences::default());
    }
    for none in [
        report.open_edges,
        report.non_manifold_edges,
        report.misoriented_edges,
    ] {
        assert_eq!(none, Occurrences::default());
    }
    assert_close(report.signed_volume.unwrap(), 6.0, "signed volume");
    assert!(report.max_non_planarity <= 1e-15);
}

#[test]
fn an_open_surface_reports_its_edges_and_the_error_the_one_call_gives() {
    let mut shape = corner_tetrahedron(1.0, 1.0, 1.0);
    shape.indices.truncate(9); // the slanted face (1, 2, 3) is gone
    shape.face_sizes.truncate(3);
    let mesh = Mesh::new(&shape.surface(), &Options::new()).unwrap();
    let report = mesh.diagnostics().unwrap();
    let error = report.error.clone().unwrap();
    assert_eq!(error.kind(), ErrorKind::Open);
    let one_call =
        polymass::mass_properties(&shape.surface(), &Options::new(), &Body::default()).unwrap_err();
    assert_eq!(error, one_call);
    assert_eq!(mesh.status(), Err(one_call));
    assert_eq!(report.open_edges.count, 3);
    // The rim of the missing face (1, 2, 3), each edge as its remaining
    // neighbour traverses it, lowest vertex pairs first.
    assert_eq!(report.open_edges.first, vec![[2, 1], [1, 3], [3, 2]]);
    assert!(report.misoriented_edges.first.is_empty());
}

#[test]
fn every_problem_is_counted_not_only_the_first() {
    let mut shape = cuboid([0.0; 3], [1.0; 3]);
    shape.positions[7][2] = 1.25; // the top quad (face 1) bends
    shape.indices.truncate(20); // and the face x = max is gone
    shape.face_sizes.truncate(5);
    let report = report(&shape.surface());
    assert_eq!(
        report.error.as_ref().map(|e| e.kind()),
        Some(ErrorKind::Open)
    );
    assert_eq!(report.open_edges.count, 4);
    assert_eq!(
        report.non_planar_faces,
        Occurrences {
            count: 1,
            first: vec![1]
        }
    );
    assert!(report.max_non_planarity > 0.01);
}

#[test]
fn many_problems_list_the_lowest_few() {
    let shape = cuboid([0.0; 3], [1.0; 3]);
    // Ten faces of two vertices after the six quads: faces 6 to 15.
    let indices: Vec<u32> = shape
        .indices
        .iter()
        .copied()
        .chain([0, 1].repeat(10))
        .collect();
    let mut sizes = shape.face_sizes.clone();
    sizes.resize(16, 2);
    let report = report(&Surface::polygons(&shape.positions, &indices, &sizes));
    assert_eq!(
        report.error.as_ref().map(|e| e.kind()),
        Some(ErrorKind::FaceTooSmall)
    );
    assert_eq!(report.small_faces.count, 10);
    assert_eq!(
        report.small_faces.first,
        (6..6 + polymass::LOCATIONS as u64).collect::<Vec<_>>()
    );
}

#[test]
fn an_inverted_solid_has_a_negative_signed_volume() {
    let report = report(&corner_tetrahedron(1.0, 2.0, 3.0).reversed().surface());
    assert_eq!(
        report.error.as_ref().map(|e| e.kind()),
        Some(ErrorKind::Inverted)
    );
    assert_close(report.signed_volume.unwrap(), -1.0, "signed volume");
}

#[test]
fn a_call_that_cannot_be_made_is_an_err_not_a_report() {
    let shape = cuboid([0.0; 3], [1.0; 3]);
    let short_sizes = &shape.face_sizes[..5]; // 20 of the 24 indices
    let surface = Surface::polygons(&shape.positions, &shape.indices, short_sizes);
    let error = Mesh::new(&surface, &Options::new()).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument, "{error}");
    assert!(error.to_string().contains("add up to"), "{error}");
}

/// The report is of the analysis the options asked for: checks skipped by
/// name are not run, and it says which ran.
#[test]
fn checks_the_options_skip_are_not_run() {
    let shape = one_face_flipped();
    let checked = report(&shape.surface());
    assert_eq!(
        checked.error.as_ref().map(|e| e.kind()),
        Some(ErrorKind::InconsistentOrientation)
    );
    assert_eq!(checked.misoriented_edges.count, 3);
    assert!(checked.checks.contains(Checks::TOPOLOGY));
    let trusting = Options::new().skip_topology_checks(true);
    let mesh = Mesh::new(&shape.surface(), &trusting).unwrap();
    let skipped = mesh.diagnostics().unwrap();
    assert!(skipped.checks.is_empty(), "{:?}", skipped.checks);
    assert_eq!(skipped.misoriented_edges, Occurrences::default());
    assert!(mesh.status().is_ok());
}

fn one_face_flipped() -> Shape {
    let mut shape = corner_tetrahedron(1.0, 1.0, 1.0);
    shape.indices[9..12].reverse();
    shape
}

#[test]
fn shells_need_indices_in_range() {
    let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let surface = Surface::triangles(&positions, &[[0u32, 1, 2], [0, 1, 7]]);
    let mesh = Mesh::new(&surface, &Options::new()).unwrap();
    let error = mesh.shell_of_face().unwrap_err();
    assert_eq!(error.kind(), ErrorKind::IndexOutOfRange, "{error}");
    assert!(error.to_string().contains("face 1"), "{error}");
    assert_eq!(mesh.status(), Err(error));
    let report = mesh.diagnostics().unwrap();
    assert_eq!(report.out_of_range_indices.first, vec![1]);
    assert_eq!(report.shell_count, 0);
}
