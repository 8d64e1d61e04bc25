//! The lecture's manifold and boundary checks for a triangle mesh.
//!
//! A mesh is a manifold surface when every edge belongs to one or two
//! triangles and the triangles around every vertex form one fan (closed
//! around an inner vertex, open around a boundary vertex, the "pacman").
//! Edges with one triangle are boundary edges; they join into loops where
//! the surface ends. A mesh with no boundary edge is closed.
//!
//! The checks are on the index structure only: two vertices at the same
//! position with different indices count as different vertices.

use std::collections::BTreeMap;

use crate::scene::mesh::Mesh;

/// What the checks found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct MeshCheck {
    /// Vertices referenced by some triangle.
    pub vertices: usize,
    /// Distinct undirected edges.
    pub edges: usize,
    /// Triangles, not counting those that repeat an index.
    pub triangles: usize,
    /// Triangles that use a vertex twice (no area; skipped by the checks).
    pub degenerate_triangles: usize,
    /// Edges with exactly one triangle.
    pub boundary_edges: usize,
    /// Lengths (in edges) of the boundary loops, longest first.
    pub boundary_loops: Vec<usize>,
    /// Edges with more than two triangles, as vertex pairs.
    pub nonmanifold_edges: Vec<[u32; 2]>,
    /// Vertices whose triangles form more than one fan.
    pub nonmanifold_vertices: Vec<u32>,
    /// Edges whose two triangles walk it in the same direction (the
    /// triangles' orientations disagree).
    pub inconsistent_edges: usize,
}

impl MeshCheck {
    /// No boundary edge.
    pub fn is_closed(&self) -> bool {
        self.boundary_edges == 0
    }

    /// Every edge has one or two triangles and every vertex one fan.
    pub fn is_manifold(&self) -> bool {
        self.nonmanifold_edges.is_empty() && self.nonmanifold_vertices.is_empty()
    }

    /// Euler characteristic V - E + F.
    pub fn euler(&self) -> i64 {
        self.vertices as i64 - self.edges as i64 + self.triangles as i64
    }

    /// One phrase: "closed manifold", "manifold with 2 boundary loops", ...
    pub fn verdict(&self) -> String {
        if !self.is_manifold() {
            return format!(
                "not manifold ({} edges with 3+ triangles, {} vertices with 2+ fans)",
                self.nonmanifold_edges.len(),
                self.nonmanifold_vertices.len()
            );
        }
        match self.boundary_loops.len() {
            0 if self.is_closed() => "closed manifold".into(),
            1 => "manifold with 1 boundary loop".into(),
            n => format!("manifold with {n} boundary loops"),
        }
    }
}

/// Union-find over small sets (the fans around one vertex).
fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// Runs every check on `mesh`.
pub fn check_mesh(mesh: &Mesh) -> MeshCheck {
    check_triangles(&mesh.triangles)
}

/// Runs every check on a mesh given by its triangles alone (the vertex
/// indices; positions play no part).
// ANCHOR: check_mesh
// ANCHOR: check_mesh_count
pub fn check_triangles(triangles: &[[u32; 3]]) -> MeshCheck {
    let mut check = MeshCheck::default();
    // Edge → the triangles on it, with the direction each walks it.
    let mut edges: BTreeMap<[u32; 2], Vec<(usize, bool)>> = BTreeMap::new();
    // Vertex → its triangles.
    let mut around: BTreeMap<u32, Vec<usize>> = BTreeMap::new();
    for (t, &[a, b, c]) in triangles.iter().enumerate() {
        if a == b || b == c || c == a {
            check.degenerate_triangles += 1;
            continue;
        }
        check.triangles += 1;
        for (i, j) in [(a, b), (b, c), (c, a)] {
            edges
                .entry([i.min(j), i.max(j)])
                .or_default()
                .push((t, i < j));
        }
        for v in [a, b, c] {
            around.entry(v).or_default().push(t);
        }
    }
    check.vertices = around.len();
    check.edges = edges.len();
    // ANCHOR_END: check_mesh_count

    // ANCHOR: check_mesh_edges
    // Every edge: one triangle is a boundary, three or more is non-manifold.
    let mut boundary: Vec<[u32; 2]> = Vec::new();
    for (e, tris) in &edges {
        match tris.len() {
            1 => boundary.push(*e),
            2 if tris[0].1 == tris[1].1 => check.inconsistent_edges += 1,
            2 => {}
            _ => check.nonmanifold_edges.push(*e),
        }
    }
    check.boundary_edges = boundary.len();
    // ANCHOR_END: check_mesh_edges

    // ANCHOR: check_mesh_vertices
    // Every vertex: its triangles are one fan when they are all connected
    // through edges at the vertex.
    for (&v, tris) in &around {
        let mut parent: Vec<usize> = (0..tris.len()).collect();
        for i in 0..tris.len() {
            for j in i + 1..tris.len() {
                let shares_edge = triangles[tris[i]]
                    .iter()
                    .filter(|&&u| u != v)
                    .any(|u| triangles[tris[j]].contains(u));
                if shares_edge {
                    let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                    parent[a] = b;
                }
            }
        }
        let fans = (0..tris.len())
            .filter(|&i| find(&mut parent, i) == i)
            .count();
        if fans > 1 {
            check.nonmanifold_vertices.push(v);
        }
    }

    check.boundary_loops = boundary_loops(&boundary);
    check
}
// ANCHOR_END: check_mesh_vertices
// ANCHOR_END: check_mesh

/// Splits the boundary edges into loops: walk from edge to edge, and each
/// time the walk comes back to a vertex already on it, cut off that loop.
/// (Where two loops touch at a vertex this finds both.) Returns the loop
/// lengths, longest first; a walk that cannot close (possible only around
/// non-manifold edges) is counted as a loop of its length too.
pub fn boundary_loops(boundary: &[[u32; 2]]) -> Vec<usize> {
    let mut next: BTreeMap<u32, Vec<usize>> = BTreeMap::new();
    for (k, [a, b]) in boundary.iter().enumerate() {
        next.entry(*a).or_default().push(k);
        next.entry(*b).or_default().push(k);
    }
    let mut used = vec![false; boundary.len()];
    let mut loops = Vec::new();
    for start in 0..boundary.len() {
        if used[start] {
            continue;
        }
        let mut path: Vec<u32> = vec![boundary[start][0]];
        let mut pending = Some(start);
        while let Some(k) = pending.take() {
            used[k] = true;
            let here = *path.last().unwrap_or(&boundary[k][0]);
            let to = if boundary[k][0] == here {
                boundary[k][1]
            } else {
                boundary[k][0]
            };
            if let Some(i) = path.iter().position(|&v| v == to) {
                loops.push(path.len() - i);
                path.truncate(i + 1);
            } else {
                path.push(to);
            }
            let at = *path.last().unwrap_or(&to);
            pending = next
                .get(&at)
                .and_then(|ks| ks.iter().copied().find(|&k| !used[k]));
            if pending.is_none() && path.len() > 1 {
                loops.push(path.len() - 1);
            }
        }
    }
    loops.sort_by(|a, b| b.cmp(a));
    loops
}
