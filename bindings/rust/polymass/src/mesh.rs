//! One analysis of a surface (`polymass_mesh`), and the questions it answers.

use std::ffi::CStr;
use std::fmt;
use std::ptr::{self, NonNull};

use polymass_sys as sys;

use crate::body::Body;
use crate::context::Context;
use crate::diagnostics::Diagnostics;
use crate::error::{Error, Result};
use crate::moments::Moments;
use crate::options::Options;
use crate::properties::MassProperties;
use crate::provenance::Provenance;
use crate::shell::Shell;
use crate::surface::{struct_size, Surface};

/// The result of one analysis of a surface with given [`Options`]: its
/// verdict, what the checks found ([`diagnostics`](Mesh::diagnostics)), its
/// [`shells`](Mesh::shells), which mode answered and what it did
/// ([`provenance`](Mesh::provenance)), and the integrals: every question is
/// a cheap read, never a second pass over the faces. Mass properties for any
/// density or mass cost no pass either. The mesh keeps none of the caller's
/// data.
///
/// A mesh is made whenever the analysis ran, whether the surface was
/// answered or refused, so that a refused surface says why:
/// [`status`](Mesh::status) is its verdict, and the questions about the body
/// ([`mass_properties`](Mesh::mass_properties), [`moments`](Mesh::moments),
/// [`provenance`](Mesh::provenance)) fail with it.
///
/// A mesh is immutable: it is `Send` and `Sync`, and any number of threads
/// may read one at once.
///
/// ```
/// use polymass::{Body, ErrorKind, Mesh, Options, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles), &Options::new())?;
/// std::thread::scope(|scope| {
///     for density in [1.0, 2.0] {
///         let mesh = &mesh;
///         scope.spawn(move || mesh.mass_properties(&Body::density(density)).unwrap());
///     }
/// });
///
/// // Open: refused, and the report says where.
/// let open = Mesh::new(&Surface::triangles(&positions, &triangles[..3]), &Options::new())?;
/// assert_eq!(open.status().unwrap_err().kind(), ErrorKind::Open);
/// assert_eq!(open.diagnostics()?.open_edges.count, 3);
/// assert_eq!(open.mass_properties(&Body::default()).unwrap_err().kind(), ErrorKind::Open);
/// # Ok::<(), polymass::Error>(())
/// ```
pub struct Mesh {
    raw: NonNull<sys::polymass_mesh>,
    /// The surface's faces, the length of shell_of_face.
    face_count: usize,
}

// SAFETY: a mesh is immutable once created and has no thread affinity; the
// header allows any number of threads to read it at once (each through its
// own context, which every method here makes or borrows mutably), and
// destroying it (Drop) takes the only reference.
unsafe impl Send for Mesh {}
// SAFETY: as above: every operation through &Mesh only reads it.
unsafe impl Sync for Mesh {}

impl Mesh {
    /// Analyses a surface once with `options`; see [`Context::mesh`] to use
    /// a context of several threads. Fails only when no analysis could run
    /// ([`ErrorKind::InvalidArgument`](crate::ErrorKind::InvalidArgument):
    /// options out of range, face sizes that do not add up; out of memory); a
    /// surface that is not a valid solid gives a mesh whose
    /// [`status`](Mesh::status) says so.
    ///
    /// ```
    /// use polymass::{ErrorKind, Mesh, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    /// let sheet = [[0u32, 1, 2], [0, 2, 1]]; // both sides of a triangle
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &sheet), &Options::new())?;
    /// assert_eq!(mesh.status().unwrap_err().kind(), ErrorKind::ZeroVolume);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn new(surface: &Surface<'_>, options: &Options) -> Result<Mesh> {
        Context::new()?.mesh(surface, options)
    }

    /// Takes ownership of a mesh from polymass_mesh_create.
    ///
    /// # Safety
    /// `raw` is a live mesh that nothing else owns or frees, made from a
    /// surface of `face_count` faces.
    pub(crate) unsafe fn from_raw(raw: NonNull<sys::polymass_mesh>, face_count: usize) -> Mesh {
        Mesh { raw, face_count }
    }

    pub(crate) fn as_raw(&self) -> *const sys::polymass_mesh {
        self.raw.as_ptr()
    }

    /// Asks this mesh a question whose answer is a C struct (`empty`, its
    /// struct_size set), through a fresh context: `call` passes the output,
    /// the context and the mesh it gets to one `polymass_mesh_*` function.
    fn ask<T>(
        &self,
        mut empty: T,
        call: impl FnOnce(&mut T, *mut sys::polymass_context, *const sys::polymass_mesh) -> i32,
    ) -> Result<T> {
        Context::new()?.mesh_call(|context| call(&mut empty, context, self.as_raw()))?;
        Ok(empty)
    }

    /// The verdict: `Ok` when a mode of the options' chain answered,
    /// otherwise the error with the mesh's message: what is wrong with the
    /// surface, then why each later mode failed. What is wrong with a
    /// surface that a later mode answered is in its
    /// [`diagnostics`](Mesh::diagnostics).
    ///
    /// ```
    /// use polymass::{Mesh, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let reversed = [[0u32, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
    /// let surface = Surface::triangles(&positions, &reversed);
    /// assert!(Mesh::new(&surface, &Options::new())?.status().is_err());
    /// assert!(Mesh::new(&surface, &Options::new().accept_inverted(true))?.status().is_ok());
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn status(&self) -> Result<()> {
        // SAFETY: a live mesh, only read.
        let status = unsafe { sys::polymass_mesh_status(self.as_raw()) };
        if status == sys::POLYMASS_OK {
            return Ok(());
        }
        Err(Error::new(status, self.message()))
    }

    /// What is wrong with the surface as given, in words
    /// (`polymass_mesh_message`): "" for a valid solid.
    fn message(&self) -> String {
        // SAFETY: never NULL, NUL-terminated, valid as long as the mesh.
        let message = unsafe { CStr::from_ptr(sys::polymass_mesh_message(self.as_raw())) };
        message.to_string_lossy().into_owned()
    }

    /// What the analysis found: every check the options did not skip, run
    /// to its end, and the surface's own verdict with its message. Written
    /// for every mesh, answered or not.
    pub fn diagnostics(&self) -> Result<Diagnostics> {
        let empty = sys::polymass_diagnostics {
            struct_size: struct_size::<sys::polymass_diagnostics>(),
            ..Default::default()
        };
        // SAFETY: ask passes an output with its struct_size set, a live
        // context used by this thread only and this live mesh.
        let raw = self.ask(empty, |out, context, mesh| unsafe {
            sys::polymass_mesh_diagnostics(out, context, mesh)
        })?;
        Ok(Diagnostics::from_raw(&raw, self.message()))
    }

    /// The shells, numbered from 0 in the order of their first faces. A
    /// shell's kind is judged when the surface passed the checks before the
    /// shells (closed, manifold, oriented, planar): by how the shells nest,
    /// counted exactly, or with
    /// [`Options::skip_intersection_check`](crate::Options::skip_intersection_check)
    /// by bounding boxes (which can show a shell to be inside out but take
    /// any negative shell within a solid's box for a cavity); otherwise every
    /// shell is [`ShellKind::Unjudged`](crate::ShellKind::Unjudged). An
    /// inside-out or overlapping shell is listed, not an `Err`.
    ///
    /// ```
    /// use polymass::{Mesh, Options, ShellKind, Surface};
    ///
    /// // A tetrahedron with legs 4 and, inside it, a cavity: a unit tetrahedron
    /// // moved by (0.5, 0.5, 0.5), its faces reversed.
    /// let positions = [
    ///     [0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 4.0],
    ///     [0.5, 0.5, 0.5], [1.5, 0.5, 0.5], [0.5, 1.5, 0.5], [0.5, 0.5, 1.5],
    /// ];
    /// let triangles = [
    ///     [0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3],
    ///     [4, 5, 6], [4, 7, 5], [4, 6, 7], [5, 7, 6],
    /// ];
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles), &Options::new())?;
    /// let shells = mesh.shells()?;
    /// let kinds: Vec<ShellKind> = shells.iter().map(|shell| shell.kind).collect();
    /// assert_eq!(kinds, [ShellKind::Solid, ShellKind::Cavity]);
    /// assert!((shells[1].signed_volume + 1.0 / 6.0).abs() < 1e-15);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn shells(&self) -> Result<Vec<Shell>> {
        let mut context = Context::new()?;
        let mut count = 0u64;
        // SAFETY: capacity 0 with no array asks for the count; see mesh_call.
        context.mesh_call(|context| unsafe {
            sys::polymass_mesh_shells(ptr::null_mut(), 0, &mut count, context, self.as_raw())
        })?;
        let blank = sys::polymass_shell {
            struct_size: struct_size::<sys::polymass_shell>(),
            ..Default::default()
        };
        let count = usize::try_from(count).expect("shells fit in memory as faces do");
        let mut shells = vec![blank; count];
        // SAFETY: `shells` holds `count` structs, each with struct_size set;
        // see mesh_call.
        context.mesh_call(|context| unsafe {
            sys::polymass_mesh_shells(
                shells.as_mut_ptr(),
                count as u64,
                &mut 0,
                context,
                self.as_raw(),
            )
        })?;
        Ok(shells.iter().map(Shell::from_raw).collect())
    }

    /// The shell of each face, numbered as [`shells`](Mesh::shells) numbers
    /// them: faces sharing a vertex are in one shell, after welding when the
    /// options weld (so a triangle soup splits as its solid does). Fails when
    /// the faces were unreadable (indices out of range, non-finite
    /// coordinates, faces of fewer than 3 vertices), with the mesh's error.
    ///
    /// ```
    /// use polymass::{Mesh, Options, Surface};
    ///
    /// // Two triangles apart, and a soup of two triangles sharing an edge.
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
    ///                  [5.0, 0.0, 0.0], [6.0, 0.0, 0.0], [5.0, 1.0, 0.0]];
    /// let apart = [[0u32, 1, 2], [3, 4, 5]];
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &apart), &Options::new())?;
    /// assert_eq!(mesh.shell_of_face()?, vec![0, 1]);
    /// let soup = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
    ///             [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    /// let triangles = [[0u32, 1, 2], [3, 4, 5]];
    /// let welding = Options::new().weld_vertices(true);
    /// let mesh = Mesh::new(&Surface::triangles(&soup, &triangles), &welding)?;
    /// assert_eq!(mesh.shell_of_face()?, vec![0, 0]);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn shell_of_face(&self) -> Result<Vec<u32>> {
        let mut of_face = vec![0u32; self.face_count];
        Context::new()?.mesh_call(|context| unsafe {
            // SAFETY: of_face has room for the capacity passed; see mesh_call.
            sys::polymass_mesh_shell_of_face(
                of_face.as_mut_ptr(),
                of_face.len() as u64,
                context,
                self.as_raw(),
            )
        })?;
        Ok(of_face)
    }

    /// Which mode of the options' chain answered, and what it did; the
    /// mesh's error when none did.
    ///
    /// ```
    /// use polymass::{Body, Mesh, Mode, Options, Surface, Warnings};
    ///
    /// // A fin on an edge of a tetrahedron: no repair is the right one; the hull answers.
    /// let positions = [
    ///     [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [2.0, 2.0, -1.0],
    /// ];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 2, 4]];
    /// let options = Options::new().fallback(&[Mode::Repair, Mode::Hull]);
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles), &options)?;
    /// let provenance = mesh.provenance()?;
    /// assert_eq!(provenance.mode, Mode::Hull);
    /// assert_eq!(provenance.hull_vertex_count, 5);
    /// assert!(mesh.mass_properties(&Body::default())?.warnings.contains(Warnings::HULL));
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn provenance(&self) -> Result<Provenance> {
        let empty = sys::polymass_provenance {
            struct_size: struct_size::<sys::polymass_provenance>(),
            ..Default::default()
        };
        // SAFETY: ask passes an output with its struct_size set, a live
        // context used by this thread only and this live mesh.
        let raw = self.ask(empty, |out, context, mesh| unsafe {
            sys::polymass_mesh_provenance(out, context, mesh)
        })?;
        Ok(Provenance::from_raw(&raw))
    }

    /// The moments (unit density) of the body that answered, to compose with
    /// others ([`Moments`]).
    ///
    /// ```
    /// use polymass::{Mesh, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles), &Options::new())?;
    /// assert!((mesh.moments()?.volume() - 1.0 / 6.0).abs() < 1e-16);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn moments(&self) -> Result<Moments> {
        Context::new()?.moments_call(|out, context| unsafe {
            // SAFETY: a live mesh, only read; see moments_call.
            sys::polymass_mesh_moments(out, context, self.as_raw())
        })
    }

    /// The mass properties of the body that answered, as `body`; see
    /// [`Context::mesh_mass_properties`] to reuse a context in a loop.
    ///
    /// ```
    /// use polymass::{Body, Mesh, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles), &Options::new())?;
    /// let p = mesh.mass_properties(&Body::density(6.0))?;
    /// assert!((p.mass - 1.0).abs() < 1e-15);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn mass_properties(&self, body: &Body) -> Result<MassProperties> {
        Context::new()?.mesh_mass_properties(self, body)
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
        formatter
            .debug_struct("Mesh")
            .field("status", &self.status())
            .field("face_count", &self.face_count)
            .finish_non_exhaustive()
    }
}
