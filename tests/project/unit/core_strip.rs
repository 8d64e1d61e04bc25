//! Unit tests of `src/core/strip.rs`.

use raystep::core::film::Film;
use raystep::core::strip::*;

fn at(px: &[u8], w: u32, x: u32, y: u32) -> (u8, u8, u8) {
    let i = ((y * w + x) * 3) as usize;
    (px[i], px[i + 1], px[i + 2])
}

#[test]
fn a_strip_keeps_its_images_and_captions_them() {
    let mut red = Film::new(40, 30);
    red.pixels.fill(glam::Vec3::X);
    let blue = Film {
        pixels: vec![glam::Vec3::Z; 40 * 30],
        ..Film::new(40, 30)
    };
    let (px, w, h) = captioned_strip(&[(&red, "one"), (&blue, "two")]).unwrap();
    assert_eq!((w, h), (82, 52));
    assert_eq!(at(&px, w, 10, 10), (255, 0, 0));
    assert_eq!(at(&px, w, 60, 10), (0, 0, 255));
    // The gap stays white, and the caption band has dark text.
    assert_eq!(at(&px, w, 40, 10), (255, 255, 255));
    let band = &px[(30 * w * 3) as usize..];
    assert!(band.chunks(3).filter(|p| p[0] < 100).count() > 20);
}
