//! Exercise 2.5: is a mesh a manifold? Count what says it is not.
//!
//! A triangle mesh is a manifold surface when every edge belongs to one
//! or two triangles and the triangles around every vertex form a single
//! fan (closed all the way round, or open at a boundary). Edges with one
//! triangle are the boundary. Two neighbouring triangles agree on their
//! orientation when they walk their shared edge in opposite directions.
//!
//! The mesh is its index triplets only: `triangles[t] = [i, j, k]` walks
//! the edges i→j, j→k, k→i. Indices are any `u32` values, in any order,
//! not 0..n; positions play no part.
//!
//! Contract (what the grader checks, exactly, on hand-made and drawn
//! meshes of up to a few thousand triangles):
//! * a triangle that repeats an index has no area: it is skipped
//!   entirely (it adds no edge and no vertex);
//! * an edge is the unordered pair {i, j}; its triangles are those having
//!   it among their three edges;
//! * `.0`: the edges with exactly one triangle (boundary edges);
//! * `.1`: the edges with three or more triangles;
//! * `.2`: the vertices whose triangles form two or more fans, where two
//!   triangles at a vertex v are in one fan when a chain of triangles at
//!   v joins them, each sharing an edge at v with the next;
//! * `.3`: the edges with exactly two triangles that walk the edge in the
//!   same direction (inconsistently oriented).
//!
//! Hints: `cargo grade --hint ch2/manifold`.
//! Grade it with: `cargo grade ch2`

/// (boundary edges, edges with 3+ triangles, vertices with 2+ fans,
/// inconsistently oriented edges) of the mesh `triangles`.
pub fn manifold_counts(triangles: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    // TODO: count the triangles on every edge, then the fans at every vertex.
    todo!()
}
