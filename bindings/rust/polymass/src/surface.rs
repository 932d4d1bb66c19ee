//! The caller's vertex and face slices, described for the library without
//! copying them.

use std::ffi::c_void;
use std::marker::PhantomData;
use std::mem::size_of;

use polymass_sys as sys;

mod sealed {
    pub trait Sealed {}
    impl Sealed for [f64; 3] {}
    impl Sealed for [f32; 3] {}
    impl Sealed for u32 {}
    impl Sealed for u16 {}
}

/// A vertex position the library reads in place: `[f64; 3]` or `[f32; 3]`
/// (x, y, z). Sealed: the library knows these two types only.
///
/// ```
/// fn volume<V: polymass::Vertex>(positions: &[V]) -> f64 {
///     let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
///     let surface = polymass::Surface::triangles(positions, &triangles);
///     polymass::mass_properties(&surface, &Default::default()).unwrap().volume
/// }
/// let corners = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let corners32 = corners.map(|p: [f64; 3]| p.map(|x| x as f32));
/// assert_eq!(volume(&corners), volume(&corners32));
/// ```
pub trait Vertex: sealed::Sealed + Copy {
    /// The `POLYMASS_POSITION_*` code of this type.
    #[doc(hidden)]
    const POSITION_TYPE: u32;
}

impl Vertex for [f64; 3] {
    const POSITION_TYPE: u32 = sys::POLYMASS_POSITION_FLOAT64;
}

impl Vertex for [f32; 3] {
    const POSITION_TYPE: u32 = sys::POLYMASS_POSITION_FLOAT32;
}

/// A vertex index the library reads in place: `u32` or `u16`. Sealed: the
/// library knows these two types only.
///
/// ```
/// fn face_count<I: polymass::Index>(triangles: &[[I; 3]]) -> usize {
///     let positions = [[0.0f64; 3]; 4];
///     polymass::Surface::triangles(&positions, triangles).face_count()
/// }
/// assert_eq!(face_count(&[[0u16, 1, 2], [0, 2, 3]]), 2);
/// assert_eq!(face_count(&[[0u32, 1, 2]]), 1);
/// ```
pub trait Index: sealed::Sealed + Copy {
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

/// A closed surface as borrowed slices: vertex positions and faces listing
/// vertex indices counter-clockwise seen from outside (the right-hand rule
/// gives outward normals). Nothing is copied; the library validates the
/// indices, so any slices are safe to pass.
///
/// A mesh may hold several shells; a cavity is a shell whose faces point into
/// the cavity.
///
/// ```
/// use polymass::Surface;
///
/// // A tetrahedron: three faces on the coordinate planes and a slanted one.
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let surface = Surface::triangles(&positions, &triangles);
/// let properties = polymass::mass_properties(&surface, &Default::default())?;
/// assert!((properties.volume - 1.0 / 6.0).abs() < 1e-15);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Surface<'a> {
    position_type: u32,
    positions: *const c_void,
    vertex_count: usize,
    index_type: u32,
    indices: *const c_void,
    index_count: usize,
    /// None: all faces are triangles.
    face_sizes: Option<&'a [u32]>,
    borrowed: PhantomData<&'a ()>,
}

// SAFETY: a Surface is shared borrows (for 'a) of slices of plain numbers,
// which may be read from any thread; the raw pointers only erase their type.
unsafe impl Send for Surface<'_> {}
// SAFETY: as above; nothing is ever written through the pointers.
unsafe impl Sync for Surface<'_> {}

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
    pub fn triangles<V: Vertex, I: Index>(positions: &'a [V], triangles: &'a [[I; 3]]) -> Self {
        Surface::new(positions, triangles.as_flattened(), None)
    }

    /// A surface of planar polygon faces (triangles, quads, any simple
    /// polygon, convex or not): `face_sizes[f]` is the number of vertices of
    /// face `f`, whose indices follow those of face `f - 1` in `indices`. The
    /// sizes must add up to `indices.len()`.
    ///
    /// ```
    /// use polymass::Surface;
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
    /// let properties = polymass::mass_properties(&surface, &Default::default())?;
    /// assert_eq!(properties.volume, 1.0);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn polygons<V: Vertex, I: Index>(
        positions: &'a [V],
        indices: &'a [I],
        face_sizes: &'a [u32],
    ) -> Self {
        Surface::new(positions, indices, Some(face_sizes))
    }

    fn new<V: Vertex, I: Index>(
        positions: &'a [V],
        indices: &'a [I],
        face_sizes: Option<&'a [u32]>,
    ) -> Self {
        Surface {
            position_type: V::POSITION_TYPE,
            positions: positions.as_ptr().cast(),
            vertex_count: positions.len(),
            index_type: I::INDEX_TYPE,
            indices: indices.as_ptr().cast(),
            index_count: indices.len(),
            face_sizes,
            borrowed: PhantomData,
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

    /// The C description of the slices, valid while 'a lasts.
    pub(crate) fn desc(&self) -> sys::polymass_mesh_desc {
        // Slice lengths fit in u64 on every platform Rust supports; the
        // library checks that the byte sizes they imply do not overflow.
        let (face_sizes, face_count) = match self.face_sizes {
            // Even an empty slice's pointer is not NULL: the library then
            // checks the (zero) sizes against the index count.
            Some(sizes) => (sizes.as_ptr(), sizes.len() as u64),
            None => (std::ptr::null(), 0), // all triangles
        };
        sys::polymass_mesh_desc {
            struct_size: struct_size::<sys::polymass_mesh_desc>(),
            position_type: self.position_type,
            positions: self.positions,
            vertex_count: self.vertex_count as u64,
            position_stride: 0, // packed: a slice of [T; 3]
            index_type: self.index_type,
            reserved: 0,
            indices: self.indices,
            index_count: self.index_count as u64,
            face_sizes,
            face_count,
        }
    }
}

/// `struct_size` of a C struct: its size as the bindings were generated.
pub(crate) fn struct_size<T>() -> u32 {
    u32::try_from(size_of::<T>()).expect("the C structs are small")
}
