//! Drawing a scene's edges: clip each edge at the near plane, project its
//! two ends through the pinhole camera, and draw the line between them.
//! No triangle is filled yet: that is chapter 2.

use glam::{Vec2, Vec3};

use super::camera::{project_pinhole, Camera};
use crate::core::draw::{self, Band};
use crate::core::film::Film;
use crate::scene::mesh::Mesh;
use crate::scene::Material;

/// How far in front of the pinhole an edge must be to be drawn. Edges that
/// cross this plane are cut there, so their visible part is kept.
pub const NEAR: f32 = 1e-3;

/// Keeps the part of the camera-space segment a→b that lies in front of the
/// near plane z = -near; `None` if nothing does.
// ANCHOR: clip_near
pub fn clip_to_near(a: Vec3, b: Vec3, near: f32) -> Option<(Vec3, Vec3)> {
    // Signed distances past the near plane: ≤ 0 means in front of it.
    let (da, db) = (a.z + near, b.z + near);
    let cut = |from: Vec3, to: Vec3, d_from: f32, d_to: f32| {
        // The point where the distance is zero, placed exactly on the plane.
        let p = from.lerp(to, d_from / (d_from - d_to));
        Vec3::new(p.x, p.y, -near)
    };
    match (da <= 0.0, db <= 0.0) {
        (true, true) => Some((a, b)),
        (true, false) => Some((a, cut(a, b, da, db))),
        (false, true) => Some((cut(a, b, da, db), b)),
        // Both behind, or a NaN made both tests false: nothing to draw.
        (false, false) => None,
    }
}
// ANCHOR_END: clip_near

/// An edge as it appears on the image, after clipping at the near plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProjectedEdge {
    /// Raster position of the first end.
    pub a: Vec2,
    /// Raster position of the second end.
    pub b: Vec2,
    /// Depth (-z) of each end.
    pub depth: [f32; 2],
    /// Whether the near plane cut the edge.
    pub clipped: bool,
}

/// Clips a camera-space edge at the near plane and projects what is left;
/// `None` when nothing is in front of the camera or the ends are not finite.
// ANCHOR: project_edge
pub fn project_edge(cam: &Camera, a: Vec3, b: Vec3) -> Option<ProjectedEdge> {
    let (ca, cb) = clip_to_near(a, b, NEAR)?;
    let (ua, ub) = (project_pinhole(ca)?, project_pinhole(cb)?);
    Some(ProjectedEdge {
        a: cam.raster_from_image_plane(ua),
        b: cam.raster_from_image_plane(ub),
        depth: [-ca.z, -cb.z],
        clipped: (ca, cb) != (a, b),
    })
}
// ANCHOR_END: project_edge

/// Counts from drawing a scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawStats {
    /// Edges drawn whole.
    pub edges_whole: usize,
    /// Edges cut at the near plane and drawn in part.
    pub edges_clipped: usize,
    /// Edges entirely behind the near plane.
    pub edges_culled: usize,
    /// Vertices drawn as dots.
    pub vertices_drawn: usize,
    /// Vertices on or behind the camera plane.
    pub vertices_culled: usize,
}

/// The colour a material gets in a wireframe: its hue at full brightness.
fn wire_color(m: &Material) -> Vec3 {
    if m.is_emissive() {
        return Vec3::new(1.0, 0.95, 0.6);
    }
    let c = m.reflectance;
    if c.max_element() > 0.0 {
        c / c.max_element() * 0.9
    } else {
        Vec3::splat(0.3)
    }
}

/// Draws `meshes` as seen by `camera`: the three [views](crate::ch1_projection::stage::VIEWS) in
/// order, each holding rows `rows` of the image (all of them:
/// `0..camera.height`).
// ANCHOR: draw_scene
pub fn draw_scene(
    camera: &Camera,
    meshes: &[Mesh],
    materials: &[Material],
    rows: std::ops::Range<u32>,
) -> (Vec<Film>, DrawStats) {
    let (w, h) = (camera.width, camera.height);
    let mut films: Vec<Band> = (0..3).map(|_| Band::new(w, rows.clone(), h)).collect();
    let mut stats = DrawStats::default();
    // Every vertex to camera space once; depth range for shading and dots.
    let cam: Vec<Vec<Vec3>> = meshes
        .iter()
        .map(|m| m.positions.iter().map(|p| camera.to_camera(*p)).collect())
        .collect();
    let depths = cam.iter().flatten().map(|p| -p.z).filter(|d| *d >= NEAR);
    let z_min = depths.clone().fold(f32::INFINITY, f32::min);
    let z_max = depths.fold(0.0, f32::max).max(z_min);
    // Brightness proportional to 1/z, which is linear along a projected edge.
    let shade = |z: f32| {
        let s = (1.0 / z - 1.0 / z_max) / (1.0 / z_min - 1.0 / z_max);
        Vec3::splat(0.15 + 0.85 * if s.is_finite() { s } else { 1.0 })
    };

    for (mesh, pts) in meshes.iter().zip(&cam) {
        let color = wire_color(&materials[mesh.material]);
        for [i, j] in mesh.edges() {
            let Some(e) = project_edge(camera, pts[i as usize], pts[j as usize]) else {
                stats.edges_culled += 1;
                continue;
            };
            if e.clipped {
                stats.edges_clipped += 1;
            } else {
                stats.edges_whole += 1;
            }
            draw::line(&mut films[0], e.a, e.b, color, color);
            draw::line(
                &mut films[1],
                e.a,
                e.b,
                shade(e.depth[0]),
                shade(e.depth[1]),
            );
        }
        // Farther is smaller: a dot's radius falls off as 1/depth.
        for p in pts {
            let raster = project_pinhole(*p).map(|uv| camera.raster_from_image_plane(uv));
            match raster.filter(|_| -p.z >= NEAR) {
                Some(r) => {
                    let radius = (2.5 * z_min / -p.z).clamp(0.6, 2.5);
                    draw::dot(&mut films[0], r, radius, color);
                    draw::dot(&mut films[2], r, radius * 1.4, color.max(Vec3::splat(0.3)));
                    stats.vertices_drawn += 1;
                }
                None => stats.vertices_culled += 1,
            }
        }
    }
    (films.into_iter().map(|band| band.film).collect(), stats)
}
// ANCHOR_END: draw_scene
