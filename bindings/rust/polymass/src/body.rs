//! How heavy a body is: a density or a mass (`polymass_mass_desc`).

use polymass_sys as sys;

use crate::surface::struct_size;

/// How heavy a body is: a density or a total mass (positive and finite; the
/// library checks). The default is unit density (mass == volume). The inertia
/// about any point comes from the mass properties afterwards
/// ([`MassProperties::inertia_about`](crate::MassProperties::inertia_about)).
///
/// Units are the caller's: lengths in L, density in M/L³, mass in M, inertia
/// in M·L².
///
/// ```
/// use polymass::Body;
///
/// let aluminium = Body::density(2700.0); // kg/m^3 with positions in metres
/// let part = Body::mass(1.5); // 1.5 kg
/// assert_ne!(aluminium, part);
/// assert_eq!(Body::default(), Body::density(1.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body(Amount);

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
        Body(Amount::Density(density))
    }

    /// A body of the given total mass (M), uniformly spread: density =
    /// mass / volume.
    ///
    /// ```
    /// let part = polymass::Body::mass(0.25);
    /// # let _ = part;
    /// ```
    pub fn mass(mass: f64) -> Body {
        Body(Amount::Mass(mass))
    }

    pub(crate) fn to_raw(self) -> sys::polymass_mass_desc {
        let (mass_mode, density, mass) = match self.0 {
            Amount::Density(density) => (sys::POLYMASS_MASS_FROM_DENSITY, density, 0.0),
            Amount::Mass(mass) => (sys::POLYMASS_MASS_FROM_TOTAL, 0.0, mass),
        };
        sys::polymass_mass_desc {
            struct_size: struct_size::<sys::polymass_mass_desc>(),
            mass_mode,
            density,
            mass,
        }
    }
}
