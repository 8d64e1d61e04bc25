//! Exercise 2.5, the lecture's manifold and boundary checks counted: the
//! four counts compared exactly with the lesson's
//! [`check_triangles`] on the lecture's cases by hand, then on meshes drawn
//! from the run's seed (closed grids, spheres and tetrahedra with holes
//! punched, fins on edges, books of pages on one edge, meshes glued at one vertex, flipped and
//! degenerate triangles, shuffled, rotated and relabelled far apart in
//! `u32`).

use crate::ch2_rasterization::mesh_check::check_triangles;
use crate::exercise::{Check, Symptom};
use crate::exercises::draws::Draws;

/// The counts: boundary edges, edges with 3+ triangles, vertices with 2+
/// fans, inconsistently oriented edges.
pub type Counts = (usize, usize, usize, usize);
/// A function counting them.
pub type ManifoldFn = fn(&[[u32; 3]]) -> Counts;

/// The boundary edges miscounted.
pub const BOUNDARY: Symptom = Symptom {
    name: "the boundary edges are miscounted",
};
/// The edges with three or more triangles miscounted.
pub const BOOK_EDGES: Symptom = Symptom {
    name: "edges with 3+ triangles are miscounted",
};
/// The vertices with two or more fans miscounted.
pub const FANS: Symptom = Symptom {
    name: "vertices with 2+ fans are miscounted",
};
/// The inconsistently oriented edges miscounted.
pub const ORIENTATION: Symptom = Symptom {
    name: "inconsistent edges are miscounted",
};
/// A triangle with a repeated index counted.
pub const REPEATED_INDEX: Symptom = Symptom {
    name: "a triangle with a repeated index was counted",
};

/// The lesson's counts of `tris`.
pub fn reference_counts(tris: &[[u32; 3]]) -> Counts {
    let c = check_triangles(tris);
    (
        c.boundary_edges,
        c.nonmanifold_edges.len(),
        c.nonmanifold_vertices.len(),
        c.inconsistent_edges,
    )
}

const TETRA: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]];

/// `mesh` with every index moved by `by`.
fn moved(mesh: &[[u32; 3]], by: u32) -> Vec<[u32; 3]> {
    mesh.iter().map(|t| t.map(|i| i + by)).collect()
}

/// The lecture's cases: (what, triangles).
fn hand_cases() -> Vec<(&'static str, Vec<[u32; 3]>)> {
    let mut flipped = TETRA.to_vec();
    flipped[0] = [0, 1, 2];
    let mut degenerate = TETRA.to_vec();
    degenerate.extend([[0, 0, 1], [2, 2, 2], [1, 3, 1], [3, 2, 3]]);
    let mut two_tetras = TETRA.to_vec();
    two_tetras.extend(moved(&TETRA, 3));
    let mut three_tetras = two_tetras.clone();
    three_tetras.extend(
        moved(&TETRA, 6)
            .iter()
            .map(|t| t.map(|i| if i == 6 { 3 } else { i })),
    );
    let mut repeated = TETRA.to_vec();
    repeated.push(TETRA[2]);
    let big = u32::MAX - 3;
    vec![
        ("a closed tetrahedron", TETRA.to_vec()),
        ("one triangle", vec![[0, 1, 2]]),
        ("a quad of two triangles", vec![[0, 1, 2], [0, 2, 3]]),
        (
            "two triangles touching at vertex 0",
            vec![[0, 1, 2], [0, 3, 4]],
        ),
        (
            "three triangles on the edge 0-1",
            vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]],
        ),
        (
            "three triangles walking the edge 0-1 the same way",
            vec![[0, 1, 2], [0, 1, 3], [0, 1, 4]],
        ),
        ("a tetrahedron with one face flipped", flipped),
        ("two tetrahedra sharing vertex 3", two_tetras),
        ("three tetrahedra sharing vertex 3", three_tetras),
        (
            "a tetrahedron with indices near u32::MAX",
            moved(&TETRA, big),
        ),
        (
            // Edges {1, 2} and {0, 65538}, {2, 3} and {1, 65539} would
            // share a key packed as low · 2¹⁶ + high.
            "two triangles whose indices pack alike in 16-bit halves",
            vec![[1, 2, 3], [0, 65538, 65539]],
        ),
        (
            "one triangle twice, corners in the same order",
            vec![[0, 1, 2], [0, 1, 2]],
        ),
        ("a tetrahedron with one face twice", repeated),
        // More triangles at one vertex than a byte counts.
        (
            "a sphere whose poles have 300 triangles each",
            sphere(2, 300, 0),
        ),
        (
            "two closed discs of 150 triangles sharing their centre (two fans of 150)",
            disc(150, 1).into_iter().chain(disc(150, 151)).collect(),
        ),
        // Last: a failure here names the repeated index.
        (
            "a tetrahedron and four triangles with a repeated index",
            degenerate,
        ),
    ]
}

/// A closed torus-like grid of m x n quads (two triangles each), its
/// indices from `first`.
fn grid(m: u32, n: u32, first: u32) -> Vec<[u32; 3]> {
    let id = |i: u32, j: u32| first + (i % m) * n + j % n;
    let mut tris = Vec::new();
    for i in 0..m {
        for j in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            tris.extend([[a, b, c], [a, c, d]]);
        }
    }
    tris
}

/// A closed fan of `m` triangles round vertex 0, its rim's indices from
/// `first`.
fn disc(m: u32, first: u32) -> Vec<[u32; 3]> {
    (0..m)
        .map(|k| [0, first + k, first + (k + 1) % m])
        .collect()
}

/// A closed sphere: two poles and `rings` rings of `m` vertices.
fn sphere(rings: u32, m: u32, first: u32) -> Vec<[u32; 3]> {
    let (north, south) = (first, first + 1);
    let id = |k: u32, j: u32| first + 2 + k * m + j % m;
    let mut tris = Vec::new();
    for j in 0..m {
        tris.push([north, id(0, j), id(0, j + 1)]);
        for k in 0..rings - 1 {
            let (a, b, c, d) = (id(k, j), id(k + 1, j), id(k + 1, j + 1), id(k, j + 1));
            tris.extend([[a, b, c], [a, c, d]]);
        }
        tris.push([south, id(rings - 1, j + 1), id(rings - 1, j)]);
    }
    tris
}

/// A closed mesh drawn: a grid, a sphere or a tetrahedron, with indices
/// from `first`; returns it and one past its largest index.
fn closed(d: &mut Draws, first: u32) -> (Vec<[u32; 3]>, u32) {
    match d.count(0, 2) {
        0 => {
            let (m, n) = (d.count(3, 24) as u32, d.count(3, 24) as u32);
            (grid(m, n, first), first + m * n)
        }
        1 => {
            // A third of them with poles of 65 to 150 triangles (more than
            // the bits of a word).
            // (Few rings then, so that the mesh stays as large as the
            // others.)
            let (r, m) = match d.unit() < 1.0 / 3.0 {
                true => (d.count(1, 4), d.count(65, 150)),
                false => (d.count(1, 16), d.count(3, 24)),
            };
            let (r, m) = (r as u32, m as u32);
            (sphere(r, m, first), first + 2 + r * m)
        }
        _ => (moved(&TETRA, first), first + 4),
    }
}

/// A drawn mesh: one to three closed meshes, glued at a vertex or apart,
/// then holes, fins, flips, copies and repeated indices, all shuffled.
fn drawn_mesh(d: &mut Draws) -> Vec<[u32; 3]> {
    let (mut tris, mut next) = closed(d, 0);
    let mut to = 0;
    for _ in 0..d.count(0, 3) {
        let (more, end) = closed(d, next);
        // Glue one vertex of the new mesh onto one of the old (a vertex
        // with two fans, or three on the same one again), or leave it
        // apart.
        let glue = d.unit() < 0.6;
        let from = next + d.count(0, 3) as u32;
        if d.unit() < 0.5 {
            to = d.count(0, next as usize - 1) as u32;
        }
        tris.extend(
            more.iter()
                .map(|t| t.map(|i| if glue && i == from { to } else { i })),
        );
        next = end;
    }
    let pick = |d: &mut Draws, tris: &[[u32; 3]]| d.count(0, tris.len() - 1);
    for _ in 0..d.count(0, 3) * d.count(0, 3) {
        if tris.len() > 1 {
            let k = pick(d, &tris);
            tris.swap_remove(k);
        }
    }
    for _ in 0..d.count(0, 3) {
        // A fin: a new triangle on an edge of an old one.
        let [a, b, _] = tris[pick(d, &tris)];
        tris.push(if d.unit() < 0.5 {
            [a, b, next]
        } else {
            [b, a, next]
        });
        next += 1;
    }
    if d.unit() < 0.5 {
        // A book: three to five pages on one new edge, each walking it
        // either way, or all the same way.
        let (a, b, pages) = (next, next + 1, d.count(3, 5) as u32);
        let all_one_way = d.unit() < 0.5;
        for page in next + 2..next + 2 + pages {
            let flip = !all_one_way && d.unit() < 0.5;
            tris.push(if flip { [b, a, page] } else { [a, b, page] });
        }
        next += 2 + pages;
    }
    for _ in 0..d.count(0, 2) * d.count(0, 2) {
        let k = pick(d, &tris);
        tris[k].swap(1, 2);
    }
    if d.unit() < 0.2 {
        let k = pick(d, &tris);
        tris.push(tris[k]);
    }
    for _ in 0..d.count(0, 3) {
        let [a, b, c] = tris[pick(d, &tris)];
        tris.push(match d.count(0, 3) {
            0 => [a, a, b],
            1 => [a, b, a],
            2 => [c, b, b],
            _ => [c, c, c],
        });
    }
    // Shuffle, rotate within triangles, relabel far apart.
    for k in (1..tris.len()).rev() {
        tris.swap(k, d.count(0, k));
    }
    let stride = d.count(1, 4) as u32 * (u32::MAX / 4 / next.max(1)).min(d.count(1, 9999) as u32);
    let base = d.count(0, (u32::MAX - stride * next) as usize) as u32;
    let shift = d.count(0, 2);
    tris.iter_mut().for_each(|t| {
        t.rotate_left(shift);
        *t = t.map(|i| base + i * stride);
    });
    tris
}

/// Three triangles apart for each round base m (10² to 10⁹, 2⁸ to 2³⁰),
/// with edges {a, b}, {a + 1, b - m} and {a + m, b - 1}: three edges,
/// which one number x m + y made of each edge's two indices (x the
/// smaller, y the larger, or the other way round) would make two. The
/// contract allows any u32 index.
fn packed_alike(d: &mut Draws) -> Vec<[u32; 3]> {
    let bases = (2..=9)
        .map(|k| 10u64.pow(k))
        .chain((8..=30).map(|k| 1 << k));
    let mut tris = Vec::new();
    for m in bases {
        // m + 2 <= b <= u32::MAX - 3 and a <= b - m - 2: every index in
        // range, a + 1 < b - m and a + m < b - 1; b + 1 to b + 3 are the
        // third corners.
        let b = d.count(m as usize + 2, u32::MAX as usize - 3) as u64;
        let a = d.count(0, (b - m - 2) as usize) as u64;
        let t = |x: u64, y: u64, k: u64| [x as u32, y as u32, (b + k) as u32];
        tris.extend([t(a, b, 1), t(a + 1, b - m, 2), t(a + m, b - 1, 3)]);
    }
    tris
}

/// The mesh for a message: its triangles when few, else its size.
fn show(tris: &[[u32; 3]]) -> String {
    if tris.len() <= 12 {
        format!("{tris:?}")
    } else {
        format!("{} triangles, from {:?}", tris.len(), &tris[..4])
    }
}

/// The first count that differs.
fn differs(got: Counts, want: Counts) -> Option<Symptom> {
    if got.0 != want.0 {
        Some(BOUNDARY)
    } else if got.1 != want.1 {
        Some(BOOK_EDGES)
    } else if got.2 != want.2 {
        Some(FANS)
    } else {
        (got.3 != want.3).then_some(ORIENTATION)
    }
}

/// Every count exactly, on the hand cases and the drawn meshes.
pub fn check_manifold(f: ManifoldFn) -> Check {
    let hand = hand_cases();
    let results: Vec<Counts> = hand.iter().map(|(_, t)| f(t)).collect();
    let wrong = |k: usize| differs(results[k], reference_counts(&hand[k].1));
    let last = hand.len() - 1;
    let first_wrong = (0..hand.len()).find(|&k| wrong(k).is_some());
    let mut failure = first_wrong.map(|k| {
        let symptom = if k == last {
            Some(REPEATED_INDEX)
        } else {
            wrong(k)
        };
        let (what, tris) = &hand[k];
        let detail = format!(
            "{what} {}: got {:?}, expected {:?}",
            show(tris),
            results[k],
            reference_counts(tris)
        );
        (detail, symptom)
    });
    let mut draws = Draws::new(25);
    let cases = draws.count(60, 120);
    // Up to the first wrong count: one is enough to fail.
    for _ in 0..cases {
        if failure.is_some() {
            break;
        }
        draws.next_case();
        let mut tris = drawn_mesh(&mut draws);
        // A third renumbered so that many vertices are alike in their
        // low 16 bits (the k-th is (k + 1)·2¹⁶ + k mod 2 to 5), the last
        // u32::MAX: a vertex is its whole index, any u32.
        if draws.unit() < 1.0 / 3.0 {
            let low = draws.count(2, 5) as u32;
            let mut order: Vec<u32> = tris.iter().flatten().copied().collect();
            order.sort_unstable();
            order.dedup();
            if order.len() < 65_535 {
                let last = order.len() as u32 - 1;
                let far = |i: &u32| match order.binary_search(i).unwrap_or_default() as u32 {
                    k if k == last => u32::MAX,
                    k => (k + 1) * 65_536 + k % low,
                };
                tris = tris
                    .iter()
                    .map(|t| [far(&t[0]), far(&t[1]), far(&t[2])])
                    .collect();
            }
        }
        // A quarter with edges whose indices pack alike for a round base.
        if draws.unit() < 0.25 {
            tris.extend(packed_alike(&mut draws));
        }
        let (got, want) = (f(&tris), reference_counts(&tris));
        if got != want {
            let detail = format!(
                "{} (a drawn case): got {got:?}, expected {want:?}",
                show(&tris)
            );
            failure = Some((detail, differs(got, want)));
        }
    }
    let detail = format!(
        "{} hand-made and {cases} drawn meshes, counts as (boundary edges, edges with 3+ triangles, vertices with 2+ fans, inconsistent edges)",
        hand.len()
    );
    match failure {
        None => Check {
            error: 0.0,
            tolerance: 0.0,
            detail,
            images: None,
            symptom: None,
        },
        Some((detail, symptom)) => Check {
            error: 1.0,
            tolerance: 0.0,
            detail,
            images: None,
            symptom,
        },
    }
}
