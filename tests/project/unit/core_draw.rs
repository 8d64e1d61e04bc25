//! Unit tests of `src/core/draw.rs`.

use glam::{DVec2, Vec2, Vec3};
use raystep::core::draw::*;
use raystep::core::film::Film;

#[test]
fn a_huge_line_is_clipped_not_walked() {
    let mut f = Film::new(8, 8);
    let lit = line(
        &mut f,
        Vec2::new(-1e9, 4.0),
        Vec2::new(1e9, 4.0),
        Vec3::ONE,
        Vec3::ONE,
    );
    assert!(lit > 0 && lit < 200);
    assert!(f.get(0, 3).x > 0.4 && f.get(7, 4).x > 0.4);
}

#[test]
fn liang_barsky_rejects_outside_segments() {
    let (lo, hi) = (DVec2::ZERO, DVec2::splat(10.0));
    assert_eq!(
        clip_segment_2d(DVec2::new(-5.0, -1.0), DVec2::new(20.0, -1.0), lo, hi),
        None
    );
    let (t0, t1) = clip_segment_2d(DVec2::new(-10.0, 5.0), DVec2::new(20.0, 5.0), lo, hi).unwrap();
    assert!((t0 - 1.0 / 3.0).abs() < 1e-12 && (t1 - 2.0 / 3.0).abs() < 1e-12);
}
