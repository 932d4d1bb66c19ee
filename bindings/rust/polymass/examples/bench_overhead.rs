//! What the safe binding adds to the C call, on a 1,000,000-triangle torus.
//!
//! ```sh
//! cargo run --release --example bench_overhead [-- TRIANGLES REPEATS]
//! ```
//!
//! Times, interleaved and each as the median of REPEATS runs, the raw
//! `polymass_mass_properties_compute` (polymass-sys, one context, the
//! description built once) and `Context::mass_properties` on the same slices.
//! Prints the figures; asserts nothing.

use std::time::Instant;

use polymass::{Body, Context, Options, Surface};
use polymass_sys as sys;

#[path = "../tests/common/torus.rs"]
mod torus;

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn main() {
    let arguments: Vec<String> = std::env::args().collect();
    let wanted: f64 = arguments.get(1).map_or(1e6, |text| text.parse().unwrap());
    let repeats: usize = arguments.get(2).map_or(21, |text| text.parse().unwrap());
    let side = (wanted / 2.0).sqrt() as u32;
    let (positions, triangles) = torus::torus(side, side, 1e3);

    let mut raw_context = std::ptr::null_mut();
    // SAFETY: a valid out pointer; NULL allocator selects malloc.
    assert_eq!(
        unsafe { sys::polymass_context_create(&mut raw_context, std::ptr::null()) },
        0
    );
    let desc = sys::polymass_mesh_desc {
        struct_size: std::mem::size_of::<sys::polymass_mesh_desc>() as u32,
        position_type: sys::POLYMASS_POSITION_FLOAT64,
        positions: positions.as_ptr().cast(),
        position_stride: 24,
        vertex_count: positions.len() as u64,
        index_type: sys::POLYMASS_INDEX_UINT32,
        indices: triangles.as_ptr().cast(),
        index_count: 3 * triangles.len() as u64,
        ..Default::default()
    };
    let mut context = Context::new().unwrap();
    let surface = Surface::triangles(&positions, &triangles);
    let options = Options::new();
    let body = Body::default();

    let (mut c_times, mut rust_times) = (Vec::new(), Vec::new());
    for _ in 0..repeats {
        let mut out = sys::polymass_mass_properties {
            struct_size: std::mem::size_of::<sys::polymass_mass_properties>() as u32,
            ..Default::default()
        };
        let start = Instant::now();
        // SAFETY: live context; desc points into positions and triangles;
        // NULL provenance, options (the defaults) and mass (unit density).
        let status = unsafe {
            sys::polymass_mass_properties_compute(
                &mut out,
                std::ptr::null_mut(),
                raw_context,
                &desc,
                std::ptr::null(),
                std::ptr::null(),
            )
        };
        c_times.push(start.elapsed().as_secs_f64());
        assert_eq!(status, 0);
        let start = Instant::now();
        let properties = context.mass_properties(&surface, &options, &body).unwrap();
        rust_times.push(start.elapsed().as_secs_f64());
        assert_eq!(properties.volume, out.volume);
    }
    // SAFETY: created above, no longer used.
    unsafe { sys::polymass_context_destroy(raw_context) };
    let (c, rust) = (median(c_times), median(rust_times));
    println!(
        "{} triangles, median of {repeats} interleaved runs",
        triangles.len()
    );
    println!("  C call:        {:8.3} ms", c * 1e3);
    println!("  Rust binding:  {:8.3} ms", rust * 1e3);
    println!(
        "  overhead:      {:8.3} ms = {:.2} %",
        (rust - c) * 1e3,
        100.0 * (rust - c) / c
    );
}
