//! Unit tests of `src/ch5_reflection/light/spherical.rs`, on the stiff
//! cases a triangle seen from a point can be: huge and near (Ω close to
//! 2π), tiny and far, a sliver, edge-on, either winding.

use glam::{DVec3, Vec2};
use raystep::ch5_reflection::light::spherical::sample_spherical_triangle;
use raystep::ch5_reflection::radiometry::triangle_solid_angle;

/// Triangles seen from the origin, by name.
fn cases() -> Vec<(&'static str, [DVec3; 3])> {
    let d = DVec3::new;
    vec![
        (
            "unit, 1 away",
            [d(0.0, 0.0, 1.0), d(1.0, 0.0, 1.0), d(0.0, 1.0, 1.0)],
        ),
        (
            "huge and near",
            [d(-1e3, -1e3, 1e-2), d(1e3, -1e3, 1e-2), d(0.0, 2e3, 1e-2)],
        ),
        (
            "tiny and far",
            [d(0.0, 0.0, 1e3), d(1.0, 0.0, 1e3), d(0.0, 1.0, 1e3)],
        ),
        (
            "sliver 1:1000",
            [d(-1.0, 0.0, 2.0), d(1.0, 0.0, 2.0), d(0.0, 1e-3, 2.0)],
        ),
        (
            "nearly edge-on",
            [d(0.0, 1.0, 1.0), d(0.0, 2.0, 1.0), d(1e-3, 1.5, 3.0)],
        ),
        (
            "other winding",
            [d(0.0, 0.0, 1.0), d(0.0, 1.0, 1.0), d(1.0, 0.0, 1.0)],
        ),
        (
            "wide angles",
            [d(1.0, 0.0, 0.1), d(-0.5, 0.87, 0.1), d(-0.5, -0.87, 0.1)],
        ),
    ]
}

fn unit(t: [DVec3; 3]) -> [DVec3; 3] {
    t.map(DVec3::normalize)
}

/// Where the ray from the origin along `w` meets the triangle's plane, in
/// barycentric coordinates.
fn barycentric(t: [DVec3; 3], w: DVec3) -> DVec3 {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    let y = w * (n.dot(t[0]) / n.dot(w));
    let area = n.length_squared();
    let b1 = (y - t[0]).cross(t[2] - t[0]).dot(n) / area;
    let b2 = (t[1] - t[0]).cross(y - t[0]).dot(n) / area;
    DVec3::new(1.0 - b1 - b2, b1, b2)
}

#[test]
fn every_direction_drawn_goes_through_the_triangle() {
    for (name, t) in cases() {
        for i in 0..32 {
            for j in 0..32 {
                let u = Vec2::new(i as f32 / 32.0, (j as f32 + 0.5) / 32.0);
                let w = sample_spherical_triangle(unit(t), u).unwrap();
                assert!((w.length() - 1.0).abs() < 1e-12, "{name}: {w}");
                let b = barycentric(t, w);
                assert!(b.min_element() > -1e-6, "{name} at {u}: barycentric {b}");
            }
        }
    }
}

#[test]
fn the_first_number_cuts_off_its_share_of_the_solid_angle() {
    // With u.y = 1 the direction is the corner c' of step 1, and the
    // triangle (a, b, c') covers the fraction u.x of the whole.
    for (name, t) in cases() {
        let [a, b, c] = unit(t);
        let whole = triangle_solid_angle(a, b, c);
        for x in [0.0f32, 0.1, 0.25, 0.5, 0.9, 0.999] {
            let c_sub = sample_spherical_triangle([a, b, c], Vec2::new(x, 1.0)).unwrap();
            let part = triangle_solid_angle(a, b, c_sub);
            let want = x as f64 * whole;
            // Step 1 finds c' by the cosine of its arc from a: where that
            // arc is short, an f64 rounding of the cosine (1e-16) moves c'
            // by 1e-8 rad, up to 1e-5 of a thin triangle's Ω.
            let allowed = 1e-5 * whole + 1e-12;
            assert!(
                (part - want).abs() <= allowed,
                "{name} at {x}: {part} vs {want} of {whole}"
            );
        }
    }
}

#[test]
fn a_triangle_with_no_area_on_the_sphere_gives_nothing() {
    let d = DVec3::new;
    // Corners on one great circle: the triangle's plane passes through p.
    let flat = unit([d(1.0, 0.0, 0.0), d(0.0, 1.0, 0.0), d(-1.0, 1.0, 0.0)]);
    assert_eq!(sample_spherical_triangle(flat, Vec2::new(0.5, 0.5)), None);
    // Two corners in the same direction.
    let double = unit([d(0.0, 0.0, 1.0), d(0.0, 0.0, 2.0), d(1.0, 0.0, 1.0)]);
    assert_eq!(sample_spherical_triangle(double, Vec2::new(0.5, 0.5)), None);
}
