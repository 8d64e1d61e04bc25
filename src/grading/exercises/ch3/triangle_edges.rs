//! Exercise 3.3's rays just beside a triangle's edges: outside is a
//! miss, by however little.

use glam::{DVec3, Vec3};

use crate::ch3_ray_triangle::triangle::intersect_f64;
use crate::exercises::draws::Draws;

/// A ray (o, d), a triangle, and the answer's (t, u, v).
type Case = (Vec3, Vec3, [Vec3; 3], Option<(f32, f32, f32)>);

/// Straight down at drawn triangles in the plane z = 0, 3·10⁻⁴ to
/// 3·10⁻³ of the way outside or inside one of their edges (no padding
/// against cracks).
pub(super) fn near_edges(draws: &mut Draws) -> Vec<Case> {
    let mut cases = Vec::new();
    for _ in 0..draws.count(20, 60) {
        draws.next_case();
        let scale = draws.triangle_scale();
        let t = [0, 1, 2].map(|_| {
            let q = draws.in_cube() * scale;
            Vec3::new(q.x, q.y, 0.0)
        });
        let area = (t[1] - t[0]).cross(t[2] - t[0]).length();
        if area < 0.05 * scale * scale {
            continue;
        }
        let (s, m) = (
            draws.range(0.1, 0.9),
            draws.sign() * draws.decades(-3.5, -2.5),
        );
        let (u, v) = match draws.count(0, 2) {
            0 => (-m, s),
            1 => (s, -m),
            _ => (s * (1.0 + m), (1.0 - s) * (1.0 + m)),
        };
        let p = t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
        let o = Vec3::new(p.x, p.y, scale);
        let want = intersect_f64(o.as_dvec3(), DVec3::NEG_Z, t.map(|q| q.as_dvec3()));
        cases.push((
            o,
            -Vec3::Z,
            t,
            want.map(|(t, u, v)| (t as f32, u as f32, v as f32)),
        ));
    }
    cases
}
