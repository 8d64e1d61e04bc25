//! The film: linear HDR RGB pixels, and how they leave the renderer.
//!
//! Colour stays linear inside raystep. Only when writing an 8-bit PNG do we
//! apply the sRGB transfer curve; EXR files keep the linear f32 values.
//! Every write goes to a temporary file beside the target and is renamed
//! into place, so a failed or interrupted run never leaves half an image.

use std::path::Path;

use glam::Vec3;

use crate::core::error::{Error, Result};
pub use crate::core::outputs::{
    create_folder, remove_temporaries_and_exit, stopping, temporaries_on_disk, write_all_synced,
    write_atomically, write_rgb8_png, OutputSet,
};

/// A width x height grid of linear RGB values, row by row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` pixels, row-major, top row first.
    pub pixels: Vec<Vec3>,
}

impl Film {
    /// A black film. Sizes are checked by the camera before we get here.
    pub fn new(width: u32, height: u32) -> Film {
        Film {
            width,
            height,
            pixels: vec![Vec3::ZERO; width as usize * height as usize],
        }
    }

    /// The pixel at column `x`, row `y`.
    pub fn get(&self, x: u32, y: u32) -> Vec3 {
        self.pixels[(y * self.width + x) as usize]
    }

    /// A mutable reference to the pixel at column `x`, row `y`.
    pub fn get_mut(&mut self, x: u32, y: u32) -> &mut Vec3 {
        &mut self.pixels[(y * self.width + x) as usize]
    }

    /// Replaces every NaN or infinite channel by 0 and returns how many
    /// pixels had one. Called before any image leaves the renderer.
    pub fn scrub_nonfinite(&mut self) -> u64 {
        let mut caught = 0;
        for p in &mut self.pixels {
            if !p.is_finite() {
                caught += 1;
                *p = Vec3::select(p.is_finite_mask(), *p, Vec3::ZERO);
            }
        }
        caught
    }

    /// Root-mean-square difference to another film of the same size, over
    /// all channels.
    pub fn rmse(&self, other: &Film) -> f64 {
        assert_eq!((self.width, self.height), (other.width, other.height));
        let sum: f64 = self
            .pixels
            .iter()
            .zip(&other.pixels)
            .map(|(a, b)| (*a - *b).as_dvec3().length_squared())
            .sum();
        (sum / (3.0 * self.pixels.len().max(1) as f64)).sqrt()
    }

    /// 8-bit sRGB bytes (RGB, row-major), values clamped to [0, 1].
    pub fn to_srgb8(&self) -> Vec<u8> {
        self.pixels
            .iter()
            .flat_map(|p| p.to_array().map(encode_srgb))
            .collect()
    }

    /// Writes an 8-bit sRGB PNG, atomically.
    pub fn write_png(&self, path: &Path) -> Result<()> {
        write_rgb8_png(&self.to_srgb8(), self.width, self.height, path)
    }

    /// Writes a linear f32 OpenEXR file, atomically.
    pub fn write_exr(&self, path: &Path) -> Result<()> {
        write_atomically(path, |tmp| {
            write_rgb_exr(tmp, (self.width, self.height), |x, y| {
                let p = self.pixels[y * self.width as usize + x];
                (p.x, p.y, p.z)
            })
        })
    }

    /// Reads an 8-bit PNG back as linear values (for graders and tests).
    pub fn read_png(path: &Path) -> Result<Film> {
        let img = image::open(path)
            .map_err(|e| Error::Image {
                path: path.to_path_buf(),
                message: e.to_string(),
            })?
            .to_rgb8();
        Ok(Film {
            width: img.width(),
            height: img.height(),
            pixels: img
                .pixels()
                .map(|p| Vec3::from(p.0.map(decode_srgb)))
                .collect(),
        })
    }

    /// Reads a linear RGB EXR file (for references and tests).
    pub fn read_exr(path: &Path) -> Result<Film> {
        use exr::prelude::*;
        let image = read_first_rgba_layer_from_file(
            path,
            |res, _| Film::new(res.width() as u32, res.height() as u32),
            |film: &mut Film, pos, (r, g, b, _a): (f32, f32, f32, f32)| {
                *film.get_mut(pos.x() as u32, pos.y() as u32) = Vec3::new(r, g, b);
            },
        )
        .map_err(|e| crate::core::error::Error::Image {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
        Ok(image.layer_data.channel_data.pixels)
    }
}

/// Writes the linear RGB EXR of a `width` x `height` image whose pixel
/// (x, y) is `pixel(x, y)` to the new file `path`, and waits until the
/// system has it: a full disk is an error. Compressed one block after
/// another: the parallel writer stores blocks in the order they finish, so
/// the same image would not always give the same bytes. The writer asks
/// for the pixels row by row.
pub fn write_rgb_exr(
    path: &Path,
    (width, height): (u32, u32),
    pixel: impl Fn(usize, usize) -> (f32, f32, f32) + Sync,
) -> std::result::Result<(), String> {
    use exr::prelude::*;
    let channels = SpecificChannels::rgb(|Vec2(x, y): Vec2<usize>| pixel(x, y));
    let mut file = std::fs::File::create(path).map_err(|e| e.to_string())?;
    Image::from_channels((width as usize, height as usize), channels)
        .write()
        .non_parallel()
        .to_buffered(std::io::BufWriter::new(&mut file))
        .map_err(|e| e.to_string())?;
    file.sync_all().map_err(|e| format!("writing: {e}"))
}

/// Linear [0, 1] → sRGB-encoded 8-bit value.
pub fn encode_srgb(linear: f32) -> u8 {
    let c = if linear.is_nan() {
        0.0
    } else {
        linear.clamp(0.0, 1.0)
    };
    let s = if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0 + 0.5) as u8
}

/// 8-bit sRGB value → linear [0, 1].
pub fn decode_srgb(v: u8) -> f32 {
    let s = v as f32 / 255.0;
    if s <= 0.04045 {
        s / 12.92
    } else {
        ((s + 0.055) / 1.055).powf(2.4)
    }
}

/// The mean value of a film over pixels and channels.
pub fn film_mean(film: &Film) -> f64 {
    let n = film.pixels.len().max(1) as f64 * 3.0;
    film.pixels
        .iter()
        .map(|p| p.as_dvec3().element_sum())
        .sum::<f64>()
        / n
}
