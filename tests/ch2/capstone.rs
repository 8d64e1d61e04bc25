//! Chapter 2's capstone: rasterizing a triangle. A solution written from
//! the lecture and the book (perspective-correct) passes; the wrong fill
//! rule and a missing depth test fail and name their mistake.

use glam::{Vec2, Vec3};
use raystep::grading::exercises::ch2;

/// The 2D cross product (b − a) × (p − a).
fn edge(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)
}

/// The capstone as a student writes it from the lecture, with the rule
/// for samples on an edge, and whether to test depth, as parameters.
#[allow(clippy::too_many_arguments)]
fn lecture(
    v: [Vec3; 3],
    colors: [Vec3; 3],
    width: u32,
    height: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
    on_edge: fn(Vec2, Vec2) -> bool,
    depth_test: bool,
) {
    let (mut v, mut colors) = (v, colors);
    let area = edge(v[0].truncate(), v[1].truncate(), v[2].truncate());
    if area == 0.0 || !v.iter().all(|p| p.is_finite()) {
        return;
    }
    if area < 0.0 {
        v.swap(1, 2);
        colors.swap(1, 2);
    }
    let [a, b, c] = v.map(|p| p.truncate());
    let lo = a.min(b).min(c).floor().max(Vec2::ZERO);
    let hi = a
        .max(b)
        .max(c)
        .ceil()
        .min(Vec2::new(width as f32, height as f32));
    for y in lo.y as u32..hi.y as u32 {
        for x in lo.x as u32..hi.x as u32 {
            let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let w = [edge(b, c, p), edge(c, a, p), edge(a, b, p)];
            let edges = [(b, c), (c, a), (a, b)];
            if !(0..3).all(|k| w[k] > 0.0 || (w[k] == 0.0 && on_edge(edges[k].0, edges[k].1))) {
                continue;
            }
            // Perspective-correct: 1/z and colour/z are linear on the screen.
            let q = Vec3::new(w[0] / v[0].z, w[1] / v[1].z, w[2] / v[2].z);
            let phi = q / (q.x + q.y + q.z);
            let z = phi.x * v[0].z + phi.y * v[1].z + phi.z * v[2].z;
            let i = (y * width + x) as usize;
            if !depth_test || z < depth[i] {
                depth[i] = z;
                image[i] = colors[0] * phi.x + colors[1] * phi.y + colors[2] * phi.z;
            }
        }
    }
}

fn top_left(a: Vec2, b: Vec2) -> bool {
    b.y < a.y || (b.y == a.y && b.x > a.x)
}

#[test]
fn the_raster_capstone_passes_from_the_lecture_and_catches_mistakes() {
    let check =
        ch2::check_rasterize_triangle(|v, c, w, h, d, i| lecture(v, c, w, h, d, i, top_left, true));
    assert!(check.passed(), "{}", check.detail);
    // Every sample on an edge counted: shared edges drawn twice.
    let check = ch2::check_rasterize_triangle(|v, c, w, h, d, i| {
        lecture(v, c, w, h, d, i, |_, _| true, true)
    });
    assert!(!check.passed(), "{}", check.detail);
    assert_eq!(check.symptom, Some(ch2::TOP_LEFT), "{}", check.detail);
    // None counted: holes along shared edges.
    let check = ch2::check_rasterize_triangle(|v, c, w, h, d, i| {
        lecture(v, c, w, h, d, i, |_, _| false, true)
    });
    assert!(!check.passed(), "{}", check.detail);
    // The bottom-right rule is as wrong as none.
    let check = ch2::check_rasterize_triangle(|v, c, w, h, d, i| {
        lecture(v, c, w, h, d, i, |a, b| !top_left(a, b), true)
    });
    assert!(!check.passed(), "{}", check.detail);
    // No depth test: the last triangle drawn wins.
    let check = ch2::check_rasterize_triangle(|v, c, w, h, d, i| {
        lecture(v, c, w, h, d, i, top_left, false)
    });
    assert!(!check.passed(), "{}", check.detail);
    assert_eq!(check.symptom, Some(ch2::DEPTH_TEST), "{}", check.detail);
}
