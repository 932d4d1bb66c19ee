//! Meshes/s of the packed call from Rust, on the C benchmark's workload.
//!
//! ```sh
//! cargo run --release --example bench_packed [-- MESHES FACES ROUNDS --checks default|topology|trusted]
//! ```
//!
//! The workload of tests/benchmark/bench_batch.c: closed latitude-longitude
//! spheres of 1,000 triangles (default 5,000 of them), each at its own place,
//! in one packed array, with the options named as bench_batch takes them
//! (default: the default options; "topology": no intersection check;
//! "trusted": no check, where the per-mesh costs around the computation
//! weigh most). Times, interleaved and each as the median of ROUNDS (default
//! 5), on one thread and on two: `polymass_packed_compute` itself through
//! polymass-sys on the arrays described once (what a C caller pays, the
//! bound of this run), `Context::packed_mass_properties` on the same slices
//! (u32 indices local to each mesh, and global ones in u32 and in u64 as
//! PyTorch3D packs them; `polymass::packed_mass_properties` is this on a context of one
//! thread made for the call), and `Context::batch` on a surface per mesh
//! (the per-item batch).
//! Prints meshes/s and the ratios; asserts nothing about speed (every path's
//! volumes are checked bit for bit against the C call's, once, outside the
//! timing).

use std::time::Instant;

use polymass::{Body, Context, Options, PackedMeshes, Surface};
use polymass_sys as sys;

/// bench_batch.c's closed sphere at `(cx, 0, 0)`: 2 poles and
/// `segments - 1` rings of `rings` vertices, `2 * rings * (segments - 1)`
/// triangles, outward.
fn sphere(rings: u32, segments: u32, cx: f64) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let pi = std::f64::consts::PI;
    let mut positions = vec![[cx, 0.0, 1.0]];
    for i in 1..segments {
        for j in 0..rings {
            let theta = pi * f64::from(i) / f64::from(segments);
            let phi = 2.0 * pi * f64::from(j) / f64::from(rings);
            positions.push([
                cx + theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ]);
        }
    }
    positions.push([cx, 0.0, -1.0]);
    let south = 1 + (segments - 1) * rings;
    let mut triangles = Vec::new();
    for j in 0..rings {
        let (a, b) = (1 + j, 1 + (j + 1) % rings);
        let last_ring = 1 + (segments - 2) * rings;
        let (c, d) = (last_ring + j, last_ring + (j + 1) % rings);
        triangles.push([0, a, b]);
        triangles.push([south, d, c]);
    }
    for i in 0..segments - 2 {
        for j in 0..rings {
            let (a, b) = (1 + i * rings + j, 1 + i * rings + (j + 1) % rings);
            let (c, d) = (a + rings, b + rings);
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
    }
    (positions, triangles)
}

/// The options `bench_batch` names `checks`, for the crate and as the C
/// flags they stand for.
fn options_named(checks: &str) -> (Options, u32) {
    match checks {
        "default" => (Options::new(), 0),
        "topology" => (
            Options::new().skip_intersection_check(true),
            sys::POLYMASS_OPTION_SKIP_INTERSECTION_CHECK,
        ),
        "trusted" => (
            Options::new().skip_topology_checks(true),
            sys::POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS,
        ),
        _ => panic!("--checks default, topology or trusted, not {checks}"),
    }
}

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// `polymass_packed_compute` on a raw context of `threads` threads, the
/// meshes described once: only the status and volume columns are written,
/// as in bench_batch.c.
struct RawCall {
    context: *mut sys::polymass_context,
    meshes: sys::polymass_packed_meshes,
    options: sys::polymass_options,
}

impl RawCall {
    fn new(threads: u32, meshes: sys::polymass_packed_meshes, flags: u32) -> RawCall {
        let mut context = std::ptr::null_mut();
        // SAFETY: a valid out pointer; NULL allocator selects malloc.
        assert_eq!(
            unsafe { sys::polymass_context_create(&mut context, std::ptr::null()) },
            0
        );
        // SAFETY: the live context just created.
        assert_eq!(
            unsafe { sys::polymass_context_set_threads(context, threads) },
            0
        );
        let mut options = sys::polymass_options::default();
        let size = std::mem::size_of::<sys::polymass_options>() as u32;
        // SAFETY: options is a polymass_options of that size.
        assert_eq!(unsafe { sys::polymass_options_init(&mut options, size) }, 0);
        options.flags = flags;
        RawCall {
            context,
            meshes,
            options,
        }
    }

    fn volumes(&self) -> Vec<f64> {
        let count = self.meshes.mesh_count as usize;
        let (mut status, mut volume) = (vec![0i32; count], vec![0.0f64; count]);
        let results = sys::polymass_packed_results {
            struct_size: std::mem::size_of::<sys::polymass_packed_results>() as u32,
            status: status.as_mut_ptr(),
            volume: volume.as_mut_ptr(),
            ..Default::default()
        };
        let mut failed = 0u64;
        // SAFETY: live context, this thread only; the meshes point into
        // slices main keeps alive; the two columns have a row per mesh.
        let code = unsafe {
            sys::polymass_packed_compute(
                &results,
                &mut failed,
                self.context,
                &self.meshes,
                &self.options,
            )
        };
        assert_eq!((code, failed), (0, 0));
        volume
    }
}

impl Drop for RawCall {
    fn drop(&mut self) {
        // SAFETY: created in new, no longer used.
        unsafe { sys::polymass_context_destroy(self.context) };
    }
}

fn main() {
    let mut arguments: Vec<String> = std::env::args().skip(1).collect();
    let mut checks = String::from("default");
    if let Some(at) = arguments.iter().position(|a| a == "--checks") {
        checks = arguments
            .get(at + 1)
            .expect("--checks needs a value")
            .clone();
        arguments.drain(at..at + 2);
    }
    let number = |i: usize, default: f64| arguments.get(i).map_or(default, |t| t.parse().unwrap());
    let count = number(0, 5000.0) as usize;
    let wanted_faces = number(1, 1000.0) as u32;
    let rounds = number(2, 5.0) as usize;
    let (options, flags) = options_named(&checks);

    // faces = 2 * rings * (segments - 1): segments = 11, rings = faces / 20.
    let (segments, rings) = (11, (wanted_faces / 20).max(3));
    let (mut positions, mut local) = (Vec::new(), Vec::new());
    let (mut vertex_offsets, mut triangle_offsets) = (vec![0u64], vec![0u64]);
    for m in 0..count {
        let (p, t) = sphere(rings, segments, 3.0 * m as f64);
        positions.extend(p);
        local.extend(t);
        vertex_offsets.push(positions.len() as u64);
        triangle_offsets.push(local.len() as u64);
    }
    let faces = local.len() / count.max(1);
    let global: Vec<[u32; 3]> = local
        .iter()
        .enumerate()
        .map(|(t, triangle)| triangle.map(|v| v + vertex_offsets[t / faces] as u32))
        .collect();
    let local_meshes = PackedMeshes::new(&positions, &local, &vertex_offsets, &triangle_offsets)
        .expect("packed meshes");
    let global_meshes = PackedMeshes::new(&positions, &global, &vertex_offsets, &triangle_offsets)
        .expect("packed meshes")
        .global_indices();
    // PyTorch3D's faces_packed: int64, counted from the first vertex of all.
    let wide: Vec<[u64; 3]> = global.iter().map(|t| t.map(u64::from)).collect();
    let wide_meshes = PackedMeshes::new(&positions, &wide, &vertex_offsets, &triangle_offsets)
        .expect("packed meshes")
        .global_indices();
    let items: Vec<(Surface, Options, Body)> = vertex_offsets
        .windows(2)
        .zip(triangle_offsets.windows(2))
        .map(|(v, t)| {
            let surface = Surface::triangles(
                &positions[v[0] as usize..v[1] as usize],
                &local[t[0] as usize..t[1] as usize],
            );
            (surface, options, Body::default())
        })
        .collect();
    let index_offsets: Vec<u64> = triangle_offsets.iter().map(|t| 3 * t).collect();
    let raw_meshes = sys::polymass_packed_meshes {
        struct_size: std::mem::size_of::<sys::polymass_packed_meshes>() as u32,
        position_type: sys::POLYMASS_POSITION_FLOAT64,
        positions: positions.as_ptr().cast(),
        position_stride: 24,
        index_type: sys::POLYMASS_INDEX_UINT32,
        index_base: sys::POLYMASS_INDICES_LOCAL,
        indices: local.as_ptr().cast(),
        mesh_count: count as u64,
        vertex_offsets: vertex_offsets.as_ptr(),
        index_offsets: index_offsets.as_ptr(),
        mass_mode: sys::POLYMASS_MASS_FROM_DENSITY,
        ..Default::default()
    };

    let raw = THREADS.map(|threads| RawCall::new(threads, raw_meshes, flags));
    let mut contexts = THREADS.map(|threads| Context::with_threads(threads).expect("context"));
    let mut run = |path: usize, t: usize| -> Vec<f64> {
        let packed = |context: &mut Context, meshes| {
            let rows = context.packed_mass_properties(meshes, &options);
            rows.expect("packed call").volume
        };
        match path {
            0 => raw[t].volumes(),
            1 => packed(&mut contexts[t], &local_meshes),
            2 => packed(&mut contexts[t], &global_meshes),
            3 => packed(&mut contexts[t], &wide_meshes),
            _ => contexts[t]
                .batch(&items)
                .expect("batch")
                .into_iter()
                .map(|properties| properties.expect("a mesh of the batch").volume)
                .collect(),
        }
    };

    // Once, outside the timing: every path's volumes bit for bit the C call's.
    let bits = |volumes: Vec<f64>| volumes.into_iter().map(f64::to_bits).collect::<Vec<_>>();
    let expected = bits(run(0, 0));
    assert_eq!(expected.len(), count);
    for (path, name) in PATHS.iter().enumerate() {
        for (t, threads) in THREADS.iter().enumerate() {
            assert!(
                bits(run(path, t)) == expected,
                "{name}, {threads} threads: other volumes"
            );
        }
    }

    let mut times = vec![[Vec::new(), Vec::new()]; PATHS.len()];
    for _ in 0..rounds {
        for (path, path_times) in times.iter_mut().enumerate() {
            for (t, thread_times) in path_times.iter_mut().enumerate() {
                let start = Instant::now();
                let volumes = run(path, t);
                thread_times.push(start.elapsed().as_secs_f64());
                assert_eq!(volumes.len(), count);
            }
        }
    }
    let rates: Vec<[f64; 2]> = times
        .into_iter()
        .map(|path_times| path_times.map(|t| count as f64 / median(t)))
        .collect();
    println!(
        "polymass {}: {count} closed meshes of {faces} triangles, {checks} options, \
         median of {rounds} interleaved rounds",
        polymass::version()
    );
    for (name, [one, two]) in PATHS.iter().zip(&rates) {
        println!(
            "  {name:36} 1 thread {one:8.0} meshes/s ({:.2} of C)  \
             2 threads {two:8.0} meshes/s ({:.2} of C, {:.2}x)",
            one / rates[0][0],
            two / rates[0][1],
            two / one
        );
    }
    println!("  every path's volumes bit for bit the C call's, on 1 and 2 threads");
}

/// The threads each path runs on.
const THREADS: [u32; 2] = [1, 2];

/// The paths timed, in `main`'s order: the first is the bound.
const PATHS: [&str; 5] = [
    "C polymass_packed_compute (sys)",
    "packed_mass_properties, u32 local",
    "packed_mass_properties, u32 global",
    "packed_mass_properties, u64 global",
    "Context::batch (an item a mesh)",
];
