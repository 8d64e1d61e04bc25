//! Unit tests of `src/ch4_implicit_surfaces/normal.rs`.

use glam::Vec3;
use raystep::ch4_implicit_surfaces::normal::*;

#[test]
fn both_schemes_find_the_sphere_normal() {
    let f = |p: Vec3| p.length() - 1.0;
    let p = Vec3::new(0.6, 0.0, 0.8);
    for scheme in [NormalScheme::Central, NormalScheme::Tetrahedron] {
        let n = normal(&f, p, 1e-3, scheme, Vec3::Z);
        assert!((n - p).length() < 1e-3, "{scheme:?}: {n}");
    }
    // At the centre the differences cancel: the fallback, not NaN.
    assert_eq!(
        normal(&f, Vec3::ZERO, 1e-3, NormalScheme::Central, Vec3::Y),
        Vec3::Y
    );
}
