//! The mass properties of a body (`polymass_mass_properties`).

use polymass_sys as sys;

use crate::codes::bit_set;
use crate::error::{Error, Result};
use crate::surface::struct_size;

/// Mass properties of a solid body. Matrices are `[row][column]`; the inertia
/// tensor is `I = ∫ρ(|r|²𝟙 − r rᵀ) dV`, so the diagonal holds the moments
/// (`Ixx = ∫ρ(y² + z²)`) and the off-diagonal terms are the *negated*
/// products of inertia (`Ixy = −∫ρxy`): the tensor URDF, SDFormat, MuJoCo,
/// PhysX and Bullet take.
///
/// ```
/// use polymass::{Body, Options, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let surface = Surface::triangles(&positions, &triangles);
/// let p = polymass::mass_properties(&surface, &Options::new(), &Body::mass(6.0))?;
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
    /// Inertia tensor about the origin; about any point:
    /// [`inertia_about`](MassProperties::inertia_about).
    pub inertia_origin: [[f64; 3]; 3],
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
/// use polymass::{Body, Options, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let surface = Surface::triangles(&positions, &triangles);
/// let p = polymass::mass_properties(&surface, &Options::new(), &Body::default())?;
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
            principal_moments: raw.principal_moments,
            principal_axes: matrix(&raw.principal_axes),
            warnings: Warnings::from_bits(raw.warnings),
            error_bound: ErrorBound {
                volume: raw.error_bound_volume,
                center_of_mass: raw.error_bound_center_of_mass,
                inertia: raw.error_bound_inertia,
                principal_moments: raw.error_bound_principal_moments,
                principal_axes: raw.error_bound_principal_axes,
            },
        }
    }

    /// The C struct these properties were read from.
    fn to_raw(self) -> sys::polymass_mass_properties {
        sys::polymass_mass_properties {
            struct_size: struct_size::<sys::polymass_mass_properties>(),
            warnings: self.warnings.bits(),
            volume: self.volume,
            mass: self.mass,
            density: self.density,
            surface_area: self.surface_area,
            center_of_mass: self.center_of_mass,
            inertia: row_major(&self.inertia),
            inertia_origin: row_major(&self.inertia_origin),
            principal_moments: self.principal_moments,
            principal_axes: row_major(&self.principal_axes),
            error_bound_volume: self.error_bound.volume,
            error_bound_center_of_mass: self.error_bound.center_of_mass,
            error_bound_inertia: self.error_bound.inertia,
            error_bound_principal_moments: self.error_bound.principal_moments,
            error_bound_principal_axes: self.error_bound.principal_axes,
        }
    }

    /// The inertia tensor of the body about `point` (M·L²), by the
    /// parallel-axis theorem from the tensor about the centre of mass
    /// (`polymass_inertia_about`). Fails with
    /// [`ErrorKind::InvalidArgument`](crate::ErrorKind::InvalidArgument) for
    /// a point that is not finite and
    /// [`ErrorKind::Overflow`](crate::ErrorKind::Overflow) for a moment
    /// beyond a double.
    ///
    /// ```
    /// use polymass::{Body, Options, Surface};
    ///
    /// // A unit cube of mass 6 about a corner: 6 (1/6 + 1/2) = 4 on the
    /// // diagonal, products -6 (1/2)(1/2) = -1.5 (negated) off it.
    /// let positions = [
    ///     [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0],
    ///     [0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 1.0, 1.0],
    /// ];
    /// let indices = [0u32, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7];
    /// let cube = Surface::polygons(&positions, &indices, &[4; 6]);
    /// let p = polymass::mass_properties(&cube, &Options::new(), &Body::mass(6.0))?;
    /// let corner = p.inertia_about([1.0, 1.0, 1.0])?;
    /// assert!((corner[0][0] - 4.0).abs() < 1e-14 && (corner[0][1] + 1.5).abs() < 1e-14);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn inertia_about(&self, point: [f64; 3]) -> Result<[[f64; 3]; 3]> {
        let raw = self.to_raw();
        let mut out = [0.0; 9];
        // SAFETY: out has 9 elements, point 3; raw is a complete struct.
        let status = unsafe { sys::polymass_inertia_about(out.as_mut_ptr(), &raw, point.as_ptr()) };
        if status != sys::POLYMASS_OK {
            // The function takes no context, so has no message of its own.
            return Err(Error::new(status, format!("inertia about {point:?}")));
        }
        Ok(matrix(&out))
    }
}

/// A row-major 3x3 matrix as rows.
fn matrix(row_major: &[f64; 9]) -> [[f64; 3]; 3] {
    std::array::from_fn(|row| std::array::from_fn(|column| row_major[3 * row + column]))
}

/// Rows as a row-major 3x3 matrix.
fn row_major(rows: &[[f64; 3]; 3]) -> [f64; 9] {
    std::array::from_fn(|i| rows[i / 3][i % 3])
}

bit_set! {
    /// What the library accepted while computing, as bits
    /// (`POLYMASS_WARNING_*`). Bits this crate has no constant for are kept.
    ///
    /// ```
    /// use polymass::Warnings;
    ///
    /// let warnings = Warnings::INVERTED | Warnings::UNCHECKED;
    /// assert!(warnings.contains(Warnings::INVERTED));
    /// assert!(!warnings.contains(Warnings::DEGENERATE_FACES));
    /// assert!(Warnings::default().is_empty());
    /// assert_eq!(Warnings::INVERTED.bits(), 1);
    /// ```
    Warnings {
        /// An inverted solid was accepted and turned
        /// ([`Options::accept_inverted`](crate::Options::accept_inverted)).
        INVERTED = sys::POLYMASS_WARNING_INVERTED;
        /// Some faces have zero area; they are harmless.
        DEGENERATE_FACES = sys::POLYMASS_WARNING_DEGENERATE_FACES;
        /// The topology checks were skipped
        /// ([`Options::skip_topology_checks`](crate::Options::skip_topology_checks)).
        UNCHECKED = sys::POLYMASS_WARNING_UNCHECKED;
        /// Balanced non-manifold edges were accepted
        /// ([`Options::accept_non_manifold`](crate::Options::accept_non_manifold)).
        NON_MANIFOLD = sys::POLYMASS_WARNING_NON_MANIFOLD;
        /// Faces touch without crossing, such as parts resting on each other;
        /// found by the intersection check (on unless
        /// [`Options::skip_intersection_check`](crate::Options::skip_intersection_check)),
        /// and listed by [`Diagnostics::touching_face_pairs`](crate::Diagnostics::touching_face_pairs).
        TOUCHING_FACES = sys::POLYMASS_WARNING_TOUCHING_FACES;
        /// Not a valid solid: the surface was repaired ([`Options::repair`](crate::Options::repair)).
        REPAIRED = sys::POLYMASS_WARNING_REPAIRED;
        /// Computed as a thin wall ([`Options::shell`](crate::Options::shell)).
        SHELL = sys::POLYMASS_WARNING_SHELL;
        /// The convex hull, not the solid ([`Options::hull`](crate::Options::hull)).
        HULL = sys::POLYMASS_WARNING_HULL;
        /// The intersection check did not run (skipped by name, or with the
        /// topology checks): overlapping parts would have passed, counted twice.
        INTERSECTIONS_UNCHECKED = sys::POLYMASS_WARNING_INTERSECTIONS_UNCHECKED;
    }
}
