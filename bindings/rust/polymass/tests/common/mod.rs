//! Solids with closed-form mass properties, transforms of them, and the
//! comparisons the tests make. Every expected value is derived from the
//! shape's dimensions by a closed form, never copied from a run.
#![allow(dead_code)] // each test file uses part of this module

use polymass::Surface;

pub mod torus;

/// Relative tolerance of every comparison with an exact value: volume, mass,
/// area; matrices relative to their largest entry; the centre of mass
/// relative to the larger of its distance from the origin and the shape's
/// size. The library is exact to ~1e-15 for these shapes.
pub const TOLERANCE: f64 = 1e-12;

pub type Matrix = [[f64; 3]; 3];

/// A closed surface of polygon faces (triangles are faces of 3).
#[derive(Debug, Clone)]
pub struct Shape {
    pub positions: Vec<[f64; 3]>,
    pub indices: Vec<u32>,
    pub face_sizes: Vec<u32>,
}

/// Unit-density mass properties of a shape, from a closed form.
#[derive(Debug, Clone, Copy)]
pub struct Exact {
    pub volume: f64,
    pub center_of_mass: [f64; 3],
    /// About the centre of mass.
    pub inertia: Matrix,
    pub surface_area: f64,
    /// The largest extent, the scale of the centre-of-mass comparison.
    pub size: f64,
}

impl Shape {
    pub fn surface(&self) -> Surface<'_> {
        Surface::polygons(&self.positions, &self.indices, &self.face_sizes)
    }

    /// The faces as triangles (fans), for shapes whose faces are convex.
    pub fn triangles(&self) -> Vec<[u32; 3]> {
        let mut triangles = Vec::new();
        let mut start = 0;
        for &size in &self.face_sizes {
            let face = &self.indices[start..start + size as usize];
            for i in 1..face.len() - 1 {
                triangles.push([face[0], face[i], face[i + 1]]);
            }
            start += size as usize;
        }
        triangles
    }

    /// The same shape with every face reversed (an inverted solid, or a
    /// cavity when added to an enclosing shape).
    pub fn reversed(&self) -> Shape {
        let mut indices = Vec::with_capacity(self.indices.len());
        let mut start = 0;
        for &size in &self.face_sizes {
            indices.extend(self.indices[start..start + size as usize].iter().rev());
            start += size as usize;
        }
        Shape {
            indices,
            ..self.clone()
        }
    }

    /// Both shapes in one surface (two shells).
    pub fn with(&self, other: &Shape) -> Shape {
        let offset = self.positions.len() as u32;
        let mut shape = self.clone();
        shape.positions.extend(&other.positions);
        shape
            .indices
            .extend(other.indices.iter().map(|i| i + offset));
        shape.face_sizes.extend(&other.face_sizes);
        shape
    }

    pub fn translated(&self, offset: [f64; 3]) -> Shape {
        let positions = self
            .positions
            .iter()
            .map(|p| [p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]])
            .collect();
        Shape {
            positions,
            ..self.clone()
        }
    }

    pub fn rotated(&self, rotation: &Matrix) -> Shape {
        let positions = self.positions.iter().map(|p| apply(rotation, p)).collect();
        Shape {
            positions,
            ..self.clone()
        }
    }
}

/// An axis-aligned box from `min` to `max` as six quads.
pub fn cuboid(min: [f64; 3], max: [f64; 3]) -> Shape {
    let corner = |i: usize| {
        std::array::from_fn(|axis| {
            if i >> axis & 1 == 1 {
                max[axis]
            } else {
                min[axis]
            }
        })
    };
    // Corner i has x from bit 0, y from bit 1, z from bit 2.
    let positions = (0..8).map(corner).collect();
    #[rustfmt::skip]
    let indices = vec![
        0, 2, 3, 1, // z = min, normal -z
        4, 5, 7, 6, // z = max
        0, 1, 5, 4, // y = min
        2, 6, 7, 3, // y = max
        0, 4, 6, 2, // x = min
        1, 3, 7, 5, // x = max
    ];
    Shape {
        positions,
        indices,
        face_sizes: vec![4; 6],
    }
}

pub fn cuboid_exact(min: [f64; 3], max: [f64; 3]) -> Exact {
    let [a, b, c] = [max[0] - min[0], max[1] - min[1], max[2] - min[2]];
    let volume = a * b * c;
    Exact {
        volume,
        center_of_mass: std::array::from_fn(|axis| (min[axis] + max[axis]) / 2.0),
        inertia: diagonal([
            volume * (b * b + c * c) / 12.0,
            volume * (a * a + c * c) / 12.0,
            volume * (a * a + b * b) / 12.0,
        ]),
        surface_area: 2.0 * (a * b + b * c + c * a),
        size: a.max(b).max(c),
    }
}

/// The tetrahedron with a right-angled corner at the origin and legs a, b, c
/// along the axes.
pub fn corner_tetrahedron(a: f64, b: f64, c: f64) -> Shape {
    Shape {
        positions: vec![[0.0, 0.0, 0.0], [a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]],
        indices: vec![0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3],
        face_sizes: vec![3; 4],
    }
}

/// V = abc/6, centroid at a quarter of each leg; about the centroid
/// Ixx = 3V(b² + c²)/80 and Ixy = +Vab/80 (the product ∫xy = −Vab/80).
pub fn corner_tetrahedron_exact(a: f64, b: f64, c: f64) -> Exact {
    let volume = a * b * c / 6.0;
    let k = volume / 80.0;
    let slanted = 0.5 * ((a * b).powi(2) + (b * c).powi(2) + (c * a).powi(2)).sqrt();
    Exact {
        volume,
        center_of_mass: [a / 4.0, b / 4.0, c / 4.0],
        inertia: [
            [3.0 * k * (b * b + c * c), k * a * b, k * a * c],
            [k * a * b, 3.0 * k * (a * a + c * c), k * b * c],
            [k * a * c, k * b * c, 3.0 * k * (a * a + b * b)],
        ],
        surface_area: (a * b + b * c + c * a) / 2.0 + slanted,
        size: a.max(b).max(c),
    }
}

/// Two unit corner tetrahedra sharing only the edge (0, 1) (the second is
/// the first turned half a turn about x): four faces use that edge, twice
/// in each direction. Each is exact: together they are twice one.
pub fn tetrahedra_sharing_an_edge() -> Shape {
    let one = corner_tetrahedron(1.0, 1.0, 1.0);
    let half_turn_about_x = [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]];
    let other = one.rotated(&half_turn_about_x);
    // The turn keeps vertices 0 and 1: the second tetrahedron reuses them
    // and adds its other two.
    let mut shape = one.clone();
    shape.positions.extend(&other.positions[2..]);
    let base = one.positions.len() as u32 - 2;
    shape.indices.extend(
        other
            .indices
            .iter()
            .map(|&i| if i < 2 { i } else { i + base }),
    );
    shape.face_sizes.extend(&other.face_sizes);
    shape
}

/// A right triangle with legs a (along x) and b (along y) extruded h along
/// z: two triangles and three quads.
pub fn triangular_prism(a: f64, b: f64, h: f64) -> Shape {
    Shape {
        positions: vec![
            [0.0, 0.0, 0.0],
            [a, 0.0, 0.0],
            [0.0, b, 0.0],
            [0.0, 0.0, h],
            [a, 0.0, h],
            [0.0, b, h],
        ],
        indices: vec![0, 2, 1, 3, 4, 5, 0, 1, 4, 3, 1, 2, 5, 4, 2, 0, 3, 5],
        face_sizes: vec![3, 3, 4, 4, 4],
    }
}

/// From the triangle's second moments of area about its centroid
/// (∫y² = ab³/36, ∫x² = a³b/36, ∫xy = −a²b²/72) times h, plus the
/// extrusion's A h³/12.
pub fn triangular_prism_exact(a: f64, b: f64, h: f64) -> Exact {
    let area = a * b / 2.0;
    let along_z = area * h.powi(3) / 12.0;
    let ixy = h * a * a * b * b / 72.0; // −∫xy dV
    Exact {
        volume: area * h,
        center_of_mass: [a / 3.0, b / 3.0, h / 2.0],
        inertia: [
            [h * a * b.powi(3) / 36.0 + along_z, ixy, 0.0],
            [ixy, h * a.powi(3) * b / 36.0 + along_z, 0.0],
            [0.0, 0.0, h * (a * b.powi(3) + a.powi(3) * b) / 36.0],
        ],
        surface_area: 2.0 * area + h * (a + b + (a * a + b * b).sqrt()),
        size: a.max(b).max(h),
    }
}

/// Two bodies as one: masses add, inertias move to the common centre by the
/// parallel-axis theorem; `sign` -1 removes `other` (a cavity).
pub fn combine(one: &Exact, other: &Exact, sign: f64, surface_area: f64) -> Exact {
    let volume = one.volume + sign * other.volume;
    let com: [f64; 3] = std::array::from_fn(|axis| {
        (one.volume * one.center_of_mass[axis] + sign * other.volume * other.center_of_mass[axis])
            / volume
    });
    let about_com = |part: &Exact| {
        let d: [f64; 3] = std::array::from_fn(|axis| part.center_of_mass[axis] - com[axis]);
        add(&part.inertia, &parallel_axis(part.volume, &d), 1.0)
    };
    Exact {
        volume,
        center_of_mass: com,
        inertia: add(&about_com(one), &about_com(other), sign),
        surface_area,
        size: one.size.max(other.size),
    }
}

/// m(|d|² 𝟙 − d dᵀ): what a body's inertia gains about a point at −d.
pub fn parallel_axis(mass: f64, d: &[f64; 3]) -> Matrix {
    let norm2 = d.iter().map(|x| x * x).sum::<f64>();
    std::array::from_fn(|i| {
        std::array::from_fn(|j| mass * (if i == j { norm2 } else { 0.0 } - d[i] * d[j]))
    })
}

pub fn diagonal(values: [f64; 3]) -> Matrix {
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { values[i] } else { 0.0 }))
}

pub fn add(a: &Matrix, b: &Matrix, sign: f64) -> Matrix {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] + sign * b[i][j]))
}

pub fn scaled(a: &Matrix, factor: f64) -> Matrix {
    a.map(|row| row.map(|x| factor * x))
}

pub fn multiply(a: &Matrix, b: &Matrix) -> Matrix {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

pub fn transpose(a: &Matrix) -> Matrix {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i]))
}

pub fn apply(a: &Matrix, p: &[f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| (0..3).map(|k| a[i][k] * p[k]).sum())
}

pub fn determinant(a: &Matrix) -> f64 {
    a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
}

/// The rotation of the unit quaternion (w, x, y, z) ∝ (1, 2, 3, 4): no axis
/// of it is a coordinate axis, so a rotated box has all products nonzero.
pub fn oblique_rotation() -> Matrix {
    let n = 30f64.sqrt();
    let [w, x, y, z] = [1.0 / n, 2.0 / n, 3.0 / n, 4.0 / n];
    [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ]
}

/// `R I Rᵀ` and the rotated centre: the exact properties of a rotated body.
pub fn rotate_exact(exact: &Exact, rotation: &Matrix) -> Exact {
    Exact {
        center_of_mass: apply(rotation, &exact.center_of_mass),
        inertia: multiply(&multiply(rotation, &exact.inertia), &transpose(rotation)),
        ..*exact
    }
}

pub fn translate_exact(exact: &Exact, offset: [f64; 3]) -> Exact {
    Exact {
        center_of_mass: std::array::from_fn(|axis| exact.center_of_mass[axis] + offset[axis]),
        ..*exact
    }
}

pub fn assert_close(actual: f64, expected: f64, what: &str) {
    let error = (actual - expected).abs();
    assert!(
        error <= TOLERANCE * expected.abs(),
        "{what}: {actual:e}, expected {expected:e} (relative error {:e})",
        error / expected.abs()
    );
}

/// Entry-wise, relative to the largest entry of `expected`.
pub fn assert_matrix_close(actual: &Matrix, expected: &Matrix, what: &str) {
    let scale = expected
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    for i in 0..3 {
        for j in 0..3 {
            let error = (actual[i][j] - expected[i][j]).abs();
            assert!(
                error <= TOLERANCE * scale,
                "{what}[{i}][{j}]: {:e}, expected {:e} (error {:e} of {scale:e})",
                actual[i][j],
                expected[i][j],
                error
            );
        }
    }
}

/// Volume, mass (unit density), area, centre of mass and the inertia about
/// the centre of mass, all against `exact`.
pub fn assert_matches(actual: &polymass::MassProperties, exact: &Exact, what: &str) {
    assert_close(actual.volume, exact.volume, &format!("{what}: volume"));
    assert_close(actual.mass, exact.volume, &format!("{what}: mass"));
    assert_close(
        actual.surface_area,
        exact.surface_area,
        &format!("{what}: surface area"),
    );
    let distance = exact
        .center_of_mass
        .iter()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let scale = distance.max(exact.size);
    for axis in 0..3 {
        let error = (actual.center_of_mass[axis] - exact.center_of_mass[axis]).abs();
        assert!(
            error <= TOLERANCE * scale,
            "{what}: centre of mass[{axis}] {:e}, expected {:e}",
            actual.center_of_mass[axis],
            exact.center_of_mass[axis]
        );
    }
    assert_matrix_close(&actual.inertia, &exact.inertia, &format!("{what}: inertia"));
    assert!(
        actual.warnings.is_empty(),
        "{what}: warnings {:?}",
        actual.warnings
    );
}

/// Every quantity of two bodies equal to the last bit; the warnings aside.
pub fn assert_same_body(a: &polymass::MassProperties, b: &polymass::MassProperties, what: &str) {
    let scalars = |p: &polymass::MassProperties| {
        let bound = p.error_bound;
        [
            p.volume,
            p.mass,
            p.density,
            p.surface_area,
            bound.volume,
            bound.center_of_mass,
            bound.inertia,
            bound.principal_moments,
            bound.principal_axes,
        ]
    };
    assert_eq!(scalars(a), scalars(b), "{what}");
    assert_eq!(a.center_of_mass, b.center_of_mass, "{what}");
    assert_eq!(a.inertia, b.inertia, "{what}");
    assert_eq!(a.inertia_origin, b.inertia_origin, "{what}");
    assert_eq!(a.principal_moments, b.principal_moments, "{what}");
    assert_eq!(a.principal_axes, b.principal_axes, "{what}");
}
