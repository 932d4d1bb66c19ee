//! What each shell of a surface is (`polymass_shell`).

use polymass_sys as sys;

use crate::codes::{known_code, known_kind};

/// What a shell is, as the library judges it (`POLYMASS_SHELL_*`).
///
/// `#[non_exhaustive]`, with [`ShellKind::Unknown`] for a kind a newer
/// library may add.
///
/// ```
/// use polymass::ShellKind;
///
/// assert_eq!(ShellKind::from_code(2), ShellKind::Cavity);
/// assert_eq!(ShellKind::Cavity.code(), 2);
/// assert_eq!(ShellKind::from_code(99), ShellKind::Unknown(99));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ShellKind {
    /// Not judged: the surface failed a check before the shells (not closed,
    /// manifold, oriented or planar), or the options skip the topology
    /// checks. Its signed volume is NaN.
    Unjudged,
    /// Encloses positive volume and lies in no other solid (or in a cavity).
    Solid,
    /// Negative volume, inside a solid: a hollow.
    Cavity,
    /// Negative volume, inside no solid: inside out, it would be subtracted
    /// from nothing.
    Inverted,
    /// Inside a solid of the same sense: its volume would be counted twice.
    Overlapping,
    /// Encloses no volume (to rounding).
    NoVolume,
    /// A kind code this crate does not know, from a newer library.
    Unknown(i32),
}

/// Each known kind with its code: the one table both directions use.
const KNOWN_KINDS: [(ShellKind, i32); 6] = [
    (ShellKind::Unjudged, sys::POLYMASS_SHELL_UNJUDGED),
    (ShellKind::Solid, sys::POLYMASS_SHELL_SOLID),
    (ShellKind::Cavity, sys::POLYMASS_SHELL_CAVITY),
    (ShellKind::Inverted, sys::POLYMASS_SHELL_INVERTED),
    (ShellKind::Overlapping, sys::POLYMASS_SHELL_OVERLAPPING),
    (ShellKind::NoVolume, sys::POLYMASS_SHELL_NO_VOLUME),
];

impl ShellKind {
    /// The kind of a `POLYMASS_SHELL_*` code.
    ///
    /// ```
    /// assert_eq!(polymass::ShellKind::from_code(1), polymass::ShellKind::Solid);
    /// ```
    pub fn from_code(code: i32) -> ShellKind {
        known_kind(&KNOWN_KINDS, code).unwrap_or(ShellKind::Unknown(code))
    }

    /// The `POLYMASS_SHELL_*` code.
    ///
    /// ```
    /// assert_eq!(polymass::ShellKind::Overlapping.code(), 4);
    /// ```
    pub fn code(self) -> i32 {
        match self {
            ShellKind::Unknown(code) => code,
            known => known_code(&KNOWN_KINDS, known),
        }
    }
}

/// One shell of a surface, as [`Mesh::shells`](crate::Mesh::shells)
/// describes it: a connected piece, faces sharing a vertex (after welding,
/// when the options weld) being in one shell.
///
/// ```
/// use polymass::{Mesh, Options, ShellKind, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles), &Options::new())?;
/// let shells = mesh.shells()?;
/// assert_eq!(shells.len(), 1);
/// assert_eq!((shells[0].kind, shells[0].face_count, shells[0].first_face), (ShellKind::Solid, 4, 0));
/// assert!((shells[0].signed_volume - 1.0 / 6.0).abs() < 1e-16);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Shell {
    /// What the shell is.
    pub kind: ShellKind,
    /// Number of faces.
    pub face_count: u64,
    /// The lowest face number of the shell.
    pub first_face: u64,
    /// Enclosed volume, signed so that the whole surface's volume is positive
    /// (a surface accepted inside out as a whole counts turned): a cavity's
    /// is negative; NaN when [unjudged](ShellKind::Unjudged), or when the
    /// volume is beyond a double's range (a shell of no volume made of
    /// coordinates near overflow).
    pub signed_volume: f64,
}

impl Shell {
    pub(crate) fn from_raw(raw: &sys::polymass_shell) -> Shell {
        Shell {
            kind: ShellKind::from_code(raw.kind),
            face_count: raw.face_count,
            first_face: raw.first_face,
            signed_volume: raw.signed_volume,
        }
    }
}
