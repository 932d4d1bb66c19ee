//! What one analysis checks and accepts (`polymass_options`), given per call.

use polymass_sys as sys;

use crate::surface::struct_size;

/// What one analysis checks and accepts, and how it turns the surface into
/// a body: a plain value given to every call that analyses a surface
/// ([`mass_properties`](crate::mass_properties), [`Mesh::new`](crate::Mesh::new),
/// a [`batch`](crate::batch) item, ...), never kept by a context. Built with
/// chained setters from the defaults, the safe ones: every check on, nothing
/// welded, the default planarity tolerance, the exact solid alone. The
/// library validates the values in the call that takes them
/// ([`ErrorKind::InvalidArgument`](crate::ErrorKind::InvalidArgument)).
///
/// ```
/// use polymass::Options;
///
/// // An STL triangle soup from a CAD export: weld vertices closer than 1e-9
/// // of the part's size before checking that the surface is closed.
/// let options = Options::new().weld_vertices(true).with_weld_tolerance(1e-9);
/// assert!(options.welds_vertices());
/// assert_eq!(options.weld_tolerance(), 1e-9);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Options {
    flags: u32,
    planarity_tolerance: f64,
    weld_tolerance: f64,
    modes: [u32; sys::POLYMASS_MAX_MODES as usize],
    shell_thickness: f64,
}

/// How a surface becomes a body (`POLYMASS_MODE_*`): see
/// [`Options::repair`], [`Options::shell`], [`Options::hull`] and
/// [`Options::fallback`], and [`Provenance::mode`](crate::Provenance::mode)
/// for the one that answered.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Mode {
    /// Exact for a valid closed solid; otherwise the solid's error.
    Solid,
    /// The surface repaired where the fix is unique, each fix recorded.
    Repair,
    /// The surface as a thin wall of the options' shell thickness.
    Shell,
    /// The convex hull of the vertices.
    Hull,
}

impl Mode {
    pub(crate) fn to_raw(self) -> u32 {
        match self {
            Mode::Solid => sys::POLYMASS_MODE_SOLID,
            Mode::Repair => sys::POLYMASS_MODE_REPAIR,
            Mode::Shell => sys::POLYMASS_MODE_SHELL,
            Mode::Hull => sys::POLYMASS_MODE_HULL,
        }
    }

    pub(crate) fn from_raw(raw: u32) -> Option<Mode> {
        match raw {
            sys::POLYMASS_MODE_SOLID => Some(Mode::Solid),
            sys::POLYMASS_MODE_REPAIR => Some(Mode::Repair),
            sys::POLYMASS_MODE_SHELL => Some(Mode::Shell),
            sys::POLYMASS_MODE_HULL => Some(Mode::Hull),
            _ => None,
        }
    }
}

impl Options {
    /// The defaults: all checks on, nothing accepted, exact welding off.
    ///
    /// ```
    /// assert!(!polymass::Options::new().skips_topology_checks());
    /// ```
    pub fn new() -> Options {
        Options::default()
    }

    fn with_flag(mut self, flag: u32, on: bool) -> Options {
        if on {
            self.flags |= flag;
        } else {
            self.flags &= !flag;
        }
        self
    }

    /// Trusted input (a game engine at load time): skip the open,
    /// non-manifold, orientation and planarity checks, and the intersection
    /// check with them. Index range and finiteness are always checked.
    /// Results then carry
    /// [`Warnings::UNCHECKED`](crate::Warnings::UNCHECKED).
    ///
    /// ```
    /// assert!(polymass::Options::new().skip_topology_checks(true).skips_topology_checks());
    /// ```
    pub fn skip_topology_checks(self, on: bool) -> Options {
        self.with_flag(sys::POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS, on)
    }

    /// Accept a solid whose faces are all reversed: its properties are those
    /// of the solid turned the right way, with
    /// [`Warnings::INVERTED`](crate::Warnings::INVERTED).
    ///
    /// ```
    /// assert!(polymass::Options::new().accept_inverted(true).accepts_inverted());
    /// ```
    pub fn accept_inverted(self, on: bool) -> Options {
        self.with_flag(sys::POLYMASS_OPTION_ACCEPT_INVERTED, on)
    }

    /// Treat vertices at the same position (within
    /// [`weld_tolerance`](Options::weld_tolerance)) as one for the topology
    /// checks, as STL-style triangle soups need. The integrals do not depend
    /// on it.
    ///
    /// ```
    /// assert!(polymass::Options::new().weld_vertices(true).welds_vertices());
    /// ```
    pub fn weld_vertices(self, on: bool) -> Options {
        self.with_flag(sys::POLYMASS_OPTION_WELD_VERTICES, on)
    }

    /// Accept edges shared by more than two faces when they are traversed as
    /// often in one direction as in the other (solids touching along an
    /// edge), with [`Warnings::NON_MANIFOLD`](crate::Warnings::NON_MANIFOLD).
    ///
    /// ```
    /// assert!(polymass::Options::new().accept_non_manifold(true).accepts_non_manifold());
    /// ```
    pub fn accept_non_manifold(self, on: bool) -> Options {
        self.with_flag(sys::POLYMASS_OPTION_ACCEPT_NON_MANIFOLD, on)
    }

    /// For trusted input only: skip the intersection check. By default faces
    /// that cross each other and shells inside a solid of the same sense
    /// (their volume would be counted twice: overlapping parts exported as
    /// one file) are refused with
    /// [`ErrorKind::Intersecting`](crate::ErrorKind::Intersecting), how
    /// shells nest judged exactly, and faces that only touch give
    /// [`Warnings::TOUCHING_FACES`](crate::Warnings::TOUCHING_FACES). The
    /// check is most of a call's time (see the README); skipped, two
    /// overlapping parts pass with their overlap counted twice. It never
    /// changes a result it accepts.
    ///
    /// ```
    /// use polymass::{Body, ErrorKind, Options, Surface};
    ///
    /// // Two unit tetrahedra, the second moved by (0.25, 0.25, 0.25) into the first.
    /// let positions = [
    ///     [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0],
    ///     [0.25, 0.25, 0.25], [1.25, 0.25, 0.25], [0.25, 1.25, 0.25], [0.25, 0.25, 1.25],
    /// ];
    /// let triangles = [
    ///     [0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3],
    ///     [4, 6, 5], [4, 5, 7], [4, 7, 6], [5, 6, 7],
    /// ];
    /// let surface = Surface::triangles(&positions, &triangles);
    /// let error = polymass::mass_properties(&surface, &Options::new(), &Body::default()).unwrap_err();
    /// assert_eq!(error.kind(), ErrorKind::Intersecting);
    /// assert!(error.message().contains("cross each other"));
    /// // Skipped, the overlap is counted twice.
    /// let trusting = Options::new().skip_intersection_check(true);
    /// let twice = polymass::mass_properties(&surface, &trusting, &Body::default())?;
    /// assert!((twice.volume - 2.0 / 6.0).abs() < 1e-15);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn skip_intersection_check(self, on: bool) -> Options {
        self.with_flag(sys::POLYMASS_OPTION_SKIP_INTERSECTION_CHECK, on)
    }

    /// The largest distance of a polygon face's vertex from the face's plane,
    /// relative to the face's diameter; 0 means the library's default
    /// (`POLYMASS_DEFAULT_PLANARITY_TOLERANCE`, 1e-6).
    ///
    /// ```
    /// let options = polymass::Options::new().with_planarity_tolerance(1e-4);
    /// assert_eq!(options.planarity_tolerance(), 1e-4);
    /// ```
    pub fn with_planarity_tolerance(mut self, tolerance: f64) -> Options {
        self.planarity_tolerance = tolerance;
        self
    }

    /// With [`weld_vertices`](Options::weld_vertices): vertices whose
    /// coordinates each differ by at most this fraction of the largest extent
    /// of the mesh's bounding box are one. 0 (the default) welds equal
    /// positions only; at most `POLYMASS_MAX_WELD_TOLERANCE` (1e-3).
    ///
    /// ```
    /// let options = polymass::Options::new().weld_vertices(true).with_weld_tolerance(1e-9);
    /// assert_eq!(options.weld_tolerance(), 1e-9);
    /// ```
    pub fn with_weld_tolerance(mut self, tolerance: f64) -> Options {
        self.weld_tolerance = tolerance;
        self
    }

    fn with_modes(mut self, modes: &[Mode]) -> Options {
        self.modes = [sys::POLYMASS_MODE_NONE; sys::POLYMASS_MAX_MODES as usize];
        for (slot, mode) in self.modes.iter_mut().zip(modes) {
            *slot = mode.to_raw();
        }
        self
    }

    /// Repair a surface that is not a valid solid where the fix is unique
    /// (orientation, duplicate and two-vertex faces, non-planar polygons,
    /// holes, balanced non-manifold edges); a valid solid is answered exactly
    /// as without. [`Mesh::provenance`](crate::Mesh::provenance) says what
    /// was done; the error bound says how far off it can be. `false` goes
    /// back to the solid alone.
    ///
    /// ```
    /// use polymass::{Body, Mesh, Mode, Options, Surface};
    ///
    /// // The unit corner tetrahedron without its slanted face: open.
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2]];
    /// let surface = Surface::triangles(&positions, &triangles);
    /// let mesh = Mesh::new(&surface, &Options::new().repair(true))?;
    /// let (p, provenance) = (mesh.mass_properties(&Body::default())?, mesh.provenance()?);
    /// assert_eq!(provenance.mode, Mode::Repair);
    /// assert_eq!(provenance.holes.count, 1);
    /// assert!((p.volume - 1.0 / 6.0).abs() <= p.error_bound.volume);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn repair(self, on: bool) -> Options {
        self.with_modes(if on { &[Mode::Repair] } else { &[] })
    }

    /// The surface as a thin wall of this thickness (mass = density ·
    /// thickness · area), open or not: sheet metal, visual meshes.
    ///
    /// ```
    /// let options = polymass::Options::new().shell(0.002);
    /// assert_eq!(options.modes(), vec![polymass::Mode::Shell]);
    /// assert_eq!(options.shell_thickness(), 0.002);
    /// ```
    pub fn shell(mut self, thickness: f64) -> Options {
        self.shell_thickness = thickness;
        self.with_modes(&[Mode::Shell])
    }

    /// The convex hull of the vertices (an upper bound of the solid).
    ///
    /// ```
    /// assert_eq!(polymass::Options::new().hull(true).modes(), vec![polymass::Mode::Hull]);
    /// ```
    pub fn hull(self, on: bool) -> Options {
        self.with_modes(if on { &[Mode::Hull] } else { &[] })
    }

    /// Modes tried in order after the solid, the first that answers giving
    /// the answer (at most three; a shell wants [`with_shell_thickness`](Options::with_shell_thickness)).
    ///
    /// ```
    /// use polymass::{Mode, Options};
    ///
    /// let options = Options::new().fallback(&[Mode::Repair, Mode::Hull]);
    /// assert_eq!(options.modes(), vec![Mode::Solid, Mode::Repair, Mode::Hull]);
    /// ```
    pub fn fallback(self, modes: &[Mode]) -> Options {
        let chain: Vec<Mode> = std::iter::once(Mode::Solid)
            .chain(modes.iter().copied())
            .collect();
        self.with_modes(&chain)
    }

    /// The wall thickness of [`Mode::Shell`] in a [`fallback`](Options::fallback).
    ///
    /// ```
    /// use polymass::{Mode, Options};
    ///
    /// let options = Options::new().fallback(&[Mode::Shell]).with_shell_thickness(0.5);
    /// assert_eq!(options.shell_thickness(), 0.5);
    /// ```
    pub fn with_shell_thickness(mut self, thickness: f64) -> Options {
        self.shell_thickness = thickness;
        self
    }

    /// The modes tried, in order (the solid alone by default).
    ///
    /// ```
    /// assert_eq!(polymass::Options::new().modes(), vec![polymass::Mode::Solid]);
    /// ```
    pub fn modes(&self) -> Vec<Mode> {
        let modes: Vec<Mode> = self
            .modes
            .iter()
            .map_while(|&raw| Mode::from_raw(raw))
            .collect();
        if modes.is_empty() {
            vec![Mode::Solid]
        } else {
            modes
        }
    }

    /// The shell thickness (0: none given).
    pub fn shell_thickness(&self) -> f64 {
        self.shell_thickness
    }

    /// Whether the topology checks are skipped.
    ///
    /// ```
    /// assert!(!polymass::Options::new().skips_topology_checks());
    /// ```
    pub fn skips_topology_checks(&self) -> bool {
        self.flags & sys::POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS != 0
    }

    /// Whether inverted solids are accepted.
    ///
    /// ```
    /// assert!(!polymass::Options::new().accepts_inverted());
    /// ```
    pub fn accepts_inverted(&self) -> bool {
        self.flags & sys::POLYMASS_OPTION_ACCEPT_INVERTED != 0
    }

    /// Whether coincident vertices are welded for the checks.
    ///
    /// ```
    /// assert!(!polymass::Options::new().welds_vertices());
    /// ```
    pub fn welds_vertices(&self) -> bool {
        self.flags & sys::POLYMASS_OPTION_WELD_VERTICES != 0
    }

    /// Whether balanced non-manifold edges are accepted.
    ///
    /// ```
    /// assert!(!polymass::Options::new().accepts_non_manifold());
    /// ```
    pub fn accepts_non_manifold(&self) -> bool {
        self.flags & sys::POLYMASS_OPTION_ACCEPT_NON_MANIFOLD != 0
    }

    /// Whether the intersection check is skipped by name (the topology
    /// checks skipped skip it too).
    ///
    /// ```
    /// assert!(!polymass::Options::new().skips_intersection_check());
    /// assert!(polymass::Options::new().skip_intersection_check(true).skips_intersection_check());
    /// ```
    pub fn skips_intersection_check(&self) -> bool {
        self.flags & sys::POLYMASS_OPTION_SKIP_INTERSECTION_CHECK != 0
    }

    /// The planarity tolerance (0: the library's default).
    ///
    /// ```
    /// assert_eq!(polymass::Options::new().planarity_tolerance(), 0.0);
    /// ```
    pub fn planarity_tolerance(&self) -> f64 {
        self.planarity_tolerance
    }

    /// The weld tolerance (0: exactly equal positions).
    ///
    /// ```
    /// assert_eq!(polymass::Options::new().weld_tolerance(), 0.0);
    /// ```
    pub fn weld_tolerance(&self) -> f64 {
        self.weld_tolerance
    }

    pub(crate) fn to_raw(self) -> sys::polymass_options {
        sys::polymass_options {
            struct_size: struct_size::<sys::polymass_options>(),
            flags: self.flags,
            planarity_tolerance: self.planarity_tolerance,
            weld_tolerance: self.weld_tolerance,
            modes: self.modes,
            shell_thickness: self.shell_thickness,
        }
    }
}
