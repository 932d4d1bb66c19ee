//! What Options accept (welding, trusted input, inverted and non-manifold
//! solids), that they hold for their call alone, what Body changes (density
//! or mass) and the inertia about any point, each against exact values.

mod common;

use common::*;
use polymass::{Body, Context, ErrorKind, Mesh, Options, Positions, Surface, Warnings};

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
    let open = polymass::mass_properties(&surface, &Options::new(), &Body::default()).unwrap_err();
    assert_eq!(open.kind(), ErrorKind::Open);
    let welding = Options::new().weld_vertices(true);
    let p = polymass::mass_properties(&surface, &welding, &Body::default()).unwrap();
    assert_matches(&p, &cuboid_exact([0.0; 3], [1.0, 2.0, 3.0]), "welded soup");
    // Welded by the caller first, the indexed solid is the same.
    let weld = polymass::weld_positions(Positions::packed(&positions), 0.0).unwrap();
    assert_eq!(weld.distinct_count, 8);
    let indexed: Vec<[u32; 3]> = triangles
        .iter()
        .map(|t| t.map(|i| weld.vertex_of[i as usize]))
        .collect();
    let welded = Surface::triangles(&positions, &indexed);
    let q = polymass::mass_properties(&welded, &Options::new(), &Body::default()).unwrap();
    assert_same_body(&p, &q, "welded by the caller");
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
    let error = polymass::mass_properties(&surface, &exact_only, &Body::default());
    assert_eq!(error.unwrap_err().kind(), ErrorKind::Open);
    let tolerant = exact_only.with_weld_tolerance(1e-9);
    let p = polymass::mass_properties(&surface, &tolerant, &Body::default()).unwrap();
    assert!((p.volume - 1.0).abs() < 1e-13, "volume {}", p.volume);
    // Welding alone finds the eight corners with the tolerance, not without.
    let near = polymass::weld_positions(Positions::packed(&positions), 1e-9).unwrap();
    assert_eq!(near.distinct_count, 8);
    let exact = polymass::weld_positions(Positions::packed(&positions), 0.0).unwrap();
    assert!(exact.distinct_count > 8);
}

#[test]
fn skipping_the_checks_is_reported() {
    let shape = cuboid([0.0; 3], [1.0; 3]);
    let trusted = Options::new().skip_topology_checks(true);
    let p = Mesh::new(&shape.surface(), &trusted)
        .unwrap()
        .mass_properties(&Body::default())
        .unwrap();
    // Skipping the topology checks skips the intersection check with them.
    assert_eq!(
        p.warnings,
        Warnings::UNCHECKED | Warnings::INTERSECTIONS_UNCHECKED
    );
    assert_close(p.volume, 1.0, "volume");
}

#[test]
fn an_accepted_inverted_solid_is_turned() {
    let shape = corner_tetrahedron(1.0, 2.0, 3.0).reversed();
    let options = Options::new().accept_inverted(true);
    let p = polymass::mass_properties(&shape.surface(), &options, &Body::default()).unwrap();
    assert_eq!(p.warnings, Warnings::INVERTED);
    let exact = corner_tetrahedron_exact(1.0, 2.0, 3.0);
    assert_close(p.volume, exact.volume, "volume");
    assert_matrix_close(&p.inertia, &exact.inertia, "inertia");
}

#[test]
fn balanced_non_manifold_edges_can_be_accepted() {
    let shape = tetrahedra_sharing_an_edge();
    let options = Options::new().accept_non_manifold(true);
    let p = polymass::mass_properties(&shape.surface(), &options, &Body::default()).unwrap();
    assert!(
        p.warnings.contains(Warnings::NON_MANIFOLD),
        "{:?}",
        p.warnings
    );
    assert_close(p.volume, 2.0 / 6.0, "volume of two tetrahedra");
}

/// Options belong to the call they are given to: a context used with
/// relaxed options checks the next call with that call's own.
#[test]
fn options_hold_for_their_call_alone() {
    let inverted = corner_tetrahedron(1.0, 2.0, 3.0).reversed();
    let surface = inverted.surface();
    let accepting = Options::new().accept_inverted(true);
    let mut context = Context::new().unwrap();
    let body = Body::default();
    assert!(context.mass_properties(&surface, &accepting, &body).is_ok());
    let refused = context
        .mass_properties(&surface, &Options::new(), &body)
        .unwrap_err();
    assert_eq!(refused.kind(), ErrorKind::Inverted);
    let accepted = context.mesh(&surface, &accepting).unwrap();
    let checked = context.mesh(&surface, &Options::new()).unwrap();
    assert!(accepted.status().is_ok());
    assert_eq!(checked.status().unwrap_err().kind(), ErrorKind::Inverted);
    let options = Options::new()
        .weld_vertices(true)
        .accept_inverted(true)
        .skip_intersection_check(true)
        .with_planarity_tolerance(1e-3)
        .with_weld_tolerance(1e-9);
    assert!(options.welds_vertices() && options.accepts_inverted());
    assert!(options.skips_intersection_check() && !options.skips_topology_checks());
    assert_eq!(
        (options.planarity_tolerance(), options.weld_tolerance()),
        (1e-3, 1e-9)
    );
}

#[test]
fn mass_mode_sets_the_mass_and_derives_the_density() {
    let mesh = Mesh::new(
        &cuboid([0.0; 3], [1.0, 2.0, 4.0]).surface(),
        &Options::new(),
    )
    .unwrap();
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
    let mesh = Mesh::new(
        &corner_tetrahedron(1.0, 2.0, 3.0).surface(),
        &Options::new(),
    )
    .unwrap();
    let point = [-1.5, 0.25, 4.0];
    let density = 2.5;
    let p = mesh.mass_properties(&Body::density(density)).unwrap();
    let mass = density * exact.volume;
    let d: [f64; 3] = std::array::from_fn(|axis| exact.center_of_mass[axis] - point[axis]);
    let at_com = scaled(&exact.inertia, density);
    assert_matrix_close(&p.inertia, &at_com, "about the centre of mass");
    assert_matrix_close(
        &p.inertia_about(point).unwrap(),
        &add(&at_com, &parallel_axis(mass, &d), 1.0),
        "about the point",
    );
    assert_matrix_close(
        &p.inertia_about(p.center_of_mass).unwrap(),
        &at_com,
        "about the centre of mass",
    );
    let from_origin = add(&at_com, &parallel_axis(mass, &exact.center_of_mass), 1.0);
    assert_matrix_close(&p.inertia_origin, &from_origin, "about the origin");
}
