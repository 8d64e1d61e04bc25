//! The wrong pictures: what a plausible student bug looks like, rendered
//! by the project, beside the right picture of the same scene.
//!
//! Each pair is drawn twice by the same driver, with the same scene,
//! camera, samples and seed: once with the lesson's function and once
//! with a copy of it that makes one mistake (the copy says which, in a
//! `BUG:` comment). The lesson code itself is never changed. Chapters 1
//! and 2 are here; 3 and 4 in [`super::wrong_rays`]; 5 and 6 in
//! [`super::wrong_light`]; what they share in [`super::wrong_pair`].

use std::path::Path;

use glam::{Vec2, Vec3};
use raystep::ch1_projection::camera::{project_pinhole, Camera};
use raystep::ch1_projection::wireframe::{clip_to_near, NEAR};
use raystep::ch2_rasterization::checker::checker_figures;
use raystep::core::draw;
use raystep::core::error::Result;
use raystep::core::film::Film;
use raystep::scene::Scene;

use super::wrong_pair::{scene, Pair};
use super::{wrong_light, wrong_rays};

/// Every pair's files and what they show, chapter by chapter.
const FILES: &[(&str, &str)] = &[
    (
        "ch1-bunny-upside-down-right.png",
        "the bunny's wireframe through the pinhole, u = x/-z, v = y/-z (right)",
    ),
    (
        "ch1-bunny-upside-down-wrong.png",
        "the same wireframe with u = x/z, v = y/z: turned upside down and mirrored (wrong)",
    ),
    (
        "ch2-checker-affine-right.png",
        "the checkered floor, (u, v) interpolated perspective-correct (right)",
    ),
    (
        "ch2-checker-affine-wrong.png",
        "the same floor, (u, v) interpolated affinely in screen space: lines bend at the diagonal (wrong)",
    ),
    (
        "ch3-leak-right.png",
        "a mesh sphere seen down an axis, normal view, the watertight test, magnified 3x (right)",
    ),
    (
        "ch3-leak-wrong.png",
        "the same with an edge function of exactly 0 counted as outside: rays through shared edges leak (wrong)",
    ),
    (
        "ch4-squared-distance-right.png",
        "three balls over a plane sphere traced, each ball's f = |p - c| - r (right)",
    ),
    (
        "ch4-squared-distance-wrong.png",
        "the same with f = |p - c|² - r², not a distance: steps jump over the floating balls' tops (wrong)",
    ),
    (
        "ch5-shadow-acne-right.png",
        "the Cornell box's direct light, shadow rays spawned off the surface (right)",
    ),
    (
        "ch5-shadow-acne-wrong.png",
        "the same with shadow rays starting at the hit point: surfaces shadow themselves (wrong)",
    ),
    (
        "ch5-lambert-pi-right.png",
        "the Cornell box's direct light with the Lambertian BRDF rho/pi (right)",
    ),
    (
        "ch5-lambert-pi-wrong.png",
        "the same with the BRDF rho, the 1/pi forgotten: pi times too bright (wrong)",
    ),
    (
        "ch6-roulette-right.png",
        "the Cornell box path traced, a roulette survivor divided by q (right)",
    ),
    (
        "ch6-roulette-wrong.png",
        "the same without dividing by q: the indirect light fades, too dark (wrong)",
    ),
];

/// Every wrong picture and its right partner: (file name, what it
/// shows). Wrong ones end in `-wrong.png`, right ones in `-right.png`.
pub fn list() -> Vec<(&'static str, &'static str)> {
    FILES.to_vec()
}

/// Renders every wrong picture and its right partner into `out`; returns
/// the file names written.
pub fn render_all(out: &Path) -> Result<Vec<String>> {
    let mut pairs = vec![ch1_upside_down()?, ch2_checker()];
    pairs.extend(wrong_rays::pairs()?);
    pairs.extend(wrong_light::pairs()?);
    let mut written = Vec::new();
    for pair in pairs {
        for (side, film) in [("right", &pair.right), ("wrong", &pair.wrong)] {
            let name = format!("{}-{side}.png", pair.stem);
            debug_assert!(
                FILES.iter().any(|(f, _)| *f == name),
                "{name} is not listed"
            );
            film.write_png(&out.join(&name))?;
            written.push(name);
        }
    }
    Ok(written)
}

// ---------------------------------------------------------------- chapter 1

/// The pinhole as a student might copy it from the slide "u = x/z": the
/// slide's camera looks down +z, ours down -z.
fn project_pinhole_wrong(p: Vec3) -> Option<Vec2> {
    if p.z >= 0.0 || p.z.is_nan() {
        return None;
    }
    // BUG: divides by z instead of -z. Every point in front has z < 0, so
    // u and v change sign: the picture turns by 180° (upside down and
    // mirrored left to right).
    let uv = Vec2::new(p.x / p.z, p.y / p.z);
    uv.is_finite().then_some(uv)
}

/// The scene's edges drawn as chapter 1's wireframe view draws them
/// (clipped at the near plane, projected, a line between the ends), with
/// `project` for the pinhole.
fn wireframe(camera: &Camera, scene: &Scene, project: fn(Vec3) -> Option<Vec2>) -> Film {
    let mut film = Film::new(camera.width, camera.height);
    for mesh in &scene.meshes {
        let c = scene.materials[mesh.material].reflectance;
        let color = if c.max_element() > 0.0 {
            c / c.max_element() * 0.9
        } else {
            Vec3::splat(0.3)
        };
        let pts: Vec<Vec3> = mesh
            .positions
            .iter()
            .map(|p| camera.to_camera(*p))
            .collect();
        for [i, j] in mesh.edges() {
            let Some((a, b)) = clip_to_near(pts[i as usize], pts[j as usize], NEAR) else {
                continue;
            };
            if let (Some(ua), Some(ub)) = (project(a), project(b)) {
                let (ra, rb) = (
                    camera.raster_from_image_plane(ua),
                    camera.raster_from_image_plane(ub),
                );
                draw::line(&mut film, ra, rb, color, color);
            }
        }
    }
    film
}

/// Chapter 1: the bunny through the right and the wrong pinhole.
fn ch1_upside_down() -> Result<Pair> {
    let scene = scene("bunny.toml")?;
    let camera = Camera::of(&scene).with_resolution(240, 180)?;
    Ok(Pair {
        stem: "ch1-bunny-upside-down",
        right: wireframe(&camera, &scene, project_pinhole),
        wrong: wireframe(&camera, &scene, project_pinhole_wrong),
    })
}

// ---------------------------------------------------------------- chapter 2

/// Chapter 2: the checkered floor, perspective-correct and affine (the
/// chapter's own figure function renders both; the affine one is the
/// barycentrics used as they come from screen space, without dividing
/// by depth).
fn ch2_checker() -> Pair {
    let figures = checker_figures(240, 180, 8, 2);
    Pair {
        stem: "ch2-checker-affine",
        right: figures.perspective,
        wrong: figures.affine,
    }
}
