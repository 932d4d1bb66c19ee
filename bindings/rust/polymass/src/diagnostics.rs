//! What a full check of a surface finds (`polymass_diagnostics`).

use polymass_sys as sys;

use crate::error::Error;

/// How often a problem occurs and where: the first few locations.
///
/// ```
/// let clean = polymass::Occurrences::<u64>::default();
/// assert_eq!(clean.count, 0);
/// assert!(clean.first.is_empty());
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Occurrences<L> {
    /// How many there are.
    pub count: u64,
    /// The first (lowest) of them, ascending: faces, vertices, shells, edges
    /// or face pairs as the caller's indices, at most
    /// [`LOCATIONS`](crate::LOCATIONS); empty when there is none.
    pub first: Vec<L>,
}

impl Occurrences<u64> {
    pub(crate) fn new(count: u64, first: &[u64]) -> Self {
        let first = first
            .iter()
            .copied()
            .take_while(|&v| v != sys::POLYMASS_NONE);
        Occurrences {
            count,
            first: first.collect(),
        }
    }
}

impl Occurrences<[u64; 2]> {
    pub(crate) fn new(count: u64, first: &[[u64; 2]]) -> Self {
        let first = first
            .iter()
            .copied()
            .take_while(|e| e[0] != sys::POLYMASS_NONE);
        Occurrences {
            count,
            first: first.collect(),
        }
    }
}

/// The report of [`check`](crate::check): every check run to the end, with
/// counts and first few locations. Vertex numbers are the caller's indices
/// (after welding: the lowest index at that position); edges are vertex pairs,
/// face pairs `[lower, higher]`; shells are numbered as
/// [`Context::shells`](crate::Context::shells) numbers them.
///
/// ```
/// use polymass::{ErrorKind, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let open = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2]];
/// let report = polymass::check(&Surface::triangles(&positions, &open))?;
/// assert_eq!(report.error.as_ref().map(|e| e.kind()), Some(ErrorKind::Open));
/// assert_eq!(report.open_edges.count, 3);
/// assert_eq!(report.open_edges.first.len(), 3); // the rim of the missing face
/// assert!(report.misoriented_edges.first.is_empty());
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Diagnostics {
    /// What creating a mesh would fail with (topology checks on), with the
    /// same message; `None` for a valid solid.
    pub error: Option<Error>,
    /// Number of faces.
    pub face_count: u64,
    /// Distinct vertices the faces use.
    pub used_vertex_count: u64,
    /// Distinct undirected edges.
    pub edge_count: u64,
    /// Vertices with a NaN or infinite coordinate.
    pub non_finite_vertices: Occurrences<u64>,
    /// Indices past the vertex slice; `first` is the face.
    pub out_of_range_indices: Occurrences<u64>,
    /// Faces of fewer than 3 vertices.
    pub small_faces: Occurrences<u64>,
    /// Faces of zero area: legal and harmless.
    pub degenerate_faces: Occurrences<u64>,
    /// Edges used by one face only.
    pub open_edges: Occurrences<[u64; 2]>,
    /// Edges used by more than two faces.
    pub non_manifold_edges: Occurrences<[u64; 2]>,
    /// Edges traversed twice the same way.
    pub misoriented_edges: Occurrences<[u64; 2]>,
    /// Polygon faces off their plane by more than the tolerance.
    pub non_planar_faces: Occurrences<u64>,
    /// Largest relative off-plane distance seen.
    pub max_non_planarity: f64,
    /// Signed enclosed volume (negative for an inverted solid); `None` when
    /// the faces could not be integrated.
    pub signed_volume: Option<f64>,
    /// Shells (connected pieces) of the surface, counted once it is closed
    /// and oriented; 0 before.
    pub shell_count: u64,
    /// Shells inside out (negative volume) that lie inside no solid shell.
    pub inverted_shells: Occurrences<u64>,
    /// Shells inside a solid of the same sense, whose volume would count
    /// twice (unless [`Options::skip_intersection_check`](crate::Options::skip_intersection_check)).
    pub overlapping_shells: Occurrences<u64>,
    /// Pairs of faces that cross each other (unless
    /// [`Options::skip_intersection_check`](crate::Options::skip_intersection_check)).
    pub intersecting_face_pairs: Occurrences<[u64; 2]>,
    /// Pairs of faces that touch without crossing nor sharing a vertex, such
    /// as parts resting on each other: legal (unless
    /// [`Options::skip_intersection_check`](crate::Options::skip_intersection_check)).
    pub touching_face_pairs: Occurrences<[u64; 2]>,
}

impl Diagnostics {
    pub(crate) fn from_raw(raw: &sys::polymass_diagnostics, error: Option<Error>) -> Diagnostics {
        Diagnostics {
            error,
            face_count: raw.face_count,
            used_vertex_count: raw.used_vertex_count,
            edge_count: raw.edge_count,
            non_finite_vertices: Occurrences::<u64>::new(
                raw.non_finite_vertices,
                &raw.first_non_finite_vertices,
            ),
            out_of_range_indices: Occurrences::<u64>::new(
                raw.out_of_range_indices,
                &raw.first_out_of_range_faces,
            ),
            small_faces: Occurrences::<u64>::new(raw.small_faces, &raw.first_small_faces),
            degenerate_faces: Occurrences::<u64>::new(
                raw.degenerate_faces,
                &raw.first_degenerate_faces,
            ),
            open_edges: Occurrences::<[u64; 2]>::new(raw.open_edges, &raw.first_open_edges),
            non_manifold_edges: Occurrences::<[u64; 2]>::new(
                raw.non_manifold_edges,
                &raw.first_non_manifold_edges,
            ),
            misoriented_edges: Occurrences::<[u64; 2]>::new(
                raw.misoriented_edges,
                &raw.first_misoriented_edges,
            ),
            non_planar_faces: Occurrences::<u64>::new(
                raw.non_planar_faces,
                &raw.first_non_planar_faces,
            ),
            max_non_planarity: raw.max_non_planarity,
            signed_volume: (!raw.signed_volume.is_nan()).then_some(raw.signed_volume),
            shell_count: raw.shell_count,
            inverted_shells: Occurrences::<u64>::new(
                raw.inverted_shells,
                &raw.first_inverted_shells,
            ),
            overlapping_shells: Occurrences::<u64>::new(
                raw.overlapping_shells,
                &raw.first_overlapping_shells,
            ),
            intersecting_face_pairs: Occurrences::<[u64; 2]>::new(
                raw.intersecting_face_pairs,
                &raw.first_intersecting_face_pairs,
            ),
            touching_face_pairs: Occurrences::<[u64; 2]>::new(
                raw.touching_face_pairs,
                &raw.first_touching_face_pairs,
            ),
        }
    }

    /// Whether the surface is a valid solid (no [`error`](Diagnostics::error)).
    ///
    /// ```
    /// use polymass::Surface;
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// assert!(polymass::check(&Surface::triangles(&positions, &triangles))?.is_solid());
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn is_solid(&self) -> bool {
        self.error.is_none()
    }
}
