//! Zoom: the preview shows a window of the image, 1/zoom of its width and
//! height, around the inspect cursor (or the image's centre); `z` and `Z`
//! zoom in and out, and moving the cursor pans. Also the picture sent
//! through a graphics protocol, with the inspect cursor drawn into its
//! pixels (a character cell drawn over a kitty or sixel image would be
//! hidden under it).

use crate::app::App;
use crate::core::film::Film;

/// The largest zoom.
pub const MAX_ZOOM: u32 = 32;

/// A window of an image (declared in `state`, which the app's state may
/// hold without importing this module).
pub use super::state::Window;

impl Window {
    /// The window `app` shows of a `width` × `height` image.
    pub fn of(app: &App, width: u32, height: u32) -> Window {
        let zoom = app.zoom.clamp(1, MAX_ZOOM);
        let (w, h) = ((width / zoom).max(1), (height / zoom).max(1));
        let (cx, cy) = app.inspect.unwrap_or((width / 2, height / 2));
        let start = |c: u32, size: u32, full: u32| c.saturating_sub(size / 2).min(full - size);
        Window {
            x0: start(cx, w, width),
            y0: start(cy, h, height),
            width: w,
            height: h,
        }
    }

    /// Whether the window is the whole `width` × `height` image.
    pub fn is_whole(&self, width: u32, height: u32) -> bool {
        (self.x0, self.y0, self.width, self.height) == (0, 0, width, height)
    }

    /// `film`'s pixels inside the window.
    pub fn crop(&self, film: &Film) -> Film {
        let mut out = Film::new(self.width, self.height);
        for y in 0..self.height {
            for x in 0..self.width {
                *out.get_mut(x, y) = film.get(self.x0 + x, self.y0 + y);
            }
        }
        out
    }

    /// Pixel `p` of the image in the window's coordinates, if inside.
    pub fn to_window(&self, (x, y): (u32, u32)) -> Option<(u32, u32)> {
        let inside = x >= self.x0 && y >= self.y0;
        let (wx, wy) = (x.wrapping_sub(self.x0), y.wrapping_sub(self.y0));
        (inside && wx < self.width && wy < self.height).then_some((wx, wy))
    }

    /// Pixel `p` of the window in the image's coordinates.
    pub fn to_image(&self, (x, y): (u32, u32)) -> (u32, u32) {
        (self.x0 + x, self.y0 + y)
    }
}

/// The next zoom in (`step` 1) or out (−1): 1, 2, 4, … [`MAX_ZOOM`].
pub fn zoomed(zoom: u32, step: i32) -> u32 {
    if step > 0 {
        (zoom.max(1) * 2).min(MAX_ZOOM)
    } else {
        (zoom / 2).max(1)
    }
}

/// The RGB bytes a graphics protocol shows of `film` (already exposed and
/// cropped), with the inspect cursor `cursor` (window coordinates) drawn
/// in as a yellow cross whose centre pixel is left as it is.
pub fn graphics_pixels(film: &Film, cursor: Option<(u32, u32)>) -> Vec<u8> {
    let mut bytes: Vec<u8> = film
        .pixels
        .iter()
        .flat_map(|p| p.to_array().map(crate::core::film::encode_srgb))
        .collect();
    if let Some((cx, cy)) = cursor {
        let arm = (film.width.max(film.height) / 64).clamp(2, 8) as i64;
        for d in -arm..=arm {
            if d.abs() < 1 {
                continue;
            }
            for (x, y) in [(cx as i64 + d, cy as i64), (cx as i64, cy as i64 + d)] {
                if x >= 0 && y >= 0 && (x as u32) < film.width && (y as u32) < film.height {
                    let i = 3 * (y as usize * film.width as usize + x as usize);
                    bytes[i..i + 3].copy_from_slice(&[255, 255, 0]);
                }
            }
        }
    }
    bytes
}
