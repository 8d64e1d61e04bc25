//! Unit tests of `src/core/preview.rs`.

use glam::Vec3;
use raystep::core::film::Film;
use raystep::core::preview::*;

#[test]
fn ascii_ramp_follows_brightness() {
    let mut f = Film::new(4, 2);
    for x in 0..4 {
        for y in 0..2 {
            *f.get_mut(x, y) = Vec3::splat(x as f32 / 3.0);
        }
    }
    let text = preview(&f, 4, PreviewStyle::Ascii);
    // The ramp is spaced in sRGB (perceptual) steps: linear 1/3 is
    // already 61% of the way up.
    assert_eq!(text, " *%@\n");
}

#[test]
fn color_cells_carry_both_pixels() {
    let mut f = Film::new(1, 2);
    *f.get_mut(0, 0) = Vec3::new(1.0, 0.0, 0.0);
    *f.get_mut(0, 1) = Vec3::new(0.0, 0.0, 1.0);
    let text = preview(&f, 1, PreviewStyle::Color);
    assert_eq!(text, "\x1b[38;2;255;0;0m\x1b[48;2;0;0;255m▀\x1b[0m\n");
}
