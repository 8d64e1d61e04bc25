//! Unit tests of `src/ch5_reflection/light/area.rs`.

use glam::{Vec2, Vec3};
use raystep::ch5_reflection::light::area::*;
use raystep::ch5_reflection::radiometry::triangle_solid_angle;
use raystep::scene::mesh::Mesh;
use raystep::scene::LightSampling;

#[test]
fn a_unit_square_light_seen_from_above_has_the_right_pdf() {
    let mesh = Mesh::rectangle(1.0, 1.0); // z = 0, facing +z
    let light = AreaLight::new(&mesh, 0, Vec3::ONE, false).unwrap();
    assert!((light.area - 1.0).abs() < 1e-6);
    let p = Vec3::new(0.0, 0.0, 2.0);
    let s = light.sample_li(p, Vec2::new(0.3, 0.7)).unwrap();
    let y = p + s.wi * s.dist;
    assert!(y.z.abs() < 1e-5);
    let cos = s.wi.z.abs();
    assert!((s.pdf - s.dist * s.dist / cos).abs() < 1e-4 * s.pdf);
    assert!((light.pdf_li(p, y, Vec3::Z) - s.pdf).abs() < 1e-4 * s.pdf);
    // One-sided: nothing reaches a point behind it.
    assert!(light.sample_li(-p, Vec2::new(0.3, 0.7)).is_none());
}

/// The unit square light, facing +z, sampled by solid angle.
fn square_by_solid_angle(two_sided: bool) -> AreaLight {
    AreaLight::new(&Mesh::rectangle(1.0, 1.0), 0, Vec3::ONE, two_sided)
        .unwrap()
        .sampled_by(LightSampling::SolidAngle)
}

/// The solid angle of `light` at `p`, worked out here in f64.
fn omega(light: &AreaLight, p: Vec3) -> f64 {
    let p = p.as_dvec3();
    light
        .triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| v.as_dvec3() - p);
            triangle_solid_angle(a, b, c)
        })
        .sum()
}

#[test]
fn by_solid_angle_every_direction_has_density_one_over_the_solid_angle() {
    let light = square_by_solid_angle(false);
    assert_eq!(light.sampling, LightSampling::SolidAngle);
    // Above the middle, just above a corner (Ω near 2π/4... and near 2π
    // for the middle), beside it nearly in its plane, and 100 sizes away.
    for p in [
        Vec3::new(0.0, 0.0, 2.0),
        Vec3::new(0.1, -0.2, 1e-3),
        Vec3::new(0.5, 0.5, 1e-2),
        Vec3::new(3.0, 0.0, 0.05),
        Vec3::new(0.0, 30.0, 100.0),
    ] {
        let want = (1.0 / omega(&light, p)) as f32;
        for (i, j) in [(0.1, 0.2), (0.5, 0.5), (0.9, 0.99), (0.0, 0.0)] {
            let s = light.sample_li(p, Vec2::new(i, j)).unwrap();
            let y = p + s.wi * s.dist;
            assert!(y.z.abs() < 1e-4 * p.length().max(1.0), "{p}: {y}");
            assert!(
                y.x.abs() <= 0.5 + 1e-4 && y.y.abs() <= 0.5 + 1e-4,
                "{p}: {y}"
            );
            assert!(
                (s.pdf - want).abs() <= 1e-5 * want,
                "{p}: {} vs {want}",
                s.pdf
            );
            assert!((light.pdf_li(p, y, Vec3::Z) - s.pdf).abs() <= 1e-6 * s.pdf);
        }
    }
}

#[test]
fn by_solid_angle_the_back_of_a_one_sided_light_gets_nothing() {
    let p = Vec3::new(0.2, 0.1, -1.0);
    let light = square_by_solid_angle(false);
    assert!(light.sample_li(p, Vec2::new(0.3, 0.7)).is_none());
    // A roof of two triangles: from below, the lower one shows its front
    // and the upper one its back. Directions go to the lower one only,
    // and a point on the upper one has density 0.
    let roof = Mesh {
        positions: vec![
            Vec3::ZERO,
            Vec3::X,
            Vec3::Y,
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(1.0, 0.0, 1.0),
            Vec3::new(0.0, 1.0, 1.0),
        ],
        triangles: vec![[0, 2, 1], [3, 4, 5]],
        ..Mesh::rectangle(1.0, 1.0)
    };
    let light = AreaLight::new(&roof, 0, Vec3::ONE, false)
        .unwrap()
        .sampled_by(LightSampling::SolidAngle);
    let below = Vec3::new(0.2, 0.2, -0.5);
    let lower = {
        let [a, b, c] = light.triangles[0].map(|v| (v - below).as_dvec3());
        triangle_solid_angle(a, b, c)
    };
    for u in [0.01, 0.5, 0.99] {
        let s = light.sample_li(below, Vec2::new(u, 0.5)).unwrap();
        assert!((s.pdf - (1.0 / lower) as f32).abs() < 1e-5 * s.pdf);
        assert!((below + s.wi * s.dist).z.abs() < 1e-5, "on the lower one");
    }
    let on_upper = Vec3::new(0.2, 0.2, 1.0);
    assert_eq!(light.pdf_li(below, on_upper, Vec3::Z), 0.0);
    // A two-sided light is seen from both sides, with the same density.
    let light = square_by_solid_angle(true);
    let s = light.sample_li(p, Vec2::new(0.3, 0.7)).unwrap();
    let above = light.sample_li(-p, Vec2::new(0.3, 0.7)).unwrap();
    assert!((s.pdf - (1.0 / omega(&light, p)) as f32).abs() < 1e-5 * s.pdf);
    assert!((s.pdf - above.pdf).abs() < 1e-5 * s.pdf);
}

#[test]
fn by_solid_angle_the_density_does_not_change_with_the_scale() {
    let u = Vec2::new(0.37, 0.61);
    let p = Vec3::new(0.3, -0.4, 0.7);
    let one = square_by_solid_angle(false).sample_li(p, u).unwrap();
    for scale in [1e-3f32, 1e3] {
        let mut mesh = Mesh::rectangle(1.0, 1.0);
        mesh.positions.iter_mut().for_each(|v| *v *= scale);
        let light = AreaLight::new(&mesh, 0, Vec3::ONE, false)
            .unwrap()
            .sampled_by(LightSampling::SolidAngle);
        let s = light.sample_li(p * scale, u).unwrap();
        assert!((s.pdf - one.pdf).abs() < 1e-5 * one.pdf, "×{scale}");
        assert!((s.wi - one.wi).length() < 1e-5, "×{scale}");
        assert!(
            (s.dist / scale - one.dist).abs() < 1e-5 * one.dist,
            "×{scale}"
        );
    }
}

#[test]
fn a_light_too_small_or_too_finely_cut_is_sampled_by_area() {
    // 2,000 sizes away the square covers 2.5e-7 sr: by area, as its pdf
    // shows (d² / cos θl, not 1 / Ω).
    let light = square_by_solid_angle(false);
    let p = Vec3::new(0.0, 0.0, 2000.0);
    let s = light.sample_li(p, Vec2::new(0.5, 0.5)).unwrap();
    let by_area = s.dist * s.dist / s.wi.z.abs();
    assert!(
        (s.pdf - by_area).abs() < 1e-4 * by_area,
        "{} vs {by_area}",
        s.pdf
    );
    // A light of more triangles than the limit is never sampled by solid
    // angle: a strip of 9 squares, 18 triangles.
    let mut mesh = Mesh::rectangle(1.0, 1.0);
    let square = mesh.clone();
    for k in 1..9 {
        let base = mesh.positions.len() as u32;
        let shift = Vec3::new(k as f32, 0.0, 0.0);
        mesh.positions
            .extend(square.positions.iter().map(|v| *v + shift));
        mesh.triangles
            .extend(square.triangles.iter().map(|t| t.map(|i| i + base)));
    }
    assert!(mesh.triangles.len() > SOLID_ANGLE_MAX_TRIANGLES);
    let light = AreaLight::new(&mesh, 0, Vec3::ONE, false)
        .unwrap()
        .sampled_by(LightSampling::SolidAngle);
    assert_eq!(light.sampling, LightSampling::Area);
}

#[test]
fn by_solid_angle_a_point_on_the_light_itself_sees_it_edge_on() {
    // A path that bounces off the light's own surface: its point is
    // rounded to a hair in front of the plane or behind it. Either way the
    // light covers no solid angle there (it would cover 2π from just in
    // front), as chapter 3's offset says: too close to tell.
    let light = square_by_solid_angle(false);
    for h in [1e-9f32, 0.0, -1e-9] {
        let p = Vec3::new(0.1, 0.2, h);
        for u in [Vec2::new(0.2, 0.3), Vec2::new(0.8, 0.9)] {
            let s = light.sample_li(p, u);
            assert!(s.is_none_or(|s| s.pdf > 1e3), "at {h}: {s:?}");
        }
        assert!(light.pdf_li(p, Vec3::new(-0.1, 0.0, 0.0), Vec3::Z) != 1.0 / std::f32::consts::TAU);
    }
}
