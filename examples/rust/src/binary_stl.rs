//! A small reader of binary STL files: an 80-byte header, a little-endian
//! u32 triangle count, then per triangle a normal and three vertices (12
//! f32s) and a u16 attribute, 50 bytes in all. ASCII STL is not read.

use std::fmt;

const HEADER_BYTES: usize = 80;
const TRIANGLE_BYTES: usize = 50;

/// An STL triangle soup: three positions per triangle, in file order, and the
/// triangles indexing them (triangle t is vertices 3t, 3t + 1, 3t + 2).
/// Vertices shared by neighbouring triangles are repeated, so computing with
/// it needs welding (`polymass::Options::weld_vertices`).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleSoup {
    /// Three vertices per triangle.
    pub positions: Vec<[f32; 3]>,
    /// `[3t, 3t + 1, 3t + 2]` for triangle t.
    pub triangles: Vec<[u32; 3]>,
}

/// Why bytes are not a binary STL.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum StlError {
    /// Shorter than the 84-byte header and count.
    TooShort(usize),
    /// The size is not 84 + 50 × the declared triangle count.
    SizeMismatch {
        /// Triangles the count field declares.
        declared: u32,
        /// Bytes actually there.
        bytes: usize,
    },
    /// More triangles than u32 vertex indices can number.
    TooManyTriangles(u32),
}

impl fmt::Display for StlError {
    fn fmt(&self, formatter: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StlError::TooShort(bytes) => write!(
                formatter,
                "{bytes} bytes: a binary STL has at least {} (header and triangle count)",
                HEADER_BYTES + 4
            ),
            StlError::SizeMismatch { declared, bytes } => write!(
                formatter,
                "{bytes} bytes, but {declared} triangles take {} (an ASCII STL, or a truncated file?)",
                HEADER_BYTES + 4 + *declared as usize * TRIANGLE_BYTES
            ),
            StlError::TooManyTriangles(count) => {
                write!(formatter, "{count} triangles: more than 32-bit indices can number")
            }
        }
    }
}

impl std::error::Error for StlError {}

/// Parses the bytes of a binary STL file.
pub fn parse(bytes: &[u8]) -> Result<TriangleSoup, StlError> {
    let count_bytes = bytes
        .get(HEADER_BYTES..HEADER_BYTES + 4)
        .ok_or(StlError::TooShort(bytes.len()))?;
    let declared = u32::from_le_bytes(count_bytes.try_into().expect("4 bytes"));
    let body = &bytes[HEADER_BYTES + 4..];
    if body.len() / TRIANGLE_BYTES != declared as usize || body.len() % TRIANGLE_BYTES != 0 {
        return Err(StlError::SizeMismatch {
            declared,
            bytes: bytes.len(),
        });
    }
    if u32::try_from(declared as u64 * 3).is_err() {
        return Err(StlError::TooManyTriangles(declared));
    }
    let mut positions = Vec::with_capacity(declared as usize * 3);
    for record in body.chunks_exact(TRIANGLE_BYTES) {
        // Bytes 0..12 are the facet normal, which the mass properties do not
        // need: the vertex order gives the orientation.
        for vertex in record[12..48].chunks_exact(12) {
            positions.push(std::array::from_fn(|axis| {
                let at = 4 * axis;
                f32::from_le_bytes(vertex[at..at + 4].try_into().expect("4 bytes"))
            }));
        }
    }
    let triangles = (0..declared)
        .map(|t| [3 * t, 3 * t + 1, 3 * t + 2])
        .collect();
    Ok(TriangleSoup {
        positions,
        triangles,
    })
}
