//! A packed call gives each mesh its single call's result, bit for bit,
//! whatever the positions' and indices' types, the index base and the thread
//! count, and keeps each failure to its own row.

mod common;

use common::torus::torus;
use polymass::{
    Body, Context, ErrorKind, MassProperties, Options, PackedIndex, PackedMassProperties,
    PackedMeshes, Surface, Vertex,
};

/// Positions, triangles with local indices, vertex and triangle offsets.
type Packed = (Vec<[f64; 3]>, Vec<[u32; 3]>, Vec<u64>, Vec<u64>);

/// Tori of several sizes, each at its own place, packed.
fn packed_tori() -> Packed {
    let (mut positions, mut triangles) = (Vec::new(), Vec::new());
    let (mut vertex_offsets, mut triangle_offsets) = (vec![0u64], vec![0u64]);
    for i in 0..5u32 {
        let (p, t) = torus(6 + 2 * i, 4 + i, 10.0 * f64::from(i) + 1e3);
        positions.extend(p);
        triangles.extend(t);
        vertex_offsets.push(positions.len() as u64);
        triangle_offsets.push(triangles.len() as u64);
    }
    (positions, triangles, vertex_offsets, triangle_offsets)
}

/// Row `i` holds exactly `single`'s numbers.
fn assert_row_is(rows: &PackedMassProperties, i: usize, single: &MassProperties) {
    assert!(rows.errors[i].is_none());
    assert_eq!(rows.warnings[i], single.warnings);
    let bits = |values: &[f64]| values.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&[rows.volume[i]]), bits(&[single.volume]));
    assert_eq!(bits(&[rows.mass[i]]), bits(&[single.mass]));
    assert_eq!(bits(&[rows.surface_area[i]]), bits(&[single.surface_area]));
    assert_eq!(bits(&rows.center_of_mass[i]), bits(&single.center_of_mass));
    assert_eq!(
        bits(rows.inertia[i].as_flattened()),
        bits(single.inertia.as_flattened())
    );
    assert_eq!(
        bits(&rows.principal_moments[i]),
        bits(&single.principal_moments)
    );
    assert_eq!(
        bits(rows.principal_axes[i].as_flattened()),
        bits(single.principal_axes.as_flattened())
    );
    assert_eq!(
        rows.error_bound_volume[i].to_bits(),
        single.error_bound.volume.to_bits()
    );
    assert_eq!(
        rows.error_bound_center_of_mass[i].to_bits(),
        single.error_bound.center_of_mass.to_bits()
    );
    assert_eq!(
        rows.error_bound_inertia[i].to_bits(),
        single.error_bound.inertia.to_bits()
    );
}

/// Rows `meshes` hold the single calls on those meshes of the packed arrays,
/// each with `body(mesh)`, on u32 local triangles (an index's type changes
/// no digit).
fn assert_rows_are_single_calls<V: Vertex>(
    rows: &PackedMassProperties,
    meshes: impl IntoIterator<Item = usize>,
    positions: &[V],
    triangles: &[[u32; 3]],
    vertex_offsets: &[u64],
    triangle_offsets: &[u64],
    body: impl Fn(usize) -> Body,
) {
    for mesh in meshes {
        let vertices = vertex_offsets[mesh] as usize..vertex_offsets[mesh + 1] as usize;
        let faces = triangle_offsets[mesh] as usize..triangle_offsets[mesh + 1] as usize;
        let surface = Surface::triangles(&positions[vertices], &triangles[faces]);
        let single = polymass::mass_properties(&surface, &Options::new(), &body(mesh)).unwrap();
        assert_row_is(rows, mesh, &single);
    }
}

/// The packed local triangles with indices of type I, counted from each
/// mesh's first vertex (local) or from the first of all (global).
fn pack_indices<I>(
    triangles: &[[u32; 3]],
    vertex_offsets: &[u64],
    triangle_offsets: &[u64],
    global: bool,
    index: impl Fn(u32) -> I,
) -> Vec<[I; 3]> {
    let mut packed = Vec::new();
    for mesh in 0..vertex_offsets.len() - 1 {
        let base = if global {
            vertex_offsets[mesh] as u32
        } else {
            0
        };
        let range = triangle_offsets[mesh] as usize..triangle_offsets[mesh + 1] as usize;
        packed.extend(triangles[range].iter().map(|t| t.map(|v| index(v + base))));
    }
    packed
}

/// Packs the tori with positions of type V and indices of type I, local or
/// global, and compares every row with the single call (u32 indices: an
/// index's type changes no digit) on 1 and 3 threads.
fn check_types<V: Vertex + Copy, I: PackedIndex + Copy>(
    vertex: impl Fn([f64; 3]) -> V,
    index: impl Fn(u32) -> I,
) {
    let (positions, triangles, vertex_offsets, triangle_offsets) = packed_tori();
    let positions: Vec<V> = positions.into_iter().map(vertex).collect();
    let densities: Vec<f64> = (0..5).map(|i| 0.5 + f64::from(i)).collect();
    for global in [false, true] {
        let packed_triangles = pack_indices(
            &triangles,
            &vertex_offsets,
            &triangle_offsets,
            global,
            &index,
        );
        let mut meshes = PackedMeshes::new(
            &positions,
            &packed_triangles,
            &vertex_offsets,
            &triangle_offsets,
        )
        .unwrap()
        .densities(&densities)
        .unwrap();
        if global {
            meshes = meshes.global_indices();
        }
        for threads in [1, 3] {
            let mut context = Context::with_threads(threads).unwrap();
            let rows = context
                .packed_mass_properties(&meshes, &Options::new())
                .unwrap();
            assert_eq!(rows.failed(), 0);
            assert_rows_are_single_calls(
                &rows,
                0..5,
                &positions,
                &triangles,
                &vertex_offsets,
                &triangle_offsets,
                |mesh| Body::density(densities[mesh]),
            );
        }
    }
}

#[test]
fn rows_are_single_calls_bit_for_bit() {
    check_types(|p| p, |i| i);
    check_types(|p| p.map(|c| c as f32), |i| i);
    check_types(|p| p, |i| u16::try_from(i).unwrap());
    check_types(|p| p.map(|c| c as f32), |i| u16::try_from(i).unwrap());
    check_types(|p| p, u64::from);
    check_types(|p| p.map(|c| c as f32), u64::from);
}

/// 64-bit indices are narrowed per mesh: one past 32 bits fails its own mesh,
/// named as written, locally and globally.
#[test]
fn a_64_bit_index_past_32_bits_fails_its_mesh_alone() {
    let (positions, triangles, vertex_offsets, triangle_offsets) = packed_tori();
    for global in [false, true] {
        let mut wide = pack_indices(
            &triangles,
            &vertex_offsets,
            &triangle_offsets,
            global,
            u64::from,
        );
        let too_large = (1u64 << 32) + 7;
        wide[triangle_offsets[2] as usize + 1][2] = too_large;
        let mut meshes =
            PackedMeshes::new(&positions, &wide, &vertex_offsets, &triangle_offsets).unwrap();
        if global {
            meshes = meshes.global_indices();
        }
        let rows = polymass::packed_mass_properties(&meshes, &Options::new()).unwrap();
        assert_eq!(rows.failed(), 1);
        let error = rows.errors[2].as_ref().unwrap();
        assert_eq!(error.kind(), ErrorKind::IndexOutOfRange);
        assert!(
            error.message().contains(&too_large.to_string()),
            "{}",
            error.message()
        );
        assert_rows_are_single_calls(
            &rows,
            [0, 1, 3, 4],
            &positions,
            &triangles,
            &vertex_offsets,
            &triangle_offsets,
            |_| Body::default(),
        );
    }
}

#[test]
fn a_failed_mesh_is_its_row_alone() {
    let (positions, mut triangles, vertex_offsets, triangle_offsets) = packed_tori();
    triangles.remove(triangle_offsets[1] as usize); // mesh 1 open ...
    let triangle_offsets: Vec<u64> = triangle_offsets
        .iter()
        .enumerate()
        .map(|(i, &t)| if i >= 2 { t - 1 } else { t })
        .collect();
    triangles[triangle_offsets[3] as usize][1] = 1_000_000; // ... mesh 3 out of range
    let meshes =
        PackedMeshes::new(&positions, &triangles, &vertex_offsets, &triangle_offsets).unwrap();
    let rows = polymass::packed_mass_properties(&meshes, &Options::new()).unwrap();
    assert_eq!(rows.failed(), 2);
    assert_eq!(rows.errors[1].as_ref().unwrap().kind(), ErrorKind::Open);
    assert_eq!(
        rows.errors[3].as_ref().unwrap().kind(),
        ErrorKind::IndexOutOfRange
    );
    assert!(rows.errors[3]
        .as_ref()
        .unwrap()
        .message()
        .contains("vertex 1000000"));
    assert!(rows.volume[1].is_nan() && rows.inertia[3][2][2].is_nan());
    assert_rows_are_single_calls(
        &rows,
        [0, 2, 4],
        &positions,
        &triangles,
        &vertex_offsets,
        &triangle_offsets,
        |_| Body::default(),
    );
}

#[test]
fn sets_that_are_not_packed_meshes_are_refused() {
    let (positions, triangles, vertex_offsets, triangle_offsets) = packed_tori();
    let short = &vertex_offsets[..5];
    let error = PackedMeshes::new(&positions, &triangles, short, &triangle_offsets).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    let cut = &triangle_offsets[..5];
    let error = PackedMeshes::new(&positions, &triangles, &vertex_offsets[..5], cut).unwrap_err();
    assert!(error.message().contains("end at"));
    let meshes =
        PackedMeshes::new(&positions, &triangles, &vertex_offsets, &triangle_offsets).unwrap();
    assert_eq!(meshes.len(), 5);
    assert!(meshes.clone().masses(&[1.0]).is_err());
    let mut descending = vertex_offsets.clone();
    descending[2] = descending[3] + 1;
    let meshes = PackedMeshes::new(&positions, &triangles, &descending, &triangle_offsets).unwrap();
    let error = polymass::packed_mass_properties(&meshes, &Options::new()).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    assert!(error.message().contains("ascend"));
}
