//! Welding over positions alone (`polymass_weld_positions`).

/// Which vertices welding makes one: [`weld_positions`](crate::weld_positions).
///
/// ```
/// use polymass::Positions;
///
/// // Two triangles of a soup sharing an edge: six vertices, four positions.
/// let soup = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
///             [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
/// let weld = polymass::weld_positions(Positions::packed(&soup), 0.0)?;
/// assert_eq!(weld.vertex_of, [0, 1, 2, 1, 4, 2]);
/// assert_eq!(weld.distinct_count, 4);
/// # Ok::<(), polymass::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Weld {
    /// For each vertex, the lowest vertex index welded to it (its own index
    /// when none lower is).
    pub vertex_of: Vec<u32>,
    /// How many vertices are their own lowest: the distinct positions.
    pub distinct_count: u64,
}
