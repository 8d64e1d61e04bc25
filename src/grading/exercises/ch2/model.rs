//! The capstone's reference with one clause changed at a time: how a
//! rasterizer with a given mistake draws. The check compares a failing
//! candidate with these to name its mistake (a picture that agrees with
//! "samples at the pixel corners" better than with the reference is
//! shifted by half a pixel), and a test holds that the model with no
//! mistake draws exactly what [`rasterize_triangle`] draws.
//!
//! [`rasterize_triangle`]: crate::ch2_rasterization::triangle::rasterize_triangle

use glam::{Vec2, Vec3};

/// What to do with a sample exactly on an edge (edge function 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    /// The top-left rule (the contract).
    TopLeft,
    /// Every such sample is inside (shared edges drawn twice).
    All,
    /// None is (cracks along shared edges).
    NoEdge,
}

/// A rasterizer: the reference, or the reference with one mistake.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Model {
    /// Where in its pixel the sample lies (0.5: the centre).
    pub offset: f32,
    /// Samples exactly on an edge.
    pub rule: Rule,
    /// Colours by screen-space barycentrics (the affine mistake).
    pub affine_colour: bool,
    /// Depth as Σ φ·z (screen-space barycentrics) instead of 1/Σ(φ/z).
    pub affine_depth: bool,
    /// Whether the colours are swapped with the corners.
    pub swap_colours: bool,
}

impl Model {
    /// The contract.
    pub const REFERENCE: Model = Model {
        offset: 0.5,
        rule: Rule::TopLeft,
        affine_colour: false,
        affine_depth: false,
        swap_colours: true,
    };

    /// Draws one triangle as this model does (same arguments as the
    /// capstone's), with the depth test of the contract.
    pub fn draw(
        &self,
        v: [Vec3; 3],
        colors: [Vec3; 3],
        width: u32,
        height: u32,
        depth: &mut [f32],
        image: &mut [Vec3],
    ) {
        let e = |a: Vec2, b: Vec2, p: Vec2| (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        let (mut v, mut colors) = (v, colors);
        let area = e(v[0].truncate(), v[1].truncate(), v[2].truncate());
        if area == 0.0 || !area.is_finite() {
            return;
        }
        if area < 0.0 {
            v.swap(1, 2);
            if self.swap_colours {
                colors.swap(1, 2);
            }
        }
        let area = area.abs();
        let [a, b, c] = v.map(|p| p.truncate());
        let edges = [(b, c), (c, a), (a, b)];
        let top_left = |s: Vec2, t: Vec2| t.y < s.y || (t.y == s.y && t.x > s.x);
        let o = self.offset;
        let (lo, hi) = (a.min(b).min(c), a.max(b).max(c));
        let x0 = (lo.x - o).ceil().max(0.0) as u32;
        let y0 = (lo.y - o).ceil().max(0.0) as u32;
        let x1 = ((hi.x - o).floor() + 1.0).clamp(0.0, width as f32) as u32;
        let y1 = ((hi.y - o).floor() + 1.0).clamp(0.0, height as f32) as u32;
        let inv_z = Vec3::new(1.0 / v[0].z, 1.0 / v[1].z, 1.0 / v[2].z);
        for y in y0..y1 {
            for x in x0..x1 {
                let p = Vec2::new(x as f32 + o, y as f32 + o);
                let w = edges.map(|(s, t)| e(s, t, p));
                let inside = (0..3).all(|k| {
                    let on_edge = match self.rule {
                        Rule::TopLeft => top_left(edges[k].0, edges[k].1),
                        Rule::All => true,
                        Rule::NoEdge => false,
                    };
                    w[k] > 0.0 || (w[k] == 0.0 && on_edge)
                });
                if !inside {
                    continue;
                }
                let phi = Vec3::from(w) / area;
                let perspective_z = 1.0 / phi.dot(inv_z);
                let z = if self.affine_depth {
                    phi.dot(Vec3::new(v[0].z, v[1].z, v[2].z))
                } else {
                    perspective_z
                };
                let weight = if self.affine_colour {
                    phi
                } else {
                    phi * inv_z * perspective_z
                };
                let i = (y * width + x) as usize;
                if z < depth[i] {
                    depth[i] = z;
                    image[i] = colors[0] * weight.x + colors[1] * weight.y + colors[2] * weight.z;
                }
            }
        }
    }
}
