//! `core::zview`: z per pixel, and the block verdict of "noise or wrong?".

use glam::Vec3;
use raystep::core::film::Film;
use raystep::core::zview::{verdict, verdict_at, z_film, BLOCK, MIN_EFFECTIVE, NOISELESS, Z_MAX};

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
    let v = verdict(&render, &err, &reference, &ref_err, (16, 0));
    assert_eq!(v.blocks, ((w / BLOCK) * (h / BLOCK)) as usize);
    assert!(v.within_noise(), "{v:?}");
    assert_eq!(v.lines()[0], "verdict: within noise");
    // A block's mean has standard error 0.1 / 8 = 0.0125: a bias of 0.1
    // (20%) is z = 8, past the limit of 5, everywhere.
    let (biased, err) = noisy(w, h, 0.1, 0.1);
    let v = verdict(&biased, &err, &reference, &ref_err, (16, 0));
    assert!(!v.within_noise() && v.worst_z > Z_MAX, "{v:?}");
    let [first, second] = v.lines();
    assert!(
        first.starts_with("verdict: biased, 2") && first.ends_with("% brighter"),
        "{first}"
    );
    assert!(second.contains("|z|"), "{second}");
    // Darker, and a NaN.
    let (dark, err) = noisy(w, h, 0.1, -0.1);
    assert!(verdict(&dark, &err, &reference, &ref_err, (16, 0)).lines()[0].ends_with("darker"));
    // A block whose samples all agreed (variance 0, a light no sample
    // found yet) is too few samples, not a bias.
    let (mut dark, mut err) = noisy(w, h, 0.1, 0.0);
    for y in 0..8 {
        for x in 0..8 {
            *dark.get_mut(x, y) = Vec3::ZERO;
            *err.get_mut(x, y) = Vec3::ZERO;
        }
    }
    let v = verdict(&dark, &err, &reference, &flat(w, h, 0.001), (16, 0));
    assert!(v.unseen && !v.within_noise(), "{v:?}");
    assert_eq!(v.lines()[0], "verdict: too few samples");
    let mut nan = render.clone();
    nan.pixels[100] = Vec3::splat(f32::NAN);
    let v = verdict(&nan, &err, &reference, &ref_err, (16, 0));
    assert_eq!(v.lines()[0], "verdict: wrong, not a number");
    assert_eq!(v.at, (32, 0), "the block holding pixel (36, 1)");
}

#[test]
fn a_block_carried_by_a_few_rare_samples_is_too_few_samples_not_a_bias() {
    // The reference is 0.5 everywhere. In the render's first block, 62
    // pixels' 16 samples found nothing and two pixels found one sample of
    // 10 each (a rare lamp): the block is 96% darker with a small
    // standard error, z ≈ 35, yet its light rests on two samples.
    let (w, h) = (64, 64);
    let reference = flat(w, h, 0.5);
    let (mut render, mut err) = noisy(w, h, 0.1, 0.0);
    let n = 16.0f32;
    for y in 0..8 {
        for x in 0..8 {
            let hit = (x, y) == (2, 3) || (x, y) == (6, 1);
            let (m, var) = match hit {
                true => (10.0 / n, (100.0 - n * (10.0 / n) * (10.0 / n)) / (n - 1.0)),
                false => (0.0, 0.0),
            };
            *render.get_mut(x, y) = Vec3::splat(m);
            *err.get_mut(x, y) = Vec3::splat((var / n).sqrt());
        }
    }
    let v = verdict(&render, &err, &reference, &flat(w, h, 0.001), (16, 0));
    assert!(!v.within_noise() && !v.unseen, "{v:?}");
    assert!(v.effective < 3.0, "two samples carry it: {}", v.effective);
    let [first, second] = v.lines();
    assert_eq!(first, "verdict: too few samples");
    assert!(second.contains("~2 samples carry it"), "{second}");
    // The same with the two sides swapped: a pinned render of 16 samples
    // per pixel as the reference. Its effective samples count too; a
    // stored reference's (0: not counted) do not.
    let v = verdict(&reference, &flat(w, h, 0.001), &render, &err, (1024, 16));
    assert_eq!(v.lines()[0], "verdict: too few samples", "{v:?}");
    let v = verdict(&reference, &flat(w, h, 0.001), &render, &err, (1024, 0));
    assert!(v.lines()[0].starts_with("verdict: biased"), "{v:?}");
    // The same bias spread over every sample is a bias: 0.5 → 0.02.
    let dark = flat(w, h, 0.02);
    let v = verdict(
        &dark,
        &flat(w, h, 0.001),
        &reference,
        &flat(w, h, 0.001),
        (16, 0),
    );
    assert!(v.effective > MIN_EFFECTIVE, "{v:?}");
    assert!(
        v.lines()[0].starts_with("verdict: biased"),
        "{:?}",
        v.lines()
    );
}

#[test]
fn an_enlarged_noisy_reference_is_compared_at_its_own_resolution() {
    // A 32² reference with noise of standard error 0.05, enlarged 4 times
    // to the render's 128²; the render is the truth with tiny noise.
    // Counted pixel by pixel, each reference value would count 16 times as
    // 16 independent measurements, and its noise would read as a bias.
    let k = 4;
    let (small, small_err) = noisy(32, 32, 0.05, 0.0);
    let enlarge = |f: &Film| {
        let mut out = Film::new(32 * k, 32 * k);
        for y in 0..32 * k {
            for x in 0..32 * k {
                *out.get_mut(x, y) = f.get(x / k, y / k);
            }
        }
        out
    };
    let (reference, reference_err) = (enlarge(&small), enlarge(&small_err));
    let (render, render_err) = (flat(128, 128, 0.5), flat(128, 128, 0.001));
    let pixelwise = verdict(&render, &render_err, &reference, &reference_err, (64, 0));
    assert!(!pixelwise.within_noise(), "the miscount: {pixelwise:?}");
    let v = verdict_at(k, &render, &render_err, &reference, &reference_err, (64, 0));
    assert!(v.within_noise(), "{v:?}");
    assert_eq!(v.blocks, 16, "blocks of 8 x 8 reference pixels");
    // A real bias is still seen, and placed in the render's pixels.
    let mut biased = render.clone();
    for y in 64..96 {
        for x in 32..64 {
            *biased.get_mut(x, y) = Vec3::splat(0.6);
        }
    }
    let v = verdict_at(k, &biased, &render_err, &reference, &reference_err, (64, 0));
    assert!(!v.within_noise(), "{v:?}");
    assert_eq!(v.at, (32, 64));
}
