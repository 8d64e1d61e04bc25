//! Unit tests of `src/ch6_global_illumination/sampler.rs`.

use raystep::ch6_global_illumination::sampler::*;
use raystep::core::sampling::mix64;

#[test]
fn sobol_numbers_are_the_crates_one_dimension_at_a_time() {
    // The group-of-four shortcut returns exactly what one-at-a-time
    // sampling of the same dimension and scramble returns.
    for sample in [0u64, 1, 5, 63, 1000] {
        let mut p = PathSampler::new(SamplerKind::Sobol, 9, 123, sample);
        for d in 0..24u64 {
            let scramble = mix64(p.pixel_scramble() ^ (d / 4)) as u32;
            let one = sobol_burley::sample(sample as u32, (d % 4) as u32, scramble)
                .min(1.0 - f32::EPSILON / 2.0);
            assert_eq!(p.next(), one, "sample {sample}, dimension {d}");
        }
    }
}

#[test]
fn independent_numbers_are_exactly_sampling_random() {
    for d in 0..40 {
        let mut p = PathSampler::new(SamplerKind::Independent, 5, 77, 3);
        for _ in 0..d {
            p.next();
        }
        assert_eq!(p.next(), raystep::core::sampling::random(5, 77, 3, d));
    }
}

#[test]
fn both_samplers_are_uniform_and_sobol_is_more_even() {
    // Estimate ∫∫ x y over [0,1)² = 1/4 with 256 points per pixel, for
    // 64 pixels: Sobol's error must be far smaller than independent's.
    let mut err = [0.0f64; 2];
    for (k, kind) in [SamplerKind::Independent, SamplerKind::Sobol]
        .into_iter()
        .enumerate()
    {
        for pixel in 0..64 {
            let mut sum = 0.0f64;
            for s in 0..256 {
                let mut p = PathSampler::new(kind, 3, pixel, s);
                p.next2();
                let u = p.next2();
                assert!((0.0..1.0).contains(&u.x) && (0.0..1.0).contains(&u.y));
                sum += (u.x * u.y) as f64;
            }
            err[k] += (sum / 256.0 - 0.25).powi(2);
        }
    }
    assert!(err[1] * 10.0 < err[0], "{err:?}");
}
