//! Area properties of planar polygons (`polymass_polygon_properties`).

use polymass_sys as sys;

/// Which way a polygon's points turn, seen from +z.
///
/// ```
/// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let p = polymass::polygon(&square)?;
/// assert_eq!(p.orientation, polymass::Orientation::CounterClockwise);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// Positive signed area.
    CounterClockwise,
    /// Negative signed area.
    Clockwise,
}

/// Second moments of area with the engineering sign: `ixx = ∫y² dA`,
/// `iyy = ∫x² dA`, `ixy = +∫xy dA` (not negated, unlike the 3D inertia
/// tensor).
///
/// ```
/// let rectangle = [[-1.0, -0.5], [1.0, -0.5], [1.0, 0.5], [-1.0, 0.5]]; // 2 x 1
/// let m = polymass::polygon(&rectangle)?.second_moments;
/// assert!((m.ixx - 2.0 / 12.0).abs() < 1e-15 && (m.iyy - 8.0 / 12.0).abs() < 1e-15);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SecondMoments {
    /// `∫y² dA`
    pub ixx: f64,
    /// `∫x² dA`
    pub iyy: f64,
    /// `∫xy dA`
    pub ixy: f64,
}

impl SecondMoments {
    fn from_raw(raw: [f64; 3]) -> SecondMoments {
        SecondMoments {
            ixx: raw[0],
            iyy: raw[1],
            ixy: raw[2],
        }
    }
}

/// Area, centroid and second moments of area of a simple planar polygon.
///
/// ```
/// // An L-shape (not convex), clockwise.
/// let l = [[0.0, 0.0], [0.0, 3.0], [1.0, 3.0], [1.0, 1.0], [4.0, 1.0], [4.0, 0.0]];
/// let p = polymass::polygon(&l)?;
/// assert_eq!(p.area, 6.0);
/// assert_eq!(p.orientation, polymass::Orientation::Clockwise);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct PolygonProperties {
    /// Which way the points turn.
    pub orientation: Orientation,
    /// Area (L²), positive whatever the orientation.
    pub area: f64,
    /// Centroid (L).
    pub centroid: [f64; 2],
    /// Second moments of area about the centroid (L⁴).
    pub second_moments: SecondMoments,
    /// Second moments of area about the origin.
    pub second_moments_origin: SecondMoments,
    /// `ixx + iyy` about the centroid.
    pub polar_moment: f64,
    /// Principal second moments about the centroid, ascending.
    pub principal_moments: [f64; 2],
    /// Angle (radians, counter-clockwise from +x, in (−π/2, π/2]) of the axis
    /// about which the second moment is `principal_moments[0]`.
    pub principal_angle: f64,
}

impl PolygonProperties {
    pub(crate) fn from_raw(raw: &sys::polymass_polygon_properties) -> PolygonProperties {
        PolygonProperties {
            // The library gives POLYMASS_COUNTER_CLOCKWISE (1) or
            // POLYMASS_CLOCKWISE (-1): the sign of the signed area.
            orientation: if raw.orientation == sys::POLYMASS_CLOCKWISE {
                Orientation::Clockwise
            } else {
                Orientation::CounterClockwise
            },
            area: raw.area,
            centroid: raw.centroid,
            second_moments: SecondMoments::from_raw(raw.second_moments),
            second_moments_origin: SecondMoments::from_raw(raw.second_moments_origin),
            polar_moment: raw.polar_moment,
            principal_moments: raw.principal_moments,
            principal_angle: raw.principal_angle,
        }
    }
}
