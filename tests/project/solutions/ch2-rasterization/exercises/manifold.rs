//! Exercise 2.5, solved: triangles per edge in a map, then the fans at
//! each vertex joined with a small union-find.

use std::collections::HashMap;

/// (boundary edges, edges with 3+ triangles, vertices with 2+ fans,
/// inconsistently oriented edges) of the mesh `triangles`.
pub fn manifold_counts(triangles: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    let good: Vec<[u32; 3]> = triangles
        .iter()
        .copied()
        .filter(|&[a, b, c]| a != b && b != c && c != a)
        .collect();
    // Edge {i, j} -> how many triangles walk it i->j (i < j) and j->i.
    let mut edges: HashMap<(u32, u32), (usize, usize)> = HashMap::new();
    // Vertex -> its triangles.
    let mut around: HashMap<u32, Vec<usize>> = HashMap::new();
    for (t, &[a, b, c]) in good.iter().enumerate() {
        for (i, j) in [(a, b), (b, c), (c, a)] {
            let e = edges.entry((i.min(j), i.max(j))).or_default();
            if i < j {
                e.0 += 1;
            } else {
                e.1 += 1;
            }
        }
        for v in [a, b, c] {
            around.entry(v).or_default().push(t);
        }
    }
    let (mut boundary, mut many, mut inconsistent) = (0, 0, 0);
    for &(up, down) in edges.values() {
        match up + down {
            1 => boundary += 1,
            2 if up != 1 => inconsistent += 1,
            2 => {}
            _ => many += 1,
        }
    }
    let mut fans = 0;
    for (&v, tris) in &around {
        let mut parent: Vec<usize> = (0..tris.len()).collect();
        fn root(p: &mut [usize], mut i: usize) -> usize {
            while p[i] != i {
                i = p[i];
            }
            i
        }
        for i in 0..tris.len() {
            for j in i + 1..tris.len() {
                let other = good[tris[i]].iter().filter(|&&u| u != v);
                if other.clone().any(|u| good[tris[j]].contains(u)) {
                    let (a, b) = (root(&mut parent, i), root(&mut parent, j));
                    parent[a] = b;
                }
            }
        }
        let roots = (0..tris.len()).filter(|&i| root(&mut parent, i) == i).count();
        if roots > 1 {
            fans += 1;
        }
    }
    (boundary, many, fans, inconsistent)
}
