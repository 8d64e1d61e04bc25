//! `core::zview`: z per pixel, and the block verdict of "noise or wrong?".

use glam::Vec3;
use raystep::core::film::Film;
use raystep::core::zview::{verdict, z_film, BLOCK, NOISELESS, Z_MAX};

fn flat(w: u32, h: u32, v: f32) -> Film {
    let mut f = Film::new(w, h);
    f.pixels.iter_mut().for_each(|p| *p = Vec3::splat(v));
    f
}

/// A noisy "render" of a flat reference 0.5: each pixel off by a
/// deterministic pseudo-random amount of standard deviation `sigma`, plus
/// `bias`, with its standard error reported as `sigma`.
fn noisy(w: u32, h: u32, sigma: f32, bias: f32) -> (Film, Film) {
    let mut f = flat(w, h, 0.5 + bias);
    let mut s = 0x9e37_79b9_u32;
    for p in f.pixels.iter_mut() {
        // Sum of 4 uniforms: about normal, variance 4/12.
        let mut u = 0.0;
        for _ in 0..4 {
            s ^= s << 13;
            s ^= s >> 17;
            s ^= s << 5;
            u += s as f32 / u32::MAX as f32 - 0.5;
        }
        *p += Vec3::splat(sigma * u / (4.0f32 / 12.0).sqrt());
    }
    (f, flat(w, h, sigma))
}

#[test]
fn z_is_the_difference_over_the_combined_standard_error() {
    let render = flat(2, 1, 0.8);
    let reference = flat(2, 1, 0.5);
    let z = z_film(&render, &flat(2, 1, 0.3), &reference, &flat(2, 1, 0.4));
    // 0.3 / √(0.09 + 0.16) = 0.6
    assert!(
        (z.pixels[0] - Vec3::splat(0.6)).abs().max_element() < 1e-6,
        "{}",
        z.pixels[0]
    );
    // No noise at all: equal is 0, different is a difference no noise explains.
    let z0 = z_film(&render, &flat(2, 1, 0.0), &render, &flat(2, 1, 0.0));
    assert_eq!(z0.pixels[0], Vec3::ZERO);
    let zd = z_film(&render, &flat(2, 1, 0.0), &reference, &flat(2, 1, 0.0));
    assert_eq!(zd.pixels[0], Vec3::splat(NOISELESS));
    // A pixel whose few samples happened to agree (standard error 0)
    // takes its block's noise, not none.
    let mut err = flat(8, 8, 0.2);
    err.pixels[9] = Vec3::ZERO;
    let z = z_film(&flat(8, 8, 0.7), &err, &flat(8, 8, 0.5), &flat(8, 8, 0.0));
    // The block's variance: 63 pixels of 0.04 and one of 0 → 0.039375.
    let want = 0.2 / 0.039375f32.sqrt();
    assert!(
        (z.pixels[9].x - want).abs() < 1e-4,
        "{} vs {want}",
        z.pixels[9]
    );
    // A NaN stays a NaN (the view paints it green).
    let mut bad = render.clone();
    bad.pixels[1] = Vec3::splat(f32::NAN);
    assert!(z_film(&bad, &flat(2, 1, 0.1), &reference, &flat(2, 1, 0.1)).pixels[1].is_nan());
}

#[test]
fn noise_is_within_noise_and_a_bias_of_a_few_standard_errors_per_block_is_not() {
    let (w, h) = (64, 64);
    let reference = flat(w, h, 0.5);
    let ref_err = flat(w, h, 0.0);
    let (render, err) = noisy(w, h, 0.1, 0.0);
    let v = verdict(&render, &err, &reference, &ref_err);
    assert_eq!(v.blocks, ((w / BLOCK) * (h / BLOCK)) as usize);
    assert!(v.within_noise(), "{v:?}");
    assert_eq!(v.lines()[0], "verdict: within noise");
    // A block's mean has standard error 0.1 / 8 = 0.0125: a bias of 0.1
    // (20%) is z = 8, past the limit of 5, everywhere.
    let (biased, err) = noisy(w, h, 0.1, 0.1);
    let v = verdict(&biased, &err, &reference, &ref_err);
    assert!(!v.within_noise() && v.worst_z > Z_MAX, "{v:?}");
    let [first, second] = v.lines();
    assert!(
        first.starts_with("verdict: biased, 2") && first.ends_with("% brighter"),
        "{first}"
    );
    assert!(second.contains("|z|"), "{second}");
    // Darker, and a NaN.
    let (dark, err) = noisy(w, h, 0.1, -0.1);
    assert!(verdict(&dark, &err, &reference, &ref_err).lines()[0].ends_with("darker"));
    // A block whose samples all agreed (variance 0, a light no sample
    // found yet) is too few samples, not a bias.
    let (mut dark, mut err) = noisy(w, h, 0.1, 0.0);
    for y in 0..8 {
        for x in 0..8 {
            *dark.get_mut(x, y) = Vec3::ZERO;
            *err.get_mut(x, y) = Vec3::ZERO;
        }
    }
    let v = verdict(&dark, &err, &reference, &flat(w, h, 0.001));
    assert!(v.unseen && !v.within_noise(), "{v:?}");
    assert_eq!(v.lines()[0], "verdict: too few samples");
    let mut nan = render.clone();
    nan.pixels[100] = Vec3::splat(f32::NAN);
    let v = verdict(&nan, &err, &reference, &ref_err);
    assert_eq!(v.lines()[0], "verdict: wrong, not a number");
    assert_eq!(v.at, (32, 0), "the block holding pixel (36, 1)");
}
