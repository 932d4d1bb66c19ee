//! Builds with `polymass = { ..., features = ["bundled"] }` alone and computes
//! the volume of a tetrahedron whose exact volume, 6, is a double.

use polymass::{Body, Options, Surface};

fn main() -> Result<(), polymass::Error> {
    let positions = [
        [0.0, 0.0, 0.0],
        [6.0, 0.0, 0.0],
        [0.0, 6.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    let surface = Surface::triangles(&positions, &triangles);
    let properties = polymass::mass_properties(&surface, &Options::new(), &Body::density(1.0))?;
    assert_eq!(properties.volume, 6.0, "the tetrahedron's volume");
    println!(
        "bundled libpolymass {}: tetrahedron volume {}",
        polymass::version(),
        properties.volume
    );
    Ok(())
}
