//! Images side by side with a caption under each: the book's strips (the
//! bounce sequence, samples per pixel).

use std::path::Path;

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::core::error::{Error, Result};
use crate::core::film::write_rgb8_png;
use crate::core::film::Film;
use crate::core::style::{font, FAMILY};

/// Images side by side on white, 2 pixels apart, each with its caption
/// centred under it: the book's strips (bounces, samples per pixel).
/// Returns 8-bit RGB pixels, width and height.
pub fn captioned_strip(images: &[(&Film, &str)]) -> Result<(Vec<u8>, u32, u32)> {
    font()?;
    let gap = 2;
    let band = 22;
    let image_h = images.iter().map(|(f, _)| f.height).max().unwrap_or(1);
    let width = images.iter().map(|(f, _)| f.width).sum::<u32>()
        + gap * images.len().saturating_sub(1) as u32;
    let (width, height) = (width.max(1), image_h + band);
    let mut pixels = vec![255u8; (width * height * 3) as usize];
    let mut x0 = 0;
    for (film, _) in images {
        let rgb = film.to_srgb8();
        for y in 0..film.height {
            let src = (y * film.width * 3) as usize;
            let dst = ((y * width + x0) * 3) as usize;
            let n = (film.width * 3) as usize;
            pixels[dst..dst + n].copy_from_slice(&rgb[src..src + n]);
        }
        x0 += film.width + gap;
    }
    {
        let root = BitMapBackend::with_buffer(&mut pixels, (width, height)).into_drawing_area();
        let style = TextStyle::from((FAMILY, 14).into_font())
            .color(&BLACK)
            .pos(Pos::new(HPos::Center, VPos::Center));
        let mut x0 = 0i32;
        for (film, caption) in images {
            let at = (x0 + film.width as i32 / 2, image_h as i32 + band as i32 / 2);
            root.draw_text(caption, &style, at)
                .map_err(|e| Error::Usage(format!("drawing a caption: {e}")))?;
            x0 += (film.width + gap) as i32;
        }
        root.present()
            .map_err(|e| Error::Usage(format!("drawing a caption: {e}")))?;
    }
    Ok((pixels, width, height))
}

/// [`captioned_strip`] written as a PNG, atomically.
pub fn write_captioned_strip(images: &[(&Film, &str)], path: &Path) -> Result<()> {
    let (pixels, width, height) = captioned_strip(images)?;
    write_rgb8_png(&pixels, width, height, path)
}
