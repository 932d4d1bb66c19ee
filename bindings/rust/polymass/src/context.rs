//! The library's per-thread working state (`polymass_context`).

use std::ffi::CStr;
use std::fmt;
use std::mem::MaybeUninit;
use std::ptr::{self, NonNull};

use polymass_sys as sys;

use crate::body::Body;
use crate::diagnostics::Diagnostics;
use crate::error::{Error, Result};
use crate::mesh::Mesh;
use crate::moments::Moments;
use crate::options::Options;
use crate::polygon::PolygonProperties;
use crate::properties::MassProperties;
use crate::provenance::Provenance;
use crate::shell::Shell;
use crate::surface::{struct_size, Surface};

/// A context: the [`Options`] calls use and the message of the last failure.
///
/// It is `Send` but not `Sync`: one thread at a time may use it, which every
/// method taking `&mut self` enforces; threads computing at once each take
/// their own. The free functions ([`mass_properties`](crate::mass_properties)
/// and friends) and [`Mesh`]'s methods make a context per call; keep one to
/// set options, or to save its allocation in a loop.
///
/// ```
/// use polymass::{Body, Context, Options, Surface, Warnings};
///
/// // An inverted tetrahedron (every face reversed), accepted and turned.
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let reversed = [[0u32, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
/// let mut context = Context::with_options(&Options::new().accept_inverted(true))?;
/// let p = context.mass_properties(&Surface::triangles(&positions, &reversed), &Body::default())?;
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
    /// A context with the default options (every check on).
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

    /// A context with the given options.
    ///
    /// ```
    /// use polymass::{Context, Options};
    ///
    /// let mut context = Context::with_options(&Options::new().weld_vertices(true))?;
    /// assert!(context.options()?.welds_vertices());
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn with_options(options: &Options) -> Result<Context> {
        let mut context = Context::new()?;
        context.set_options(options)?;
        Ok(context)
    }

    /// Sets the options later calls use; fails with
    /// [`ErrorKind::InvalidArgument`](crate::ErrorKind::InvalidArgument) for
    /// a tolerance out of range, leaving the options as they were.
    ///
    /// ```
    /// use polymass::{Context, ErrorKind, Options};
    ///
    /// let mut context = Context::new()?;
    /// let too_coarse = Options::new().weld_vertices(true).weld_tolerance(0.5);
    /// assert_eq!(context.set_options(&too_coarse).unwrap_err().kind(), ErrorKind::InvalidArgument);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn set_options(&mut self, options: &Options) -> Result<()> {
        let raw = options.to_raw();
        // SAFETY: live context, used by this thread only (&mut self); the
        // options struct outlives the call.
        let status = unsafe { sys::polymass_context_set_options(self.raw.as_ptr(), &raw) };
        self.result(status)
    }

    /// The options in use, as the library holds them.
    ///
    /// ```
    /// let mut context = polymass::Context::new()?;
    /// assert!(!context.options()?.accepts_inverted());
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn options(&mut self) -> Result<Options> {
        let mut raw = sys::polymass_options {
            struct_size: struct_size::<sys::polymass_options>(),
            ..Default::default()
        };
        // SAFETY: live context, this thread only; out-pointer to a local.
        let status = unsafe { sys::polymass_context_get_options(&mut raw, self.raw.as_ptr()) };
        self.result(status)?;
        Ok(Options::from_raw(&raw))
    }

    /// Validates and integrates a surface once, for mass properties of any
    /// number of bodies afterwards. The mesh keeps only the integrals: the
    /// surface's slices may go once this returns.
    ///
    /// ```
    /// use polymass::{Body, Context, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mut context = Context::new()?;
    /// let mesh = context.mesh(&Surface::triangles(&positions, &triangles))?;
    /// let light = context.mesh_mass_properties(&mesh, &Body::mass(1.0))?;
    /// let heavy = context.mesh_mass_properties(&mesh, &Body::mass(2.0))?;
    /// assert_eq!(2.0 * light.inertia[0][0], heavy.inertia[0][0]);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn mesh(&mut self, surface: &Surface<'_>) -> Result<Mesh> {
        let desc = surface.desc();
        let mut raw = ptr::null_mut();
        // SAFETY: live context, this thread only; desc points into slices
        // borrowed by `surface` for the whole call.
        let status = unsafe { sys::polymass_mesh_create(&mut raw, self.raw.as_ptr(), &desc) };
        self.result(status)?;
        let raw = NonNull::new(raw).expect("polymass_mesh_create succeeded with NULL");
        // SAFETY: a mesh polymass_mesh_create just made, owned by no one else.
        Ok(unsafe { Mesh::from_raw(raw) })
    }

    /// The mass properties of a mesh made before, as `body`.
    ///
    /// ```
    /// use polymass::{Body, Context, Mesh, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles))?;
    /// let mut context = Context::new()?;
    /// for density in [1000.0, 2700.0, 7850.0] {
    ///     let p = context.mesh_mass_properties(&mesh, &Body::density(density))?;
    ///     assert!((p.mass - density / 6.0).abs() < 1e-12 * p.mass);
    /// }
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn mesh_mass_properties(&mut self, mesh: &Mesh, body: &Body) -> Result<MassProperties> {
        let mass = body.to_raw();
        let mut out = MaybeUninit::<sys::polymass_mass_properties>::zeroed();
        // SAFETY: the zeroed struct is a valid polymass_mass_properties (all
        // numbers); struct_size is set before the call reads it.
        unsafe { (*out.as_mut_ptr()).struct_size = struct_size::<sys::polymass_mass_properties>() };
        // SAFETY: live context, this thread only; the mesh is alive and may be
        // read by several threads at once; out and mass outlive the call.
        let status = unsafe {
            sys::polymass_mesh_mass_properties(
                out.as_mut_ptr(),
                self.raw.as_ptr(),
                mesh.as_raw(),
                &mass,
            )
        };
        self.result(status)?;
        // SAFETY: zero-initialised, and filled on success.
        Ok(MassProperties::from_raw(unsafe { out.assume_init_ref() }))
    }

    /// Validates and integrates a surface and returns its mass properties as
    /// `body`, keeping no mesh.
    ///
    /// ```
    /// use polymass::{Body, Context, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mut context = Context::new()?;
    /// let p = context.mass_properties(&Surface::triangles(&positions, &triangles), &Body::default())?;
    /// assert!((p.surface_area - (1.5 + 3f64.sqrt() / 2.0)).abs() < 1e-15);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn mass_properties(
        &mut self,
        surface: &Surface<'_>,
        body: &Body,
    ) -> Result<MassProperties> {
        let desc = surface.desc();
        let mass = body.to_raw();
        let mut out = MaybeUninit::<sys::polymass_mass_properties>::zeroed();
        // SAFETY: as in mesh_mass_properties.
        unsafe { (*out.as_mut_ptr()).struct_size = struct_size::<sys::polymass_mass_properties>() };
        // SAFETY: live context, this thread only; desc points into slices
        // borrowed by `surface`; out, desc and mass outlive the call.
        let status = unsafe {
            sys::polymass_mass_properties_compute(out.as_mut_ptr(), self.raw.as_ptr(), &desc, &mass)
        };
        self.result(status)?;
        // SAFETY: zero-initialised, and filled on success.
        Ok(MassProperties::from_raw(unsafe { out.assume_init_ref() }))
    }

    /// [`mass_properties`](Context::mass_properties) by the options' chain of
    /// modes ([`Options::repair`](crate::Options::repair),
    /// [`Options::fallback`](crate::Options::fallback), ...), and which mode
    /// answered, with what it did.
    ///
    /// ```
    /// use polymass::{Body, Context, Mode, Options, Surface};
    ///
    /// // A fin on an edge of a tetrahedron: no repair is the right one; the hull answers.
    /// let positions = [
    ///     [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [2.0, 2.0, -1.0],
    /// ];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 2, 4]];
    /// let options = Options::new().fallback(&[Mode::Repair, Mode::Hull]);
    /// let mut context = Context::with_options(&options)?;
    /// let surface = Surface::triangles(&positions, &triangles);
    /// let (p, provenance) = context.mass_properties_with_provenance(&surface, &Body::default())?;
    /// assert_eq!(provenance.mode, Mode::Hull);
    /// assert_eq!(provenance.hull_vertex_count, 5);
    /// assert!(p.warnings.contains(polymass::Warnings::HULL));
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn mass_properties_with_provenance(
        &mut self,
        surface: &Surface<'_>,
        body: &Body,
    ) -> Result<(MassProperties, Provenance)> {
        let desc = surface.desc();
        let mass = body.to_raw();
        let mut out = MaybeUninit::<sys::polymass_mass_properties>::zeroed();
        let mut provenance = MaybeUninit::<sys::polymass_provenance>::zeroed();
        // SAFETY: as in mesh_mass_properties (both outputs zeroed, sized).
        unsafe {
            (*out.as_mut_ptr()).struct_size = struct_size::<sys::polymass_mass_properties>();
            (*provenance.as_mut_ptr()).struct_size = struct_size::<sys::polymass_provenance>();
        }
        // SAFETY: live context, this thread only; desc points into slices
        // borrowed by `surface`; the outputs, desc and mass outlive the call.
        let status = unsafe {
            sys::polymass_mass_properties_with_provenance(
                out.as_mut_ptr(),
                provenance.as_mut_ptr(),
                self.raw.as_ptr(),
                &desc,
                &mass,
                std::ptr::null(),
            )
        };
        self.result(status)?;
        // SAFETY: zero-initialised, and filled on success.
        Ok(unsafe {
            (
                MassProperties::from_raw(out.assume_init_ref()),
                Provenance::from_raw(provenance.assume_init_ref()),
            )
        })
    }

    /// Runs every check on a surface without stopping at the first finding
    /// (the topology checks even when the options skip them; welding and the
    /// tolerances apply). A bad surface is not an `Err`: its failure is in
    /// [`Diagnostics::error`]. `Err` means no report could be made.
    ///
    /// Crossing faces, shells nested twice and touching faces are found too,
    /// unless [`Options::skip_intersection_check`].
    ///
    /// ```
    /// use polymass::{Context, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let report = Context::new()?.check(&Surface::triangles(&positions, &triangles))?;
    /// assert_eq!((report.face_count, report.edge_count, report.used_vertex_count), (4, 6, 4));
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn check(&mut self, surface: &Surface<'_>) -> Result<Diagnostics> {
        let desc = surface.desc();
        let mut report = MaybeUninit::<sys::polymass_diagnostics>::zeroed();
        // The library writes the report whenever it can read the report's
        // struct_size; a status left at a value no call returns tells that it
        // could not (a library older than these bindings).
        let unwritten = i32::MIN;
        // SAFETY: the zeroed struct is a valid polymass_diagnostics (all
        // numbers); these fields are set before the call reads them.
        unsafe {
            (*report.as_mut_ptr()).struct_size = struct_size::<sys::polymass_diagnostics>();
            (*report.as_mut_ptr()).status = unwritten;
        }
        // SAFETY: live context, this thread only; desc points into slices
        // borrowed by `surface`; report and desc outlive the call.
        let status =
            unsafe { sys::polymass_mesh_check(report.as_mut_ptr(), self.raw.as_ptr(), &desc) };
        // SAFETY: zero-initialised, possibly filled.
        let report = unsafe { report.assume_init_ref() };
        if report.status != status {
            self.result(status)?;
            return Err(Error::new(
                sys::POLYMASS_ERROR_INTERNAL,
                format!(
                    "polymass_mesh_check returned {status} but reported {}",
                    report.status
                ),
            ));
        }
        // Failures of the call itself (a bad argument, out of memory) leave no
        // report worth reading, whatever was written: they are the Err.
        if matches!(
            status,
            sys::POLYMASS_ERROR_INVALID_ARGUMENT
                | sys::POLYMASS_ERROR_OUT_OF_MEMORY
                | sys::POLYMASS_ERROR_INTERNAL
        ) {
            self.result(status)?;
        }
        Ok(Diagnostics::from_raw(report, self.result(status).err()))
    }

    /// The shell (connected piece of surface) of each face, numbered from 0 in
    /// the order of the shells' first faces. Faces sharing a vertex are in one
    /// shell, after welding when the options weld (so a triangle soup splits
    /// as its solid does). Indices out of range and non-finite coordinates are
    /// errors; the topology is not checked.
    ///
    /// ```
    /// use polymass::{Context, Options, Surface};
    ///
    /// // Two triangles apart, and a soup of two triangles sharing an edge.
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
    ///                  [5.0, 0.0, 0.0], [6.0, 0.0, 0.0], [5.0, 1.0, 0.0]];
    /// let apart = [[0u32, 1, 2], [3, 4, 5]];
    /// let mut context = Context::new()?;
    /// assert_eq!(context.shells(&Surface::triangles(&positions, &apart))?, vec![0, 1]);
    /// let soup = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
    ///             [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    /// let triangles = [[0u32, 1, 2], [3, 4, 5]];
    /// context.set_options(&Options::new().weld_vertices(true))?;
    /// assert_eq!(context.shells(&Surface::triangles(&soup, &triangles))?, vec![0, 0]);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn shells(&mut self, surface: &Surface<'_>) -> Result<Vec<u32>> {
        let desc = surface.desc();
        let mut of_face = vec![0u32; surface.face_count()];
        let mut count = 0u64;
        // SAFETY: live context, this thread only; desc points into slices
        // borrowed by `surface`; of_face has room for every face of it.
        let status = unsafe {
            sys::polymass_mesh_shells(of_face.as_mut_ptr(), &mut count, self.raw.as_ptr(), &desc)
        };
        self.result(status)?;
        Ok(of_face)
    }

    /// What each shell of a closed surface is: shell `i` of the list is the
    /// one [`shells`](Context::shells) numbers `i`. The surface must pass the
    /// checks that come before the shells (closed, manifold, oriented,
    /// planar, with a volume), otherwise their error; the shells are
    /// described whether or not they pass themselves, so an inside-out or
    /// overlapping shell is listed, not an `Err`. The nesting of the shells
    /// is counted exactly; with [`Options::skip_intersection_check`] it is
    /// judged by bounding boxes, which can show a shell to be inside out but
    /// take any negative shell within a solid's box for a cavity. Fails with
    /// [`ErrorKind::InvalidArgument`](crate::ErrorKind::InvalidArgument) when
    /// the options skip the topology checks.
    ///
    /// ```
    /// use polymass::{Context, Options, ShellKind, Surface};
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
    /// let mut context = Context::with_options(&Options::new())?;
    /// let shells = context.shell_list(&Surface::triangles(&positions, &triangles))?;
    /// let kinds: Vec<ShellKind> = shells.iter().map(|shell| shell.kind).collect();
    /// assert_eq!(kinds, [ShellKind::Solid, ShellKind::Cavity]);
    /// assert!((shells[1].signed_volume + 1.0 / 6.0).abs() < 1e-15);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn shell_list(&mut self, surface: &Surface<'_>) -> Result<Vec<Shell>> {
        // Room for this many in the first call: most surfaces need no second.
        const FIRST_GUESS: usize = 16;
        let desc = surface.desc();
        let blank = sys::polymass_shell {
            struct_size: struct_size::<sys::polymass_shell>(),
            ..Default::default()
        };
        let mut described = vec![blank; FIRST_GUESS];
        loop {
            let mut count = 0u64;
            // SAFETY: live context, this thread only; desc points into slices
            // borrowed by `surface`; `described` holds as many shells, each
            // with struct_size set, as the capacity passed.
            let status = unsafe {
                sys::polymass_mesh_shell_list(
                    described.as_mut_ptr(),
                    described.len() as u64,
                    &mut count,
                    self.raw.as_ptr(),
                    &desc,
                )
            };
            self.result(status)?;
            let count = usize::try_from(count).expect("shells fit in memory as faces do");
            if count <= described.len() {
                return Ok(described[..count].iter().map(Shell::from_raw).collect());
            }
            described.resize(count, blank);
        }
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
        let mut out = MaybeUninit::<sys::polymass_polygon_properties>::zeroed();
        // SAFETY: the zeroed struct is a valid polymass_polygon_properties
        // (all numbers); struct_size is set before the call reads it.
        unsafe {
            (*out.as_mut_ptr()).struct_size = struct_size::<sys::polymass_polygon_properties>()
        };
        // SAFETY: live context, this thread only; points.len() packed (x, y)
        // pairs (stride 0) that outlive the call.
        let status = unsafe {
            sys::polymass_polygon_compute(
                out.as_mut_ptr(),
                self.raw.as_ptr(),
                points.as_flattened().as_ptr(),
                points.len() as u64,
                0,
            )
        };
        self.result(status)?;
        // SAFETY: zero-initialised, and filled on success.
        Ok(PolygonProperties::from_raw(unsafe {
            out.assume_init_ref()
        }))
    }

    /// The moments (unit density) of a closed surface, checked with this
    /// context's options.
    ///
    /// ```
    /// use polymass::{Context, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let moments = Context::new()?.moments(&Surface::triangles(&positions, &triangles))?;
    /// assert!((moments.volume() - 1.0 / 6.0).abs() < 1e-16);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn moments(&mut self, surface: &Surface<'_>) -> Result<Moments> {
        let desc = surface.desc();
        self.moments_call(|out, context| unsafe {
            // SAFETY: desc points into slices borrowed by `surface`; NULL
            // options: the context's. See moments_call.
            sys::polymass_moments_compute(out, context, &desc, ptr::null())
        })
    }

    /// The moments of the faces `faces` of a surface about `reference` (the
    /// same point for every range of one surface), for a caller's own
    /// threads: the ranges added up, then
    /// [`completed`](Moments::completed), are the surface's moments.
    ///
    /// ```
    /// use polymass::{Context, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let surface = Surface::triangles(&positions, &triangles);
    /// let mut context = Context::new()?;
    /// let at = [0.25, 0.25, 0.25];
    /// let sum = (context.moments_of_faces(&surface, 0..1, at)?
    ///     + context.moments_of_faces(&surface, 1..4, at)?)?;
    /// assert!(sum.is_partial());
    /// assert!((sum.completed().volume() - 1.0 / 6.0).abs() < 1e-16);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn moments_of_faces(
        &mut self,
        surface: &Surface<'_>,
        faces: std::ops::Range<usize>,
        reference: [f64; 3],
    ) -> Result<Moments> {
        let desc = surface.desc();
        let count = faces.end.saturating_sub(faces.start);
        self.moments_call(|out, context| unsafe {
            // SAFETY: desc points into slices borrowed by `surface`;
            // reference has 3 elements. See moments_call.
            sys::polymass_moments_compute_faces(
                out,
                context,
                &desc,
                faces.start as u64,
                count as u64,
                reference.as_ptr(),
                ptr::null(),
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
        let mut out = MaybeUninit::<sys::polymass_mass_properties>::zeroed();
        // SAFETY: as in mesh_mass_properties.
        unsafe { (*out.as_mut_ptr()).struct_size = struct_size::<sys::polymass_mass_properties>() };
        // SAFETY: live context, this thread only; moments, mass and out
        // outlive the call; NULL mass: as the moments are weighted.
        let status = unsafe {
            sys::polymass_moments_mass_properties(
                out.as_mut_ptr(),
                self.raw.as_ptr(),
                moments.as_raw(),
                mass.as_ref().map_or(ptr::null(), |mass| mass as *const _),
            )
        };
        self.result(status)?;
        // SAFETY: zero-initialised, and filled on success.
        Ok(MassProperties::from_raw(unsafe { out.assume_init_ref() }))
    }

    /// The mass properties of many surfaces in one call, in order: each item
    /// its own result, bit for bit [`mass_properties`](Context::mass_properties)'s,
    /// or its own error, which does not stop the others. The outer `Err` is a
    /// failure of the call itself.
    ///
    /// ```
    /// use polymass::{Body, Context, ErrorKind, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let closed = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let open = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2]];
    /// let items = [
    ///     (Surface::triangles(&positions, &closed), Body::density(2.0)),
    ///     (Surface::triangles(&positions, &open), Body::default()),
    /// ];
    /// let results = Context::new()?.batch(&items)?;
    /// assert!((results[0].as_ref().unwrap().mass - 2.0 / 6.0).abs() < 1e-15);
    /// assert_eq!(results[1].as_ref().unwrap_err().kind(), ErrorKind::Open);
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn batch(&mut self, items: &[(Surface<'_>, Body)]) -> Result<Vec<Result<MassProperties>>> {
        let descs: Vec<sys::polymass_mesh_desc> =
            items.iter().map(|(surface, _)| surface.desc()).collect();
        let masses: Vec<sys::polymass_mass_desc> =
            items.iter().map(|(_, body)| body.to_raw()).collect();
        let mut results = vec![
            sys::polymass_mass_properties {
                struct_size: struct_size::<sys::polymass_mass_properties>(),
                ..Default::default()
            };
            items.len()
        ];
        let mut raw: Vec<sys::polymass_batch_item> = descs
            .iter()
            .zip(&masses)
            .zip(results.iter_mut())
            .map(|((desc, mass), result)| sys::polymass_batch_item {
                struct_size: struct_size::<sys::polymass_batch_item>(),
                status: 0,
                desc,
                mass,
                options: ptr::null(),
                properties: result,
                message: [0; sys::POLYMASS_BATCH_MESSAGE_SIZE as usize],
            })
            .collect();
        let mut failed = 0u64;
        // SAFETY: live context, this thread only; every item points into
        // descs, masses and results (alive and not moved during the call),
        // and the descs into slices borrowed by `items`.
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
