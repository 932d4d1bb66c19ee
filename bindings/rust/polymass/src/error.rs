//! Failures: the library's status code, its kind and the context's message.

use std::ffi::CStr;
use std::fmt;

use polymass_sys as sys;

use crate::codes::{known_code, known_kind};

/// A `Result` whose error is a [`polymass::Error`](Error).
pub type Result<T> = std::result::Result<T, Error>;

/// What went wrong, one variant per status code of the C API.
///
/// The enum is `#[non_exhaustive]` and has [`ErrorKind::Unknown`]: a newer
/// library may add status codes, and one this crate does not know keeps its
/// code instead of being mistaken for another.
///
/// ```
/// use polymass::ErrorKind;
///
/// assert_eq!(ErrorKind::from_code(20), Some(ErrorKind::Open));
/// assert_eq!(ErrorKind::Open.code(), 20);
/// assert_eq!(ErrorKind::from_code(0), None); // success is not an error
/// assert_eq!(ErrorKind::from_code(999), Some(ErrorKind::Unknown(999)));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A value the library does not accept: a density, mass or point that is
    /// not finite and positive, a tolerance out of range, face sizes that do
    /// not add up to the number of indices.
    InvalidArgument,
    /// The allocator returned no memory.
    OutOfMemory,
    /// A bug in the library; please report it with the message.
    Internal,
    /// A coordinate used by a face is NaN or infinite.
    NonFinite,
    /// A face refers to a vertex past the end of the vertex slice.
    IndexOutOfRange,
    /// A face (or a 2D polygon) has fewer than 3 vertices.
    FaceTooSmall,
    /// An edge is used by one face only: the surface has a hole.
    Open,
    /// An edge is used by more than two faces.
    NonManifold,
    /// Two faces traverse an edge in the same direction: one of them is flipped.
    InconsistentOrientation,
    /// A polygon face's vertices are off its plane by more than the tolerance.
    NonPlanarFace,
    /// Faces cross each other (or lie on another shell's faces, facing the
    /// same way), or a shell lies inside a solid of the same sense or passes
    /// through another's surface: some region would be counted twice
    /// (overlapping parts exported as one file, a surface written twice, a
    /// surface folded through itself). Found by default (not with
    /// [`Options::skip_intersection_check`](crate::Options::skip_intersection_check)
    /// or [`Options::skip_topology_checks`](crate::Options::skip_topology_checks));
    /// the message names a pair of faces, or the shell.
    Intersecting,
    /// The enclosed volume is negative: every face is reversed, or one shell
    /// is inside out while lying inside no solid shell.
    Inverted,
    /// The surface encloses no volume, e.g. a flat double-sided sheet.
    ZeroVolume,
    /// A 2D polygon encloses no area.
    ZeroArea,
    /// A result does not fit in a double (coordinates, density, mass or point
    /// too large or too small).
    Overflow,
    /// A status code this crate does not know, from a newer library.
    Unknown(i32),
}

/// Each known kind with its status code: the one table both directions use.
const KNOWN_KINDS: [(ErrorKind, i32); 15] = [
    (
        ErrorKind::InvalidArgument,
        sys::POLYMASS_ERROR_INVALID_ARGUMENT,
    ),
    (ErrorKind::OutOfMemory, sys::POLYMASS_ERROR_OUT_OF_MEMORY),
    (ErrorKind::Internal, sys::POLYMASS_ERROR_INTERNAL),
    (ErrorKind::NonFinite, sys::POLYMASS_ERROR_NON_FINITE),
    (
        ErrorKind::IndexOutOfRange,
        sys::POLYMASS_ERROR_INDEX_OUT_OF_RANGE,
    ),
    (ErrorKind::FaceTooSmall, sys::POLYMASS_ERROR_FACE_TOO_SMALL),
    (ErrorKind::Open, sys::POLYMASS_ERROR_OPEN),
    (ErrorKind::NonManifold, sys::POLYMASS_ERROR_NON_MANIFOLD),
    (
        ErrorKind::InconsistentOrientation,
        sys::POLYMASS_ERROR_INCONSISTENT_ORIENTATION,
    ),
    (
        ErrorKind::NonPlanarFace,
        sys::POLYMASS_ERROR_NON_PLANAR_FACE,
    ),
    (ErrorKind::Intersecting, sys::POLYMASS_ERROR_INTERSECTING),
    (ErrorKind::Inverted, sys::POLYMASS_ERROR_INVERTED),
    (ErrorKind::ZeroVolume, sys::POLYMASS_ERROR_ZERO_VOLUME),
    (ErrorKind::ZeroArea, sys::POLYMASS_ERROR_ZERO_AREA),
    (ErrorKind::Overflow, sys::POLYMASS_ERROR_OVERFLOW),
];

impl ErrorKind {
    /// The kind of a C status code; `None` for `POLYMASS_OK` (0).
    ///
    /// ```
    /// use polymass::ErrorKind;
    ///
    /// assert_eq!(ErrorKind::from_code(31), Some(ErrorKind::ZeroVolume));
    /// ```
    pub fn from_code(code: i32) -> Option<ErrorKind> {
        if code == sys::POLYMASS_OK {
            return None;
        }
        Some(known_kind(&KNOWN_KINDS, code).unwrap_or(ErrorKind::Unknown(code)))
    }

    /// The C status code (`POLYMASS_ERROR_*`).
    ///
    /// ```
    /// use polymass::ErrorKind;
    ///
    /// assert_eq!(ErrorKind::InvalidArgument.code(), 1);
    /// ```
    pub fn code(self) -> i32 {
        match self {
            ErrorKind::Unknown(code) => code,
            known => known_code(&KNOWN_KINDS, known),
        }
    }

    /// The library's name for the status (`polymass_status_string`), e.g.
    /// "open surface"; "unknown status" for a code the library does not know.
    ///
    /// ```
    /// use polymass::ErrorKind;
    ///
    /// assert!(!ErrorKind::NonManifold.description().is_empty());
    /// ```
    pub fn description(self) -> &'static str {
        // SAFETY: polymass_status_string returns static, NUL-terminated text
        // for every code, never NULL.
        let text = unsafe { CStr::from_ptr(sys::polymass_status_string(self.code())) };
        text.to_str().unwrap_or("(status text is not UTF-8)")
    }
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, formatter: &mut fmt::Formatter<'_>) -> fmt::Result {
        formatter.write_str(self.description())
    }
}

/// A failed call: the kind of failure and the library's message saying what
/// and where ("face 6 has 2 vertices; a face needs at least 3").
///
/// `Display` gives both, e.g. `open surface: edge (1, 2) is used by one face
/// only: the surface is open (3 such edges)`.
///
/// ```
/// use polymass::{ErrorKind, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let open = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2]]; // the slanted face is missing
/// let surface = Surface::triangles(&positions, &open);
/// let error = polymass::mass_properties(&surface, &polymass::Options::new(), &Default::default()).unwrap_err();
/// assert_eq!(error.kind(), ErrorKind::Open);
/// assert!(error.message().contains("edge"));
/// println!("{error}");
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    kind: ErrorKind,
    message: String,
}

impl Error {
    /// An error of status `code` with the library's message; `code` is not 0.
    pub(crate) fn new(code: i32, message: String) -> Error {
        let kind = ErrorKind::from_code(code).expect("an error status is not POLYMASS_OK");
        Error { kind, message }
    }

    /// The kind of failure.
    ///
    /// ```
    /// use polymass::ErrorKind;
    ///
    /// let error = polymass::polygon(&[[0.0, 0.0], [1.0, 0.0]]).unwrap_err();
    /// assert_eq!(error.kind(), ErrorKind::FaceTooSmall);
    /// ```
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// The C status code (`POLYMASS_ERROR_*`).
    ///
    /// ```
    /// let error = polymass::polygon(&[[0.0, 0.0], [1.0, 0.0]]).unwrap_err();
    /// assert_eq!(error.code(), 12);
    /// ```
    pub fn code(&self) -> i32 {
        self.kind.code()
    }

    /// The library's detailed message (what and where), without the kind's
    /// description; empty if the library gave none.
    ///
    /// ```
    /// let error = polymass::polygon(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]).unwrap_err();
    /// assert!(!error.message().is_empty());
    /// ```
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for Error {
    fn fmt(&self, formatter: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.message.is_empty() {
            write!(formatter, "{}", self.kind)
        } else {
            write!(formatter, "{}: {}", self.kind, self.message)
        }
    }
}

impl std::error::Error for Error {}
