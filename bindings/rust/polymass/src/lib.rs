//! Mass properties of solid polyhedra and planar polygons: volume, mass,
//! centre of mass, inertia tensor (about the centre of mass, the origin or any
//! point), principal moments and axes, surface area — a safe binding of the
//! libpolymass C library.
//!
//! ```
//! use polymass::{Body, Options, Surface};
//!
//! // A unit cube of aluminium (kg/m^3, positions in metres), as twelve triangles.
//! let positions = [
//!     [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0],
//!     [0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 1.0, 1.0],
//! ];
//! let triangles = [
//!     [0u32, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
//!     [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7],
//! ];
//! let cube = Surface::triangles(&positions, &triangles);
//! let p = polymass::mass_properties(&cube, &Options::new(), &Body::density(2700.0))?;
//! assert!((p.mass - 2700.0).abs() < 1e-12);
//! assert!((p.inertia[0][0] - 2700.0 / 6.0).abs() < 1e-10);
//! # Ok::<(), polymass::Error>(())
//! ```
//!
//! # Input
//! A [`Surface`] borrows the caller's data: [`Positions`] as `&[[f64; 3]]`
//! or `&[[f32; 3]]`, or interleaved with other vertex attributes at any
//! stride (an engine's vertex buffer, read in place); triangles as
//! `&[[u32; 3]]` or `&[[u16; 3]]`, or polygon faces as indices plus face
//! sizes. Faces are counter-clockwise seen from outside.
//!
//! # Options, per call
//! Every call that analyses a surface takes [`Options`]; the defaults check
//! everything (indices, finiteness, closed, manifold, consistently oriented,
//! planar polygons, not inverted, no faces crossing and no shells nested
//! twice, whose volume would count twice): bad input gives an [`Error`],
//! never a crash. Options relax the checks by name (welding for STL triangle
//! soups, inverted solids, trusted input: [`Options::skip_topology_checks`],
//! [`Options::skip_intersection_check`]) or ask for an approximation that
//! says what it did ([`Options::repair`], [`Options::fallback`]).
//!
//! # One call, or one analysis
//! - [`mass_properties`]: surface, options and body in, properties out; an
//!   engine's load path. [`batch`]: many at once.
//! - [`Mesh::new`]: one analysis of a surface, whose every question is a
//!   cheap read: [`Mesh::status`], [`Mesh::diagnostics`] (every problem at
//!   once, with locations), [`Mesh::shells`], [`Mesh::shell_of_face`],
//!   [`Mesh::provenance`], [`Mesh::moments`], [`Mesh::mass_properties`] for
//!   any density or mass.
//! - [`MassProperties::inertia_about`]: the inertia about any point.
//! - [`Moments`]: parts added, subtracted, moved, scaled and weighted.
//! - [`weld_positions`]: the library's welding over positions alone.
//!
//! # Conventions
//! No units of its own: lengths in L, density in M/L³ ([`Body`]), mass in M,
//! inertia in M·L². The inertia tensor is `∫ρ(|r|²𝟙 − r rᵀ) dV`, with the
//! negated products of inertia off the diagonal (URDF, SDFormat, MuJoCo,
//! PhysX, Bullet). Matrices are `[row][column]`.
//!
//! # Contexts and threads
//! The C library keeps a caller's worker threads, scratch memory and last
//! error message in a context that one thread uses at a time. Here:
//! - the free functions and [`Mesh`]'s methods make a context for the call:
//!   nothing to manage, and any thread may call them;
//! - a [`Context`] (`Send`, not `Sync`) is kept for worker threads
//!   ([`Context::set_threads`]) or reuse, one thread at a time;
//! - a [`Mesh`] (`Send + Sync`) is immutable: any number of threads read it;
//! - a [`Surface`] (`Send + Sync`) is shared borrows of the caller's data.
//!
//! # Linking
//! `polymass-sys` finds the C library through `POLYMASS_LIB_DIR`, pkg-config
//! or the project's build tree, and links it dynamically (the `static`
//! feature links `libpolymass.a`; `bundled` builds it from source). See the
//! crate README.
#![warn(missing_docs)]

mod body;
mod codes;
mod context;
mod diagnostics;
mod error;
mod mesh;
mod moments;
mod options;
mod packed;
mod polygon;
mod properties;
mod provenance;
mod shell;
mod surface;
mod weld;

use std::ffi::CStr;

pub use body::Body;
pub use context::Context;
pub use diagnostics::{Checks, Diagnostics, Occurrences};
pub use error::{Error, ErrorKind, Result};
pub use mesh::Mesh;
pub use moments::Moments;
pub use options::{Mode, Options};
pub use packed::{packed_mass_properties, PackedMassProperties, PackedMeshes};
pub use polygon::{Orientation, PolygonProperties, SecondMoments};
pub use properties::{ErrorBound, MassProperties, Warnings};
pub use provenance::Provenance;
pub use shell::{Shell, ShellKind};
pub use surface::{Coordinate, Index, PackedIndex, Positions, Surface, Vertex};
pub use weld::Weld;

/// How many locations [`Occurrences::first`] lists at most: the C library's
/// `POLYMASS_DIAGNOSTIC_LOCATIONS`.
///
/// ```
/// assert_eq!(polymass::LOCATIONS, 8);
/// ```
pub const LOCATIONS: usize = polymass_sys::POLYMASS_DIAGNOSTIC_LOCATIONS as usize;

/// How many face pairs of a kind (crossing, touching) the intersection check
/// counts: past that, [`Diagnostics::intersecting_face_pairs`] and
/// [`Diagnostics::touching_face_pairs`] are lower bounds. Once that many
/// cross, the check ends there: the touching count is then a lower bound
/// whatever its value. The C library's `POLYMASS_MAX_COUNTED_FACE_PAIRS`.
///
/// ```
/// assert_eq!(polymass::MAX_COUNTED_FACE_PAIRS, 2048);
/// ```
pub const MAX_COUNTED_FACE_PAIRS: u64 = polymass_sys::POLYMASS_MAX_COUNTED_FACE_PAIRS as u64;

use polymass_sys as sys;

/// The README's example, compiled and run as a doc test.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

/// The mass properties of a surface as `body`, analysed with `options`; see
/// [`Context::mass_properties`]. To ask more of one analysis (what is wrong,
/// the shells, several bodies), make a [`Mesh`].
///
/// ```
/// use polymass::{Body, Options, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let surface = Surface::triangles(&positions, &triangles);
/// let p = polymass::mass_properties(&surface, &Options::new(), &Body::mass(2.0))?;
/// assert!((p.density - 12.0).abs() < 1e-13);
/// # Ok::<(), polymass::Error>(())
/// ```
pub fn mass_properties(
    surface: &Surface<'_>,
    options: &Options,
    body: &Body,
) -> Result<MassProperties> {
    Context::new()?.mass_properties(surface, options, body)
}

/// The mass properties of many surfaces in one call, each with its own
/// options and body; see [`Context::batch`].
///
/// ```
/// use polymass::{Body, Options, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let surface = Surface::triangles(&positions, &triangles);
/// let results = polymass::batch(&[
///     (surface, Options::new(), Body::default()),
///     (surface, Options::new(), Body::mass(1.0)),
/// ])?;
/// assert_eq!(results.len(), 2);
/// # Ok::<(), polymass::Error>(())
/// ```
pub fn batch(items: &[(Surface<'_>, Options, Body)]) -> Result<Vec<Result<MassProperties>>> {
    Context::new()?.batch(items)
}

/// Area properties of a simple polygon in the xy plane; see
/// [`Context::polygon`].
///
/// ```
/// let p = polymass::polygon(&[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]])?;
/// assert_eq!((p.area, p.centroid), (2.0, [1.0, 0.5]));
/// # Ok::<(), polymass::Error>(())
/// ```
pub fn polygon(points: &[[f64; 2]]) -> Result<PolygonProperties> {
    Context::new()?.polygon(points)
}

/// The library's welding over positions alone; see
/// [`Context::weld_positions`] and [`Weld`].
pub fn weld_positions(positions: Positions<'_>, tolerance: f64) -> Result<Weld> {
    Context::new()?.weld_positions(positions, tolerance)
}

/// The version of the C library loaded at run time, "MAJOR.MINOR.PATCH".
/// Its major version is that of the header the bindings were generated from
/// (the shared library is linked by its SONAME, `libpolymass.so.MAJOR`).
///
/// ```
/// assert!(polymass::version().starts_with("2."));
/// ```
pub fn version() -> &'static str {
    // SAFETY: static, NUL-terminated text, never NULL.
    let text = unsafe { CStr::from_ptr(sys::polymass_version_string()) };
    text.to_str().unwrap_or("(version text is not UTF-8)")
}
