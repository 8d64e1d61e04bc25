//! Unit tests of `src/ch2_rasterization/edge.rs`.

use glam::{I64Vec2, Vec2, Vec3};
use raystep::ch2_rasterization::edge::*;

#[test]
fn barycentrics_of_hand_computed_points() {
    let (a, b, c) = (Vec2::ZERO, Vec2::new(4.0, 0.0), Vec2::new(0.0, 2.0));
    // The centroid has φ = 1/3 each.
    let phi = barycentric(a, b, c, Vec2::new(4.0 / 3.0, 2.0 / 3.0)).unwrap();
    assert!((phi - Vec3::splat(1.0 / 3.0)).abs().max_element() < 1e-6);
    // (1, 0.5): φj = 1/4, φk = 1/4, φi = 1/2, worked out by hand.
    let phi = barycentric(a, b, c, Vec2::new(1.0, 0.5)).unwrap();
    assert_eq!(phi, Vec3::new(0.5, 0.25, 0.25));
    // A vertex has φ = (1, 0, 0); a collinear triangle has none.
    assert_eq!(barycentric(a, b, c, b).unwrap(), Vec3::Y);
    assert_eq!(barycentric(a, b, Vec2::new(8.0, 0.0), c), None);
}

#[test]
fn shared_edge_is_top_left_for_exactly_one_side() {
    let pts = [
        I64Vec2::new(0, 0),
        I64Vec2::new(5, 0),
        I64Vec2::new(0, 7),
        I64Vec2::new(-3, -9),
    ];
    for a in pts {
        for b in pts {
            if a != b {
                assert_ne!(is_top_left(a, b), is_top_left(b, a), "{a} {b}");
            }
        }
    }
}
