//! The warp test itself: the χ² survival function against known values,
//! the built-in routines accepted, and wrong routines rejected.

use glam::{Vec2, Vec3};
use raystep::ch5_reflection::warp::{cosine_hemisphere, uniform_hemisphere};
use raystep::ch5_reflection::warp_test::ROUTINES;
use raystep::core::warp_test::{
    chi2_survival, ln_gamma, pearson, run, Warp, COS_CELLS, DEFAULT_DRAWS, PHI_CELLS,
};

#[test]
fn chi2_survival_matches_tables_and_closed_forms() {
    // Two degrees of freedom: Q = e^(−x/2) exactly.
    for x in [0.1, 1.0, 4.0, 20.0] {
        let q = chi2_survival(x, 2);
        assert!((q - (-x / 2.0f64).exp()).abs() < 1e-12, "x {x}: {q}");
    }
    // Table values: the 5% and 1% points.
    for (x, dof, p) in [
        (3.841_458_820_694_124, 1, 0.05),
        (18.307_038_053_275_146, 10, 0.05),
        (23.209_251_158_954_356, 10, 0.01),
        (135.806_723_442_190_3, 100, 0.01),
        (553.127_039_9, 500, 0.05),
    ] {
        let q = chi2_survival(x, dof);
        assert!(
            (q - p).abs() < 1e-6 * p.max(1e-3) * 1e3,
            "dof {dof}: {q} vs {p}"
        );
    }
    assert_eq!(chi2_survival(0.0, 5), 1.0);
    assert_eq!(chi2_survival(f64::INFINITY, 5), 0.0);
    assert_eq!(chi2_survival(f64::NAN, 5), 0.0);
    assert!((ln_gamma(5.0) - 24f64.ln()).abs() < 1e-12);
    assert!((ln_gamma(0.5) - std::f64::consts::PI.sqrt().ln()).abs() < 1e-12);
}

#[test]
fn pearson_pools_small_cells_and_counts_degrees_of_freedom() {
    // Three cells of 10 expected, one of 1 pooled with the lost cell's 2.
    let (stat, dof) = pearson(
        &[12.0, 8.0, 10.0, 0.0],
        &[10.0, 10.0, 10.0, 1.0],
        (3.0, 2.0),
    );
    // 0.4 + 0.4 + 0 for the big cells; the pool (3 vs 3 < 5) has no draws
    // missing, so it adds (3 − 3)² / max(3, 1) = 0.
    assert!((stat - 0.8).abs() < 1e-12, "{stat}");
    assert_eq!(dof, 3);
}

#[test]
fn the_built_in_routines_are_accepted() {
    for (index, routine) in ROUTINES.iter().enumerate() {
        for seed in [1, 2] {
            let t = routine.run(DEFAULT_DRAWS, seed);
            assert!(t.passes(), "{}: {}", t.name, t.verdict());
            assert_eq!(t.observed.len(), COS_CELLS * PHI_CELLS);
            // A hemisphere covers half the cells (the semi-gloss paint's
            // diffuse base too); the light, seen from the origin, and the
            // glossy lobe far fewer.
            let cells = if matches!(index, 2 | 3 | 5) { 40 } else { 200 };
            assert!(t.dof > cells, "{}: {} degrees of freedom", t.name, t.dof);
            let total: f64 = t.observed.iter().sum::<f64>() + t.lost.0;
            assert_eq!(total, DEFAULT_DRAWS as f64);
        }
    }
    // The area light misses no draw and expects none lost, by area or by
    // solid angle.
    for index in [2, 5] {
        let t = ROUTINES[index].run(10_000, 3);
        assert_eq!(t.lost.0, 0.0);
        assert!(t.lost.1 < 1.0, "{:?}", t.lost);
    }
}

#[test]
fn wrong_routines_are_rejected() {
    // Uniform directions claimed to be cosine-distributed.
    let t = run(
        &Warp {
            name: "uniform as cosine",
            sample: &|u| Some(uniform_hemisphere(u)),
            pdf: &|w| (w.z / std::f32::consts::PI).max(0.0),
        },
        DEFAULT_DRAWS,
        1,
    );
    assert!(!t.passes(), "{}", t.verdict());
    assert!(t.p_value < 1e-9, "{}", t.verdict());
    // Malley's method without the square root: r = u instead of √u.
    let t = run(
        &Warp {
            name: "no square root",
            sample: &|u: Vec2| {
                let (r, phi) = (u.x, 2.0 * std::f32::consts::PI * u.y);
                let z = (1.0 - r * r).max(0.0).sqrt();
                Some(Vec3::new(r * phi.cos(), r * phi.sin(), z))
            },
            pdf: &|w| (w.z / std::f32::consts::PI).max(0.0),
        },
        DEFAULT_DRAWS,
        1,
    );
    assert!(!t.passes(), "{}", t.verdict());
    // The right directions, a lower hemisphere: all mass where the pdf
    // says none.
    let t = run(
        &Warp {
            name: "flipped",
            sample: &|u| Some(-cosine_hemisphere(u)),
            pdf: &|w| (w.z / std::f32::consts::PI).max(0.0),
        },
        10_000,
        1,
    );
    assert!(!t.passes(), "{}", t.verdict());
    // Not unit length.
    let t = run(
        &Warp {
            name: "long",
            sample: &|u| Some(2.0 * cosine_hemisphere(u)),
            pdf: &|w| (w.z / std::f32::consts::PI).max(0.0),
        },
        1000,
        1,
    );
    assert_eq!(t.bad, 1000);
    assert!(
        !t.passes() && t.verdict().contains("not unit length"),
        "{}",
        t.verdict()
    );
}
