//! Mass properties of the solid in a binary STL file.
//!
//!     cargo run -p polymass-examples --bin stl_mass_properties -- FILE.stl [DENSITY]
//!
//! Lengths are the file's (STL from CAD is usually in millimetres); DENSITY
//! is in mass per length unit cubed (aluminium: 2.7e-6 kg/mm³), 1 by default.
//! STL files are triangle soups, so vertices at equal positions are welded
//! for the checks. The file is analysed once: a surface that is refused is
//! reported from the same analysis, every problem with its first locations.

use std::process::ExitCode;

use polymass::{Body, Mesh, Options, Surface};
use polymass_examples::binary_stl;

fn main() -> ExitCode {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let (path, density) = match arguments.as_slice() {
        [path] => (path, 1.0),
        [path, density] => match density.parse::<f64>() {
            Ok(density) => (path, density),
            Err(_) => return usage(&format!("density '{density}' is not a number")),
        },
        _ => return usage("expected a file and an optional density"),
    };
    match run(path, density) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("stl_mass_properties: {path}: {message}");
            ExitCode::FAILURE
        }
    }
}

fn usage(problem: &str) -> ExitCode {
    eprintln!("stl_mass_properties: {problem}\nusage: stl_mass_properties FILE.stl [DENSITY]");
    ExitCode::from(2)
}

fn run(path: &str, density: f64) -> Result<(), String> {
    let bytes = std::fs::read(path).map_err(|error| error.to_string())?;
    let soup = binary_stl::parse(&bytes).map_err(|error| error.to_string())?;
    let surface = Surface::triangles(&soup.positions, &soup.triangles);

    // STL repeats each vertex once per triangle: weld them. Every check is on
    // by default, crossing faces too (parts that overlap would have their
    // common volume counted twice).
    let options = Options::new().weld_vertices(true);
    let mesh = Mesh::new(&surface, &options).map_err(|error| error.to_string())?;
    // On failure, the analysis's report says everything that is wrong, not
    // just the first problem.
    let properties = match mesh.mass_properties(&Body::density(density)) {
        Ok(properties) => properties,
        Err(error) => {
            if let Ok(report) = mesh.diagnostics() {
                eprintln!("{report:#?}");
            }
            return Err(error.to_string());
        }
    };

    println!("triangles        {}", soup.triangles.len());
    println!("volume           {:.9e}", properties.volume);
    println!("mass             {:.9e}", properties.mass);
    println!("surface area     {:.9e}", properties.surface_area);
    let [x, y, z] = properties.center_of_mass;
    println!("centre of mass   ({x:.9e}, {y:.9e}, {z:.9e})");
    for (row, values) in properties.inertia.iter().enumerate() {
        let label = if row == 0 { "inertia (COM)" } else { "" };
        println!(
            "{label:<16} [{:>16.9e} {:>16.9e} {:>16.9e}]",
            values[0], values[1], values[2]
        );
    }
    let [first, second, third] = properties.principal_moments;
    println!("principal        {first:.9e}, {second:.9e}, {third:.9e}");
    if !properties.warnings.is_empty() {
        println!("warnings         {:?}", properties.warnings);
    }
    Ok(())
}
