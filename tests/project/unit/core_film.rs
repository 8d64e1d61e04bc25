//! Unit tests of `src/core/film.rs`.

use glam::Vec3;
use raystep::core::film::*;

#[test]
fn srgb_round_trips_every_byte() {
    for v in 0..=255u8 {
        assert_eq!(encode_srgb(decode_srgb(v)), v);
    }
}

#[test]
fn scrub_counts_and_zeroes_nonfinite() {
    let mut f = Film::new(2, 1);
    f.pixels[0] = Vec3::new(f32::NAN, 1.0, f32::INFINITY);
    assert_eq!(f.scrub_nonfinite(), 1);
    assert_eq!(f.pixels[0], Vec3::new(0.0, 1.0, 0.0));
}
