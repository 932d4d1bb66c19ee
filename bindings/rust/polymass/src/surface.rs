//! The caller's vertex and face data, described for the library without
//! copying them: packed slices, or positions interleaved with other vertex
//! attributes at any byte stride.

use std::fmt;
use std::mem::{size_of, size_of_val};

use polymass_sys as sys;

use crate::error::{Error, Result};

mod sealed {
    /// Plain numbers, and arrays of them: no padding byte and every bit
    /// pattern valid, so their memory may be read as bytes. Sealed: the
    /// library reads these types only.
    pub trait Sealed: Copy {}
    impl Sealed for f64 {}
    impl Sealed for f32 {}
    impl Sealed for [f64; 3] {}
    impl Sealed for [f32; 3] {}
    impl Sealed for u32 {}
    impl Sealed for u16 {}
    impl Sealed for u64 {}
}

/// A coordinate type the library reads in place: `f64` or `f32`. Sealed.
///
/// ```
/// use polymass::Positions;
///
/// // The same two vertices, x y z then a pad, in f64 and in f32.
/// let wide = [0.0f64, 1.0, 2.0, 9.0, 3.0, 4.0, 5.0, 9.0];
/// let narrow = wide.map(|x| x as f32);
/// assert_eq!(Positions::interleaved(&wide, 4)?.len(), Positions::interleaved(&narrow, 4)?.len());
/// # Ok::<(), polymass::Error>(())
/// ```
pub trait Coordinate: sealed::Sealed {
    /// The `POLYMASS_POSITION_*` code of this type.
    #[doc(hidden)]
    const POSITION_TYPE: u32;
}

impl Coordinate for f64 {
    const POSITION_TYPE: u32 = sys::POLYMASS_POSITION_FLOAT64;
}

impl Coordinate for f32 {
    const POSITION_TYPE: u32 = sys::POLYMASS_POSITION_FLOAT32;
}

/// A packed vertex position the library reads in place: `[f64; 3]` or
/// `[f32; 3]` (x, y, z). Sealed.
///
/// ```
/// fn volume<V: polymass::Vertex>(positions: &[V]) -> f64 {
///     let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
///     let surface = polymass::Surface::triangles(positions, &triangles);
///     polymass::mass_properties(&surface, &Default::default(), &Default::default())
///         .unwrap()
///         .volume
/// }
/// let corners = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let corners32 = corners.map(|p: [f64; 3]| p.map(|x| x as f32));
/// assert_eq!(volume(&corners), volume(&corners32));
/// ```
pub trait Vertex: sealed::Sealed {
    /// The type of its coordinates.
    #[doc(hidden)]
    type Coordinate: Coordinate;
}

impl Vertex for [f64; 3] {
    type Coordinate = f64;
}

impl Vertex for [f32; 3] {
    type Coordinate = f32;
}

/// A vertex index the library reads in place: `u32` or `u16`. Sealed.
///
/// ```
/// fn face_count<I: polymass::Index>(triangles: &[[I; 3]]) -> usize {
///     let positions = [[0.0f64; 3]; 4];
///     polymass::Surface::triangles(&positions, triangles).face_count()
/// }
/// assert_eq!(face_count(&[[0u16, 1, 2], [0, 2, 3]]), 2);
/// assert_eq!(face_count(&[[0u32, 1, 2]]), 1);
/// ```
pub trait Index: sealed::Sealed {
    /// The `POLYMASS_INDEX_*` code of this type.
    #[doc(hidden)]
    const INDEX_TYPE: u32;
}

impl Index for u32 {
    const INDEX_TYPE: u32 = sys::POLYMASS_INDEX_UINT32;
}

impl Index for u16 {
    const INDEX_TYPE: u32 = sys::POLYMASS_INDEX_UINT16;
}

/// An index type the packed call ([`PackedMeshes`](crate::PackedMeshes))
/// reads in place: `u16`, `u32`, or `u64` for packed sets only, as PyTorch3D
/// keeps `faces_packed` (int64, its values never negative). Each mesh's
/// 64-bit indices are narrowed to 32 bits inside the library; one that does
/// not fit fails its own mesh. Sealed.
pub trait PackedIndex: sealed::Sealed {
    /// The `POLYMASS_INDEX_*` code of this type.
    #[doc(hidden)]
    const PACKED_INDEX_TYPE: u32;
}

impl PackedIndex for u64 {
    const PACKED_INDEX_TYPE: u32 = sys::POLYMASS_INDEX_UINT64;
}

impl PackedIndex for u32 {
    const PACKED_INDEX_TYPE: u32 = sys::POLYMASS_INDEX_UINT32;
}

impl PackedIndex for u16 {
    const PACKED_INDEX_TYPE: u32 = sys::POLYMASS_INDEX_UINT16;
}

/// The memory of plain numbers, as bytes, for as long as the numbers are
/// borrowed.
fn bytes_of<T: sealed::Sealed>(items: &[T]) -> &[u8] {
    // SAFETY: T is one of the sealed plain types: no padding, so every byte
    // of the slice is initialised; u8 needs no alignment; the length is the
    // slice's size in bytes and the result borrows the slice.
    unsafe { std::slice::from_raw_parts(items.as_ptr().cast::<u8>(), size_of_val(items)) }
}

/// The vertex positions of a [`Surface`], borrowed in place: a packed slice
/// of `[f64; 3]` or `[f32; 3]`, or the x, y, z of each vertex at a fixed
/// stride among other attributes (an engine's interleaved vertex buffer:
/// position, normal, texture coordinates, ...). Nothing is copied. Every
/// constructor checks that each vertex it describes lies within the
/// borrowed memory, so the library reads nothing else.
///
/// A packed slice converts by itself (`From`), so
/// [`Surface::triangles`] and [`Surface::polygons`] take one directly.
///
/// ```
/// use polymass::{Options, Positions, Surface};
///
/// // Four vertices of position, normal and texture coordinates: 8 f32 each.
/// let vertices: [[f32; 8]; 4] = [
///     [0.0, 0.0, 0.0, /* normal */ 0.0, 0.0, -1.0, /* uv */ 0.0, 0.0],
///     [1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0],
///     [0.0, 1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0],
///     [0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 1.0],
/// ];
/// let positions = Positions::interleaved(vertices.as_flattened(), 8)?;
/// assert_eq!(positions.len(), 4);
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let surface = Surface::triangles(positions, &triangles);
/// let p = polymass::mass_properties(&surface, &Options::new(), &Default::default())?;
/// assert!((p.volume - 1.0 / 6.0).abs() < 1e-15);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Clone, Copy)]
pub struct Positions<'a> {
    /// From the first coordinate of vertex 0 to (at least) the last of the
    /// last vertex.
    bytes: &'a [u8],
    position_type: u32,
    count: usize,
    /// Bytes from one vertex to the next.
    stride: usize,
}

impl<'a> Positions<'a> {
    /// Packed positions, one `[f64; 3]` or `[f32; 3]` per vertex (what
    /// `From` makes of a slice, an array or a `Vec`).
    ///
    /// ```
    /// let corners = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
    /// assert_eq!(polymass::Positions::packed(&corners).len(), 2);
    /// ```
    pub fn packed<V: Vertex>(positions: &'a [V]) -> Positions<'a> {
        Positions {
            bytes: bytes_of(positions),
            position_type: V::Coordinate::POSITION_TYPE,
            count: positions.len(),
            stride: size_of::<V>(),
        }
    }

    /// Positions interleaved in a slice of coordinates: vertex `i`'s x, y, z
    /// are `data[i * stride..i * stride + 3]`, `stride` (at least 3) counted
    /// in coordinates. One vertex per `stride` coordinates; the last may be
    /// cut short after its z, so `&buffer[offset..]` reads the attribute at
    /// `offset` of every vertex of a buffer.
    ///
    /// Fails with [`ErrorKind::InvalidArgument`](crate::ErrorKind::InvalidArgument)
    /// for a stride below 3 or a last vertex without its three coordinates.
    ///
    /// ```
    /// use polymass::{ErrorKind, Positions};
    ///
    /// // Two vertices of x y z and a colour index, read from the second's x.
    /// let buffer = [0.0f64, 0.0, 0.0, 7.0, 1.0, 2.0, 3.0, 7.0];
    /// assert_eq!(Positions::interleaved(&buffer, 4)?.len(), 2);
    /// assert_eq!(Positions::interleaved(&buffer[4..], 4)?.len(), 1);
    /// let error = Positions::interleaved(&buffer[..6], 4).unwrap_err();
    /// assert_eq!(error.kind(), ErrorKind::InvalidArgument);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn interleaved<C: Coordinate>(data: &'a [C], stride: usize) -> Result<Positions<'a>> {
        if stride < 3 {
            return Err(invalid(format!(
                "a stride of {stride} coordinates is shorter than a position (3)"
            )));
        }
        let count = data.len().div_ceil(stride);
        if data.len() % stride != 0 && data.len() % stride < 3 {
            return Err(invalid(format!(
                "the last of {count} vertices has {} of its 3 coordinates",
                data.len() % stride
            )));
        }
        Ok(Positions {
            bytes: bytes_of(data),
            position_type: C::POSITION_TYPE,
            count,
            stride: stride * size_of::<C>(),
        })
    }

    /// `count` positions of coordinate type `C` in raw bytes, as a vertex
    /// buffer or a glTF accessor holds them: vertex `i`'s x, y, z start at
    /// byte `i * stride` (at least the size of three `C`s), in the machine's
    /// byte order, at any alignment. Start the slice at the first vertex's x:
    /// `&buffer[offset..]`.
    ///
    /// Fails with [`ErrorKind::InvalidArgument`](crate::ErrorKind::InvalidArgument)
    /// for a stride shorter than a position, or bytes too few for `count`
    /// vertices.
    ///
    /// ```
    /// use polymass::{Options, Positions, Surface};
    ///
    /// // A unit corner tetrahedron in a buffer of 20-byte vertices: a u32
    /// // material id, then x y z as f32, then an f32 weight.
    /// let corners = [[0.0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let mut buffer = Vec::new();
    /// for corner in corners {
    ///     buffer.extend(7u32.to_ne_bytes());
    ///     corner.iter().for_each(|x| buffer.extend(x.to_ne_bytes()));
    ///     buffer.extend(0.5f32.to_ne_bytes());
    /// }
    /// let positions = Positions::from_bytes::<f32>(&buffer[4..], 20, 4)?;
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let surface = Surface::triangles(positions, &triangles);
    /// let p = polymass::mass_properties(&surface, &Options::new(), &Default::default())?;
    /// assert!((p.volume - 1.0 / 6.0).abs() < 1e-15);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn from_bytes<C: Coordinate>(
        bytes: &'a [u8],
        stride: usize,
        count: usize,
    ) -> Result<Positions<'a>> {
        let position = 3 * size_of::<C>();
        if stride < position {
            return Err(invalid(format!(
                "a stride of {stride} bytes is shorter than a position ({position})"
            )));
        }
        let needed = match count.checked_sub(1) {
            None => 0,
            Some(last) => last
                .checked_mul(stride)
                .and_then(|start| start.checked_add(position))
                .unwrap_or(usize::MAX),
        };
        if needed > bytes.len() {
            return Err(invalid(format!(
                "{count} vertices {stride} bytes apart take {needed} bytes; {} given",
                bytes.len()
            )));
        }
        Ok(Positions {
            bytes,
            position_type: C::POSITION_TYPE,
            count,
            stride,
        })
    }

    /// The number of vertices.
    pub fn len(&self) -> usize {
        self.count
    }

    /// Whether there is no vertex.
    ///
    /// ```
    /// assert!(polymass::Positions::packed::<[f64; 3]>(&[]).is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The library's `POLYMASS_POSITION_*` code, the bytes and the stride.
    pub(crate) fn raw_parts(&self) -> (u32, &'a [u8], u64) {
        (self.position_type, self.bytes, self.stride as u64)
    }
}

/// What the data are, not the numbers: a vertex buffer may be large.
impl fmt::Debug for Positions<'_> {
    fn fmt(&self, formatter: &mut fmt::Formatter<'_>) -> fmt::Result {
        let coordinate = match self.position_type {
            sys::POLYMASS_POSITION_FLOAT32 => "f32",
            _ => "f64",
        };
        formatter
            .debug_struct("Positions")
            .field("coordinate", &coordinate)
            .field("len", &self.count)
            .field("stride_bytes", &self.stride)
            .finish()
    }
}

fn invalid(message: String) -> Error {
    Error::new(sys::POLYMASS_ERROR_INVALID_ARGUMENT, message)
}

impl<'a, V: Vertex> From<&'a [V]> for Positions<'a> {
    fn from(positions: &'a [V]) -> Positions<'a> {
        Positions::packed(positions)
    }
}

impl<'a, V: Vertex, const N: usize> From<&'a [V; N]> for Positions<'a> {
    fn from(positions: &'a [V; N]) -> Positions<'a> {
        Positions::packed(positions)
    }
}

impl<'a, V: Vertex> From<&'a Vec<V>> for Positions<'a> {
    fn from(positions: &'a Vec<V>) -> Positions<'a> {
        Positions::packed(positions)
    }
}

/// A closed surface as borrowed data: vertex [`Positions`] and faces listing
/// vertex indices counter-clockwise seen from outside (the right-hand rule
/// gives outward normals). Nothing is copied; the library validates the
/// indices, so any data are safe to pass. Being only shared borrows of plain
/// numbers, a surface is `Send` and `Sync`.
///
/// A mesh may hold several shells; a cavity is a shell whose faces point into
/// the cavity.
///
/// ```
/// use polymass::{Options, Surface};
///
/// // A tetrahedron: three faces on the coordinate planes and a slanted one.
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let surface = Surface::triangles(&positions, &triangles);
/// let properties = polymass::mass_properties(&surface, &Options::new(), &Default::default())?;
/// assert!((properties.volume - 1.0 / 6.0).abs() < 1e-15);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Clone, Copy)]
pub struct Surface<'a> {
    positions: Positions<'a>,
    index_type: u32,
    indices: &'a [u8],
    index_count: usize,
    /// None: all faces are triangles.
    face_sizes: Option<&'a [u32]>,
}

impl<'a> Surface<'a> {
    /// A surface of triangles, each three indices into `positions`.
    ///
    /// ```
    /// use polymass::Surface;
    ///
    /// // f32 positions and u16 indices are read in place too.
    /// let positions: [[f32; 3]; 4] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles: [[u16; 3]; 4] = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let surface = Surface::triangles(&positions, &triangles);
    /// assert_eq!(surface.face_count(), 4);
    /// ```
    pub fn triangles<I: Index>(
        positions: impl Into<Positions<'a>>,
        triangles: &'a [[I; 3]],
    ) -> Self {
        Surface::new(
            positions.into(),
            I::INDEX_TYPE,
            triangles.as_flattened(),
            None,
        )
    }

    /// The triangles of a packed set, whose indices may be 64-bit.
    pub(crate) fn packed_triangles<I: PackedIndex>(
        positions: Positions<'a>,
        triangles: &'a [[I; 3]],
    ) -> Self {
        Surface::new(
            positions,
            I::PACKED_INDEX_TYPE,
            triangles.as_flattened(),
            None,
        )
    }

    /// A surface of planar polygon faces (triangles, quads, any simple
    /// polygon, convex or not): `face_sizes[f]` is the number of vertices of
    /// face `f`, whose indices follow those of face `f - 1` in `indices`. The
    /// sizes must add up to `indices.len()`.
    ///
    /// ```
    /// use polymass::{Options, Surface};
    ///
    /// // A unit cube as six quads.
    /// let positions = [
    ///     [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0],
    ///     [0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 1.0, 1.0],
    /// ];
    /// let indices = [
    ///     0u32, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7,
    /// ];
    /// let surface = Surface::polygons(&positions, &indices, &[4; 6]);
    /// let properties = polymass::mass_properties(&surface, &Options::new(), &Default::default())?;
    /// assert_eq!(properties.volume, 1.0);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn polygons<I: Index>(
        positions: impl Into<Positions<'a>>,
        indices: &'a [I],
        face_sizes: &'a [u32],
    ) -> Self {
        Surface::new(positions.into(), I::INDEX_TYPE, indices, Some(face_sizes))
    }

    fn new<I: sealed::Sealed>(
        positions: Positions<'a>,
        index_type: u32,
        indices: &'a [I],
        face_sizes: Option<&'a [u32]>,
    ) -> Self {
        Surface {
            positions,
            index_type,
            indices: bytes_of(indices),
            index_count: indices.len(),
            face_sizes,
        }
    }

    /// The number of faces.
    ///
    /// ```
    /// use polymass::Surface;
    ///
    /// let positions = [[0.0f64; 3]; 3];
    /// assert_eq!(Surface::polygons(&positions, &[0u32, 1, 2], &[3]).face_count(), 1);
    /// ```
    pub fn face_count(&self) -> usize {
        match self.face_sizes {
            Some(sizes) => sizes.len(),
            None => self.index_count / 3,
        }
    }

    /// The C description of the data, valid while 'a lasts.
    pub(crate) fn desc(&self) -> sys::polymass_mesh_desc {
        // Lengths fit in u64 on every platform Rust supports; the library
        // checks that the byte sizes they imply do not overflow.
        let (face_sizes, face_count) = match self.face_sizes {
            // Even an empty slice's pointer is not NULL: the library then
            // checks the (zero) sizes against the index count.
            Some(sizes) => (sizes.as_ptr(), sizes.len() as u64),
            None => (std::ptr::null(), 0), // all triangles
        };
        let (position_type, positions, position_stride) = self.positions.raw_parts();
        sys::polymass_mesh_desc {
            struct_size: struct_size::<sys::polymass_mesh_desc>(),
            position_type,
            positions: positions.as_ptr().cast(),
            vertex_count: self.positions.len() as u64,
            position_stride,
            index_type: self.index_type,
            reserved: 0,
            indices: self.indices.as_ptr().cast(),
            index_count: self.index_count as u64,
            face_sizes,
            face_count,
        }
    }
}

/// What the data are, not the numbers.
///
/// ```
/// let positions = [[0.0f32; 3]; 3];
/// let surface = polymass::Surface::triangles(&positions, &[[0u16, 1, 2]]);
/// assert_eq!(
///     format!("{surface:?}"),
///     "Surface { positions: Positions { coordinate: \"f32\", len: 3, stride_bytes: 12 }, \
///      index_count: 3, face_count: 1 }"
/// );
/// ```
impl fmt::Debug for Surface<'_> {
    fn fmt(&self, formatter: &mut fmt::Formatter<'_>) -> fmt::Result {
        formatter
            .debug_struct("Surface")
            .field("positions", &self.positions)
            .field("index_count", &self.index_count)
            .field("face_count", &self.face_count())
            .finish()
    }
}

/// `struct_size` of a C struct: its size as the bindings were generated.
pub(crate) fn struct_size<T>() -> u32 {
    u32::try_from(size_of::<T>()).expect("the C structs are small")
}
