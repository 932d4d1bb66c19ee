//! What Options accept (welding, trusted input, inverted and non-manifold
//! solids) and what Body changes (density or mass, reference point), each
//! against exact values.

mod common;

use common::*;
use polymass::{Body, Context, ErrorKind, Mesh, Options, Surface, Warnings};

/// The shape as an STL-style soup: three fresh vertices per triangle.
fn soup(shape: &Shape) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let triangles = shape.triangles();
    let positions = triangles
        .iter()
        .flatten()
        .map(|&i| shape.positions[i as usize])
        .collect();
    let soup_triangles = (0..triangles.len() as u32)
        .map(|t| [3 * t, 3 * t + 1, 3 * t + 2])
        .collect();
    (positions, soup_triangles)
}

#[test]
fn welding_closes_a_triangle_soup() {
    let (positions, triangles) = soup(&cuboid([0.0; 3], [1.0, 2.0, 3.0]));
    let surface = Surface::triangles(&positions, &triangles);
    let open = polymass::mass_properties(&surface, &Body::default()).unwrap_err();
    assert_eq!(open.kind(), ErrorKind::Open);
    let mut context = Context::with_options(&Options::new().weld_vertices(true)).unwrap();
    let p = context.mass_properties(&surface, &Body::default()).unwrap();
    assert_matches(&p, &cuboid_exact([0.0; 3], [1.0, 2.0, 3.0]), "welded soup");
}

#[test]
fn weld_tolerance_closes_a_soup_with_rounding_noise() {
    let (mut positions, triangles) = soup(&cuboid([0.0; 3], [1.0; 3]));
    for (i, position) in positions.iter_mut().enumerate() {
        // Each copy of a corner a different few ulps away: 1e-14 of the size.
        position[i % 3] += (i % 5) as f64 * 2e-15;
    }
    let surface = Surface::triangles(&positions, &triangles);
    let exact_only = Options::new().weld_vertices(true);
    let error = Context::with_options(&exact_only)
        .unwrap()
        .mass_properties(&surface, &Body::default());
    assert_eq!(error.unwrap_err().kind(), ErrorKind::Open);
    let tolerant = exact_only.weld_tolerance(1e-9);
    let p = Context::with_options(&tolerant)
        .unwrap()
        .mass_properties(&surface, &Body::default())
        .unwrap();
    assert!((p.volume - 1.0).abs() < 1e-13, "volume {}", p.volume);
}

#[test]
fn skipping_the_checks_is_reported() {
    let shape = cuboid([0.0; 3], [1.0; 3]);
    let trusted = Options::new().skip_topology_checks(true);
    let p = Mesh::with_options(&shape.surface(), &trusted)
        .unwrap()
        .mass_properties(&Body::default())
        .unwrap();
    assert_eq!(p.warnings, Warnings::UNCHECKED);
    assert_close(p.volume, 1.0, "volume");
}

#[test]
fn an_accepted_inverted_solid_is_turned() {
    let shape = corner_tetrahedron(1.0, 2.0, 3.0).reversed();
    let options = Options::new().accept_inverted(true);
    let p = Context::with_options(&options)
        .unwrap()
        .mass_properties(&shape.surface(), &Body::default())
        .unwrap();
    assert_eq!(p.warnings, Warnings::INVERTED);
    let exact = corner_tetrahedron_exact(1.0, 2.0, 3.0);
    assert_close(p.volume, exact.volume, "volume");
    assert_matrix_close(&p.inertia, &exact.inertia, "inertia");
}

#[test]
fn balanced_non_manifold_edges_can_be_accepted() {
    let shape = tetrahedra_sharing_an_edge();
    let options = Options::new().accept_non_manifold(true);
    let p = Context::with_options(&options)
        .unwrap()
        .mass_properties(&shape.surface(), &Body::default())
        .unwrap();
    assert!(
        p.warnings.contains(Warnings::NON_MANIFOLD),
        "{:?}",
        p.warnings
    );
    assert_close(p.volume, 2.0 / 6.0, "volume of two tetrahedra");
}

#[test]
fn a_context_keeps_the_options_it_was_given() {
    let options = Options::new()
        .weld_vertices(true)
        .accept_inverted(true)
        .skip_intersection_check(true)
        .planarity_tolerance(1e-3)
        .weld_tolerance(1e-9);
    let mut context = Context::with_options(&options).unwrap();
    assert_eq!(context.options().unwrap(), options);
    let cleared = Options::new().planarity_tolerance(1e-3);
    context.set_options(&cleared).unwrap();
    assert_eq!(context.options().unwrap(), cleared);
}

#[test]
fn mass_mode_sets_the_mass_and_derives_the_density() {
    let mesh = Mesh::new(&cuboid([0.0; 3], [1.0, 2.0, 4.0]).surface()).unwrap();
    let p = mesh.mass_properties(&Body::mass(3.0)).unwrap();
    assert_eq!(p.mass, 3.0);
    assert_close(p.density, 3.0 / 8.0, "density");
    let by_density = mesh.mass_properties(&Body::density(3.0 / 8.0)).unwrap();
    assert_close(by_density.mass, 3.0, "mass");
    assert_matrix_close(&by_density.inertia, &p.inertia, "inertia");
    let unit = cuboid_exact([0.0; 3], [1.0, 2.0, 4.0]);
    assert_close(
        p.inertia[1][1],
        unit.inertia[1][1] * 3.0 / 8.0,
        "Iyy scales with the density",
    );
}

#[test]
fn inertia_about_a_point_is_the_parallel_axis_transfer() {
    let exact = corner_tetrahedron_exact(1.0, 2.0, 3.0);
    let mesh = Mesh::new(&corner_tetrahedron(1.0, 2.0, 3.0).surface()).unwrap();
    let point = [-1.5, 0.25, 4.0];
    let density = 2.5;
    let p = mesh
        .mass_properties(&Body::density(density).about(point))
        .unwrap();
    let mass = density * exact.volume;
    let d: [f64; 3] = std::array::from_fn(|axis| exact.center_of_mass[axis] - point[axis]);
    let at_com = scaled(&exact.inertia, density);
    assert_matrix_close(&p.inertia, &at_com, "about the centre of mass");
    assert_matrix_close(
        &p.inertia_point,
        &add(&at_com, &parallel_axis(mass, &d), 1.0),
        "about the point",
    );
    let from_origin = add(&at_com, &parallel_axis(mass, &exact.center_of_mass), 1.0);
    assert_matrix_close(&p.inertia_origin, &from_origin, "about the origin");
}
