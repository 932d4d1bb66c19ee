//! Mass properties of solid polyhedra and planar polygons: volume, mass,
//! centre of mass, inertia tensor (about the centre of mass, the origin or any
//! point), principal moments and axes, surface area — a safe binding of the
//! libpolymass C library.
//!
//! ```
//! use polymass::{Body, Surface};
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
//! let p = polymass::mass_properties(&cube, &Body::density(2700.0))?;
//! assert!((p.mass - 2700.0).abs() < 1e-12);
//! assert!((p.inertia[0][0] - 2700.0 / 6.0).abs() < 1e-10);
//! # Ok::<(), polymass::Error>(())
//! ```
//!
//! # Input
//! A [`Surface`] borrows the caller's slices: positions as `&[[f64; 3]]` or
//! `&[[f32; 3]]`, triangles as `&[[u32; 3]]` or `&[[u16; 3]]`, or polygon
//! faces as indices plus face sizes. Faces are counter-clockwise seen from
//! outside. The library checks everything (indices, finiteness, closed,
//! manifold, consistently oriented, planar polygons, not inverted): bad input
//! gives an [`Error`], never a crash, and so do faces crossing each other
//! and shells nested twice, whose volume would count twice. [`Options`] relax
//! the checks (welding for STL triangle soups, inverted solids, trusted input:
//! [`Options::skip_topology_checks`], [`Options::skip_intersection_check`]);
//! [`check`] reports every problem
//! of a surface at once, [`shell_list`] what each shell is.
//!
//! # Conventions
//! No units of its own: lengths in L, density in M/L³ ([`Body`]), mass in M,
//! inertia in M·L². The inertia tensor is `∫ρ(|r|²𝟙 − r rᵀ) dV`, with the
//! negated products of inertia off the diagonal (URDF, SDFormat, MuJoCo,
//! PhysX, Bullet). Matrices are `[row][column]`.
//!
//! # Contexts and threads
//! The C library keeps options and the last error message in a context that
//! one thread uses at a time. Here:
//! - the free functions [`mass_properties`], [`check`], [`shell_list`] and
//!   [`polygon`], and [`Mesh::new`]/[`Mesh::mass_properties`], make a
//!   context for the call: nothing to manage, and any thread may call them;
//! - a [`Context`] (`Send`, not `Sync`) holds [`Options`] and is reused
//!   across calls, one thread at a time;
//! - a [`Mesh`] (`Send + Sync`) is a surface validated and integrated once,
//!   immutable, from which any number of threads compute bodies at once.
//!
//! # Linking
//! `polymass-sys` finds the C library through `POLYMASS_LIB_DIR`, pkg-config
//! or the project's build tree, and links it dynamically (the `static`
//! feature links `libpolymass.a`). See the crate README.
#![warn(missing_docs)]

mod body;
mod codes;
mod context;
mod diagnostics;
mod error;
mod mesh;
mod moments;
mod options;
mod polygon;
mod properties;
mod provenance;
mod shell;
mod surface;

use std::ffi::CStr;

pub use body::Body;
pub use context::Context;
pub use diagnostics::{Diagnostics, Occurrences};
pub use error::{Error, ErrorKind, Result};
pub use mesh::Mesh;
pub use moments::Moments;
pub use options::{Mode, Options};
pub use polygon::{Orientation, PolygonProperties, SecondMoments};
pub use properties::{ErrorBound, MassProperties, Warnings};
pub use provenance::Provenance;
pub use shell::{Shell, ShellKind};
pub use surface::{Index, Surface, Vertex};

/// How many locations [`Occurrences::first`] lists at most: the C library's
/// `POLYMASS_DIAGNOSTIC_LOCATIONS`.
///
/// ```
/// assert_eq!(polymass::LOCATIONS, 8);
/// ```
pub const LOCATIONS: usize = polymass_sys::POLYMASS_DIAGNOSTIC_LOCATIONS as usize;

use polymass_sys as sys;

/// The README's example, compiled and run as a doc test.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

/// The mass properties of a surface as `body`, with the default options
/// (every check on). To set options use a [`Context`]; to compute several
/// bodies from one surface, a [`Mesh`].
///
/// ```
/// use polymass::{Body, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let p = polymass::mass_properties(&Surface::triangles(&positions, &triangles), &Body::mass(2.0))?;
/// assert!((p.density - 12.0).abs() < 1e-13);
/// # Ok::<(), polymass::Error>(())
/// ```
pub fn mass_properties(surface: &Surface<'_>, body: &Body) -> Result<MassProperties> {
    Context::new()?.mass_properties(surface, body)
}

/// The mass properties of many surfaces in one call, with the default
/// options; see [`Context::batch`].
///
/// ```
/// use polymass::{Body, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let surface = Surface::triangles(&positions, &triangles);
/// let results = polymass::batch(&[(surface, Body::default()), (surface, Body::mass(1.0))])?;
/// assert_eq!(results.len(), 2);
/// # Ok::<(), polymass::Error>(())
/// ```
pub fn batch(items: &[(Surface<'_>, Body)]) -> Result<Vec<Result<MassProperties>>> {
    Context::new()?.batch(items)
}

/// Every check of a surface, run to the end, with the default options (every
/// check, crossing faces included); see [`Context::check`].
///
/// ```
/// use polymass::Surface;
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let report = polymass::check(&Surface::triangles(&positions, &triangles))?;
/// assert!(report.is_solid());
/// # Ok::<(), polymass::Error>(())
/// ```
pub fn check(surface: &Surface<'_>) -> Result<Diagnostics> {
    Context::new()?.check(surface)
}

/// What each shell of a closed surface is, with the default options; see
/// [`Context::shell_list`]; how shells nest is counted exactly.
///
/// ```
/// use polymass::{ErrorKind, Surface};
///
/// // A unit tetrahedron and, apart, a smaller one inside out.
/// let positions = [
///     [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0],
///     [3.0, 0.0, 0.0], [3.5, 0.0, 0.0], [3.0, 0.5, 0.0], [3.0, 0.0, 0.5],
/// ];
/// let triangles = [
///     [0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3],
///     [4, 5, 6], [4, 7, 5], [4, 6, 7], [5, 7, 6],
/// ];
/// let surface = Surface::triangles(&positions, &triangles);
/// let shells = polymass::shell_list(&surface)?;
/// assert_eq!(shells[1].kind, polymass::ShellKind::Inverted);
/// assert!((shells[1].signed_volume + 1.0 / 48.0).abs() < 1e-16);
/// // Which is why the surface is refused.
/// let error = polymass::mass_properties(&surface, &Default::default()).unwrap_err();
/// assert_eq!(error.kind(), ErrorKind::Inverted);
/// # Ok::<(), polymass::Error>(())
/// ```
pub fn shell_list(surface: &Surface<'_>) -> Result<Vec<Shell>> {
    Context::new()?.shell_list(surface)
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

/// The version of the C library loaded at run time, "MAJOR.MINOR.PATCH".
/// Its major version is that of the header the bindings were generated from
/// (the shared library is linked by its SONAME, `libpolymass.so.MAJOR`).
///
/// ```
/// assert!(polymass::version().starts_with("1."));
/// ```
pub fn version() -> &'static str {
    // SAFETY: static, NUL-terminated text, never NULL.
    let text = unsafe { CStr::from_ptr(sys::polymass_version_string()) };
    text.to_str().unwrap_or("(version text is not UTF-8)")
}
