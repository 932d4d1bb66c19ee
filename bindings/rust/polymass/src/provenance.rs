//! How an answer was reached (`polymass_provenance`).

use polymass_sys as sys;

use crate::diagnostics::Occurrences;
use crate::options::Mode;

/// Which mode of the options' chain answered and what it did: from
/// [`Mesh::provenance`](crate::Mesh::provenance).
/// Faces are the caller's face numbers, vertices its indices (after welding:
/// the lowest index at that position).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Provenance {
    /// The mode that answered ([`Mode::Solid`] for a valid solid in any chain
    /// that starts with the solid or repair).
    pub mode: Mode,
    /// Faces turned to agree with the rest of their shell.
    pub reoriented_faces: Occurrences<u64>,
    /// Shells turned inside out, each located by its first face.
    pub turned_shells: Occurrences<u64>,
    /// Faces dropped as copies of another (or of its reverse).
    pub duplicate_faces: Occurrences<u64>,
    /// Faces of fewer than three distinct vertices, dropped.
    pub degenerate_faces: Occurrences<u64>,
    /// Non-planar polygon faces triangulated.
    pub triangulated_faces: Occurrences<u64>,
    /// Non-manifold edges split into manifold pairs.
    pub split_edges: Occurrences<[u64; 2]>,
    /// Holes capped, each located by its lowest vertex.
    pub holes: Occurrences<u64>,
    /// Triangles of the caps.
    pub cap_triangles: u64,
    /// The caps' area.
    pub cap_area: f64,
    /// The caps' area over the repaired surface's.
    pub cap_area_fraction: f64,
    /// The approximation's share of the error bound's volume, centre of mass
    /// and inertia (0 for an exact answer).
    pub approximation_bound: [f64; 3],
    /// [`Mode::Shell`]: the wall's thickness and the surface's area.
    pub shell_thickness: f64,
    /// See `shell_thickness`.
    pub shell_area: f64,
    /// [`Mode::Hull`]: the hull's vertices, triangles and volume.
    pub hull_vertex_count: u64,
    /// See `hull_vertex_count`.
    pub hull_triangle_count: u64,
    /// See `hull_vertex_count`.
    pub hull_volume: f64,
}

impl Provenance {
    pub(crate) fn from_raw(raw: &sys::polymass_provenance) -> Provenance {
        Provenance {
            mode: Mode::from_raw(raw.mode as u32).unwrap_or(Mode::Solid),
            reoriented_faces: Occurrences::<u64>::new(
                raw.reoriented_faces,
                &raw.first_reoriented_faces,
            ),
            turned_shells: Occurrences::<u64>::new(raw.turned_shells, &raw.first_turned_shells),
            duplicate_faces: Occurrences::<u64>::new(
                raw.duplicate_faces,
                &raw.first_duplicate_faces,
            ),
            degenerate_faces: Occurrences::<u64>::new(
                raw.degenerate_faces,
                &raw.first_degenerate_faces,
            ),
            triangulated_faces: Occurrences::<u64>::new(
                raw.triangulated_faces,
                &raw.first_triangulated_faces,
            ),
            split_edges: Occurrences::<[u64; 2]>::new(raw.split_edges, &raw.first_split_edges),
            holes: Occurrences::<u64>::new(raw.holes, &raw.first_holes),
            cap_triangles: raw.cap_triangles,
            cap_area: raw.cap_area,
            cap_area_fraction: raw.cap_area_fraction,
            approximation_bound: [
                raw.approximation_bound_volume,
                raw.approximation_bound_center_of_mass,
                raw.approximation_bound_inertia,
            ],
            shell_thickness: raw.shell_thickness,
            shell_area: raw.shell_area,
            hull_vertex_count: raw.hull_vertex_count,
            hull_triangle_count: raw.hull_triangle_count,
            hull_volume: raw.hull_volume,
        }
    }
}
