//! Mass properties of an aluminium L-bracket, a mesh built in code.
//!
//! The bracket is an L-shaped profile (a non-convex hexagon, 40 x 30 mm with
//! 10 mm thick legs) extruded 20 mm along z: two hexagonal caps and six quads,
//! given as polygon faces. Lengths are in metres and the density in kg/m³, so
//! the mass is in kg and the inertia in kg·m².
//!
//!     cargo run -p polymass-examples --bin mass_properties

use std::process::ExitCode;

use polymass::{Body, MassProperties, Options, Surface};

/// The L profile, counter-clockwise seen from +z, at z = 0 (vertices 0-5) and
/// at z = 0.02 (vertices 6-11).
const POSITIONS: [[f64; 3]; 12] = [
    [0.00, 0.00, 0.00],
    [0.04, 0.00, 0.00],
    [0.04, 0.01, 0.00],
    [0.01, 0.01, 0.00], // the inner (reflex) corner
    [0.01, 0.03, 0.00],
    [0.00, 0.03, 0.00],
    [0.00, 0.00, 0.02],
    [0.04, 0.00, 0.02],
    [0.04, 0.01, 0.02],
    [0.01, 0.01, 0.02],
    [0.01, 0.03, 0.02],
    [0.00, 0.03, 0.02],
];

/// Counter-clockwise seen from outside: the bottom cap is the profile
/// reversed, the top cap the profile, then one quad per profile edge.
#[rustfmt::skip]
const INDICES: [u32; 36] = [
    5, 4, 3, 2, 1, 0,   // bottom cap (z = 0), normal -z
    6, 7, 8, 9, 10, 11, // top cap (z = 0.02), normal +z
    0, 1, 7, 6,         // side on edge 0-1
    1, 2, 8, 7,         // side on edge 1-2
    2, 3, 9, 8,         // side on edge 2-3
    3, 4, 10, 9,        // side on edge 3-4
    4, 5, 11, 10,       // side on edge 4-5
    5, 0, 6, 11,        // side on edge 5-0
];
const FACE_SIZES: [u32; 8] = [6, 6, 4, 4, 4, 4, 4, 4];

/// Aluminium, kg/m³.
const DENSITY: f64 = 2700.0;

fn main() -> ExitCode {
    println!("libpolymass {}", polymass::version());
    let bracket = Surface::polygons(&POSITIONS, &INDICES, &FACE_SIZES);
    match polymass::mass_properties(&bracket, &Options::new(), &Body::density(DENSITY)) {
        Ok(properties) => {
            print_properties(&properties);
            ExitCode::SUCCESS
        }
        Err(error) => {
            eprintln!("mass properties failed: {error}");
            ExitCode::FAILURE
        }
    }
}

fn print_properties(p: &MassProperties) {
    println!("volume           {:.6e} m^3", p.volume);
    println!("mass             {:.6e} kg", p.mass);
    println!("surface area     {:.6e} m^2", p.surface_area);
    let [x, y, z] = p.center_of_mass;
    println!("centre of mass   ({x:.6e}, {y:.6e}, {z:.6e}) m");
    for (row, values) in p.inertia.iter().enumerate() {
        let label = if row == 0 { "inertia (COM)" } else { "" };
        println!(
            "{label:<16} [{:>13.6e} {:>13.6e} {:>13.6e}] kg*m^2",
            values[0], values[1], values[2]
        );
    }
    for (i, moment) in p.principal_moments.iter().enumerate() {
        // Column i of the rotation is the axis of principal moment i.
        let axis = p.principal_axes.map(|row| row[i]);
        println!(
            "principal {}      {moment:.6e} kg*m^2 about ({:+.4}, {:+.4}, {:+.4})",
            i + 1,
            axis[0],
            axis[1],
            axis[2]
        );
    }
    if !p.warnings.is_empty() {
        println!("warnings         {:?}", p.warnings);
    }
}
