//! The mass properties of a body (`polymass_mass_properties`).

use polymass_sys as sys;

/// Mass properties of a solid body. Matrices are `[row][column]`; the inertia
/// tensor is `I = ∫ρ(|r|²𝟙 − r rᵀ) dV`, so the diagonal holds the moments
/// (`Ixx = ∫ρ(y² + z²)`) and the off-diagonal terms are the *negated*
/// products of inertia (`Ixy = −∫ρxy`): the tensor URDF, SDFormat, MuJoCo,
/// PhysX and Bullet take.
///
/// ```
/// use polymass::{Body, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let surface = Surface::triangles(&positions, &triangles);
/// let p = polymass::mass_properties(&surface, &Body::mass(6.0))?;
/// assert!((p.center_of_mass[0] - 0.25).abs() < 1e-15);
/// // Principal moments ascending; the axes are the columns of a rotation.
/// assert!(p.principal_moments[0] <= p.principal_moments[1]);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct MassProperties {
    /// Enclosed volume (L³), positive.
    pub volume: f64,
    /// Mass (M).
    pub mass: f64,
    /// Density (M/L³): the one given, or mass / volume.
    pub density: f64,
    /// Total area of the faces (L²).
    pub surface_area: f64,
    /// Centre of mass (L).
    pub center_of_mass: [f64; 3],
    /// Inertia tensor about the centre of mass (M·L²).
    pub inertia: [[f64; 3]; 3],
    /// Inertia tensor about the origin.
    pub inertia_origin: [[f64; 3]; 3],
    /// Inertia tensor about the body's reference point
    /// ([`Body::about`](crate::Body::about)).
    pub inertia_point: [[f64; 3]; 3],
    /// Eigenvalues of `inertia`, ascending.
    pub principal_moments: [f64; 3],
    /// A rotation `R` (det +1) whose column `i` is the axis of
    /// `principal_moments[i]`: `inertia = R diag(principal_moments) Rᵀ`.
    pub principal_axes: [[f64; 3]; 3],
    /// What was accepted on the way (all clear for a checked, proper solid).
    pub warnings: Warnings,
    /// Bounds on the rounding errors of the results above.
    pub error_bound: ErrorBound,
}

/// Bounds on the rounding errors of [`MassProperties`]: absolute, in the
/// results' units, carried from the integration through the move to the
/// centre of mass and the principal-axes step. They hold for the surface as
/// given (its coordinates taken as exact).
///
/// ```
/// use polymass::{Body, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let p = polymass::mass_properties(&Surface::triangles(&positions, &triangles), &Body::default())?;
/// assert!((p.volume - 1.0 / 6.0).abs() <= p.error_bound.volume);
/// assert!(p.error_bound.volume < 1e-12);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct ErrorBound {
    /// Of the volume (L³).
    pub volume: f64,
    /// Of each coordinate of the centre of mass (L).
    pub center_of_mass: f64,
    /// Of each entry of the inertia tensor about the centre of mass (M·L²).
    pub inertia: f64,
    /// Of each principal moment.
    pub principal_moments: f64,
    /// Of the angle of each principal axis the moments determine (radians):
    /// it grows as two moments approach each other, and is π/2 when they are
    /// closer than their bounds tell apart.
    pub principal_axes: f64,
}

impl MassProperties {
    pub(crate) fn from_raw(raw: &sys::polymass_mass_properties) -> MassProperties {
        MassProperties {
            volume: raw.volume,
            mass: raw.mass,
            density: raw.density,
            surface_area: raw.surface_area,
            center_of_mass: raw.center_of_mass,
            inertia: matrix(&raw.inertia),
            inertia_origin: matrix(&raw.inertia_origin),
            inertia_point: matrix(&raw.inertia_point),
            principal_moments: raw.principal_moments,
            principal_axes: matrix(&raw.principal_axes),
            warnings: Warnings(raw.warnings),
            error_bound: ErrorBound {
                volume: raw.error_bound_volume,
                center_of_mass: raw.error_bound_center_of_mass,
                inertia: raw.error_bound_inertia,
                principal_moments: raw.error_bound_principal_moments,
                principal_axes: raw.error_bound_principal_axes,
            },
        }
    }
}

/// A row-major 3x3 matrix as rows.
fn matrix(row_major: &[f64; 9]) -> [[f64; 3]; 3] {
    std::array::from_fn(|row| std::array::from_fn(|column| row_major[3 * row + column]))
}

/// What the library accepted while computing, as bits (`POLYMASS_WARNING_*`).
/// Bits this crate has no constant for are kept.
///
/// ```
/// use polymass::Warnings;
///
/// let warnings = Warnings::INVERTED | Warnings::UNCHECKED;
/// assert!(warnings.contains(Warnings::INVERTED));
/// assert!(!warnings.contains(Warnings::DEGENERATE_FACES));
/// assert!(Warnings::default().is_empty());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Warnings(u32);

impl Warnings {
    /// An inverted solid was accepted and turned
    /// ([`Options::accept_inverted`](crate::Options::accept_inverted)).
    pub const INVERTED: Warnings = Warnings(sys::POLYMASS_WARNING_INVERTED);
    /// Some faces have zero area; they are harmless.
    pub const DEGENERATE_FACES: Warnings = Warnings(sys::POLYMASS_WARNING_DEGENERATE_FACES);
    /// The topology checks were skipped
    /// ([`Options::skip_topology_checks`](crate::Options::skip_topology_checks)).
    pub const UNCHECKED: Warnings = Warnings(sys::POLYMASS_WARNING_UNCHECKED);
    /// Balanced non-manifold edges were accepted
    /// ([`Options::accept_non_manifold`](crate::Options::accept_non_manifold)).
    pub const NON_MANIFOLD: Warnings = Warnings(sys::POLYMASS_WARNING_NON_MANIFOLD);
    /// Faces touch without crossing, such as parts resting on each other;
    /// found by the intersection check (on unless
    /// [`Options::skip_intersection_check`](crate::Options::skip_intersection_check)),
    /// and listed by [`Diagnostics::touching_face_pairs`](crate::Diagnostics::touching_face_pairs).
    pub const TOUCHING_FACES: Warnings = Warnings(sys::POLYMASS_WARNING_TOUCHING_FACES);
    /// Not a valid solid: the surface was repaired ([`Options::repair`](crate::Options::repair)).
    pub const REPAIRED: Warnings = Warnings(sys::POLYMASS_WARNING_REPAIRED);
    /// Computed as a thin wall ([`Options::shell`](crate::Options::shell)).
    pub const SHELL: Warnings = Warnings(sys::POLYMASS_WARNING_SHELL);
    /// The convex hull, not the solid ([`Options::hull`](crate::Options::hull)).
    pub const HULL: Warnings = Warnings(sys::POLYMASS_WARNING_HULL);

    /// Whether every bit of `other` is set.
    ///
    /// ```
    /// use polymass::Warnings;
    ///
    /// assert!(Warnings::UNCHECKED.contains(Warnings::UNCHECKED));
    /// ```
    pub fn contains(self, other: Warnings) -> bool {
        self.0 & other.0 == other.0
    }

    /// Whether no warning is set.
    ///
    /// ```
    /// assert!(polymass::Warnings::default().is_empty());
    /// ```
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The raw `POLYMASS_WARNING_*` bits.
    ///
    /// ```
    /// assert_eq!(polymass::Warnings::INVERTED.bits(), 1);
    /// ```
    pub fn bits(self) -> u32 {
        self.0
    }
}

impl std::ops::BitOr for Warnings {
    type Output = Warnings;

    fn bitor(self, other: Warnings) -> Warnings {
        Warnings(self.0 | other.0)
    }
}
