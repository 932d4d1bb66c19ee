//! Surfaces that bound a region twice (faces crossing, shells nested in a
//! solid of the same sense, shells inside out) and those that only look alike
//! (cavities, parts in hollows, parts resting on each other), as the library
//! reports them through this crate: the error kind, the option, the report's
//! fields and the shells.
//!
//! Every verdict is also checked far from the origin and at tiny and huge
//! scales: the library decides them with exact predicates, so they must not
//! change.

mod common;

use common::*;
use polymass::{
    Body, Checks, Context, Diagnostics, ErrorKind, MassProperties, Mesh, Options, Shell, ShellKind,
    Warnings,
};

/// (name, scale, translation): each case is also tried at x' = scale x + t.
const PLACEMENTS: [(&str, f64, [f64; 3]); 5] = [
    ("as given", 1.0, [0.0, 0.0, 0.0]),
    ("at 1e6", 1.0, [1e6, -1e6, 1e6]),
    ("at 1e8", 1.0, [1e8, 1e8, -1e8]),
    ("scaled 1e-60", 1e-60, [0.0, 0.0, 0.0]),
    ("scaled 1e60", 1e60, [0.0, 0.0, 0.0]),
];

fn placed(shape: &Shape, scale: f64, translation: [f64; 3]) -> Shape {
    let positions = shape
        .positions
        .iter()
        .map(|p| std::array::from_fn(|axis| scale * p[axis] + translation[axis]))
        .collect();
    Shape {
        positions,
        ..shape.clone()
    }
}

/// The same surface with its (convex) faces split into triangles.
fn triangulated(shape: &Shape) -> Shape {
    let triangles = shape.triangles();
    Shape {
        positions: shape.positions.clone(),
        indices: triangles.as_flattened().to_vec(),
        face_sizes: vec![3; triangles.len()],
    }
}

/// The options with the intersection check on (the default) or skipped.
fn checking(check_intersections: bool) -> Options {
    Options::new().skip_intersection_check(!check_intersections)
}

/// Two unit cubes overlapping by an eighth: 1.875 enclosed, 2 counted.
fn overlapping_cubes() -> Shape {
    cuboid([0.0; 3], [1.0; 3]).with(&cuboid([0.5; 3], [1.5; 3]))
}

fn solid_in_solid() -> Shape {
    cuboid([0.0; 3], [4.0; 3]).with(&triangulated(&cuboid([1.0; 3], [2.0; 3])))
}

fn cube_with_cavity() -> Shape {
    cuboid([0.0; 3], [4.0; 3]).with(&cuboid([1.0; 3], [3.0; 3]).reversed())
}

/// A hollow cube (6³ − 4³) and, in its hollow, a cube of 2³.
fn part_in_hollow() -> Shape {
    cuboid([0.0; 3], [6.0; 3])
        .with(&triangulated(&cuboid([1.0; 3], [5.0; 3])).reversed())
        .with(&cuboid([2.0; 3], [4.0; 3]))
}

fn inverted_apart() -> Shape {
    cuboid([0.0; 3], [1.0; 3]).with(&cuboid([3.0, 0.0, 0.0], [3.5, 0.5, 0.5]).reversed())
}

/// An L-shaped prism 0 <= z <= 1 whose notch is the square [1, 4] x [1, 4].
fn l_prism() -> Shape {
    let outline = [
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 1.0],
        [1.0, 1.0],
        [1.0, 4.0],
        [0.0, 4.0],
    ];
    let n = outline.len() as u32;
    let mut positions: Vec<[f64; 3]> = outline.iter().map(|&[x, y]| [x, y, 0.0]).collect();
    positions.extend(outline.iter().map(|&[x, y]| [x, y, 1.0]));
    let mut indices: Vec<u32> = (0..n).rev().collect(); // bottom, seen from below
    indices.extend(n..2 * n); // top
    for i in 0..n {
        let j = (i + 1) % n;
        indices.extend([i, j, n + j, n + i]);
    }
    let mut face_sizes = vec![n, n];
    face_sizes.extend(std::iter::repeat(4).take(n as usize));
    Shape {
        positions,
        indices,
        face_sizes,
    }
}

/// Within the L's bounding box, outside the L: only counted nesting tells it
/// from a cavity.
fn inverted_in_the_notch() -> Shape {
    l_prism().with(&triangulated(&cuboid([2.5, 2.5, 0.25], [3.0, 3.0, 0.75])).reversed())
}

struct Verdict {
    case: &'static str,
    make: fn() -> Shape,
    /// The error with the check (None: accepted), and without.
    checked: Option<ErrorKind>,
    unchecked: Option<ErrorKind>,
    /// When accepted with the check, before placement.
    volume: f64,
}

const VERDICTS: [Verdict; 6] = [
    Verdict {
        case: "overlapping cubes",
        make: overlapping_cubes,
        checked: Some(ErrorKind::Intersecting),
        unchecked: None,
        volume: 2.0,
    },
    Verdict {
        case: "a solid cube in a solid cube",
        make: solid_in_solid,
        checked: Some(ErrorKind::Intersecting),
        unchecked: None,
        volume: 65.0,
    },
    Verdict {
        case: "a cube with a cavity",
        make: cube_with_cavity,
        checked: None,
        unchecked: None,
        volume: 64.0 - 8.0,
    },
    Verdict {
        case: "a part in a hollow part",
        make: part_in_hollow,
        checked: None,
        unchecked: None,
        volume: 216.0 - 64.0 + 8.0,
    },
    Verdict {
        case: "an inside-out cube apart",
        make: inverted_apart,
        checked: Some(ErrorKind::Inverted),
        unchecked: Some(ErrorKind::Inverted),
        volume: 0.0,
    },
    Verdict {
        case: "an inside-out cube in an L's notch",
        make: inverted_in_the_notch,
        checked: Some(ErrorKind::Inverted),
        unchecked: None,
        volume: 0.0,
    },
];

fn compute(shape: &Shape, check_intersections: bool) -> polymass::Result<MassProperties> {
    let options = checking(check_intersections);
    polymass::mass_properties(&shape.surface(), &options, &Body::default())
}

fn analyse(shape: &Shape, check_intersections: bool) -> Mesh {
    Mesh::new(&shape.surface(), &checking(check_intersections)).unwrap()
}

fn report(shape: &Shape, check_intersections: bool) -> Diagnostics {
    analyse(shape, check_intersections).diagnostics().unwrap()
}

fn shells(shape: &Shape, check_intersections: bool) -> Vec<Shell> {
    analyse(shape, check_intersections).shells().unwrap()
}

/// With the check skipped, the only difference is the warning that says so.
fn assert_same_but_unchecked(checked: &MassProperties, unchecked: &MassProperties, what: &str) {
    assert_eq!(
        unchecked.warnings,
        checked.warnings | Warnings::INTERSECTIONS_UNCHECKED,
        "{what}"
    );
    assert_same_body(checked, unchecked, what);
}

#[test]
fn verdicts_everywhere() {
    for verdict in &VERDICTS {
        for (name, scale, translation) in PLACEMENTS {
            let what = format!("{}, {name}", verdict.case);
            let shape = placed(&(verdict.make)(), scale, translation);
            let with_check = compute(&shape, true);
            let without = compute(&shape, false);
            let kinds = [&with_check, &without].map(|r| r.as_ref().err().map(|e| e.kind()));
            assert_eq!(kinds, [verdict.checked, verdict.unchecked], "{what}");
            if let Ok(checked) = &with_check {
                assert_close(checked.volume, verdict.volume * scale.powi(3), &what);
                assert!(
                    checked.warnings.is_empty(),
                    "{what}: {:?}",
                    checked.warnings
                );
                // The check changes nothing it accepts, to the last bit.
                assert_same_but_unchecked(checked, without.as_ref().unwrap(), &what);
            }
            // The analysis reports what computing does, with the same options.
            for (on, expected) in [(true, verdict.checked), (false, verdict.unchecked)] {
                let mesh = analyse(&shape, on);
                let found = mesh.status().err().map(|e| e.kind());
                assert_eq!(found, expected, "{what}: mesh with the check {on}");
                let verdict = mesh.diagnostics().unwrap().error.map(|e| e.kind());
                assert_eq!(verdict, expected, "{what}: report with the check {on}");
            }
        }
    }
}

/// Two unit cubes overlapping by an eighth (the solid is 1.875, their sum 2): every
/// call refuses them with the default options, and gives the sum only when the check
/// is skipped by name, or with the topology checks.
#[test]
fn every_call_refuses_overlapping_cubes_by_default() {
    let shape = overlapping_cubes();
    let surface = shape.surface();
    let body = Body::default();
    let defaults = Options::default();
    let refused = |result: polymass::Result<f64>, what: &str| {
        let error = result.expect_err(what);
        assert_eq!(error.kind(), ErrorKind::Intersecting, "{what}: {error}");
    };
    refused(
        polymass::mass_properties(&surface, &defaults, &body).map(|p| p.volume),
        "mass_properties",
    );
    refused(
        polymass::batch(&[(surface, defaults, body)])
            .unwrap()
            .remove(0)
            .map(|p| p.volume),
        "batch",
    );
    let mut context = Context::new().unwrap();
    refused(
        context
            .mass_properties(&surface, &defaults, &body)
            .map(|p| p.volume),
        "Context::mass_properties",
    );
    let mesh = context.mesh(&surface, &defaults).unwrap();
    refused(mesh.status().map(|_| 0.0), "mesh");
    refused(mesh.mass_properties(&body).map(|p| p.volume), "mesh mass");
    refused(mesh.moments().map(|m| m.volume()), "moments");
    assert_eq!(
        mesh.diagnostics().unwrap().error,
        Some(mesh.status().unwrap_err())
    );
    for options in [
        Options::new().skip_intersection_check(true),
        Options::new().skip_topology_checks(true),
    ] {
        let what = format!("{options:?}");
        let twice = polymass::mass_properties(&surface, &options, &body).unwrap();
        assert_close(twice.volume, 2.0, &what);
        let mesh = context.mesh(&surface, &options).unwrap();
        assert_close(
            context.mesh_mass_properties(&mesh, &body).unwrap().volume,
            2.0,
            &what,
        );
        assert_close(mesh.moments().unwrap().volume(), 2.0, &what);
        let batch = context
            .batch(&[(surface, options, body)])
            .unwrap()
            .remove(0)
            .unwrap();
        assert_close(batch.volume, 2.0, &what);
    }
}

#[test]
fn overlapping_cubes_are_refused_naming_the_faces_and_counted_twice_skipped() {
    let shape = overlapping_cubes();
    let error = compute(&shape, true).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Intersecting);
    assert_eq!(error.code(), 24);
    assert!(error.to_string().starts_with(error.kind().description()));
    // The pair named is the report's first, each face in its cube.
    let report = report(&shape, true);
    let [low, high] = report.intersecting_face_pairs.first[0];
    assert!(low < 6 && (6..12).contains(&high), "{low}, {high}");
    let named = format!("faces {low} (shell 0) and {high} (shell 1) cross each other");
    assert!(error.message().contains(&named), "{error}");
    assert_eq!(report.error, Some(error.clone()));
    // A mesh is refused the same way, with the same message.
    assert_eq!(analyse(&shape, true).status(), Err(error));
    // Without the check the overlap is counted twice: what the library reports.
    assert_close(compute(&shape, false).unwrap().volume, 2.0, "volume");
}

#[test]
fn the_report_lists_crossing_face_pairs_lowest_first() {
    let shape = overlapping_cubes();
    let found = report(&shape, true);
    assert_eq!(
        found.error.as_ref().map(|e| e.kind()),
        Some(ErrorKind::Intersecting)
    );
    assert!(found.checks.contains(Checks::INTERSECTIONS));
    assert_eq!(found.shell_count, 2);
    let pairs = &found.intersecting_face_pairs;
    assert!(pairs.count >= 3, "{pairs:?}");
    assert_eq!(
        pairs.first.len() as u64,
        pairs.count.min(polymass::LOCATIONS as u64)
    );
    assert!(pairs
        .first
        .iter()
        .all(|&[a, b]| a < 6 && (6..12).contains(&b)));
    assert!(pairs.first.windows(2).all(|w| w[0] < w[1]), "{pairs:?}");
    assert_eq!(found.touching_face_pairs, Default::default());
    assert_eq!(found.inverted_shells, Default::default());
    // Skipped by name, no pair is looked for: the verdict of computing so.
    let plain = report(&shape, false);
    assert!(plain.is_solid() && plain.shell_count == 2);
    assert_eq!(plain.checks, Checks::TOPOLOGY | Checks::SHELLS);
    assert_eq!(plain.intersecting_face_pairs, Default::default());
}

#[test]
fn the_report_names_shells_inside_out_and_counted_twice() {
    let shape = cube_with_cavity().with(&cuboid([6.0, 0.0, 0.0], [7.0, 1.0, 1.0]).reversed());
    let mesh = analyse(&shape, true);
    let found = mesh.diagnostics().unwrap();
    assert_eq!(
        found.error.as_ref().map(|e| e.kind()),
        Some(ErrorKind::Inverted)
    );
    let error = mesh.status().unwrap_err();
    assert!(error.message().contains("shell 2"), "{error}");
    assert_eq!(found.shell_count, 3);
    assert_eq!(
        (found.inverted_shells.count, found.inverted_shells.first),
        (1, vec![2])
    );
    assert_eq!(found.overlapping_shells, Default::default());

    let mesh = analyse(&solid_in_solid(), true);
    let found = mesh.diagnostics().unwrap();
    assert_eq!(
        found.error.as_ref().map(|e| e.kind()),
        Some(ErrorKind::Intersecting)
    );
    let error = mesh.status().unwrap_err();
    assert!(error.message().contains("shell 1"), "{error}");
    assert_eq!(
        (
            found.overlapping_shells.count,
            found.overlapping_shells.first
        ),
        (1, vec![1])
    );
    assert_eq!(found.intersecting_face_pairs.count, 0);
}

fn kinds(shells: &[Shell]) -> Vec<ShellKind> {
    shells.iter().map(|shell| shell.kind).collect()
}

#[test]
fn the_shell_list_describes_each_shell_everywhere() {
    use ShellKind::*;
    for (name, scale, translation) in PLACEMENTS {
        let at = |shape: Shape| placed(&shape, scale, translation);
        let shape =
            at(cube_with_cavity().with(&cuboid([6.0, 0.0, 0.0], [7.0, 1.0, 1.0]).reversed()));
        let shells = shells(&shape, true);
        assert_eq!(kinds(&shells), [Solid, Cavity, Inverted], "{name}");
        let faces: Vec<(u64, u64)> = shells
            .iter()
            .map(|s| (s.face_count, s.first_face))
            .collect();
        assert_eq!(faces, [(6, 0), (6, 6), (6, 12)], "{name}");
        for (shell, volume) in shells.iter().zip([64.0, -8.0, -1.0]) {
            assert_close(shell.signed_volume, volume * scale.powi(3), name);
        }

        let listed = |shape: Shape| kinds(&self::shells(&at(shape), true));
        assert_eq!(listed(solid_in_solid()), [Solid, Overlapping], "{name}");
        assert_eq!(listed(part_in_hollow()), [Solid, Cavity, Solid], "{name}");
        assert_eq!(listed(inverted_in_the_notch()), [Solid, Inverted], "{name}");
        assert_eq!(listed(overlapping_cubes())[0], Solid, "{name}");
        // Without the check nesting is judged by bounding boxes, as the library
        // documents: a negative shell within a solid's box is taken for a cavity.
        let boxed = self::shells(&at(inverted_in_the_notch()), false);
        assert_eq!(kinds(&boxed), [Solid, Cavity], "{name}");
    }
}

#[test]
fn a_double_sided_sheet_is_a_shell_without_volume() {
    let sheet = Shape {
        positions: vec![[3.0, 0.0, 0.0], [4.0, 0.0, 0.0], [3.0, 1.0, 0.0]],
        indices: vec![0, 1, 2, 0, 2, 1],
        face_sizes: vec![3, 3],
    };
    let shape = cuboid([0.0; 3], [1.0; 3]).with(&sheet);
    let shells = shells(&shape, true);
    assert_eq!(kinds(&shells), [ShellKind::Solid, ShellKind::NoVolume]);
    assert_eq!((shells[1].face_count, shells[1].first_face), (2, 6));
    assert_eq!(shells[1].signed_volume, 0.0);
}

#[test]
fn the_shell_list_lists_many_shells() {
    let mut shape = cuboid([0.0; 3], [1.0; 3]);
    for k in 1..40 {
        let x = 3.0 * f64::from(k);
        shape = shape.with(&cuboid([x, 0.0, 0.0], [x + 1.0, 1.0, 1.0 + f64::from(k)]));
    }
    let shells = shells(&shape, true);
    assert_eq!(shells.len(), 40);
    for (k, shell) in shells.iter().enumerate() {
        assert_eq!(
            (shell.kind, shell.first_face),
            (ShellKind::Solid, 6 * k as u64)
        );
        assert_close(shell.signed_volume, 1.0 + k as f64, "volume");
    }
}

/// Shells of a surface that fails a check before the shells (closed,
/// manifold, oriented, planar), or whose topology checks are skipped, are
/// listed as connected pieces but not judged.
#[test]
fn shells_before_the_checks_that_judge_them_are_listed_unjudged() {
    let mut open = corner_tetrahedron(1.0, 1.0, 1.0);
    open.indices.truncate(9);
    open.face_sizes.truncate(3);
    let mesh = analyse(&open, true);
    let unjudged = mesh.shells().unwrap();
    assert_eq!(kinds(&unjudged), [ShellKind::Unjudged]);
    assert_eq!((unjudged[0].face_count, unjudged[0].first_face), (3, 0));
    assert!(unjudged[0].signed_volume.is_nan());
    assert!(!mesh.diagnostics().unwrap().checks.contains(Checks::SHELLS));
    let trusting = Options::new().skip_topology_checks(true);
    let cube = Mesh::new(&cuboid([0.0; 3], [1.0; 3]).surface(), &trusting).unwrap();
    assert_eq!(kinds(&cube.shells().unwrap()), [ShellKind::Unjudged]);
    assert!(cube.diagnostics().unwrap().checks.is_empty());
}

/// A surface inside out as a whole is closed and oriented: its shell is
/// judged, inside out and signed as found - or, accepted inverted, a solid
/// counted turned.
#[test]
fn a_surface_inside_out_as_a_whole_has_its_shell_judged() {
    let inverted = corner_tetrahedron(1.0, 1.0, 1.0).reversed();
    let mesh = analyse(&inverted, true);
    let listed = mesh.shells().unwrap();
    assert_eq!(kinds(&listed), [ShellKind::Inverted]);
    assert_close(listed[0].signed_volume, -1.0 / 6.0, "inverted volume");
    let report = mesh.diagnostics().unwrap();
    assert!(report.checks.contains(Checks::SHELLS));
    assert_eq!(report.error, Some(mesh.status().unwrap_err()));
    assert_eq!(report.error.map(|e| e.kind()), Some(ErrorKind::Inverted));
    let accepting = Options::new().accept_inverted(true);
    let turned = Mesh::new(&inverted.surface(), &accepting)
        .unwrap()
        .shells()
        .unwrap();
    assert_eq!(kinds(&turned), [ShellKind::Solid]);
    assert_close(turned[0].signed_volume, 1.0 / 6.0, "turned volume");
}

#[test]
fn valid_solids_give_bit_identical_results_with_the_check() {
    let rotation = oblique_rotation();
    let solids = [
        cuboid([0.0; 3], [1.0, 2.0, 3.0]),
        corner_tetrahedron(1.0, 2.0, 3.0),
        triangular_prism(3.0, 1.0, 2.0),
        triangulated(&triangular_prism(1.0, 4.0, 0.5)),
        cube_with_cavity(),
        part_in_hollow(),
    ];
    for (k, solid) in solids.iter().enumerate() {
        for offset in [[0.0; 3], [1e6, -2e6, 3e6], [1e8, 1e8, -1e8]] {
            let shape = solid.rotated(&rotation).translated(offset);
            let what = format!("solid {k} at {offset:?}");
            let checked = compute(&shape, true).unwrap_or_else(|e| panic!("{what}: {e}"));
            assert_same_but_unchecked(&checked, &compute(&shape, false).unwrap(), &what);
            let found = report(&shape, true);
            assert!(found.is_solid(), "{what}: {:?}", found.error);
            assert_eq!(found.intersecting_face_pairs.count, 0, "{what}");
            assert_eq!(found.touching_face_pairs.count, 0, "{what}");
        }
    }
}

fn resting_cubes() -> Shape {
    cuboid([0.0; 3], [1.0; 3]).with(&cuboid([1.0, 0.0, 0.0], [2.0, 1.0, 1.0]))
}

fn resting_half_on() -> Shape {
    triangulated(&cuboid([0.0; 3], [1.0; 3]))
        .with(&triangulated(&cuboid([0.25, 0.5, 1.0], [1.25, 1.5, 2.0])))
}

/// An octahedral cavity whose lowest corner (2, 2, 0) is on the outer bottom
/// face of a cube of 4.
fn cavity_touching_its_wall() -> Shape {
    let c = [2.0, 2.0, 1.0];
    let positions = vec![
        [c[0] + 1.0, c[1], c[2]],
        [c[0], c[1] + 1.0, c[2]],
        [c[0], c[1], c[2] + 1.0],
        [c[0] - 1.0, c[1], c[2]],
        [c[0], c[1] - 1.0, c[2]],
        [c[0], c[1], c[2] - 1.0],
    ];
    #[rustfmt::skip]
    let indices = vec![
        0, 1, 2, 1, 3, 2, 3, 4, 2, 4, 0, 2,
        1, 0, 5, 3, 1, 5, 4, 3, 5, 0, 4, 5,
    ];
    let octahedron = Shape {
        positions,
        indices,
        face_sizes: vec![3; 8],
    };
    cuboid([0.0; 3], [4.0; 3]).with(&octahedron.reversed())
}

/// Accepted with and without the check; with it, with TOUCHING_FACES.
const TOUCHING: [Verdict; 3] = [
    Verdict {
        case: "two cubes resting against each other",
        make: resting_cubes,
        checked: None,
        unchecked: None,
        volume: 2.0,
    },
    Verdict {
        case: "a cube resting half on another",
        make: resting_half_on,
        checked: None,
        unchecked: None,
        volume: 2.0,
    },
    Verdict {
        case: "a cavity touching its wall in one point",
        make: cavity_touching_its_wall,
        checked: None,
        unchecked: None,
        volume: 64.0 - 4.0 / 3.0,
    },
];

#[test]
fn touching_faces_are_a_warning_with_locations() {
    for touching in &TOUCHING {
        for (name, scale, translation) in PLACEMENTS {
            let (case, volume) = (touching.case, touching.volume);
            let shape = placed(&(touching.make)(), scale, translation);
            let what = format!("{case}, {name}");
            let checked = compute(&shape, true).unwrap_or_else(|e| panic!("{what}: {e}"));
            assert_eq!(checked.warnings, Warnings::TOUCHING_FACES, "{what}");
            assert_close(checked.volume, volume * scale.powi(3), &what);
            let plain = compute(&shape, false).unwrap();
            assert_eq!(plain.warnings, Warnings::INTERSECTIONS_UNCHECKED, "{what}");
            assert_same_body(&checked, &plain, &what);
            let found = report(&shape, true);
            assert!(found.is_solid(), "{what}: {:?}", found.error);
            assert_eq!(found.intersecting_face_pairs.count, 0, "{what}");
            let touching = &found.touching_face_pairs;
            assert!(touching.count >= 1, "{what}");
            assert!(touching.first.iter().all(|&[a, b]| a < b), "{what}");
        }
    }
}
