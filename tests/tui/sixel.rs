//! The preview's sixel encoder: a picture decodes back to the palette
//! entry of every pixel, the palette fits a VT340-class terminal's 256
//! registers, and the ordered dither keeps a tile's mean colour.

use image::{Rgb, RgbImage};
use raystep::tui::sixel::{encode, palette_colour, palette_index};

/// A decoded picture: its raster size, its palette (0..=100 per channel)
/// and each pixel's colour register, by row.
type Decoded = ((u32, u32), Vec<[u32; 3]>, Vec<Vec<Option<usize>>>);

/// A sixel decoder of what [`encode`] writes.
fn decode(s: &str) -> Decoded {
    let body = s.strip_prefix("\x1bP0;1;0q\"1;1;").expect("the header");
    let body = body.strip_suffix("\x1b\\").expect("the terminator");
    let size_end = body.find('#').unwrap();
    let (w, h) = body[..size_end].split_once(';').unwrap();
    let (w, h): (u32, u32) = (w.parse().unwrap(), h.parse().unwrap());
    let mut pixels = vec![vec![None; w as usize]; h as usize];
    let mut palette = vec![[0; 3]; 256];
    let chars: Vec<char> = body[size_end..].chars().collect();
    let (mut i, mut colour, mut x, mut band) = (0, 0usize, 0usize, 0usize);
    let number = |i: &mut usize| {
        let start = *i;
        while chars[*i].is_ascii_digit() {
            *i += 1;
        }
        chars[start..*i]
            .iter()
            .collect::<String>()
            .parse::<usize>()
            .unwrap()
    };
    while i < chars.len() {
        match chars[i] {
            '#' => {
                i += 1;
                colour = number(&mut i);
                if chars.get(i) == Some(&';') {
                    i += 3; // ";2;"
                    let r = number(&mut i);
                    i += 1;
                    let g = number(&mut i);
                    i += 1;
                    let b = number(&mut i);
                    palette[colour] = [r as u32, g as u32, b as u32];
                }
            }
            '$' => {
                x = 0;
                i += 1;
            }
            '-' => {
                (x, band) = (0, band + 1);
                i += 1;
            }
            c => {
                let run = match c {
                    '!' => {
                        i += 1;
                        number(&mut i)
                    }
                    _ => 1,
                };
                let bits = chars[i] as u32 - 63;
                for _ in 0..run {
                    for dy in 0..6 {
                        if bits & (1 << dy) != 0 {
                            let cell = &mut pixels[band * 6 + dy][x];
                            assert!(cell.is_none(), "pixel ({x}, {}) drawn twice", band * 6 + dy);
                            *cell = Some(colour);
                        }
                    }
                    x += 1;
                }
                i += 1;
            }
        }
    }
    ((w, h), palette, pixels)
}

#[test]
fn a_picture_decodes_to_the_palette_entry_of_every_pixel() {
    // 37 x 20: neither a multiple of six rows nor of eight columns.
    let img = RgbImage::from_fn(37, 20, |x, y| {
        Rgb([(x * 7) as u8, (y * 13) as u8, ((x * y) % 256) as u8])
    });
    let ((w, h), palette, pixels) = decode(&encode(&img));
    assert_eq!((w, h), (37, 20));
    for (i, colour) in palette.iter().enumerate().take(252) {
        assert_eq!(*colour, palette_colour(i), "register {i}");
    }
    for (y, row) in pixels.iter().enumerate() {
        for (x, p) in row.iter().enumerate() {
            let want = palette_index(img.get_pixel(x as u32, y as u32).0, x as u32, y as u32);
            assert_eq!(*p, Some(want), "pixel ({x}, {y})");
        }
    }
}

#[test]
fn the_palette_spans_black_to_white_and_the_dither_keeps_the_mean() {
    assert_eq!(palette_colour(palette_index([0, 0, 0], 3, 5)), [0, 0, 0]);
    assert_eq!(
        palette_colour(palette_index([255, 255, 255], 3, 5)),
        [100, 100, 100]
    );
    assert!((0..252).all(|i| palette_colour(i).iter().all(|c| *c <= 100)));
    // Over an 8 x 8 tile the dithered colours average to the input,
    // within a step of 1/64 of a level and rounding: much closer than one
    // level (20% for red and blue).
    let mut s = 0x1234_5678u32;
    for _ in 0..200 {
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        let p = s.to_le_bytes();
        let p = [p[0], p[1], p[2]];
        let mut mean = [0.0f64; 3];
        for y in 0..8 {
            for x in 0..8 {
                let c = palette_colour(palette_index(p, x, y));
                (0..3).for_each(|k| mean[k] += f64::from(c[k]) / 64.0);
            }
        }
        for k in 0..3 {
            let want = f64::from(p[k]) * 100.0 / 255.0;
            assert!((mean[k] - want).abs() < 2.5, "{p:?}: {mean:?}");
        }
    }
}
