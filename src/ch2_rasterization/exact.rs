//! The exact reference for anti-aliasing: how much of each pixel a triangle
//! covers, by clipping the triangle to the pixel's square in f64 and taking
//! the area of what is left (the shoelace formula).

use glam::DVec2;

/// Area of a polygon (shoelace formula), positive when counter-clockwise in
/// a y-up frame.
pub fn polygon_area(p: &[DVec2]) -> f64 {
    let n = p.len();
    (0..n).map(|i| p[i].perp_dot(p[(i + 1) % n])).sum::<f64>() / 2.0
}

/// Keeps the part of a polygon where `inside(v) >= 0`; `inside` must be
/// affine (a half-plane).
fn clip_half_plane(p: &[DVec2], inside: impl Fn(DVec2) -> f64) -> Vec<DVec2> {
    let mut out = Vec::with_capacity(p.len() + 1);
    for i in 0..p.len() {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        let (da, db) = (inside(a), inside(b));
        if da >= 0.0 {
            out.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            out.push(a.lerp(b, da / (da - db)));
        }
    }
    out
}

/// The exact area of pixel (x, y), the unit square [x, x+1] x [y, y+1],
/// covered by the triangle `tri` (raster coordinates).
// ANCHOR: pixel_coverage
pub fn pixel_coverage(tri: &[DVec2; 3], x: u32, y: u32) -> f64 {
    let (x0, y0) = (x as f64, y as f64);
    let mut p = tri.to_vec();
    p = clip_half_plane(&p, |v| v.x - x0);
    p = clip_half_plane(&p, |v| x0 + 1.0 - v.x);
    p = clip_half_plane(&p, |v| v.y - y0);
    p = clip_half_plane(&p, |v| y0 + 1.0 - v.y);
    if p.len() < 3 {
        0.0
    } else {
        polygon_area(&p).abs()
    }
}
// ANCHOR_END: pixel_coverage

/// The exact coverage image of triangles that do not overlap: per pixel,
/// the sum of the covered areas (only over each triangle's bounding box).
pub fn coverage_image(tris: &[[DVec2; 3]], width: u32, height: u32) -> Vec<f64> {
    let mut img = vec![0.0; (width * height) as usize];
    for t in tris {
        let lo = t[0].min(t[1]).min(t[2]).floor().max(DVec2::ZERO);
        let hi = t[0].max(t[1]).max(t[2]).ceil();
        let (x1, y1) = ((hi.x as u32).min(width), (hi.y as u32).min(height));
        for y in lo.y as u32..y1 {
            for x in lo.x as u32..x1 {
                img[(y * width + x) as usize] += pixel_coverage(t, x, y);
            }
        }
    }
    img
}
