//! What belongs to a caller (`polymass_context`): worker threads, scratch
//! memory, the last message.

use std::ffi::CStr;
use std::fmt;
use std::ptr::{self, NonNull};

use polymass_sys as sys;

use crate::body::Body;
use crate::error::{Error, Result};
use crate::mesh::Mesh;
use crate::moments::Moments;
use crate::options::Options;
use crate::polygon::PolygonProperties;
use crate::properties::MassProperties;
use crate::surface::{struct_size, Positions, Surface};
use crate::weld::Weld;

/// A context: what belongs to the caller, never how a surface is checked
/// ([`Options`] are given per call). It holds the worker threads a call may
/// use ([`set_threads`](Context::set_threads)), the scratch memory large
/// calls reuse, and the message of the last failure.
///
/// It is `Send` but not `Sync`: one thread at a time may use it, which every
/// method taking `&mut self` enforces; threads computing at once each take
/// their own. The free functions ([`mass_properties`](crate::mass_properties)
/// and friends) and [`Mesh`]'s methods make a context per call; keep one for
/// threads, or to save its allocation and scratch memory in a loop.
///
/// ```
/// use polymass::{Body, Context, Options, Surface, Warnings};
///
/// // An inverted tetrahedron (every face reversed), accepted and turned.
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let reversed = [[0u32, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
/// let mut context = Context::new()?;
/// let accepting = Options::new().accept_inverted(true);
/// let surface = Surface::triangles(&positions, &reversed);
/// let p = context.mass_properties(&surface, &accepting, &Body::default())?;
/// assert!(p.volume > 0.0 && p.warnings.contains(Warnings::INVERTED));
/// # Ok::<(), polymass::Error>(())
/// ```
///
/// A context cannot be shared between threads:
///
/// ```compile_fail
/// fn shared<T: Sync>(_: &T) {}
/// shared(&polymass::Context::new().unwrap());
/// ```
pub struct Context {
    raw: NonNull<sys::polymass_context>,
}

// SAFETY: the library has no thread affinity: a context may be used from any
// thread, one at a time. Context is not Sync, and every call through it takes
// &mut self, so two threads never use it at once.
unsafe impl Send for Context {}

impl Context {
    /// A context of one thread (the calling one) and the default scratch
    /// limit.
    ///
    /// ```
    /// let context = polymass::Context::new()?;
    /// # drop(context);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn new() -> Result<Context> {
        let mut raw = ptr::null_mut();
        // SAFETY: out-pointer to a local; NULL allocator means malloc.
        let status = unsafe { sys::polymass_context_create(&mut raw, ptr::null()) };
        if status != sys::POLYMASS_OK {
            // No context: no message beyond the status.
            return Err(Error::new(status, String::new()));
        }
        let raw = NonNull::new(raw).expect("polymass_context_create succeeded with NULL");
        Ok(Context { raw })
    }

    /// A context whose calls may use `threads` threads; see
    /// [`set_threads`](Context::set_threads).
    ///
    /// ```
    /// let threads = std::thread::available_parallelism().map_or(1, |n| n.get() as u32);
    /// let context = polymass::Context::with_threads(threads)?;
    /// # drop(context);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn with_threads(threads: u32) -> Result<Context> {
        let mut context = Context::new()?;
        context.set_threads(threads)?;
        Ok(context)
    }

    /// How many threads one call through this context may use: the calling
    /// thread and `threads - 1` workers, started on first use, reused, and
    /// joined when the context is dropped. 1, the default, starts no thread;
    /// at most `POLYMASS_MAX_THREADS` (256). The passes over one surface's
    /// faces and [`batch`](Context::batch)'s items are spread over them.
    /// Every count gives the same bits.
    ///
    /// ```
    /// use polymass::{Context, ErrorKind};
    ///
    /// let mut context = Context::new()?;
    /// context.set_threads(4)?;
    /// assert_eq!(context.set_threads(100_000).unwrap_err().kind(), ErrorKind::InvalidArgument);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn set_threads(&mut self, threads: u32) -> Result<()> {
        // SAFETY: live context, used by this thread only (&mut self).
        let status = unsafe { sys::polymass_context_set_threads(self.raw.as_ptr(), threads) };
        self.result(status)
    }

    /// Bounds the scratch memory this context keeps between calls (the
    /// topology check's edge lists, the shells' tables: up to about 16 bytes
    /// per triangle), freeing what is beyond it now: 0 keeps nothing. By
    /// default a context keeps what its largest recent call used, so that a
    /// loop over large meshes does not map and fault fresh memory each time.
    ///
    /// ```
    /// let mut context = polymass::Context::new()?;
    /// context.set_scratch_limit(64 << 20)?; // at most 64 MiB between calls
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn set_scratch_limit(&mut self, max_kept_bytes: u64) -> Result<()> {
        // SAFETY: live context, used by this thread only (&mut self).
        let status =
            unsafe { sys::polymass_context_set_scratch_limit(self.raw.as_ptr(), max_kept_bytes) };
        self.result(status)
    }

    /// Analyses a surface once with `options`: see [`Mesh`]. Fails only when
    /// no analysis could run (an invalid argument, out of memory); a surface
    /// that is not a valid solid gives a mesh that says so. The mesh keeps
    /// none of the surface's data: they may go once this returns.
    ///
    /// ```
    /// use polymass::{Body, Context, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mut context = Context::new()?;
    /// let mesh = context.mesh(&Surface::triangles(&positions, &triangles), &Options::new())?;
    /// let light = context.mesh_mass_properties(&mesh, &Body::mass(1.0))?;
    /// let heavy = context.mesh_mass_properties(&mesh, &Body::mass(2.0))?;
    /// assert_eq!(2.0 * light.inertia[0][0], heavy.inertia[0][0]);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn mesh(&mut self, surface: &Surface<'_>, options: &Options) -> Result<Mesh> {
        let desc = surface.desc();
        let options = options.to_raw();
        let mut raw = ptr::null_mut();
        // SAFETY: live context, this thread only; desc points into data
        // borrowed by `surface` for the whole call; options outlive it.
        let status =
            unsafe { sys::polymass_mesh_create(&mut raw, self.raw.as_ptr(), &desc, &options) };
        let Some(raw) = NonNull::new(raw) else {
            self.result(status)?;
            return Err(Error::new(
                sys::POLYMASS_ERROR_INTERNAL,
                "polymass_mesh_create succeeded without a mesh".to_owned(),
            ));
        };
        // SAFETY: a mesh polymass_mesh_create just made, owned by no one
        // else, of the surface's faces.
        Ok(unsafe { Mesh::from_raw(raw, surface.face_count()) })
    }

    /// The mass properties of a mesh, as `body`: [`Mesh::mass_properties`]
    /// through this context.
    ///
    /// ```
    /// use polymass::{Body, Context, Mesh, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles), &Options::new())?;
    /// let mut context = Context::new()?;
    /// for density in [1000.0, 2700.0, 7850.0] {
    ///     let p = context.mesh_mass_properties(&mesh, &Body::density(density))?;
    ///     assert!((p.mass - density / 6.0).abs() < 1e-12);
    /// }
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn mesh_mass_properties(&mut self, mesh: &Mesh, body: &Body) -> Result<MassProperties> {
        let mass = body.to_raw();
        let mut out = empty_properties();
        // SAFETY: live context, this thread only; the mesh is alive and may be
        // read by several threads at once; out and mass outlive the call.
        let status = unsafe {
            sys::polymass_mesh_mass_properties(&mut out, self.raw.as_ptr(), mesh.as_raw(), &mass)
        };
        self.result(status)?;
        Ok(MassProperties::from_raw(&out))
    }

    /// The mass properties of a surface as `body`, analysed with `options`,
    /// keeping no mesh: the same analysis as [`mesh`](Context::mesh),
    /// stopping at the first defect. An engine's load path.
    ///
    /// ```
    /// use polymass::{Body, Context, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mut context = Context::new()?;
    /// let surface = Surface::triangles(&positions, &triangles);
    /// let p = context.mass_properties(&surface, &Options::new(), &Body::default())?;
    /// assert!((p.surface_area - (1.5 + 3f64.sqrt() / 2.0)).abs() < 1e-15);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn mass_properties(
        &mut self,
        surface: &Surface<'_>,
        options: &Options,
        body: &Body,
    ) -> Result<MassProperties> {
        let desc = surface.desc();
        let options = options.to_raw();
        let mass = body.to_raw();
        let mut out = empty_properties();
        // SAFETY: live context, this thread only; desc points into data
        // borrowed by `surface`; out, desc, options and mass outlive the
        // call; no provenance asked.
        let status = unsafe {
            sys::polymass_mass_properties_compute(
                &mut out,
                ptr::null_mut(),
                self.raw.as_ptr(),
                &desc,
                &options,
                &mass,
            )
        };
        self.result(status)?;
        Ok(MassProperties::from_raw(&out))
    }

    /// Area, centroid and second moments of area of a simple polygon in the
    /// xy plane, convex or not, either orientation. The polygon closes itself:
    /// do not repeat the first point. Self-intersections are not detected.
    ///
    /// ```
    /// let mut context = polymass::Context::new()?;
    /// let triangle = context.polygon(&[[0.0, 0.0], [3.0, 0.0], [0.0, 3.0]])?;
    /// assert_eq!(triangle.area, 4.5);
    /// assert_eq!(triangle.centroid, [1.0, 1.0]);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn polygon(&mut self, points: &[[f64; 2]]) -> Result<PolygonProperties> {
        let mut out = sys::polymass_polygon_properties {
            struct_size: struct_size::<sys::polymass_polygon_properties>(),
            ..Default::default()
        };
        // SAFETY: live context, this thread only; points.len() packed (x, y)
        // pairs (stride 0) that outlive the call.
        let status = unsafe {
            sys::polymass_polygon_compute(
                &mut out,
                self.raw.as_ptr(),
                points.as_flattened().as_ptr(),
                points.len() as u64,
                0,
            )
        };
        self.result(status)?;
        Ok(PolygonProperties::from_raw(&out))
    }

    /// The moments of the faces `faces` of a surface about `reference` (the
    /// same point for every range of one surface), for a caller's own
    /// threads: the ranges added up, then
    /// [`completed`](Moments::completed), are the surface's moments. Indices
    /// and coordinates are checked, and polygon faces' planarity unless
    /// `options` skip the topology checks; whether the whole is closed is the
    /// whole's question. Face numbers in messages count from the range's
    /// first face.
    ///
    /// ```
    /// use polymass::{Context, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let surface = Surface::triangles(&positions, &triangles);
    /// let mut context = Context::new()?;
    /// let at = [0.25, 0.25, 0.25];
    /// let options = Options::new();
    /// let sum = (context.moments_of_faces(&surface, 0..1, at, &options)?
    ///     + context.moments_of_faces(&surface, 1..4, at, &options)?)?;
    /// assert!(sum.is_partial());
    /// assert!((sum.completed().volume() - 1.0 / 6.0).abs() < 1e-16);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn moments_of_faces(
        &mut self,
        surface: &Surface<'_>,
        faces: std::ops::Range<usize>,
        reference: [f64; 3],
        options: &Options,
    ) -> Result<Moments> {
        let desc = surface.desc();
        let options = options.to_raw();
        let count = faces.end.saturating_sub(faces.start);
        self.moments_call(|out, context| unsafe {
            // SAFETY: desc points into data borrowed by `surface`; reference
            // has 3 elements; options outlive the call. See moments_call.
            sys::polymass_moments_compute_faces(
                out,
                context,
                &desc,
                faces.start as u64,
                count as u64,
                reference.as_ptr(),
                &options,
            )
        })
    }

    /// See [`Moments::mass_properties`].
    pub fn moments_mass_properties(
        &mut self,
        moments: &Moments,
        body: Option<&Body>,
    ) -> Result<MassProperties> {
        let mass = body.map(|body| body.to_raw());
        let mut out = empty_properties();
        // SAFETY: live context, this thread only; moments, mass and out
        // outlive the call; NULL mass: as the moments are weighted.
        let status = unsafe {
            sys::polymass_moments_mass_properties(
                &mut out,
                self.raw.as_ptr(),
                moments.as_raw(),
                mass.as_ref().map_or(ptr::null(), |mass| mass as *const _),
            )
        };
        self.result(status)?;
        Ok(MassProperties::from_raw(&out))
    }

    /// The mass properties of many surfaces in one call, in order, each with
    /// its own options and body: each item its own result, bit for bit
    /// [`mass_properties`](Context::mass_properties)'s, or its own error,
    /// which does not stop the others. With several threads
    /// ([`set_threads`](Context::set_threads)) the items are spread over
    /// them. The outer `Err` is a failure of the call itself.
    ///
    /// ```
    /// use polymass::{Body, Context, ErrorKind, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let closed = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let open = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2]];
    /// let items = [
    ///     (Surface::triangles(&positions, &closed), Options::new(), Body::density(2.0)),
    ///     (Surface::triangles(&positions, &open), Options::new(), Body::default()),
    /// ];
    /// let results = Context::new()?.batch(&items)?;
    /// assert!((results[0].as_ref().unwrap().mass - 2.0 / 6.0).abs() < 1e-15);
    /// assert_eq!(results[1].as_ref().unwrap_err().kind(), ErrorKind::Open);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn batch(
        &mut self,
        items: &[(Surface<'_>, Options, Body)],
    ) -> Result<Vec<Result<MassProperties>>> {
        let descs: Vec<sys::polymass_mesh_desc> =
            items.iter().map(|(surface, _, _)| surface.desc()).collect();
        let options: Vec<sys::polymass_options> = items
            .iter()
            .map(|(_, options, _)| options.to_raw())
            .collect();
        let masses: Vec<sys::polymass_mass_desc> =
            items.iter().map(|(_, _, body)| body.to_raw()).collect();
        let mut results = vec![empty_properties(); items.len()];
        let mut raw: Vec<sys::polymass_batch_item> = descs
            .iter()
            .zip(&options)
            .zip(&masses)
            .zip(results.iter_mut())
            .map(
                |(((desc, options), mass), result)| sys::polymass_batch_item {
                    struct_size: struct_size::<sys::polymass_batch_item>(),
                    status: 0,
                    desc,
                    options,
                    mass,
                    properties: result,
                    provenance: ptr::null_mut(),
                    message: [0; sys::POLYMASS_BATCH_MESSAGE_SIZE as usize],
                },
            )
            .collect();
        let mut failed = 0u64;
        // SAFETY: live context, this thread only; every item points into
        // descs, options, masses and results (alive and not moved during the
        // call), and the descs into data borrowed by `items`.
        let status = unsafe {
            sys::polymass_batch_compute(
                raw.as_mut_ptr(),
                raw.len() as u64,
                &mut failed,
                self.raw.as_ptr(),
            )
        };
        self.result(status)?;
        Ok(raw
            .iter()
            .zip(&results)
            .map(|(item, result)| {
                if item.status == sys::POLYMASS_OK {
                    return Ok(MassProperties::from_raw(result));
                }
                // SAFETY: the library NUL-terminates the message within the array.
                let message = unsafe { CStr::from_ptr(item.message.as_ptr()) };
                Err(Error::new(
                    item.status,
                    message.to_string_lossy().into_owned(),
                ))
            })
            .collect())
    }

    /// Welds positions alone, for a caller that numbers vertices before
    /// handing a surface over (a triangle soup such as STL repeats a vertex
    /// once per face): see [`Weld`]. `tolerance` is
    /// [`Options::with_weld_tolerance`]'s, relative to the largest extent of
    /// the positions' bounding box: 0 welds exactly equal positions (+0 and
    /// -0 being one, and NaNs of one payload, compared quiet), above 0
    /// chains of near positions are one and non-finite coordinates are an
    /// error. At most `u32::MAX` vertices.
    ///
    /// ```
    /// use polymass::{Context, Positions};
    ///
    /// let soup = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
    ///             [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 1e-12]];
    /// let mut context = Context::new()?;
    /// let exact = context.weld_positions(Positions::packed(&soup), 0.0)?;
    /// assert_eq!((exact.vertex_of, exact.distinct_count), (vec![0, 1, 2, 1, 4, 5], 5));
    /// let near = context.weld_positions(Positions::packed(&soup), 1e-9)?;
    /// assert_eq!((near.vertex_of, near.distinct_count), (vec![0, 1, 2, 1, 4, 2], 4));
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn weld_positions(&mut self, positions: Positions<'_>, tolerance: f64) -> Result<Weld> {
        let (position_type, bytes, stride) = positions.raw_parts();
        let mut vertex_of = vec![0u32; positions.len()];
        let mut distinct_count = 0u64;
        // SAFETY: live context, this thread only; `positions` describes
        // len() vertices within `bytes`, borrowed for the call; vertex_of has
        // room for each.
        let status = unsafe {
            sys::polymass_weld_positions(
                vertex_of.as_mut_ptr(),
                &mut distinct_count,
                self.raw.as_ptr(),
                bytes.as_ptr().cast(),
                position_type,
                positions.len() as u64,
                stride,
                tolerance,
            )
        };
        self.result(status)?;
        Ok(Weld {
            vertex_of,
            distinct_count,
        })
    }

    /// Runs a `polymass_mesh_*` question through this context. `call` must
    /// pass the context it gets, a live mesh and outputs that outlive it.
    pub(crate) fn mesh_call(
        &mut self,
        call: impl FnOnce(*mut sys::polymass_context) -> i32,
    ) -> Result<()> {
        let status = call(self.raw.as_ptr());
        self.result(status)
    }

    /// Runs a `polymass_moments_*` call writing to a fresh output struct
    /// through this context. `call` must pass the pointers it gets and
    /// arguments that outlive it.
    pub(crate) fn moments_call(
        &mut self,
        call: impl FnOnce(*mut sys::polymass_moments, *mut sys::polymass_context) -> i32,
    ) -> Result<Moments> {
        let mut out = Moments::empty();
        let status = call(&mut out, self.raw.as_ptr());
        self.result(status)?;
        Ok(Moments::from_raw(out))
    }

    /// `Ok` for POLYMASS_OK, otherwise the error with this context's message
    /// (copied now: the next call through the context replaces it).
    fn result(&self, status: i32) -> Result<()> {
        if status == sys::POLYMASS_OK {
            return Ok(());
        }
        // SAFETY: live context; the message is never NULL and is valid until
        // the next call through the context, which cannot happen before the
        // copy below (&mut self borrows are not held across this).
        let message = unsafe { CStr::from_ptr(sys::polymass_context_message(self.raw.as_ptr())) };
        Err(Error::new(status, message.to_string_lossy().into_owned()))
    }
}

/// An output struct for mass properties, its struct_size set.
fn empty_properties() -> sys::polymass_mass_properties {
    sys::polymass_mass_properties {
        struct_size: struct_size::<sys::polymass_mass_properties>(),
        ..Default::default()
    }
}

impl Drop for Context {
    fn drop(&mut self) {
        // SAFETY: the context is ours and nothing uses it any more. Meshes
        // made through it do not depend on it.
        unsafe { sys::polymass_context_destroy(self.raw.as_ptr()) }
    }
}

impl fmt::Debug for Context {
    fn fmt(&self, formatter: &mut fmt::Formatter<'_>) -> fmt::Result {
        formatter.debug_struct("Context").finish_non_exhaustive()
    }
}
