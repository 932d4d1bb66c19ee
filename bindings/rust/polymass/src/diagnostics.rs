//! What the analysis of a surface finds (`polymass_diagnostics`).

use polymass_sys as sys;

use crate::codes::bit_set;
use crate::error::{Error, ErrorKind};

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

bit_set! {
    /// Which checks of an analysis ran to their end (`POLYMASS_CHECKED_*`):
    /// those the options skip, and those after a finding that leaves nothing
    /// to judge (unreadable faces; shells of a surface that is not closed),
    /// did not.
    ///
    /// ```
    /// use polymass::{Checks, Mesh, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let surface = Surface::triangles(&positions, &triangles);
    /// let every = Checks::TOPOLOGY | Checks::SHELLS | Checks::INTERSECTIONS;
    /// assert_eq!(Mesh::new(&surface, &Options::new())?.diagnostics()?.checks, every);
    /// let trusting = Options::new().skip_intersection_check(true);
    /// let report = Mesh::new(&surface, &trusting)?.diagnostics()?;
    /// assert!(!report.checks.contains(Checks::INTERSECTIONS));
    /// # Ok::<(), polymass::Error>(())
    /// ```
    Checks {
        /// Closed, manifold, consistently oriented, planar polygon faces.
        TOPOLOGY = sys::POLYMASS_CHECKED_TOPOLOGY;
        /// The shells judged: their volumes and how they nest.
        SHELLS = sys::POLYMASS_CHECKED_SHELLS;
        /// Faces crossing or touching, shells counted twice.
        INTERSECTIONS = sys::POLYMASS_CHECKED_INTERSECTIONS;
    }
}

/// What the analysis of a surface found ([`Mesh::diagnostics`](crate::Mesh::diagnostics)):
/// every check the options did not skip run to its end, with counts and
/// first few locations. Vertex numbers are the caller's indices (after
/// welding: the lowest index at that position); edges are vertex pairs, face
/// pairs `[lower, higher]`; shells are numbered as
/// [`Mesh::shells`](crate::Mesh::shells) numbers them. Faces of fewer than 3
/// vertices, indices out of range and non-finite coordinates leave the faces
/// unreadable: the report then holds only those findings.
///
/// ```
/// use polymass::{ErrorKind, Mesh, Options, Surface};
///
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let open = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2]];
/// let mesh = Mesh::new(&Surface::triangles(&positions, &open), &Options::new())?;
/// let report = mesh.diagnostics()?;
/// assert_eq!(report.error.as_ref().map(|e| e.kind()), Some(ErrorKind::Open));
/// assert!(report.error.unwrap().message().contains("edge"));
/// assert_eq!(report.open_edges.count, 3);
/// assert_eq!(report.open_edges.first.len(), 3); // the rim of the missing face
/// assert!(report.misoriented_edges.first.is_empty());
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Diagnostics {
    /// The surface's own verdict, as the solid mode judges it whatever mode
    /// answered: `None` for a valid solid, else its first defect with the
    /// library's message saying where (when no mode answered, each later
    /// mode's reason follows, as in [`Mesh::status`](crate::Mesh::status)).
    pub error: Option<Error>,
    /// Which checks ran to their end.
    pub checks: Checks,
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
    /// Shells (connected pieces) of the surface; 0 when the faces are
    /// unreadable.
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
    /// The report, and the mesh's message, which is its status's.
    pub(crate) fn from_raw(raw: &sys::polymass_diagnostics, message: String) -> Diagnostics {
        Diagnostics {
            error: ErrorKind::from_code(raw.status).map(|_| Error::new(raw.status, message)),
            checks: Checks::from_bits(raw.checks),
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
    /// use polymass::{Mesh, Options, Surface};
    ///
    /// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let triangles = [[0u32, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mesh = Mesh::new(&Surface::triangles(&positions, &triangles), &Options::new())?;
    /// assert!(mesh.diagnostics()?.is_solid());
    /// # Ok::<(), polymass::Error>(())
    /// ```
    pub fn is_solid(&self) -> bool {
        self.error.is_none()
    }
}
