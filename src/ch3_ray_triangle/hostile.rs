//! The BVH builds on hostile geometry, as a benchmark (`ch3 --bench
//! hostile`): collapsed spheres away from the origin and many overlapping
//! triangles, each built into both BVHs and timed against an ordinary mesh
//! of as many triangles, with a budget of [`BUDGET`] times that. A build
//! that splits badly degrades towards n² and shows here as a ratio in the
//! hundreds; the tests check only that every case is here and builds
//! (speed lives in benchmarks, not in timed tests).

use std::time::Instant;

use glam::Vec3;

use crate::ch3_ray_triangle::obvhs_bvh::Bvh;
use crate::ch3_ray_triangle::wide_bvh::WideBvh;
use crate::core::format::{format_number, format_seconds};
use crate::core::report::Table;
use crate::core::sampling::random;

/// A hostile build may take this many times an ordinary one.
pub const BUDGET: f64 = 4.0;

/// A geodesic-ish sphere of `rings × segments × 2` triangles, radius `r`
/// about `centre` (built here so the case does not depend on the scene
/// loader's own limits).
pub fn sphere(centre: Vec3, r: f32, rings: u32, segments: u32) -> Vec<[Vec3; 3]> {
    let point = |i: u32, j: u32| {
        let theta = std::f32::consts::PI * i as f32 / rings as f32;
        let phi = std::f32::consts::TAU * j as f32 / segments as f32;
        centre
            + r * Vec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                theta.sin() * phi.sin(),
            )
    };
    let mut tris = Vec::with_capacity((2 * rings * segments) as usize);
    for i in 0..rings {
        for j in 0..segments {
            let (a, b) = (point(i, j), point(i + 1, j));
            let (c, d) = (point(i + 1, j + 1), point(i, j + 1));
            tris.push([a, b, c]);
            tris.push([a, c, d]);
        }
    }
    tris
}

/// `n` large triangles through one small region, each turned at random:
/// every box overlaps every other, the worst case for a split.
pub fn overlapping(n: usize) -> Vec<[Vec3; 3]> {
    (0..n as u64)
        .map(|i| {
            let u = |d| random(7, 0, i, d) * 2.0 - 1.0;
            let a = Vec3::new(u(0), u(1), u(2)).normalize_or(Vec3::X);
            let b = a.cross(Vec3::new(u(3), u(4), u(5))).normalize_or(Vec3::Y);
            [a * 10.0, b * 10.0, -(a + b) * 5.0]
        })
        .collect()
}

/// The cases: (name, triangles), at `scale` (1.0: the benchmark's
/// sizes; smaller for tests).
pub fn cases(scale: f64) -> Vec<(String, Vec<[Vec3; 3]>)> {
    let rings = ((256.0 * scale.sqrt()) as u32).max(4);
    let n = ((100_000.0 * scale) as usize).max(16);
    vec![
        (
            "ordinary sphere, r 1 at the origin".into(),
            sphere(Vec3::ZERO, 1.0, rings, 2 * rings),
        ),
        (
            "collapsed sphere, r 1e-30 at (1000, 1000, 1000)".into(),
            sphere(Vec3::splat(1000.0), 1e-30, rings, 2 * rings),
        ),
        (
            "collapsed sphere, r 1e-6 at (0.5, 0.5, -3)".into(),
            sphere(Vec3::new(0.5, 0.5, -3.0), 1e-6, rings, 2 * rings),
        ),
        (
            "collapsed sphere, r 1e-4 at (1e6, 1e6, 1e6), below f32's spacing there".into(),
            sphere(Vec3::splat(1e6), 1e-4, rings, 2 * rings),
        ),
        (
            format!("{n} overlapping triangles through one point"),
            overlapping(n),
        ),
        (
            format!("{n} copies of one triangle"),
            vec![[Vec3::ZERO, Vec3::X, Vec3::Y]; n],
        ),
    ]
}

/// Builds both BVHs over each case; seconds each.
fn build_seconds(tris: &[[Vec3; 3]]) -> f64 {
    let start = Instant::now();
    let bvh = Bvh::build(tris);
    let wide = WideBvh::build(tris);
    assert!(bvh.is_some() && wide.is_some(), "non-empty cases build");
    start.elapsed().as_secs_f64()
}

/// The table: each case's build against an ordinary mesh's per triangle.
pub fn hostile_builds(scale: f64) -> Table {
    let mut t = Table::new(
        &format!(
            "BVH builds on hostile geometry (both BVHs; budget {BUDGET}x an ordinary \
             mesh per triangle)"
        ),
        &["case", "triangles", "build", "vs ordinary", "within budget"],
    );
    let cases = cases(scale);
    let mut ordinary = None;
    for (name, tris) in &cases {
        let seconds = build_seconds(tris);
        let per = seconds / tris.len() as f64;
        let base = *ordinary.get_or_insert(per);
        let ratio = per / base;
        t.row(vec![
            name.clone(),
            tris.len().to_string(),
            format_seconds(seconds),
            format!("{}x", format_number(ratio)),
            if ratio <= BUDGET { "yes" } else { "NO" }.into(),
        ]);
    }
    t
}
