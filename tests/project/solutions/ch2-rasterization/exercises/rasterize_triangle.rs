//! A student's solution of capstone 2 (the grader's tests run it).

use glam::{Vec2, Vec3};

fn edge(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)
}

/// A top edge (horizontal, inside below) or a left edge, for a triangle
/// whose edge functions are positive inside (raster y down).
fn top_left(a: Vec2, b: Vec2) -> bool {
    b.y < a.y || (b.y == a.y && b.x > a.x)
}

/// Draws the triangle `v` with vertex colours `colors` into `image`,
/// with the depth test against `depth`.
pub fn rasterize_triangle(
    v: [Vec3; 3],
    colors: [Vec3; 3],
    width: u32,
    height: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
) {
    let [mut p0, mut p1, mut p2] = v;
    let [c0, mut c1, mut c2] = colors;
    let area = edge(p0.truncate(), p1.truncate(), p2.truncate());
    if area == 0.0 || !area.is_finite() || ![p0, p1, p2].iter().all(|p| p.is_finite()) {
        return;
    }
    if area < 0.0 {
        std::mem::swap(&mut p1, &mut p2);
        std::mem::swap(&mut c1, &mut c2);
    }
    let area = area.abs();
    let (a, b, c) = (p0.truncate(), p1.truncate(), p2.truncate());
    let min = a.min(b).min(c).max(Vec2::ZERO);
    let max = a.max(b).max(c).min(Vec2::new(width as f32, height as f32));
    for y in min.y.floor() as u32..max.y.ceil() as u32 {
        for x in min.x.floor() as u32..max.x.ceil() as u32 {
            let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let w = [(b, c), (c, a), (a, b)].map(|(s, t)| (edge(s, t, p), top_left(s, t)));
            if !w.iter().all(|&(e, tl)| e > 0.0 || (e == 0.0 && tl)) {
                continue;
            }
            // Perspective-correct: φ/z is linear on the screen.
            let q = Vec3::new(w[0].0 / p0.z, w[1].0 / p1.z, w[2].0 / p2.z) / area;
            let inv_z = q.x + q.y + q.z;
            let z = 1.0 / inv_z;
            let i = (y * width + x) as usize;
            if z < depth[i] {
                depth[i] = z;
                image[i] = (c0 * q.x + c1 * q.y + c2 * q.z) * z;
            }
        }
    }
}
