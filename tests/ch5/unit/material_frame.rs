//! Unit tests of `src/ch5_reflection/material/frame.rs`.

use glam::Vec3;
use raystep::ch5_reflection::material::frame::*;

#[test]
fn orthonormal_for_every_normal_even_minus_z() {
    let ns = [
        Vec3::Z,
        -Vec3::Z,
        Vec3::X,
        Vec3::new(1.0, 2.0, -3.0).normalize(),
        Vec3::new(1e-7, 0.0, -1.0).normalize(),
    ];
    for n in ns {
        let f = Frame::from_normal(n);
        for (a, b) in [(f.s, f.t), (f.t, f.n), (f.s, f.n)] {
            assert!(a.dot(b).abs() < 1e-5, "{n}");
        }
        for v in [f.s, f.t] {
            assert!((v.length() - 1.0).abs() < 1e-5, "{n}");
        }
        assert!((f.s.cross(f.t) - n).length() < 1e-5, "right-handed for {n}");
        let w = Vec3::new(0.3, -0.4, 0.5);
        assert!((f.to_world(f.to_local(w)) - w).length() < 1e-5);
    }
}
