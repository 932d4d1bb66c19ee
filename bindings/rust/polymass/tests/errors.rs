//! Every error kind the safe API can meet, each with the library's message
//! saying what and where; the status table both ways, unknown codes included.

mod common;

use common::*;
use polymass::{Body, ErrorKind, Mesh, Options, Surface};

/// Computes `shape` as `body` and checks the failure's kind and that its
/// message names what is wrong.
fn assert_fails(shape: &Shape, body: &Body, kind: ErrorKind, words: &[&str]) {
    let error = polymass::mass_properties(&shape.surface(), &Options::new(), body).unwrap_err();
    assert_eq!(error.kind(), kind, "{error}");
    assert_eq!(error.code(), kind.code());
    for word in words {
        assert!(
            error.message().contains(word),
            "'{word}' not in '{}'",
            error.message()
        );
    }
    // Display: the kind's description, then the message.
    assert_eq!(
        error.to_string(),
        format!("{}: {}", kind.description(), error.message())
    );
}

fn tetrahedron() -> Shape {
    corner_tetrahedron(1.0, 1.0, 1.0)
}

#[test]
fn invalid_density_mass_and_face_sizes() {
    let unit = Body::default();
    assert_fails(
        &tetrahedron(),
        &Body::density(-1.0),
        ErrorKind::InvalidArgument,
        &["density"],
    );
    assert_fails(
        &tetrahedron(),
        &Body::density(f64::NAN),
        ErrorKind::InvalidArgument,
        &["density"],
    );
    assert_fails(
        &tetrahedron(),
        &Body::mass(0.0),
        ErrorKind::InvalidArgument,
        &["mass"],
    );
    let mut sizes_short = tetrahedron();
    sizes_short.face_sizes.pop();
    assert_fails(&sizes_short, &unit, ErrorKind::InvalidArgument, &["face"]);
}

#[test]
fn inertia_about_a_point_that_is_not_finite() {
    let p = polymass::mass_properties(&tetrahedron().surface(), &Options::new(), &Body::default())
        .unwrap();
    for point in [[f64::INFINITY, 0.0, 0.0], [0.0, f64::NAN, 0.0]] {
        let error = p.inertia_about(point).unwrap_err();
        assert_eq!(error.kind(), ErrorKind::InvalidArgument, "{error}");
    }
    let huge = p.inertia_about([1e300, 0.0, 0.0]).unwrap_err();
    assert_eq!(huge.kind(), ErrorKind::Overflow, "{huge}");
}

#[test]
fn polygons_without_face_sizes_are_not_taken_for_triangles() {
    let shape = tetrahedron();
    let surface = Surface::polygons(&shape.positions, &shape.indices, &[]);
    let error = polymass::mass_properties(&surface, &Options::new(), &Body::default()).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument, "{error}");
}

/// Options are checked by the call they are given to, each call alike.
#[test]
fn invalid_options_are_refused_by_every_call_that_takes_them() {
    let shape = tetrahedron();
    let surface = shape.surface();
    let body = Body::default();
    for (options, word) in [
        (
            Options::new().with_planarity_tolerance(-1.0),
            "planarity_tolerance",
        ),
        (
            Options::new().with_planarity_tolerance(f64::NAN),
            "planarity_tolerance",
        ),
        (
            Options::new().weld_vertices(true).with_weld_tolerance(0.1),
            "weld_tolerance",
        ),
    ] {
        let errors = [
            polymass::mass_properties(&surface, &options, &body).unwrap_err(),
            Mesh::new(&surface, &options).unwrap_err(),
            polymass::batch(&[(surface, options, body)]).unwrap()[0]
                .clone()
                .unwrap_err(),
        ];
        for error in errors {
            assert_eq!(error.kind(), ErrorKind::InvalidArgument, "{error}");
            assert!(error.message().contains(word), "{error}");
        }
    }
}

#[test]
fn non_finite_coordinate() {
    let mut shape = tetrahedron();
    shape.positions[2][1] = f64::NAN;
    assert_fails(
        &shape,
        &Body::default(),
        ErrorKind::NonFinite,
        &["vertex 2"],
    );
}

#[test]
fn index_past_the_vertices() {
    let mut shape = tetrahedron();
    shape.indices[7] = 4;
    assert_fails(
        &shape,
        &Body::default(),
        ErrorKind::IndexOutOfRange,
        &["face 2", "4"],
    );
}

#[test]
fn face_of_two_vertices() {
    let mut shape = tetrahedron();
    shape.indices.push(0);
    shape.indices.push(1);
    shape.face_sizes.push(2);
    assert_fails(
        &shape,
        &Body::default(),
        ErrorKind::FaceTooSmall,
        &["face 4", "2"],
    );
}

#[test]
fn open_surface() {
    let mut shape = tetrahedron();
    shape.indices.truncate(9);
    shape.face_sizes.truncate(3);
    assert_fails(&shape, &Body::default(), ErrorKind::Open, &["edge"]);
}

#[test]
fn edge_shared_by_four_faces() {
    let shape = tetrahedra_sharing_an_edge();
    assert_fails(
        &shape,
        &Body::default(),
        ErrorKind::NonManifold,
        &["edge (0, 1)"],
    );
}

#[test]
fn one_flipped_face() {
    let mut shape = tetrahedron();
    shape.indices[9..12].reverse();
    assert_fails(
        &shape,
        &Body::default(),
        ErrorKind::InconsistentOrientation,
        &["edge"],
    );
}

#[test]
fn quad_off_its_plane() {
    let mut shape = cuboid([0.0; 3], [1.0; 3]);
    shape.positions[7][2] = 1.25; // corner (1, 1, 1) raised: the top quad bends
    assert_fails(
        &shape,
        &Body::default(),
        ErrorKind::NonPlanarFace,
        &["face"],
    );
}

#[test]
fn every_face_reversed() {
    assert_fails(
        &tetrahedron().reversed(),
        &Body::default(),
        ErrorKind::Inverted,
        &[],
    );
}

#[test]
fn flat_double_sided_sheet() {
    let shape = Shape {
        positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        indices: vec![0, 1, 2, 0, 2, 1],
        face_sizes: vec![3, 3],
    };
    assert_fails(&shape, &Body::default(), ErrorKind::ZeroVolume, &[]);
}

#[test]
fn polygon_errors() {
    let collinear = polymass::polygon(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]).unwrap_err();
    assert_eq!(collinear.kind(), ErrorKind::ZeroArea, "{collinear}");
    let two = polymass::polygon(&[[0.0, 0.0], [1.0, 1.0]]).unwrap_err();
    assert_eq!(two.kind(), ErrorKind::FaceTooSmall, "{two}");
    let nan = polymass::polygon(&[[0.0, 0.0], [1.0, f64::NAN], [0.0, 1.0]]).unwrap_err();
    assert_eq!(nan.kind(), ErrorKind::NonFinite, "{nan}");
}

#[test]
fn results_beyond_a_double() {
    let cube = cuboid([0.0; 3], [2.0; 3]);
    assert_fails(&cube, &Body::density(f64::MAX), ErrorKind::Overflow, &[]);
    let huge = cuboid([0.0; 3], [1e300; 3]);
    assert_fails(&huge, &Body::default(), ErrorKind::Overflow, &[]);
}

#[test]
fn every_status_code_maps_to_its_kind_and_back() {
    let known = [
        (1, ErrorKind::InvalidArgument),
        (2, ErrorKind::OutOfMemory),
        (3, ErrorKind::Internal),
        (10, ErrorKind::NonFinite),
        (11, ErrorKind::IndexOutOfRange),
        (12, ErrorKind::FaceTooSmall),
        (20, ErrorKind::Open),
        (21, ErrorKind::NonManifold),
        (22, ErrorKind::InconsistentOrientation),
        (23, ErrorKind::NonPlanarFace),
        (24, ErrorKind::Intersecting),
        (30, ErrorKind::Inverted),
        (31, ErrorKind::ZeroVolume),
        (32, ErrorKind::ZeroArea),
        (40, ErrorKind::Overflow),
    ];
    let unknown_text = ErrorKind::Unknown(4).description();
    for (code, kind) in known {
        assert_eq!(ErrorKind::from_code(code), Some(kind));
        assert_eq!(kind.code(), code);
        assert_ne!(kind.description(), unknown_text, "{kind:?}");
    }
    assert_eq!(ErrorKind::from_code(0), None);
    for code in [-1, 4, 13, 41, i32::MAX] {
        assert_eq!(ErrorKind::from_code(code), Some(ErrorKind::Unknown(code)));
        assert_eq!(ErrorKind::Unknown(code).code(), code);
        assert_eq!(ErrorKind::Unknown(code).description(), "unknown status");
    }
}

#[test]
fn errors_are_std_errors_that_cross_threads() {
    fn takes<E: std::error::Error + Send + Sync + 'static>(_: &E) {}
    let error = polymass::polygon(&[[0.0, 0.0]]).unwrap_err();
    takes(&error);
    let boxed: Box<dyn std::error::Error + Send + Sync> = Box::new(error.clone());
    assert_eq!(boxed.to_string(), error.to_string());
}
