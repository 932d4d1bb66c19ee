//! Many triangle meshes packed into shared slices, as datasets keep them
//! (`polymass_packed_compute`): [`PackedMeshes`] in, [`PackedMassProperties`]
//! (columns, a result per mesh) out.

use std::ffi::CStr;
use std::os::raw::c_char;
use std::ptr;

use polymass_sys as sys;

use crate::context::Context;
use crate::error::{Error, Result};
use crate::options::Options;
use crate::properties::Warnings;
use crate::surface::{struct_size, PackedIndex, Positions, Surface};

/// Many triangle meshes in shared slices, borrowed in place: mesh `i` is the
/// vertices `vertex_offsets[i]..vertex_offsets[i + 1]` of `positions` and
/// the triangles `triangle_offsets[i]..triangle_offsets[i + 1]` of
/// `triangles`, its indices counted from its own first vertex or, with
/// [`global_indices`](PackedMeshes::global_indices), from the first vertex
/// of all (PyTorch3D's packed form). Nothing but the triangle offsets (as
/// index offsets, one `u64` a mesh) is copied.
///
/// ```
/// use polymass::{Options, PackedMeshes};
///
/// // Two unit corner tetrahedra, the second one moved along x.
/// let positions = [
///     [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0],
///     [5.0, 0.0, 0.0], [6.0, 0.0, 0.0], [5.0, 1.0, 0.0], [5.0, 0.0, 1.0],
/// ];
/// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]].repeat(2);
/// let meshes = PackedMeshes::new(&positions, &triangles, &[0, 4, 8], &[0, 4, 8])?
///     .densities(&[1.0, 3.0])?;
/// let p = polymass::packed_mass_properties(&meshes, &Options::new())?;
/// assert!(p.errors.iter().all(Option::is_none));
/// assert!((p.mass[1] - 0.5).abs() < 1e-15 && (p.center_of_mass[1][0] - 5.25).abs() < 1e-15);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct PackedMeshes<'a> {
    /// Every mesh's positions and triangles, one mesh after another.
    all: Surface<'a>,
    vertex_offsets: &'a [u64],
    index_offsets: Vec<u64>,
    global_indices: bool,
    mass_mode: u32,
    mass_values: Option<&'a [f64]>,
}

impl<'a> PackedMeshes<'a> {
    /// The meshes of shared positions and triangles: `vertex_offsets` and
    /// `triangle_offsets` hold the mesh count + 1 offsets each, ascending
    /// from 0 to `positions.len()` and `triangles.len()`. Unit density for
    /// every mesh until [`densities`](PackedMeshes::densities) or
    /// [`masses`](PackedMeshes::masses) says otherwise.
    ///
    /// An error of kind `InvalidArgument` when the offsets are not as many
    /// or do not end at the slices' ends (the library checks that they
    /// ascend from 0).
    pub fn new<I: PackedIndex>(
        positions: impl Into<Positions<'a>>,
        triangles: &'a [[I; 3]],
        vertex_offsets: &'a [u64],
        triangle_offsets: &[u64],
    ) -> Result<Self> {
        let positions = positions.into();
        if vertex_offsets.len() != triangle_offsets.len() || vertex_offsets.is_empty() {
            return Err(invalid(format!(
                "{} vertex offsets and {} triangle offsets: the mesh count + 1 each",
                vertex_offsets.len(),
                triangle_offsets.len()
            )));
        }
        for (offsets, name, total) in [
            (vertex_offsets, "vertex", positions.len()),
            (triangle_offsets, "triangle", triangles.len()),
        ] {
            let last = offsets[offsets.len() - 1];
            if last != total as u64 {
                return Err(invalid(format!(
                    "the {name} offsets end at {last} but there are {total} {name}s: the last \
                     offset is the end of the last mesh"
                )));
            }
        }
        Ok(PackedMeshes {
            all: Surface::packed_triangles(positions, triangles),
            vertex_offsets,
            // Saturating: an offset past the slice is refused by the library.
            index_offsets: triangle_offsets
                .iter()
                .map(|&t| t.saturating_mul(3))
                .collect(),
            global_indices: false,
            mass_mode: sys::POLYMASS_MASS_FROM_DENSITY,
            mass_values: None,
        })
    }

    /// The indices count from the first vertex of all (PyTorch3D's
    /// `faces_packed`), each mesh's still within its own vertices.
    pub fn global_indices(mut self) -> Self {
        self.global_indices = true;
        self
    }

    /// The density of each mesh (M/L³), one per mesh.
    pub fn densities(self, densities: &'a [f64]) -> Result<Self> {
        self.weighted(sys::POLYMASS_MASS_FROM_DENSITY, densities, "densities")
    }

    /// The mass of each mesh (M), one per mesh.
    pub fn masses(self, masses: &'a [f64]) -> Result<Self> {
        self.weighted(sys::POLYMASS_MASS_FROM_TOTAL, masses, "masses")
    }

    /// The number of meshes.
    pub fn len(&self) -> usize {
        self.vertex_offsets.len() - 1
    }

    /// Whether there is no mesh.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn weighted(mut self, mode: u32, values: &'a [f64], name: &str) -> Result<Self> {
        if values.len() != self.len() {
            return Err(invalid(format!(
                "{} {name} for {} meshes: one per mesh",
                values.len(),
                self.len()
            )));
        }
        self.mass_mode = mode;
        self.mass_values = Some(values);
        Ok(self)
    }

    /// The C description, valid while `self` lives.
    fn to_raw(&self) -> sys::polymass_packed_meshes {
        let all = self.all.desc();
        sys::polymass_packed_meshes {
            struct_size: struct_size::<sys::polymass_packed_meshes>(),
            position_type: all.position_type,
            positions: all.positions,
            position_stride: all.position_stride,
            index_type: all.index_type,
            index_base: if self.global_indices {
                sys::POLYMASS_INDICES_GLOBAL
            } else {
                sys::POLYMASS_INDICES_LOCAL
            },
            indices: all.indices,
            mesh_count: self.len() as u64,
            vertex_offsets: self.vertex_offsets.as_ptr(),
            index_offsets: self.index_offsets.as_ptr(),
            mass_mode: self.mass_mode,
            reserved: 0,
            mass_values: self.mass_values.map_or(ptr::null(), <[f64]>::as_ptr),
        }
    }
}

/// The mass properties of packed meshes in columns: entry `i` of each is
/// mesh `i`'s, bit for bit what
/// [`mass_properties`](crate::mass_properties) gives for it alone. A failed
/// mesh has its error in `errors` and NaN numbers. Matrices are
/// `[row][column]`, as in [`MassProperties`](crate::MassProperties).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct PackedMassProperties {
    /// `None` where the mesh was answered, else why not.
    pub errors: Vec<Option<Error>>,
    /// What was accepted on the way (empty for a failed mesh).
    pub warnings: Vec<Warnings>,
    /// Enclosed volume (L³).
    pub volume: Vec<f64>,
    /// Mass (M).
    pub mass: Vec<f64>,
    /// Total area of the faces (L²).
    pub surface_area: Vec<f64>,
    /// Centre of mass (L).
    pub center_of_mass: Vec<[f64; 3]>,
    /// Inertia tensor about the centre of mass (M·L²).
    pub inertia: Vec<[[f64; 3]; 3]>,
    /// Eigenvalues of the inertia, ascending.
    pub principal_moments: Vec<[f64; 3]>,
    /// The rotations whose columns are the principal axes.
    pub principal_axes: Vec<[[f64; 3]; 3]>,
    /// Bound on the rounding error of the volume (L³).
    pub error_bound_volume: Vec<f64>,
    /// Of each coordinate of the centre of mass (L).
    pub error_bound_center_of_mass: Vec<f64>,
    /// Of each entry of the inertia (M·L²).
    pub error_bound_inertia: Vec<f64>,
}

impl PackedMassProperties {
    /// How many meshes failed.
    pub fn failed(&self) -> usize {
        self.errors.iter().filter(|error| error.is_some()).count()
    }
}

impl Context {
    /// The mass properties of every mesh of a packed set in one call, with
    /// the same options for all: see [`PackedMeshes`] and
    /// [`PackedMassProperties`]. With several threads
    /// ([`set_threads`](Context::set_threads)) the meshes are spread over
    /// them, each mesh's result the same. The outer `Err` is a failure of
    /// the call itself (offsets that do not ascend, a count of indices not a
    /// whole number of triangles).
    pub fn packed_mass_properties(
        &mut self,
        meshes: &PackedMeshes<'_>,
        options: &Options,
    ) -> Result<PackedMassProperties> {
        let count = meshes.len();
        let mut status = vec![0i32; count];
        let mut warnings = vec![0u32; count];
        let mut messages: Vec<c_char> = vec![0; count * sys::POLYMASS_BATCH_MESSAGE_SIZE as usize];
        let mut rows = PackedMassProperties {
            errors: Vec::new(),
            warnings: Vec::new(),
            volume: vec![0.0; count],
            mass: vec![0.0; count],
            surface_area: vec![0.0; count],
            center_of_mass: vec![[0.0; 3]; count],
            inertia: vec![[[0.0; 3]; 3]; count],
            principal_moments: vec![[0.0; 3]; count],
            principal_axes: vec![[[0.0; 3]; 3]; count],
            error_bound_volume: vec![0.0; count],
            error_bound_center_of_mass: vec![0.0; count],
            error_bound_inertia: vec![0.0; count],
        };
        // Arrays of [f64; 3] and [[f64; 3]; 3] are the 3 and 9 doubles a
        // mesh the library writes, contiguous.
        let results = sys::polymass_packed_results {
            struct_size: struct_size::<sys::polymass_packed_results>(),
            reserved: 0,
            status: status.as_mut_ptr(),
            warnings: warnings.as_mut_ptr(),
            volume: rows.volume.as_mut_ptr(),
            mass: rows.mass.as_mut_ptr(),
            surface_area: rows.surface_area.as_mut_ptr(),
            center_of_mass: rows.center_of_mass.as_mut_ptr().cast(),
            inertia: rows.inertia.as_mut_ptr().cast(),
            principal_moments: rows.principal_moments.as_mut_ptr().cast(),
            principal_axes: rows.principal_axes.as_mut_ptr().cast(),
            error_bound_volume: rows.error_bound_volume.as_mut_ptr(),
            error_bound_center_of_mass: rows.error_bound_center_of_mass.as_mut_ptr(),
            error_bound_inertia: rows.error_bound_inertia.as_mut_ptr(),
            messages: messages.as_mut_ptr(),
        };
        let raw_meshes = meshes.to_raw();
        let raw_options = options.to_raw();
        let mut failed = 0u64;
        self.mesh_call(|context| {
            // SAFETY: live context, this thread only; the meshes' pointers
            // borrow the caller's slices (the library checks the offsets
            // against the counts they end at, which `PackedMeshes::new`
            // checked against the slices) and `meshes`' own offsets; every
            // column has room for `count` rows and outlives the call.
            unsafe {
                sys::polymass_packed_compute(
                    &results,
                    &mut failed,
                    context,
                    &raw_meshes,
                    &raw_options,
                )
            }
        })?;
        let message_size = sys::POLYMASS_BATCH_MESSAGE_SIZE as usize;
        rows.errors = status
            .iter()
            .zip(messages.chunks(message_size))
            .map(|(&code, message)| {
                (code != sys::POLYMASS_OK).then(|| {
                    // SAFETY: the library NUL-terminates each message within its row.
                    let text = unsafe { CStr::from_ptr(message.as_ptr()) };
                    Error::new(code, text.to_string_lossy().into_owned())
                })
            })
            .collect();
        rows.warnings = warnings.into_iter().map(Warnings::from_bits).collect();
        Ok(rows)
    }
}

/// The mass properties of every mesh of a packed set; see
/// [`Context::packed_mass_properties`] (here on a context of one thread, made
/// for the call).
pub fn packed_mass_properties(
    meshes: &PackedMeshes<'_>,
    options: &Options,
) -> Result<PackedMassProperties> {
    Context::new()?.packed_mass_properties(meshes, options)
}

fn invalid(message: String) -> Error {
    Error::new(sys::POLYMASS_ERROR_INVALID_ARGUMENT, message)
}
