//! The BVH builds on the worst shapes we could construct, as a benchmark
//! (`ch3 --bench hostile`): collapsed spheres (to a point, or flat along
//! one axis, away from the origin), a fan-triangulated convex polygon,
//! slivers, zero-area triangles, overlapping triangles and copies of one
//! triangle, each built into both BVHs at 10⁴, 10⁵ and 10⁶ triangles. The
//! table gives each case's growth exponent from 10⁵ to 10⁶ (1 for n, about
//! 1.1 for n log n, 2 for a quadratic build) and its time per triangle
//! against an ordinary mesh, with a budget of [`BUDGET`] times that. The
//! tests check only that every case is here and builds (speed lives in
//! benchmarks, not in timed tests).

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

/// `n` triangles fanned from the first corner of a convex polygon of
/// `n + 2` corners on the unit circle (what the OBJ loader makes of one
/// `f` line with that many corners).
pub fn fan(n: usize) -> Vec<[Vec3; 3]> {
    let corner = |k: usize| {
        let a = std::f32::consts::TAU * k as f32 / (n + 2) as f32;
        Vec3::new(a.cos(), a.sin(), 0.0)
    };
    (1..=n)
        .map(|k| [corner(0), corner(k), corner(k + 1)])
        .collect()
}

/// `n` needles ten units long and 1e-6 wide, side by side 2e-6 apart.
pub fn slivers(n: usize) -> Vec<[Vec3; 3]> {
    (0..n)
        .map(|k| {
            let y = k as f32 * 2e-6;
            [
                Vec3::new(0.0, y, 0.0),
                Vec3::new(10.0, y, 0.0),
                Vec3::new(10.0, y + 1e-6, 0.0),
            ]
        })
        .collect()
}

/// `n` zero-area triangles: three points on a random line each.
pub fn zero_area(n: usize) -> Vec<[Vec3; 3]> {
    (0..n as u64)
        .map(|i| {
            let u = |d| random(11, 0, i, d) * 2.0 - 1.0;
            let a = Vec3::new(u(0), u(1), u(2));
            let d = Vec3::new(u(3), u(4), u(5));
            [a, a + d, a + 2.0 * d]
        })
        .collect()
}

/// A sphere of about `n` triangles with one axis multiplied by `squash`.
fn squashed(n: usize, centre: Vec3, axis: usize, squash: f32) -> Vec<[Vec3; 3]> {
    let rings = ((n as f64 / 4.0).sqrt() as u32).max(2);
    let mut scale = Vec3::ONE;
    scale[axis] = squash;
    sphere(Vec3::ZERO, 1.0, rings, 2 * rings)
        .into_iter()
        .map(|t| t.map(|p| p * scale + centre))
        .collect()
}

/// The cases at about `n` triangles each: (name, triangles). The first is
/// the ordinary mesh the others are measured against.
pub fn cases(n: usize) -> Vec<(String, Vec<[Vec3; 3]>)> {
    let rings = ((n as f64 / 4.0).sqrt() as u32).max(2);
    let round = |c: Vec3, r: f32| sphere(c, r, rings, 2 * rings);
    vec![
        (
            "ordinary sphere, r 1 at the origin".into(),
            round(Vec3::ZERO, 1.0),
        ),
        (
            "sphere collapsed to a point, r 1e-30 at (1000, 1000, 1000)".into(),
            round(Vec3::splat(1000.0), 1e-30),
        ),
        (
            "sphere below f32's spacing, r 1e-4 at (1e6, 1e6, 1e6)".into(),
            round(Vec3::splat(1e6), 1e-4),
        ),
        (
            "sphere flat in x (x 1e-38) at (0, 1000, 1000)".into(),
            squashed(n, Vec3::new(0.0, 1000.0, 1000.0), 0, 1e-38),
        ),
        (
            "sphere flat in z (z 1e-20) at (-3e4, 7, 2e5)".into(),
            squashed(n, Vec3::new(-3e4, 7.0, 2e5), 2, 1e-20),
        ),
        ("convex polygon, fan-triangulated".into(), fan(n)),
        ("slivers 1e-6 wide".into(), slivers(n)),
        ("zero-area triangles".into(), zero_area(n)),
        (
            "overlapping triangles through one point".into(),
            overlapping(n),
        ),
        (
            "copies of one triangle".into(),
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

/// The table: each case built at every size in `sizes` (ascending), its
/// growth exponent between the last two, and its time per triangle at the
/// largest against the ordinary mesh's.
pub fn hostile_builds(sizes: &[usize]) -> Table {
    let mut columns: Vec<String> = vec!["case".into()];
    columns.extend(
        sizes
            .iter()
            .map(|n| format!("build at {}", format_number(*n as f64))),
    );
    columns.extend([
        "growth exponent".into(),
        "vs ordinary".into(),
        "within budget".into(),
    ]);
    let columns: Vec<&str> = columns.iter().map(String::as_str).collect();
    let mut t = Table::new(
        &format!(
            "BVH builds on the worst shapes (both BVHs; growth exponent of time in n between \
             the two largest sizes; budget {BUDGET}x an ordinary mesh per triangle)"
        ),
        &columns,
    );
    let per_size: Vec<Vec<(String, usize, f64)>> = sizes
        .iter()
        .map(|&n| {
            cases(n)
                .into_iter()
                .map(|(name, tris)| (name, tris.len(), build_seconds(&tris)))
                .collect()
        })
        .collect();
    let largest = per_size.last().expect("at least one size");
    let ordinary = largest[0].2 / largest[0].1 as f64;
    for (c, (name, count, seconds)) in largest.iter().enumerate() {
        let mut row = vec![name.clone()];
        row.extend(per_size.iter().map(|cases| format_seconds(cases[c].2)));
        let exponent = match per_size.len() {
            1 => "-".to_string(),
            k => {
                let (n0, t0) = (per_size[k - 2][c].1 as f64, per_size[k - 2][c].2);
                format_number((seconds / t0).ln() / (*count as f64 / n0).ln())
            }
        };
        let ratio = seconds / *count as f64 / ordinary;
        row.extend([
            exponent,
            format!("{}x", format_number(ratio)),
            if ratio <= BUDGET { "yes" } else { "NO" }.into(),
        ]);
        t.row(row);
    }
    t
}
