//! Moments that compose (`polymass_moments`): parts added and subtracted,
//! moved, mirrored, scaled and weighted, then turned into mass properties.

use std::ops::{Add, Sub};

use polymass_sys as sys;

use crate::body::Body;
use crate::context::Context;
use crate::error::Result;
use crate::properties::MassProperties;
use crate::surface::struct_size;

/// The mass integrals of a body about its own reference point, near the body,
/// so that a part far from the origin keeps its digits: a `Copy` value.
///
/// Parts add (`a + b`) and subtract (a bore removed from a block: `a - b`);
/// both give a [`Result`], and a `Result` adds to further moments, so a sum of
/// many parts is one expression ending in `?`. The derivations are in the
/// repository's `docs/moments.md`.
///
/// A mesh gives the moments of its body ([`Mesh::moments`](crate::Mesh::moments)).
///
/// ```
/// use polymass::{Body, Mesh, Options, Surface};
///
/// // Two unit tetrahedra, one moved 1e8 along x: the sum keeps every digit.
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let part = Mesh::new(&Surface::triangles(&positions, &triangles), &Options::new())?.moments()?;
/// let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let far = part.transformed(&identity, [1e8, 0.0, 0.0])?;
/// let steel = part.weighted(&Body::density(7850.0))?;
/// let both = (steel + far.weighted(&Body::mass(2.0))?)?;
/// let p = both.mass_properties(None)?;
/// assert!((p.mass - (7850.0 / 6.0 + 2.0)).abs() < 1e-12 * p.mass);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Clone, Copy)]
pub struct Moments {
    raw: sys::polymass_moments,
}

impl Moments {
    pub(crate) fn empty() -> sys::polymass_moments {
        sys::polymass_moments {
            struct_size: struct_size::<sys::polymass_moments>(),
            ..Default::default()
        }
    }

    pub(crate) fn from_raw(raw: sys::polymass_moments) -> Moments {
        Moments { raw }
    }

    pub(crate) fn as_raw(&self) -> &sys::polymass_moments {
        &self.raw
    }

    /// The point the integrals are about.
    pub fn reference(&self) -> [f64; 3] {
        self.raw.reference
    }

    /// The solid's volume (L³); a difference may be zero or negative.
    pub fn volume(&self) -> f64 {
        self.raw.volume
    }

    /// `∫ρ dV` (M): the volume until a density or mass is applied.
    pub fn mass(&self) -> f64 {
        self.raw.mass
    }

    /// `∫ρ r dV`, with `r` measured from [`reference`](Moments::reference).
    pub fn first(&self) -> [f64; 3] {
        self.raw.first
    }

    /// `∫ρ r rᵀ dV`, `[row][column]`.
    pub fn second(&self) -> [[f64; 3]; 3] {
        let [xx, yy, zz, xy, yz, zx] = self.raw.second;
        [[xx, xy, zx], [xy, yy, yz], [zx, yz, zz]]
    }

    /// The moments of a range of faces ([`Context::moments_of_faces`]), which
    /// add only to each other until [`completed`](Moments::completed).
    pub fn is_partial(&self) -> bool {
        self.raw.flags & sys::POLYMASS_MOMENTS_PARTIAL != 0
    }

    /// These moments as a body: say so once the ranges of faces added up
    /// cover the whole closed surface.
    pub fn completed(mut self) -> Moments {
        self.raw.flags &= !sys::POLYMASS_MOMENTS_PARTIAL;
        self
    }

    /// The body moved by `x -> rotation x + translation`; `rotation` is
    /// orthonormal, `[row][column]` (determinant −1 mirrors: the result is
    /// the mirror-image solid, of the same positive volume).
    pub fn transformed(&self, rotation: &[[f64; 3]; 3], translation: [f64; 3]) -> Result<Moments> {
        let flat = rotation.as_flattened();
        Context::new()?.moments_call(|out, context| unsafe {
            // SAFETY: rotation has 9 and translation 3 elements; see moments_call.
            sys::polymass_moments_transform(
                out,
                context,
                &self.raw,
                flat.as_ptr(),
                translation.as_ptr(),
            )
        })
    }

    /// The body stretched along each axis about the origin (negative factors
    /// mirror); the density is kept, so the mass scales with the volume.
    pub fn scaled(&self, factors: [f64; 3]) -> Result<Moments> {
        Context::new()?.moments_call(|out, context| unsafe {
            // SAFETY: factors has 3 elements; see moments_call.
            sys::polymass_moments_scale(out, context, &self.raw, factors.as_ptr())
        })
    }

    /// The body made of a material of `body`'s density, or of its mass: the
    /// whole mass distribution rescaled to that mean density or total mass.
    pub fn weighted(&self, body: &Body) -> Result<Moments> {
        let mass = body.to_raw();
        Context::new()?.moments_call(|out, context| unsafe {
            // SAFETY: mass outlives the call; see moments_call.
            sys::polymass_moments_weight(out, context, &self.raw, &mass)
        })
    }

    /// The mass properties of the body: as weighted (`None`), or weighted as
    /// by [`weighted`](Moments::weighted). `surface_area` is NaN: moments do
    /// not keep the surface.
    pub fn mass_properties(&self, body: Option<&Body>) -> Result<MassProperties> {
        Context::new()?.moments_mass_properties(self, body)
    }
}

impl Add for Moments {
    type Output = Result<Moments>;

    /// Two disjoint bodies as one, about the left operand's reference point.
    fn add(self, other: Moments) -> Result<Moments> {
        Context::new()?.moments_call(|out, context| unsafe {
            // SAFETY: see moments_call.
            sys::polymass_moments_add(out, context, &self.raw, &other.raw)
        })
    }
}

impl Sub for Moments {
    type Output = Result<Moments>;

    /// `other` removed from this body (it must lie inside).
    fn sub(self, other: Moments) -> Result<Moments> {
        Context::new()?.moments_call(|out, context| unsafe {
            // SAFETY: see moments_call.
            sys::polymass_moments_subtract(out, context, &self.raw, &other.raw)
        })
    }
}

impl Add<Moments> for Result<Moments> {
    type Output = Result<Moments>;

    /// Lets sums chain: `(a + b + c)?`.
    fn add(self, other: Moments) -> Result<Moments> {
        self? + other
    }
}

impl Sub<Moments> for Result<Moments> {
    type Output = Result<Moments>;

    /// Lets differences chain: `(block - bore - bore)?`.
    fn sub(self, other: Moments) -> Result<Moments> {
        self? - other
    }
}

impl std::fmt::Debug for Moments {
    fn fmt(&self, formatter: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        formatter
            .debug_struct("Moments")
            .field("reference", &self.reference())
            .field("volume", &self.volume())
            .field("mass", &self.mass())
            .field("first", &self.first())
            .field("second", &self.second())
            .field("partial", &self.is_partial())
            .finish()
    }
}
