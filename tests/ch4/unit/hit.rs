//! Unit tests of `src/ch4_implicit_surfaces/hit.rs`.

use glam::Vec3;
use raystep::ch4_implicit_surfaces::hit::*;

fn at(t: f32, surface: Surface) -> SurfaceHit {
    SurfaceHit {
        t,
        normal: Vec3::Z,
        material: 0,
        surface,
    }
}

#[test]
fn the_nearest_wins() {
    let s = at(2.0, Surface::Sdf(0));
    let m = at(1.0, Surface::Mesh(3));
    assert_eq!(nearest_hit(Some(s), Some(m)), Some(m));
    assert_eq!(nearest_hit(Some(m), Some(s)).unwrap().t, 1.0);
    assert_eq!(nearest_hit(Some(s), None), Some(s));
    assert_eq!(nearest_hit(None, Some(m)), Some(m));
    assert_eq!(nearest_hit(None, None), None);
    let tie = at(2.0, Surface::Mesh(0));
    assert_eq!(nearest_hit(Some(s), Some(tie)), Some(s));
}
