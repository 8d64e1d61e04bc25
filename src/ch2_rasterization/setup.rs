//! Triangle setup: from world-space meshes to screen triangles the coverage
//! loop can use. The lecture's pipeline, one step per block: transform every
//! vertex to camera space, clip at the near plane, project to raster
//! coordinates, clip to the guard band, snap to 1/256 pixel, cull back faces
//! if asked, and orient every triangle so its inside has positive edge
//! functions.

use glam::{DVec2, DVec3, I64Vec2, Vec3};
use rayon::prelude::*;

use super::clip::{clip_guard_band, clip_near, Attributes, ClipVertex};
use super::edge::{edge_fixed, to_fixed, SUBPIXEL};
use crate::ch1_projection::camera::Camera;
use crate::ch1_projection::wireframe::NEAR;
use crate::scene::mesh::Mesh;
use crate::scene::Material;

/// A triangle on the screen, ready for coverage and interpolation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScreenTriangle {
    /// Vertices in fixed point (1/256 pixel), ordered so that the doubled
    /// area `area` is positive.
    pub v: [I64Vec2; 3],
    /// Doubled area in 1/65536 pixel² (> 0).
    pub area: i64,
    /// 1/w of each vertex, w being the depth in front of the camera.
    pub inv_w: [f64; 3],
    /// Attribute values at each vertex (see [`Attributes`]).
    pub attr: [Attributes; 3],
    /// World-space unit normal of the original triangle (right-hand rule).
    pub normal: Vec3,
    /// Index of the original triangle, counting through every mesh.
    pub id: u32,
    /// Whether the original triangle faces the camera.
    pub front: bool,
    /// Pixels whose samples may be covered: [x0, y0, x1, y1], inclusive.
    pub bbox: [u32; 4],
}

/// What setup did with the scene's triangles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SetupStats {
    /// Triangles in the scene.
    pub triangles: usize,
    /// Triangles cut by the near plane (their front part kept).
    pub clipped_near: usize,
    /// Triangles entirely behind the near plane.
    pub behind: usize,
    /// Triangles cut by the guard band.
    pub clipped_guard: usize,
    /// Back faces dropped (only with culling on).
    pub culled_back: usize,
    /// Pieces with zero area after snapping (they cover nothing).
    pub zero_area: usize,
    /// Pieces entirely off screen.
    pub off_screen: usize,
    /// Triangles with a NaN or infinite coordinate, dropped.
    pub nonfinite: usize,
    /// Screen triangles produced.
    pub screen_triangles: usize,
}

impl std::ops::Add for SetupStats {
    type Output = SetupStats;
    fn add(self, o: SetupStats) -> SetupStats {
        SetupStats {
            triangles: self.triangles + o.triangles,
            clipped_near: self.clipped_near + o.clipped_near,
            behind: self.behind + o.behind,
            clipped_guard: self.clipped_guard + o.clipped_guard,
            culled_back: self.culled_back + o.culled_back,
            zero_area: self.zero_area + o.zero_area,
            off_screen: self.off_screen + o.off_screen,
            nonfinite: self.nonfinite + o.nonfinite,
            screen_triangles: self.screen_triangles + o.screen_triangles,
        }
    }
}

/// The attributes of a vertex: colour, then barycentric identity `corner`.
pub fn attributes(color: Vec3, corner: usize) -> Attributes {
    let mut a = [
        color.x as f64,
        color.y as f64,
        color.z as f64,
        0.0,
        0.0,
        0.0,
    ];
    a[3 + corner] = 1.0;
    a
}

/// A headlight at the eye: 0.1 + 0.9 |cos θ| between the camera-space
/// normal `n` and the direction from the point `p` back to the eye (the
/// same shading as chapters 3 and 4).
pub fn headlight(n: DVec3, p: DVec3) -> f32 {
    let cos = n.dot(-p.normalize_or_zero()).abs();
    (0.1 + 0.9 * cos) as f32
}

/// The colour a triangle gets without vertex colours: its material's
/// reflectance, or its emission scaled into [0, 1] for lights.
pub fn material_color(m: &Material) -> Vec3 {
    if m.is_emissive() {
        m.emission / m.emission.max_element().max(1e-6)
    } else {
        m.reflectance
    }
}

/// Camera space to continuous raster coordinates in f64 (the same mapping
/// as [`Camera::raster_from_image_plane`]), plus 1/w.
pub fn raster_from_camera(cam: &Camera, p: DVec3) -> DVec3 {
    let inv_w = 1.0 / -p.z;
    let (u, v) = (p.x * inv_w, p.y * inv_w);
    let t = cam.tan_half_fov as f64;
    let ndc = DVec2::new(u / (cam.aspect as f64 * t), v / t);
    DVec3::new(
        (ndc.x + 1.0) * 0.5 * cam.width as f64,
        (1.0 - ndc.y) * 0.5 * cam.height as f64,
        inv_w,
    )
}

/// Sets up every triangle of every mesh, in parallel; the result is in
/// mesh and triangle order whatever the number of threads.
// ANCHOR: setup_scene
pub fn setup_scene(
    cam: &Camera,
    meshes: &[Mesh],
    materials: &[Material],
    cull_back_faces: bool,
) -> (Vec<ScreenTriangle>, SetupStats) {
    let mut all = Vec::new();
    let mut stats = SetupStats::default();
    let mut first_id = 0u32;
    for mesh in meshes {
        // Transform every vertex to camera space once.
        let camera_space: Vec<DVec3> = mesh
            .positions
            .iter()
            .map(|p| cam.to_camera(*p).as_dvec3())
            .collect();
        let base = materials
            .get(mesh.material)
            .map(material_color)
            .unwrap_or(Vec3::splat(0.5));
        // Material colours are lit by a headlight, as in chapters 3 and 4,
        // so faces at different angles differ; vertex colours and lights
        // are shown as they are.
        let lit = mesh.colors.is_none()
            && !materials
                .get(mesh.material)
                .is_some_and(|m| m.is_emissive());
        // Each worker appends to a list of its own, and the lists are joined
        // in triangle order (one small list per triangle cost 1.5 KB a
        // triangle at the peak).
        let (tris, s) = mesh
            .triangles
            .par_iter()
            .enumerate()
            .fold(no_triangles, |(mut out, s), (t, idx)| {
                let cam_n = (camera_space[idx[1] as usize] - camera_space[idx[0] as usize])
                    .cross(camera_space[idx[2] as usize] - camera_space[idx[0] as usize])
                    .normalize_or_zero();
                let corner = |n: usize| {
                    let i = idx[n] as usize;
                    let color = mesh.colors.as_ref().map_or(base, |c| c[i]);
                    let color = if lit {
                        color * headlight(cam_n, camera_space[i])
                    } else {
                        color
                    };
                    ClipVertex {
                        p: camera_space[i],
                        attr: attributes(color, n),
                    }
                };
                let world = idx.map(|i| mesh.positions[i as usize]);
                let normal = (world[1] - world[0])
                    .cross(world[2] - world[0])
                    .normalize_or_zero();
                let id = first_id + t as u32;
                let s = setup_camera_triangle(
                    cam,
                    [corner(0), corner(1), corner(2)],
                    normal,
                    id,
                    cull_back_faces,
                    &mut out,
                ) + s;
                (out, s)
            })
            .reduce(no_triangles, |(mut a, sa), (b, sb)| {
                a.extend(b);
                (a, sa + sb)
            });
        all.extend(tris);
        stats = stats + s;
        first_id += mesh.triangles.len() as u32;
    }
    (all, stats)
}
// ANCHOR_END: setup_scene

/// An empty list of screen triangles and its (zero) statistics.
fn no_triangles() -> (Vec<ScreenTriangle>, SetupStats) {
    (Vec::new(), SetupStats::default())
}

/// Sets up one camera-space triangle: near-plane clip, projection, then
/// [`setup_raster_polygon`].
// ANCHOR: setup_camera_triangle
// ANCHOR: setup_camera_triangle_clip
pub fn setup_camera_triangle(
    cam: &Camera,
    corners: [ClipVertex; 3],
    normal: Vec3,
    id: u32,
    cull_back_faces: bool,
    out: &mut Vec<ScreenTriangle>,
) -> SetupStats {
    let mut stats = SetupStats {
        triangles: 1,
        ..SetupStats::default()
    };
    if corners.iter().any(|c| !c.p.is_finite()) {
        stats.nonfinite = 1;
        return stats;
    }
    // Clip at the near plane: the part in front stays.
    let near = NEAR as f64;
    let polygon = clip_near(&corners, near);
    if polygon.len() < 3 {
        stats.behind = 1;
        return stats;
    }
    if polygon.len() != 3 || polygon[..] != corners[..] {
        stats.clipped_near = 1;
    }
    // ANCHOR_END: setup_camera_triangle_clip
    // ANCHOR: setup_camera_triangle_project
    // Project: x, y in pixels, 1/w; attributes divided by w so they are
    // linear on the screen.
    let raster: Vec<ClipVertex> = polygon
        .iter()
        .map(|v| {
            let p = raster_from_camera(cam, v.p);
            ClipVertex {
                p,
                attr: v.attr.map(|a| a * p.z),
            }
        })
        .collect();
    let s = setup_raster_polygon(
        raster,
        cam.width,
        cam.height,
        normal,
        id,
        cull_back_faces,
        out,
    );
    stats + s
}
// ANCHOR_END: setup_camera_triangle_project
// ANCHOR_END: setup_camera_triangle

/// Sets up a convex raster-space polygon (x, y, 1/w; attributes/w): guard
/// band, snapping, culling, orientation, bounding box. The polygon is cut
/// into a fan of triangles.
pub fn setup_raster_polygon(
    polygon: Vec<ClipVertex>,
    width: u32,
    height: u32,
    normal: Vec3,
    id: u32,
    cull_back_faces: bool,
    out: &mut Vec<ScreenTriangle>,
) -> SetupStats {
    let mut stats = SetupStats::default();
    let n = polygon.len();
    let polygon = clip_guard_band(polygon, width, height);
    if polygon.len() != n {
        stats.clipped_guard = 1;
    }
    // Snap to fixed point; recover attribute values from attribute/w.
    let mut verts = Vec::with_capacity(polygon.len());
    for v in &polygon {
        let Some(fixed) = to_fixed(v.p.x, v.p.y) else {
            stats.nonfinite = 1;
            return stats;
        };
        let inv_w = v.p.z;
        if !(inv_w > 0.0 && inv_w.is_finite()) {
            stats.nonfinite = 1;
            return stats;
        }
        verts.push((fixed, inv_w, v.attr.map(|a| a / inv_w)));
    }
    for k in 1..verts.len().saturating_sub(1) {
        let (mut a, mut b, c) = (verts[0], verts[k], verts[k + 1]);
        let area = edge_fixed(a.0, b.0, c.0);
        if area == 0 {
            stats.zero_area += 1;
            continue;
        }
        // Raster y points down: a counter-clockwise (front) face has a
        // negative edge function here.
        let front = area < 0;
        if cull_back_faces && !front {
            stats.culled_back += 1;
            continue;
        }
        if area < 0 {
            std::mem::swap(&mut a, &mut b);
        }
        let v = [a.0, b.0, c.0];
        let Some(bbox) = pixel_bbox(&v, width, height) else {
            stats.off_screen += 1;
            continue;
        };
        out.push(ScreenTriangle {
            v,
            area: area.abs(),
            inv_w: [a.1, b.1, c.1],
            attr: [a.2, b.2, c.2],
            normal,
            id,
            front,
            bbox,
        });
        stats.screen_triangles += 1;
    }
    stats
}

/// The inclusive pixel range whose samples the triangle may cover, or
/// `None` when it misses the screen. A sample of pixel x lies in
/// [x·256, x·256 + 255] in fixed point.
pub fn pixel_bbox(v: &[I64Vec2; 3], width: u32, height: u32) -> Option<[u32; 4]> {
    let min = v[0].min(v[1]).min(v[2]);
    let max = v[0].max(v[1]).max(v[2]);
    let (x0, y0) = (
        min.x.div_euclid(SUBPIXEL).max(0),
        min.y.div_euclid(SUBPIXEL).max(0),
    );
    let x1 = max.x.div_euclid(SUBPIXEL).min(width as i64 - 1);
    let y1 = max.y.div_euclid(SUBPIXEL).min(height as i64 - 1);
    (x0 <= x1 && y0 <= y1).then_some([x0 as u32, y0 as u32, x1 as u32, y1 as u32])
}

/// A screen triangle straight from raster positions (pixels), at depth 1
/// with white colour: for tests, studies and exercises in 2D. Empty when
/// the triangle has no area or misses the screen.
pub fn raster_triangle(p: [DVec2; 3], id: u32, width: u32, height: u32) -> Vec<ScreenTriangle> {
    let polygon = (0..3)
        .map(|n| ClipVertex {
            p: p[n].extend(1.0),
            attr: attributes(Vec3::ONE, n),
        })
        .collect();
    let mut out = Vec::new();
    setup_raster_polygon(polygon, width, height, Vec3::Z, id, false, &mut out);
    out
}
