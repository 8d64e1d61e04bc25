//! A sixel encoder fast enough for a progressive preview: a fixed palette
//! of 6 x 7 x 6 colours (red, green, blue levels) with 8 x 8 ordered
//! dithering, so each pixel is mapped in a few operations and the picture
//! is written band by band. A general encoder (median-cut palette, error
//! diffusion) took 250 to 330 ms for a 720 x 600 picture on this machine,
//! long enough to make the keys wait while a render streams its passes;
//! this one takes a few milliseconds, and the preview needs no more.

use std::fmt::Write;

use image::RgbImage;

/// Levels per channel: red, green, blue (green gets one more: the eye
/// sees it best).
const LEVELS: [u32; 3] = [6, 7, 6];
/// Palette entries: 252, within the 256 colour registers of a VT340-class
/// terminal.
const COLOURS: usize = (LEVELS[0] * LEVELS[1] * LEVELS[2]) as usize;

/// The 8 x 8 Bayer matrix, thresholds 0..64.
const BAYER: [[u8; 8]; 8] = [
    [0, 32, 8, 40, 2, 34, 10, 42],
    [48, 16, 56, 24, 50, 18, 58, 26],
    [12, 44, 4, 36, 14, 46, 6, 38],
    [60, 28, 52, 20, 62, 30, 54, 22],
    [3, 35, 11, 43, 1, 33, 9, 41],
    [51, 19, 59, 27, 49, 17, 57, 25],
    [15, 47, 7, 39, 13, 45, 5, 37],
    [63, 31, 55, 23, 61, 29, 53, 21],
];

/// The palette index of the sRGB pixel `p` at (`x`, `y`): each channel
/// rounded to one of its levels, up or down by the ordered dither's
/// threshold at that position.
pub fn palette_index(p: [u8; 3], x: u32, y: u32) -> usize {
    let t = u32::from(BAYER[(y % 8) as usize][(x % 8) as usize]);
    let level = |v: u8, n: u32| {
        // v in 0..=255 onto 0..=n-1 steps of 64ths: floor plus dither.
        let scaled = u32::from(v) * (n - 1) * 64 / 255;
        ((scaled + t) / 64).min(n - 1)
    };
    let (r, g, b) = (
        level(p[0], LEVELS[0]),
        level(p[1], LEVELS[1]),
        level(p[2], LEVELS[2]),
    );
    ((r * LEVELS[1] + g) * LEVELS[2] + b) as usize
}

/// The colour of palette entry `i`, each channel in 0..=100 as sixel
/// writes it.
pub fn palette_colour(i: usize) -> [u32; 3] {
    let i = i as u32;
    let (r, g, b) = (
        i / (LEVELS[1] * LEVELS[2]),
        i / LEVELS[2] % LEVELS[1],
        i % LEVELS[2],
    );
    let pct = |v: u32, n: u32| (v * 100 + (n - 1) / 2) / (n - 1);
    [pct(r, LEVELS[0]), pct(g, LEVELS[1]), pct(b, LEVELS[2])]
}

/// `img` as a sixel sequence, from the device control string to its end.
pub fn encode(img: &RgbImage) -> String {
    let (w, h) = (img.width(), img.height());
    let mut out = String::with_capacity((w * h / 2) as usize + COLOURS * 16);
    // P2 = 1: pixels left at 0 keep the background. Raster attributes:
    // square pixels, the picture's size.
    let _ = write!(out, "\x1bP0;1;0q\"1;1;{w};{h}");
    for i in 0..COLOURS {
        let [r, g, b] = palette_colour(i);
        let _ = write!(out, "#{i};2;{r};{g};{b}");
    }
    let width = w as usize;
    // Per band of six rows: each colour's six-bit column masks.
    let mut masks = vec![0u8; COLOURS * width];
    let mut used = vec![false; COLOURS];
    let mut indices = vec![0u16; width];
    for band in (0..h).step_by(6) {
        masks.fill(0);
        used.fill(false);
        for dy in 0..6.min(h - band) {
            let y = band + dy;
            for (x, slot) in indices.iter_mut().enumerate() {
                *slot = palette_index(img.get_pixel(x as u32, y).0, x as u32, y) as u16;
            }
            for (x, &i) in indices.iter().enumerate() {
                masks[i as usize * width + x] |= 1 << dy;
                used[i as usize] = true;
            }
        }
        for (i, _) in used.iter().enumerate().filter(|(_, u)| **u) {
            let _ = write!(out, "#{i}");
            write_row(&mut out, &masks[i * width..(i + 1) * width]);
            out.push('$');
        }
        out.push('-');
    }
    out.push_str("\x1b\\");
    out
}

/// One colour's row of a band: a sixel character per column, runs of the
/// same one written `!count` then the character.
fn write_row(out: &mut String, masks: &[u8]) {
    let mut x = 0;
    while x < masks.len() {
        let m = masks[x];
        let run = masks[x..].iter().take_while(|&&n| n == m).count();
        let c = char::from(63 + m);
        if run > 3 {
            let _ = write!(out, "!{run}{c}");
        } else {
            (0..run).for_each(|_| out.push(c));
        }
        x += run;
    }
}
