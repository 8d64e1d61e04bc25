//! One triangle, start to finish, in `f32` as the book writes it (exercise
//! 2.4): the bounding box clipped to the image, one sample at each pixel
//! centre, three edge functions with the top-left rule, the depth test,
//! and perspective-correct colours. The fast rasterizer ([`super::coverage`])
//! does the same in fixed point, many triangles at once.

use glam::{Vec2, Vec3};

use super::edge::edge_function;

/// Draws the triangle `v` (raster x and y, y down, and the depth z > 0 of
/// each vertex: its distance in front of the camera) with vertex colours
/// `colors` into `image`, testing and updating `depth` (`width` × `height`,
/// index y·width + x). A sample is drawn when it is nearer (z smaller)
/// than what `depth` holds; it then stores its depth.
// ANCHOR: rasterize_triangle
// ANCHOR: rasterize_triangle_area
pub fn rasterize_triangle(
    v: [Vec3; 3],
    colors: [Vec3; 3],
    width: u32,
    height: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
) {
    let (mut v, mut colors) = (v, colors);
    let area = edge_function(v[0].truncate(), v[1].truncate(), v[2].truncate());
    // No area, or a corner that is not finite (its depth too): nothing
    // to draw.
    if area == 0.0 || !area.is_finite() || !v.iter().all(|p| p.is_finite()) {
        return;
    }
    // Either winding: swap two corners, with their colours, so that the
    // edge functions are positive inside.
    if area < 0.0 {
        v.swap(1, 2);
        colors.swap(1, 2);
    }
    // ANCHOR_END: rasterize_triangle_area
    // ANCHOR: rasterize_triangle_box
    let area = area.abs();
    let [a, b, c] = v.map(|p| p.truncate());
    let edges = [(b, c), (c, a), (a, b)];
    // A sample on an edge counts for a top edge or a left edge only.
    let top_left = |s: Vec2, t: Vec2| t.y < s.y || (t.y == s.y && t.x > s.x);
    // The pixels whose centres can be inside, clipped to the image.
    let (lo, hi) = (a.min(b).min(c), a.max(b).max(c));
    let x0 = (lo.x - 0.5).ceil().max(0.0) as u32;
    let y0 = (lo.y - 0.5).ceil().max(0.0) as u32;
    let x1 = ((hi.x - 0.5).floor() + 1.0).clamp(0.0, width as f32) as u32;
    let y1 = ((hi.y - 0.5).floor() + 1.0).clamp(0.0, height as f32) as u32;
    // 1/z is linear on the screen, and so is colour/z.
    let inv_z = Vec3::new(1.0 / v[0].z, 1.0 / v[1].z, 1.0 / v[2].z);
    // ANCHOR_END: rasterize_triangle_box
    // ANCHOR: rasterize_triangle_loop
    for y in y0..y1 {
        for x in x0..x1 {
            let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let w = edges.map(|(s, t)| edge_function(s, t, p));
            let inside =
                (0..3).all(|k| w[k] > 0.0 || (w[k] == 0.0 && top_left(edges[k].0, edges[k].1)));
            if !inside {
                continue;
            }
            // Screen-space barycentrics, then the depth and colour there.
            let phi = Vec3::from(w) / area;
            let z = 1.0 / phi.dot(inv_z);
            let i = (y * width + x) as usize;
            if z < depth[i] {
                depth[i] = z;
                let weight = phi * inv_z * z;
                image[i] = colors[0] * weight.x + colors[1] * weight.y + colors[2] * weight.z;
            }
        }
    }
}
// ANCHOR_END: rasterize_triangle_loop
// ANCHOR_END: rasterize_triangle
