//! A large closed triangle mesh of any size, for the thread tests and the
//! overhead benchmark (examples/bench_overhead.rs includes this file).

/// A torus of `2 * rings * sides` triangles (major radius 3, minor 1)
/// around `(centre, centre, centre)`, outward.
pub fn torus(rings: u32, sides: u32, centre: f64) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let tau = std::f64::consts::TAU;
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for i in 0..rings {
        for j in 0..sides {
            let (u, v) = (tau * i as f64 / rings as f64, tau * j as f64 / sides as f64);
            let radius = 3.0 + v.cos();
            positions.push([
                centre + radius * u.cos(),
                centre + radius * u.sin(),
                centre + v.sin(),
            ]);
            let a = i * sides + j;
            let b = (i + 1) % rings * sides + j;
            let c = (i + 1) % rings * sides + (j + 1) % sides;
            let d = i * sides + (j + 1) % sides;
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    (positions, triangles)
}
