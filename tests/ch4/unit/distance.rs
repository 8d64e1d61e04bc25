//! Unit tests of `src/ch4_implicit_surfaces/distance.rs`.

use glam::Quat;
use glam::Vec3;
use raystep::ch4_implicit_surfaces::distance::*;

#[test]
fn transforms_move_the_surface() {
    let s = Sdf::Translate {
        offset: Vec3::new(2.0, 0.0, 0.0),
        of: Box::new(Sdf::Sphere { radius: 1.0 }),
    };
    assert_eq!(s.eval(Vec3::new(2.0, 2.0, 0.0)), 1.0);
    let r = Sdf::Rotate {
        rotation: Quat::from_rotation_z(std::f32::consts::FRAC_PI_2),
        of: Box::new(Sdf::Box {
            half_size: Vec3::new(2.0, 0.5, 0.5),
        }),
    };
    // The long axis now points along y.
    assert!((r.eval(Vec3::new(0.0, 3.0, 0.0)) - 1.0).abs() < 1e-5);
    let u = Sdf::Scale {
        factor: 2.0,
        of: Box::new(Sdf::Sphere { radius: 1.0 }),
    };
    assert_eq!(u.eval(Vec3::new(5.0, 0.0, 0.0)), 3.0);
    let e = Sdf::ScaleAxes {
        factors: Vec3::new(4.0, 1.0, 1.0),
        bound: ScaleBound::Max,
        of: Box::new(Sdf::Sphere { radius: 1.0 }),
    };
    // True distance from (0, 2, 0) to the ellipsoid is 1; max overestimates.
    assert_eq!(e.eval(Vec3::new(0.0, 2.0, 0.0)), 4.0);
    assert_eq!(e.exactness(), Exactness::Unsafe);
    assert_eq!(e.lipschitz(), 4.0);
    assert_eq!(u.exactness(), Exactness::Exact);
}
