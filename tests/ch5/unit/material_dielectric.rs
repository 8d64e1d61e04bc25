//! Unit tests of `src/ch5_reflection/material/dielectric.rs`.

use glam::Vec3;
use raystep::ch5_reflection::material::dielectric::*;

#[test]
fn normal_incidence_reflects_the_textbook_four_percent() {
    let g = Dielectric { ior: 1.5 };
    let (f, _) = g.fresnel(Vec3::Z);
    assert!((f - 0.04).abs() < 1e-6, "{f}");
    // The same from inside.
    let (f, _) = g.fresnel(-Vec3::Z);
    assert!((f - 0.04).abs() < 1e-6, "{f}");
}

#[test]
fn snell_holds_and_total_internal_reflection_starts_at_the_critical_angle() {
    let g = Dielectric { ior: 1.5 };
    let theta = 50f32.to_radians();
    let wo = Vec3::new(theta.sin(), 0.0, theta.cos());
    let wi = refract_local(wo, 1.0 / 1.5).unwrap();
    // η_o sin θ_o = η_i sin θ_i, and wi is on the other side.
    assert!((theta.sin() - 1.5 * wi.x.abs()).abs() < 1e-5);
    assert!(wi.z < 0.0 && (wi.length() - 1.0).abs() < 1e-5);
    // From inside, beyond asin(1/1.5) ≈ 41.8°: everything reflects.
    let crit = (1.0f32 / 1.5).asin();
    for (deg, tir) in [(-0.5f32, false), (0.5, true)] {
        let a = crit + deg.to_radians();
        let wo = Vec3::new(a.sin(), 0.0, -a.cos());
        assert_eq!(g.fresnel(wo).0 == 1.0, tir, "{deg}");
        assert_eq!(refract_local(wo, 1.5).is_none(), tir);
        if tir {
            for u in [0.0, 0.5, 0.999] {
                let s = g.sample(wo, u).unwrap();
                assert_eq!(s.wi, Vec3::new(-wo.x, -wo.y, wo.z));
            }
        }
    }
}

#[test]
fn index_one_passes_straight_through() {
    let g = Dielectric { ior: 1.0 };
    let wo = Vec3::new(0.3, -0.4, 0.5).normalize();
    for u in [0.0, 0.5, 0.999] {
        let s = g.sample(wo, u).unwrap();
        assert!((s.wi + wo).length() < 1e-6);
        assert_eq!(s.weight, Vec3::ONE);
    }
}

#[test]
fn reflectance_and_transmittance_sum_to_one() {
    // The expected weight of a sample, without the radiance scaling, is
    // F · 1 + (1 - F) · 1 = 1: no energy is lost or made.
    let g = Dielectric { ior: 1.7 };
    for k in 1..20 {
        let a = k as f32 * 0.078;
        for wo in [
            Vec3::new(a.sin(), 0.0, a.cos()),
            Vec3::new(a.sin(), 0.0, -a.cos()),
        ] {
            let (f, eta) = g.fresnel(wo);
            assert!((0.0..=1.0).contains(&f));
            let mut sum = 0.0;
            let n = 1000;
            for i in 0..n {
                let s = g.sample(wo, (i as f32 + 0.5) / n as f32).unwrap();
                let scale = if s.wi.z * wo.z > 0.0 { 1.0 } else { eta * eta };
                sum += s.weight.x / scale;
            }
            assert!((sum / n as f32 - 1.0).abs() < 1e-5);
        }
    }
}
