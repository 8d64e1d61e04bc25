//! The checkered floor: perspective-correct (u, v) give the same squares as
//! a ray cast through every pixel centre; affine (u, v) do not.

use glam::{DVec2, DVec3};
use raystep::ch2_rasterization::checker::{
    checker, checker_camera, checker_counts, checker_figures, floor_uv, raycast_uv, FLOOR,
};
use raystep::ch2_rasterization::interpolate::Interpolation;

const W: u32 = 320;
const H: u32 = 240;

/// The exact (u, v) where the ray through raster point (x, y) meets the
/// plane y = 0, in world space and double precision from the camera's own
/// description (independent of the library's camera-space ray cast), and
/// whether the point is on the board.
fn world_hit(x: f64, y: f64) -> Option<(DVec2, bool)> {
    let d = checker_camera(W, H).desc;
    let back = (d.eye - d.target).normalize();
    let right = d.up.cross(back).normalize();
    let up = back.cross(right);
    let t = (d.fov_degrees.to_radians() * 0.5).tan();
    let aspect = d.width as f64 / d.height as f64;
    let ndc = DVec2::new(2.0 * x / W as f64 - 1.0, 1.0 - 2.0 * y / H as f64);
    let dir = right * (ndc.x * aspect * t) + up * (ndc.y * t) - back;
    let s = -d.eye.y / dir.y;
    if s <= 0.0 {
        return None;
    }
    let p: DVec3 = d.eye + s * dir;
    // FLOOR: x in [-4, 4] is u in [0, 8]; z in [-1, -9] is v in [0, 8].
    let (x0, z0) = (FLOOR[0].0[0], FLOOR[0].0[2]);
    let uv = DVec2::new(p.x - x0, z0 - p.z);
    let on_board = (0.0..=8.0).contains(&uv.x) && (0.0..=8.0).contains(&uv.y);
    Some((uv, on_board))
}

/// How far (u, v) moves from one pixel to the next around raster (x, y).
fn footprint(x: f64, y: f64) -> f64 {
    let at = |x, y| world_hit(x, y).map(|h| h.0);
    match (at(x, y), at(x + 1.0, y), at(x, y + 1.0)) {
        (Some(a), Some(b), Some(c)) => (b - a).abs().max_element().max((c - a).abs().max_element()),
        _ => f64::INFINITY,
    }
}

/// Distance from `t` to the nearest whole number.
fn to_line(t: f64) -> f64 {
    (t - t.round()).abs()
}

/// Pixels where `uv` (at pixel centres) and the world ray cast disagree
/// about the square's colour or about being on the floor, leaving out the
/// pixels whose centre lies within 1% of a pixel of a line between squares
/// or of the board's edge (vertex snapping moves lines by up to 1/512
/// pixel). Returns (disagreements left, board pixels).
fn disagreements(uv: &[Option<DVec2>]) -> (usize, usize) {
    let (mut wrong, mut board) = (0, 0);
    for y in 0..H {
        for x in 0..W {
            let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
            let exact = world_hit(cx, cy);
            let on_board = exact.is_some_and(|e| e.1);
            board += usize::from(on_board);
            let got = uv[(y * W + x) as usize];
            let agree = match (on_board, got) {
                (true, Some(g)) => checker(g) == checker(exact.unwrap().0),
                (false, None) => true,
                _ => false,
            };
            if agree {
                continue;
            }
            let near_line = exact.is_some_and(|(e, _)| {
                let tol = 0.01 * footprint(cx, cy);
                to_line(e.x) < tol || to_line(e.y) < tol
            });
            if !near_line {
                wrong += 1;
            }
        }
    }
    (wrong, board)
}

#[test]
fn perspective_correct_matches_the_ray_cast_and_affine_does_not() {
    let persp = floor_uv(W, H, 1, 0, Interpolation::Perspective);
    let (wrong, board) = disagreements(&persp);
    assert!(
        board > 20_000,
        "the board should fill the view: {board} pixels"
    );
    assert_eq!(
        wrong, 0,
        "perspective-correct squares differ from the ray cast"
    );

    let affine = floor_uv(W, H, 1, 0, Interpolation::Affine);
    let (wrong, _) = disagreements(&affine);
    assert!(
        wrong * 4 > board,
        "affine squares should differ on over a quarter of the board: {wrong} of {board}"
    );
}

#[test]
fn the_report_counts_agree_with_the_images() {
    let c = checker_counts(W, H);
    let persp = floor_uv(W, H, 1, 0, Interpolation::Perspective);
    let affine = floor_uv(W, H, 1, 0, Interpolation::Affine);
    let floor = persp.iter().filter(|p| p.is_some()).count();
    assert!(c.floor_pixels.abs_diff(floor) < 50, "{c:?} vs {floor}");
    // Affine and perspective see the same pixels (same triangles); the
    // squares differ on a large part of them.
    assert_eq!(floor, affine.iter().filter(|p| p.is_some()).count());
    assert!(c.affine_vs_perspective * 3 > c.floor_pixels, "{c:?}");
    assert!(c.affine_vs_exact * 3 > c.floor_pixels, "{c:?}");
    assert!(c.perspective_vs_exact * 1000 < c.floor_pixels, "{c:?}");
    // The library's camera-space ray cast agrees with the world-space one.
    let lib = raycast_uv(W, H);
    for y in (0..H).step_by(7) {
        for x in (0..W).step_by(5) {
            let ours = world_hit(x as f64 + 0.5, y as f64 + 0.5).filter(|h| h.1);
            let theirs = lib[(y * W + x) as usize];
            match (ours, theirs) {
                (Some((a, _)), Some(b)) => assert!((a - b).length() < 1e-3, "{a} {b}"),
                (None, None) => {}
                // The board's outline: both within a hair of the edge.
                (a, b) => {
                    let e = world_hit(x as f64 + 0.5, y as f64 + 0.5).map(|h| h.0);
                    let edge = e.is_some_and(|e| {
                        [e.x, e.y, 8.0 - e.x, 8.0 - e.y]
                            .iter()
                            .any(|d| d.abs() < 1e-4)
                    });
                    assert!(edge, "({x}, {y}): {a:?} vs {b:?}");
                }
            }
        }
    }
}

#[test]
fn the_difference_image_shows_the_disagreement() {
    let f = checker_figures(W, H, 4, 0);
    let lit = |film: &raystep::core::film::Film| film.pixels.iter().filter(|p| p.x > 0.0).count();
    let (floor, differ) = (lit(&f.perspective), lit(&f.difference));
    assert!(floor > 20_000 && differ * 4 > floor, "{differ} of {floor}");
    assert!(f.perspective.rmse(&f.affine) > 0.1);
    // Same seed, same bytes.
    let g = checker_figures(W, H, 4, 0);
    assert_eq!(f.affine.pixels, g.affine.pixels);
}
