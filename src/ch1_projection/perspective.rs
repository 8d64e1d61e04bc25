//! What perspective does to the picture: farther is smaller, and parallel
//! lines meet at a vanishing point.

use glam::{Vec2, Vec3};

use super::camera::{project_pinhole, Camera};
use super::wireframe::project_edge;
use crate::core::format::format_number;
use crate::core::report::Table;
use crate::scene::mesh::Mesh;

/// The image height of an upright stick 1 unit tall, straight ahead at
/// growing distances: it halves each time the distance doubles.
pub fn farther_is_smaller(cam: &Camera) -> Table {
    let mut t = Table::new(
        "Farther is smaller: a 1-unit upright stick straight ahead",
        &["distance", "height (px)", "height x distance"],
    );
    let d = &cam.desc;
    let forward = (d.target - d.eye).normalize();
    let up = forward.cross(d.up).cross(forward).normalize() * -1.0;
    for k in 0..6 {
        let dist = 2f64.powi(k);
        let centre = d.eye + forward * dist;
        let (a, b) = (
            cam.project((centre - up * 0.5).as_vec3()),
            cam.project((centre + up * 0.5).as_vec3()),
        );
        let h = match (a, b) {
            (Some(a), Some(b)) => a.distance(b) as f64,
            _ => f64::NAN,
        };
        t.row(vec![
            format_number(dist),
            format_number(h),
            format_number(h * dist),
        ]);
    }
    t
}

/// A family of parallel edges and where their images meet.
#[derive(Clone, Debug, PartialEq)]
pub struct VanishingPoint {
    /// Their common direction in world space.
    pub direction: Vec3,
    /// How many edges share it.
    pub lines: usize,
    /// Where the direction itself projects: the point at infinity's image.
    pub analytic: Vec2,
    /// The least-squares meeting point of the drawn edges, if they are not
    /// all one line.
    pub measured: Option<Vec2>,
    /// Root-mean-square distance of the drawn edges from `measured`.
    pub rms_miss: f32,
}

/// The vanishing points of the three largest families of parallel edges
/// that are not parallel to the image plane.
pub fn vanishing_points(cam: &Camera, meshes: &[Mesh]) -> Vec<VanishingPoint> {
    use std::collections::BTreeMap;
    // Quantised direction → (direction, the edges along it).
    type Family = (Vec3, Vec<(Vec3, Vec3)>);
    let mut families: BTreeMap<[i32; 3], Family> = BTreeMap::new();
    for m in meshes {
        for [i, j] in m.edges() {
            let (a, b) = (m.positions[i as usize], m.positions[j as usize]);
            let Some(mut dir) = (b - a).try_normalize() else {
                continue;
            };
            // One sign per direction: the first non-zero component positive.
            let first = dir
                .to_array()
                .into_iter()
                .find(|c| c.abs() > 1e-4)
                .unwrap_or(1.0);
            if first < 0.0 {
                dir = -dir;
            }
            let key = (dir * 1000.0).round().as_ivec3().to_array();
            families
                .entry(key)
                .or_insert((dir, Vec::new()))
                .1
                .push((a, b));
        }
    }
    let mut out: Vec<VanishingPoint> = families
        .into_values()
        .filter(|(_, edges)| edges.len() >= 3)
        .filter_map(|(direction, edges)| {
            let mut dc = cam.camera_from_world.transform_vector3(direction);
            if dc.z.abs() < 0.05 {
                return None; // parallel to the image plane: they meet nowhere
            }
            if dc.z > 0.0 {
                dc = -dc;
            }
            let analytic = cam.raster_from_image_plane(project_pinhole(dc)?);
            // Least squares: the point closest to every drawn line.
            let lines: Vec<(glam::DVec2, glam::DVec2)> = edges
                .iter()
                .filter_map(|(a, b)| {
                    let e = project_edge(cam, cam.to_camera(*a), cam.to_camera(*b))?;
                    let t = (e.b - e.a).as_dvec2().try_normalize()?;
                    Some((e.a.as_dvec2(), t.perp()))
                })
                .collect();
            let (mut a, mut rhs) = (glam::DMat2::ZERO, glam::DVec2::ZERO);
            for (p, n) in &lines {
                let nn = glam::DMat2::from_cols(*n * n.x, *n * n.y);
                a += nn;
                rhs += nn * *p;
            }
            let measured = (a.determinant().abs() > 1e-9 * a.col(0).length_squared().max(1.0))
                .then(|| a.inverse() * rhs);
            let rms_miss = measured
                .map(|x| {
                    let s: f64 = lines.iter().map(|(p, n)| n.dot(x - *p).powi(2)).sum();
                    (s / lines.len().max(1) as f64).sqrt() as f32
                })
                .unwrap_or(0.0);
            Some(VanishingPoint {
                direction,
                lines: edges.len(),
                analytic,
                measured: measured.map(|m| m.as_vec2()),
                rms_miss,
            })
        })
        .collect();
    out.sort_by_key(|v| std::cmp::Reverse(v.lines));
    out.truncate(3);
    out
}
