//! Every chapter 5 BRDF, checked against its definition: the pdf integrates
//! to the fraction of draws that return a direction, sample() follows pdf()
//! (χ² on a grid of incident angles), the weight is f cos θ / pdf, no
//! material reflects more than arrives (white furnace by quadrature and by
//! sampling), and f is reciprocal.

use crate::common;
use common::chi2::{chi2, expected_mass, p_value};
use glam::{Vec2, Vec3};
use raystep::ch5_reflection::material::glossy::Glossy;
use raystep::ch5_reflection::material::lambert::Lambertian;
use raystep::ch5_reflection::material::retro::Retro;
use raystep::ch5_reflection::material::semigloss::SemiGloss;
use raystep::ch5_reflection::material::Bsdf;
use raystep::core::sampling::random;

fn bsdfs() -> Vec<(&'static str, Bsdf)> {
    vec![
        ("lambert", Bsdf::Lambertian(Lambertian { rho: Vec3::ONE })),
        (
            "glossy n=1",
            Bsdf::Glossy(Glossy {
                rs: Vec3::ONE,
                n: 1.0,
            }),
        ),
        (
            "glossy n=30",
            Bsdf::Glossy(Glossy {
                rs: Vec3::ONE,
                n: 30.0,
            }),
        ),
        (
            "retro n=4",
            Bsdf::Retro(Retro {
                rho: Vec3::ONE,
                n: 4.0,
            }),
        ),
        (
            "retro n=30",
            Bsdf::Retro(Retro {
                rho: Vec3::ONE,
                n: 30.0,
            }),
        ),
        (
            "semigloss",
            Bsdf::SemiGloss(SemiGloss {
                rho: Vec3::ONE,
                ks: 0.3,
                n: 20.0,
            }),
        ),
    ]
}

/// ωo at θo degrees from the normal (φ = 0.7 rad, off any axis).
fn wo_at(theta_deg: f32) -> Vec3 {
    let t = theta_deg.to_radians();
    Vec3::new(t.sin() * 0.7f32.cos(), t.sin() * 0.7f32.sin(), t.cos())
}

const ANGLES: [f32; 4] = [0.0, 35.0, 65.0, 85.0];

fn draws(
    b: &Bsdf,
    wo: Vec3,
    n: usize,
    seed: u64,
) -> Vec<raystep::ch5_reflection::material::BsdfSample> {
    (0..n as u64)
        .filter_map(|i| {
            let u = Vec2::new(random(seed, i, 0, 0), random(seed, i, 0, 1));
            b.sample(wo, u, random(seed, i, 0, 2))
        })
        .collect()
}

#[test]
fn every_pdf_integrates_to_the_fraction_of_draws_that_succeed() {
    for (name, b) in bsdfs() {
        for theta in ANGLES {
            let wo = wo_at(theta);
            let total: f64 = expected_mass(&|w| b.pdf(wo, w), 12).iter().sum();
            let n = 20_000;
            let kept = draws(&b, wo, n, 1).len() as f64 / n as f64;
            // The kept fraction is binomial: σ ≤ 0.5/√n ≈ 0.0035.
            assert!(
                (total - kept).abs() < 0.015,
                "{name} at {theta}°: ∫pdf = {total}, kept {kept}"
            );
            if name == "lambert" {
                assert!((total - 1.0).abs() < 2e-3, "{name}: {total}");
            }
        }
    }
}

#[test]
fn samples_follow_the_pdf_chi_square() {
    for (name, b) in bsdfs() {
        for theta in ANGLES {
            let wo = wo_at(theta);
            let mass = expected_mass(&|w| b.pdf(wo, w), 12);
            let n = 40_000;
            let got: Vec<Vec3> = draws(&b, wo, n, 2).iter().map(|s| s.wi).collect();
            let (stat, dof) = chi2(&got, n, &mass);
            let p = p_value(stat, dof);
            // 24 tests: reject only below 1e-4 each.
            assert!(
                p > 1e-4,
                "{name} at {theta}°: χ² = {stat:.1} on {dof} dof, p = {p:e}"
            );
        }
    }
    // The test has power: a sampler that ignores the lobe fails.
    let b = Bsdf::Glossy(Glossy {
        rs: Vec3::ONE,
        n: 30.0,
    });
    let wo = wo_at(35.0);
    let mass = expected_mass(&|w| b.pdf(wo, w), 12);
    let n = 40_000;
    let lambert = Bsdf::Lambertian(Lambertian { rho: Vec3::ONE });
    let wrong: Vec<Vec3> = draws(&lambert, wo, n, 3).iter().map(|s| s.wi).collect();
    let (stat, dof) = chi2(&wrong, n, &mass);
    assert!(p_value(stat, dof) < 1e-10);
}

#[test]
fn weights_are_f_cos_over_pdf_and_f_is_reciprocal() {
    for (name, b) in bsdfs() {
        for theta in ANGLES {
            let wo = wo_at(theta);
            for s in draws(&b, wo, 2000, 4) {
                let want = b.f(wo, s.wi) * s.wi.z.abs() / b.pdf(wo, s.wi);
                assert!(
                    (s.weight - want).abs().max_element() <= 1e-4 * want.max_element().max(1.0),
                    "{name}: {} vs {want}",
                    s.weight
                );
                assert!((s.pdf - b.pdf(wo, s.wi)).abs() <= 1e-4 * s.pdf);
                let (a, c) = (b.f(wo, s.wi), b.f(s.wi, wo));
                assert!(
                    (a - c).abs().max_element() <= 1e-4 * a.max_element().max(1e-3),
                    "{name}: f(wo, wi) = {a}, f(wi, wo) = {c}"
                );
            }
        }
    }
}

/// ∫ f(ωo, ωi) cos θi dωi by a midpoint rule in (cos θ, φ) over ωo's side.
fn albedo_by_quadrature(b: &Bsdf, wo: Vec3) -> f64 {
    let (nc, np) = (400, 400);
    let mut sum = 0.0;
    for i in 0..nc {
        let z = (i as f64 + 0.5) / nc as f64;
        let r = (1.0 - z * z).sqrt();
        for j in 0..np {
            let phi = 2.0 * std::f64::consts::PI * (j as f64 + 0.5) / np as f64;
            let wi = Vec3::new((r * phi.cos()) as f32, (r * phi.sin()) as f32, z as f32);
            sum += b.f(wo, wi).x as f64 * z;
        }
    }
    sum * 2.0 * std::f64::consts::PI / (nc * np) as f64
}

#[test]
fn no_brdf_reflects_more_than_arrives_white_furnace() {
    for (name, b) in bsdfs() {
        for theta in [0.0, 20.0, 35.0, 50.0, 65.0, 80.0, 89.0] {
            let wo = wo_at(theta);
            let quad = albedo_by_quadrature(&b, wo);
            assert!(quad <= 1.0 + 2e-3, "{name} at {theta}°: albedo {quad}");
            // By sampling: the mean weight, with its standard error.
            let n = 20_000;
            let w: Vec<f64> = draws(&b, wo, n, 5)
                .iter()
                .map(|s| s.weight.x as f64)
                .collect();
            let mean = w.iter().sum::<f64>() / n as f64;
            let var = w.iter().map(|x| x * x).sum::<f64>() / n as f64 - mean * mean;
            let se = (var.max(0.0) / n as f64).sqrt();
            assert!(
                (mean - quad).abs() < 5.0 * se + 3e-3,
                "{name} at {theta}°: sampled {mean} ± {se}, quadrature {quad}"
            );
            assert!(mean <= 1.0 + 5.0 * se, "{name} at {theta}°: {mean}");
        }
    }
    // Known values at normal incidence: Lambert reflects ρ, the glossy and
    // retro lobes their ρ exactly (that is what the normalisation is for).
    for (name, b) in bsdfs() {
        let a = albedo_by_quadrature(&b, Vec3::Z);
        if !name.starts_with("semi") {
            assert!((a - 1.0).abs() < 5e-3, "{name}: {a}");
        }
    }
}

#[test]
fn erfc_matches_known_values() {
    // erfc(0) = 1, erfc(1) = 0.157299207, erfc(-1) = 1.842700793.
    for (x, want) in [
        (0.0, 1.0),
        (1.0, 0.157299207),
        (-1.0, 1.842700793),
        (2.0, 0.004677735),
    ] {
        assert!(
            (common::chi2::erfc(x) - want).abs() < 2e-7,
            "erfc({x}) = {}",
            common::chi2::erfc(x)
        );
    }
}
