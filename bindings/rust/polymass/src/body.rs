//! How a solid becomes a body: density or mass, and a reference point
//! (`polymass_mass_desc`).

use polymass_sys as sys;

use crate::surface::struct_size;

/// The material and reference point for mass properties: a density or a
/// total mass (positive and finite; the library checks), and the point
/// [`MassProperties::inertia_point`](crate::MassProperties::inertia_point) is
/// taken about. The default is unit density (mass == volume) about the origin.
///
/// Units are the caller's: lengths in L, density in M/L³, mass in M, inertia
/// in M·L².
///
/// ```
/// use polymass::Body;
///
/// let aluminium = Body::density(2700.0); // kg/m^3 with positions in metres
/// let about_hinge = Body::mass(1.5).about([0.1, 0.0, 0.0]); // 1.5 kg, inertia about a hinge
/// assert_ne!(aluminium, about_hinge);
/// assert_eq!(Body::default(), Body::density(1.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    amount: Amount,
    point: [f64; 3],
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Amount {
    Density(f64),
    Mass(f64),
}

impl Default for Body {
    fn default() -> Body {
        Body::density(1.0)
    }
}

impl Body {
    /// A body of uniform density (M/L³): mass = density × volume.
    ///
    /// ```
    /// let steel = polymass::Body::density(7850.0);
    /// # let _ = steel;
    /// ```
    pub fn density(density: f64) -> Body {
        Body {
            amount: Amount::Density(density),
            point: [0.0; 3],
        }
    }

    /// A body of the given total mass (M), uniformly spread: density =
    /// mass / volume.
    ///
    /// ```
    /// let part = polymass::Body::mass(0.25);
    /// # let _ = part;
    /// ```
    pub fn mass(mass: f64) -> Body {
        Body {
            amount: Amount::Mass(mass),
            point: [0.0; 3],
        }
    }

    /// The same body, with `inertia_point` taken about `point` instead of
    /// the origin.
    ///
    /// ```
    /// let body = polymass::Body::density(1000.0).about([0.0, 0.0, -0.5]);
    /// # let _ = body;
    /// ```
    pub fn about(mut self, point: [f64; 3]) -> Body {
        self.point = point;
        self
    }

    pub(crate) fn to_raw(self) -> sys::polymass_mass_desc {
        let (mass_mode, density, mass) = match self.amount {
            Amount::Density(density) => (sys::POLYMASS_MASS_FROM_DENSITY, density, 0.0),
            Amount::Mass(mass) => (sys::POLYMASS_MASS_FROM_TOTAL, 0.0, mass),
        };
        sys::polymass_mass_desc {
            struct_size: struct_size::<sys::polymass_mass_desc>(),
            mass_mode,
            density,
            mass,
            point: self.point,
        }
    }
}
