//! The checkered floor: where affine interpolation goes visibly wrong.
//!
//! A large floor quad, two triangles, seen at a grazing angle, carries
//! texture coordinates (u, v) at its corners. A pixel's colour is a
//! checkerboard of those coordinates, computed on the spot (no texture
//! file): light where ⌊u⌋ + ⌊v⌋ is even, dark where it is odd. The (u, v) a
//! pixel sees come from the rasterizer's interpolation, perspective-correct
//! or affine, so the checker shows every error of the interpolation as a
//! bent line. A ray cast through each pixel centre onto the floor's plane
//! gives the exact (u, v) to compare both with.

use glam::{DVec2, DVec3, Vec3};
use rayon::prelude::*;

use super::clip::ClipVertex;
use super::coverage::rasterize;
use super::interpolate::{interpolate_phi, screen_barycentrics, Interpolation};
use super::setup::{attributes, setup_camera_triangle, ScreenTriangle};
use crate::ch1_projection::camera::{Camera, CameraDesc};
use crate::core::film::Film;

/// The figure's size in pixels.
pub const CHECKER_SIZE: (u32, u32) = (320, 240);

/// Samples per pixel of the figures (stratified, so the far squares blend
/// to grey instead of flickering).
pub const CHECKER_SPP: u32 = 16;

/// The floor's corners in world space (the plane y = 0) with their texture
/// coordinates: a board of 8 x 8 squares, one world unit each.
pub const FLOOR: [([f64; 3], [f64; 2]); 4] = [
    ([-4.0, 0.0, -1.0], [0.0, 0.0]),
    ([4.0, 0.0, -1.0], [8.0, 0.0]),
    ([4.0, 0.0, -9.0], [8.0, 8.0]),
    ([-4.0, 0.0, -9.0], [0.0, 8.0]),
];

/// The two triangles of the quad, as indices into [`FLOOR`].
pub const FLOOR_TRIANGLES: [[usize; 3]; 2] = [[0, 1, 2], [0, 2, 3]];

/// The light and dark squares.
pub const LIGHT: Vec3 = Vec3::new(0.85, 0.82, 0.72);
/// See [`LIGHT`].
pub const DARK: Vec3 = Vec3::new(0.08, 0.1, 0.16);

/// The camera of the figure: 2.2 units above the floor and 5 in front of
/// the board's near edge, looking down at a point beyond its middle, a 60°
/// vertical field of view. The whole board is in view.
pub fn checker_camera(width: u32, height: u32) -> Camera {
    Camera::new(CameraDesc {
        eye: DVec3::new(0.0, 2.6, 2.0),
        target: DVec3::new(0.0, 0.0, -4.0),
        up: DVec3::Y,
        fov_degrees: 60.0,
        width,
        height,
    })
    .expect("a valid camera")
}

/// Whether (u, v) falls on a light square.
// ANCHOR: checker
pub fn checker(uv: DVec2) -> bool {
    (uv.x.floor() + uv.y.floor()).rem_euclid(2.0) == 0.0
}
// ANCHOR_END: checker

/// The floor's corners in camera space (through the same f32 transform
/// the scene's meshes take).
fn camera_space_floor(cam: &Camera) -> [DVec3; 4] {
    FLOOR.map(|(p, _)| cam.to_camera(DVec3::from(p).as_vec3()).as_dvec3())
}

/// The floor's two triangles set up for `cam`. The attributes carry (u, v)
/// where the other triangles carry a colour; they pass through clipping,
/// projection and snapping like any colour.
pub fn floor_triangles(cam: &Camera) -> Vec<ScreenTriangle> {
    let p = camera_space_floor(cam);
    let mut out = Vec::new();
    for (id, tri) in FLOOR_TRIANGLES.iter().enumerate() {
        let corner = |n: usize| {
            let [u, v] = FLOOR[tri[n]].1;
            ClipVertex {
                p: p[tri[n]],
                attr: attributes(Vec3::new(u as f32, v as f32, 0.0), n),
            }
        };
        setup_camera_triangle(
            cam,
            [corner(0), corner(1), corner(2)],
            Vec3::Y,
            id as u32,
            false,
            &mut out,
        );
    }
    out
}

/// The (u, v) of every sample of the floor rendered at `spp` samples per
/// pixel with interpolation `mode`, pixel by pixel: `None` off the floor.
pub fn floor_uv(
    width: u32,
    height: u32,
    spp: u32,
    seed: u64,
    mode: Interpolation,
) -> Vec<Option<DVec2>> {
    let cam = checker_camera(width, height);
    let tris = floor_triangles(&cam);
    let buf = rasterize(&tris, width, 0..height, spp, seed);
    (0..width * height * spp)
        .into_par_iter()
        .map(|i| {
            let sample = buf.samples[i as usize];
            if !sample.is_covered() {
                return None;
            }
            let (pixel, s) = (i / spp, i % spp);
            let tri = &tris[sample.tri as usize];
            let p = buf.position(pixel % width, pixel / width, s);
            let (a, _) = interpolate_phi(tri, screen_barycentrics(tri, p), mode);
            Some(DVec2::new(a[0], a[1]))
        })
        .collect()
}

/// The exact (u, v) at each pixel centre: the ray through it meets the
/// floor's plane, and (u, v) there follows from the hit point's position in
/// the quad. `None` where the ray misses the quad.
// ANCHOR: raycast_uv
// ANCHOR: raycast_uv_setup
pub fn raycast_uv(width: u32, height: u32) -> Vec<Option<DVec2>> {
    let cam = checker_camera(width, height);
    let p = camera_space_floor(&cam);
    let uv = FLOOR.map(|(_, uv)| DVec2::from(uv));
    let n = (p[1] - p[0]).cross(p[2] - p[0]);
    let t = cam.tan_half_fov as f64;
    // Barycentrics of q (on the plane) in triangle (a, b, c).
    let bary = |q: DVec3, a: DVec3, b: DVec3, c: DVec3| {
        let area = |x: DVec3, y: DVec3| (y - x).cross(q - x).dot(n);
        let whole = (b - a).cross(c - a).dot(n);
        [area(b, c), area(c, a), area(a, b)].map(|x| x / whole)
    };
    // ANCHOR_END: raycast_uv_setup
    // ANCHOR: raycast_uv_pixels
    (0..width * height)
        .map(|i| {
            let (x, y) = ((i % width) as f64 + 0.5, (i / width) as f64 + 0.5);
            let ndc = DVec2::new(2.0 * x / width as f64 - 1.0, 1.0 - 2.0 * y / height as f64);
            let d = DVec3::new(ndc.x * cam.aspect as f64 * t, ndc.y * t, -1.0);
            // The pinhole is the origin: the hit is s·d with n·(s·d) = n·p0.
            let s = n.dot(p[0]) / n.dot(d);
            if !(s > 0.0 && s.is_finite()) {
                return None;
            }
            let q = s * d;
            let [b0, b1, b2] = bary(q, p[0], p[1], p[2]);
            let [c0, _, c2] = bary(q, p[0], p[2], p[3]);
            let inside = [b0, b1, b2].iter().all(|b| *b >= 0.0)
                || [c0, 1.0 - c0 - c2, c2].iter().all(|b| *b >= 0.0);
            // (u, v) is affine on the plane: one triangle's barycentrics
            // give it everywhere.
            inside.then(|| b0 * uv[0] + b1 * uv[1] + b2 * uv[2])
        })
        .collect()
}
// ANCHOR_END: raycast_uv_pixels
// ANCHOR_END: raycast_uv

/// The checkered floor with perspective-correct and affine interpolation,
/// and their difference (the fraction of each pixel's samples on which the
/// two disagree about the square's colour: white where they always do).
pub struct CheckerFigures {
    /// Perspective-correct (u, v).
    pub perspective: Film,
    /// Affine (u, v).
    pub affine: Film,
    /// Where the two disagree.
    pub difference: Film,
}

/// Renders the three images at `spp` samples per pixel.
pub fn checker_figures(width: u32, height: u32, spp: u32, seed: u64) -> CheckerFigures {
    let persp = floor_uv(width, height, spp, seed, Interpolation::Perspective);
    let affine = floor_uv(width, height, spp, seed, Interpolation::Affine);
    let color = |uv: &Option<DVec2>| match uv {
        Some(uv) if checker(*uv) => LIGHT,
        Some(_) => DARK,
        None => Vec3::ZERO,
    };
    let mut films = [0, 1, 2].map(|_| Film::new(width, height));
    for i in 0..(width * height) as usize {
        let range = i * spp as usize..(i + 1) * spp as usize;
        let mut sums = [Vec3::ZERO; 3];
        for (a, b) in persp[range.clone()].iter().zip(&affine[range]) {
            sums[0] += color(a);
            sums[1] += color(b);
            if color(a) != color(b) {
                sums[2] += Vec3::ONE;
            }
        }
        for (film, sum) in films.iter_mut().zip(sums) {
            film.pixels[i] = sum / spp as f32;
        }
    }
    let [perspective, affine, difference] = films;
    CheckerFigures {
        perspective,
        affine,
        difference,
    }
}

/// The study's numbers, at one sample per pixel centre.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CheckerCounts {
    /// Pixels whose centre sees the floor, by the ray cast.
    pub floor_pixels: usize,
    /// Floor pixels where affine and perspective-correct disagree about
    /// the square's colour.
    pub affine_vs_perspective: usize,
    /// Floor pixels where perspective-correct disagrees with the ray cast
    /// (or only one of the two sees the floor).
    pub perspective_vs_exact: usize,
    /// The same for affine.
    pub affine_vs_exact: usize,
}

/// Counts the disagreements at pixel centres.
pub fn checker_counts(width: u32, height: u32) -> CheckerCounts {
    let exact = raycast_uv(width, height);
    let persp = floor_uv(width, height, 1, 0, Interpolation::Perspective);
    let affine = floor_uv(width, height, 1, 0, Interpolation::Affine);
    let parity = |uv: &Option<DVec2>| uv.map(checker);
    let differ = |a: &[Option<DVec2>], b: &[Option<DVec2>]| {
        a.iter()
            .zip(b)
            .filter(|(x, y)| (x.is_some() || y.is_some()) && parity(x) != parity(y))
            .count()
    };
    CheckerCounts {
        floor_pixels: exact.iter().filter(|uv| uv.is_some()).count(),
        affine_vs_perspective: differ(&affine, &persp),
        perspective_vs_exact: differ(&persp, &exact),
        affine_vs_exact: differ(&affine, &exact),
    }
}
