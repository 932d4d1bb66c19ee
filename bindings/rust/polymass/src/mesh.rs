//! A validated, integrated solid (`polymass_mesh`).

use std::fmt;
use std::ptr::NonNull;

use polymass_sys as sys;

use crate::body::Body;
use crate::context::Context;
use crate::error::Result;
use crate::options::Options;
use crate::properties::MassProperties;
use crate::surface::Surface;

/// A surface validated and integrated once: it holds the integrals, not the
/// caller's slices, so mass properties for any density, mass or reference
/// point cost no pass over the faces.
///
/// A mesh is immutable: it is `Send` and `Sync`, and any number of threads
/// may compute from one at once (each call uses its own [`Context`]).
///
/// ```
/// use polymass::{Body, Mesh, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles))?;
/// std::thread::scope(|scope| {
///     for density in [1.0, 2.0] {
///         let mesh = &mesh;
///         scope.spawn(move || mesh.mass_properties(&Body::density(density)).unwrap());
///     }
/// });
/// # Ok::<(), polymass::Error>(())
/// ```
pub struct Mesh {
    raw: NonNull<sys::polymass_mesh>,
}

// SAFETY: a mesh is immutable once created and has no thread affinity; the
// header allows any number of threads to read it at once, and destroying it
// (Drop) takes the only reference.
unsafe impl Send for Mesh {}
// SAFETY: as above: every operation through &Mesh only reads it.
unsafe impl Sync for Mesh {}

impl Mesh {
    /// Validates and integrates a surface with the default options.
    ///
    /// ```
    /// use polymass::{ErrorKind, Mesh, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    /// let sheet = [[0u32, 1, 2], [0, 2, 1]]; // both sides of a triangle
    /// let error = Mesh::new(&Surface::triangles(&positions, &sheet)).unwrap_err();
    /// assert_eq!(error.kind(), ErrorKind::ZeroVolume);
    /// ```
    pub fn new(surface: &Surface<'_>) -> Result<Mesh> {
        Context::new()?.mesh(surface)
    }

    /// Validates and integrates a surface with the given options.
    ///
    /// ```
    /// use polymass::{Mesh, Options, Surface, Warnings};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let trusted = Options::new().skip_topology_checks(true);
    /// let mesh = Mesh::with_options(&Surface::triangles(&positions, &triangles), &trusted)?;
    /// assert!(mesh.mass_properties(&Default::default())?.warnings.contains(Warnings::UNCHECKED));
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn with_options(surface: &Surface<'_>, options: &Options) -> Result<Mesh> {
        Context::with_options(options)?.mesh(surface)
    }

    /// The mass properties of this solid as `body`.
    ///
    /// ```
    /// use polymass::{Body, Mesh, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles))?;
    /// let p = mesh.mass_properties(&Body::density(6.0))?;
    /// assert!((p.mass - 1.0).abs() < 1e-15);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn mass_properties(&self, body: &Body) -> Result<MassProperties> {
        Context::new()?.mesh_mass_properties(self, body)
    }

    /// Takes ownership of a mesh from polymass_mesh_create.
    ///
    /// # Safety
    /// `raw` is a live mesh that nothing else owns or frees.
    pub(crate) unsafe fn from_raw(raw: NonNull<sys::polymass_mesh>) -> Mesh {
        Mesh { raw }
    }

    pub(crate) fn as_raw(&self) -> *const sys::polymass_mesh {
        self.raw.as_ptr()
    }
}

impl Drop for Mesh {
    fn drop(&mut self) {
        // SAFETY: the mesh is ours and no other reference to it is left.
        unsafe { sys::polymass_mesh_destroy(self.raw.as_ptr()) }
    }
}

impl fmt::Debug for Mesh {
    fn fmt(&self, formatter: &mut fmt::Formatter<'_>) -> fmt::Result {
        formatter.debug_struct("Mesh").finish_non_exhaustive()
    }
}
