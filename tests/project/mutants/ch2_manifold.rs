//! Exercise 2.5's grader against plausible wrong counts, written from the
//! stub's contract (each must fail under every seed, naming its symptom
//! where the grader can tell), and correct alternatives written
//! differently (each must pass under every seed).

use std::collections::{BTreeMap, HashMap};
use std::panic::{catch_unwind, AssertUnwindSafe};

use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch2::{self, manifold};

use super::{fails_under as fails, passes_under as passes, under_seeds, SEEDS};

/// Which mistake the counting makes, one knob each.
#[derive(Clone, Copy, Default)]
struct Knobs {
    /// Edges keyed by (from, to), not by the pair.
    directed: bool,
    /// An odd number of triangles on an edge taken for a boundary.
    odd_is_boundary: bool,
    /// No vertex counted (the fans never looked at).
    no_fans: bool,
    /// A vertex is bad when its neighbours are neither as many as its
    /// triangles (closed fan) nor one more (open fan).
    degree: bool,
    /// A vertex is bad when one of its triangles shares no edge there
    /// (neighbours, not chains).
    no_chains: bool,
    /// A vertex counted once per extra fan.
    per_fan: bool,
    /// Inconsistent when the two triangles walk the edge opposite ways.
    inverted: bool,
    /// Inconsistency counted on edges of three triangles too.
    any_pair: bool,
    /// Triangles with a repeated index kept.
    keep_degenerate: bool,
    /// Only a == b taken for a repeated index.
    first_pair_only: bool,
    /// An edge keyed by one number, lower · 10⁶ + higher (the twenty-third
    /// fresh set's): edges collide once an index reaches 10⁶.
    decimal_key: bool,
}

fn counts(k: Knobs, triangles: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    let good: Vec<[u32; 3]> = triangles
        .iter()
        .copied()
        .filter(|&[a, b, c]| {
            k.keep_degenerate || (a != b && (k.first_pair_only || (b != c && c != a)))
        })
        .collect();
    let mut edges: BTreeMap<(u32, u32), (usize, usize)> = BTreeMap::new();
    let mut around: BTreeMap<u32, Vec<usize>> = BTreeMap::new();
    for (t, &[a, b, c]) in good.iter().enumerate() {
        for (i, j) in [(a, b), (b, c), (c, a)] {
            let key = if k.directed {
                (i, j)
            } else if k.decimal_key {
                let n = u64::from(i.min(j)) * 1_000_000 + u64::from(i.max(j));
                ((n >> 32) as u32, n as u32)
            } else {
                (i.min(j), i.max(j))
            };
            let e = edges.entry(key).or_default();
            if i <= j {
                e.0 += 1;
            } else {
                e.1 += 1;
            }
        }
        for v in [a, b, c] {
            around.entry(v).or_default().push(t);
        }
    }
    let (mut boundary, mut many, mut bad) = (0, 0, 0);
    for &(up, down) in edges.values() {
        let n = up + down;
        if n == 1 || (k.odd_is_boundary && n % 2 == 1) {
            boundary += 1;
        } else if n >= 3 {
            many += 1;
        }
        let same = if k.inverted { up == 1 } else { up != 1 };
        if (n == 2 || (k.any_pair && n > 2)) && same {
            bad += 1;
        }
    }
    let mut fans = 0;
    for (&v, tris) in &around {
        let share = |i: usize, j: usize| {
            good[tris[i]]
                .iter()
                .filter(|&&u| u != v)
                .any(|u| good[tris[j]].contains(u))
        };
        if k.no_fans {
            continue;
        }
        if k.degree {
            let mut near: Vec<u32> = tris
                .iter()
                .flat_map(|&t| good[t])
                .filter(|&u| u != v)
                .collect();
            near.sort_unstable();
            near.dedup();
            fans += usize::from(near.len() != tris.len() && near.len() != tris.len() + 1);
            continue;
        }
        if k.no_chains {
            let alone = (0..tris.len()).any(|i| (0..tris.len()).all(|j| i == j || !share(i, j)));
            fans += usize::from(alone && tris.len() > 1);
            continue;
        }
        let mut label: Vec<usize> = (0..tris.len()).collect();
        // Spread the smallest label until nothing changes.
        let mut changed = true;
        while changed {
            changed = false;
            for i in 0..tris.len() {
                for j in 0..tris.len() {
                    if share(i, j) && label[j] < label[i] {
                        label[i] = label[j];
                        changed = true;
                    }
                }
            }
        }
        label.sort_unstable();
        label.dedup();
        if label.len() > 1 {
            fans += if k.per_fan { label.len() - 1 } else { 1 };
        }
    }
    (boundary, many, fans, bad)
}

/// Vertices looked up in a table of as many entries as triangles (right
/// while the indices are 0..n and there are more triangles than
/// vertices; a panic otherwise).
fn table_of_triangles(triangles: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    let mut seen = vec![0u32; triangles.len()];
    for t in triangles {
        for &i in t {
            seen[i as usize] += 1;
        }
    }
    counts(Knobs::default(), triangles)
}

/// Right, another way: the directed edges sorted, runs of one undirected
/// edge counted; fans by a walk over the triangles at each vertex.
fn sorted_edges(triangles: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    let good: Vec<[u32; 3]> = triangles
        .iter()
        .copied()
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
        .collect();
    let mut directed: Vec<(u32, u32, bool)> = good
        .iter()
        .flat_map(|&[a, b, c]| [(a, b), (b, c), (c, a)])
        .map(|(i, j)| (i.min(j), i.max(j), i < j))
        .collect();
    directed.sort_unstable();
    let (mut boundary, mut many, mut bad) = (0, 0, 0);
    for run in directed.chunk_by(|x, y| (x.0, x.1) == (y.0, y.1)) {
        match run.len() {
            1 => boundary += 1,
            2 => bad += usize::from(run[0].2 == run[1].2),
            _ => many += 1,
        }
    }
    let mut at: HashMap<u32, Vec<[u32; 3]>> = HashMap::new();
    for t in &good {
        for &v in t {
            at.entry(v).or_default().push(*t);
        }
    }
    let mut fans = 0;
    for (v, tris) in at {
        let mut seen = vec![false; tris.len()];
        let mut stack = vec![0];
        seen[0] = true;
        while let Some(i) = stack.pop() {
            for j in 0..tris.len() {
                let shares = tris[i].iter().any(|&u| u != v && tris[j].contains(&u));
                if !seen[j] && shares {
                    seen[j] = true;
                    stack.push(j);
                }
            }
        }
        fans += usize::from(seen.contains(&false));
    }
    (boundary, many, fans, bad)
}

macro_rules! knob {
    ($($field:ident),*) => {
        |t: &[[u32; 3]]| counts(Knobs { $($field: true,)* ..Knobs::default() }, t)
    };
}

#[test]
fn wrong_counts_fail_under_every_seed() {
    let mut wrong = Vec::new();
    fails(
        &mut wrong,
        "directed edges",
        Some(manifold::BOUNDARY),
        || ch2::check_manifold(knob!(directed)),
    );
    fails(
        &mut wrong,
        "an odd count taken for a boundary",
        Some(manifold::BOUNDARY),
        || ch2::check_manifold(knob!(odd_is_boundary)),
    );
    fails(&mut wrong, "no fans counted", Some(manifold::FANS), || {
        ch2::check_manifold(knob!(no_fans))
    });
    fails(
        &mut wrong,
        "fans by vertex degree",
        Some(manifold::FANS),
        || ch2::check_manifold(knob!(degree)),
    );
    fails(&mut wrong, "fans without chains", None, || {
        ch2::check_manifold(knob!(no_chains))
    });
    fails(&mut wrong, "a vertex counted per extra fan", None, || {
        ch2::check_manifold(knob!(per_fan))
    });
    fails(
        &mut wrong,
        "orientation inverted",
        Some(manifold::ORIENTATION),
        || ch2::check_manifold(knob!(inverted)),
    );
    fails(&mut wrong, "orientation on edges of three", None, || {
        ch2::check_manifold(knob!(any_pair))
    });
    fails(
        &mut wrong,
        "degenerate triangles kept",
        Some(manifold::REPEATED_INDEX),
        || ch2::check_manifold(knob!(keep_degenerate)),
    );
    fails(
        &mut wrong,
        "only a == b is degenerate",
        Some(manifold::REPEATED_INDEX),
        || ch2::check_manifold(knob!(first_pair_only)),
    );
    fails(
        &mut wrong,
        "an edge keyed lower · 10⁶ + higher",
        None,
        || ch2::check_manifold(knob!(decimal_key)),
    );
    // Indices taken for positions in a table sized by the triangles: it
    // panics (which fails a grading) or counts wrong.
    for (seed, outcome) in under_seeds(&SEEDS, || {
        catch_unwind(AssertUnwindSafe(|| ch2::check_manifold(table_of_triangles))).unwrap_or_else(
            |_| Check {
                error: f64::INFINITY,
                tolerance: 0.0,
                detail: "panicked".into(),
                images: None,
                symptom: None,
            },
        )
    }) {
        assert!(!outcome.passed(), "seed {seed}: {}", outcome.detail);
    }
    assert!(wrong.is_empty(), "{wrong:#?}");
}

#[test]
fn right_counts_pass_under_every_seed() {
    let mut wrong = Vec::new();
    passes(&mut wrong, "labels spread until stable, BTreeMap", || {
        ch2::check_manifold(knob!())
    });
    passes(&mut wrong, "sorted directed edges and a walk", || {
        ch2::check_manifold(sorted_edges)
    });
    passes(&mut wrong, "the lesson", || {
        ch2::check_manifold(manifold::reference_counts)
    });
    assert!(wrong.is_empty(), "{wrong:#?}");
}
