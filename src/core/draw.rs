//! Drawing lines and dots on a film, for chapter 1's wireframes. This is
//! plumbing, not the lesson: lines are sampled every quarter pixel and each
//! sample lights the four nearest pixel centres with a tent weight, keeping
//! the brighter value where lines cross. Deterministic and free of gaps.

use glam::{DVec2, Vec2, Vec3};

use crate::core::film::Film;

/// Clips the segment a→b to the rectangle [lo, hi] (Liang–Barsky); returns
/// the parameters (t0, t1) of the visible part, if any. In f64: an edge can
/// reach a million pixels off screen, where f32 would misplace its visible
/// part by many pixels.
pub fn clip_segment_2d(a: DVec2, b: DVec2, lo: DVec2, hi: DVec2) -> Option<(f64, f64)> {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, a.x - lo.x),
        (d.x, hi.x - a.x),
        (-d.y, a.y - lo.y),
        (d.y, hi.y - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then_some((t0, t1))
}

/// Where lines and dots are drawn: a whole film, or a [`Band`] of rows of
/// a larger image. Coordinates are the image's either way.
pub trait Canvas {
    /// The image's width and height.
    fn size(&self) -> (u32, u32);
    /// Pixel (x, y) of the image, `None` where the canvas does not hold it.
    fn pixel(&mut self, x: u32, y: u32) -> Option<&mut Vec3>;
}

impl Canvas for Film {
    fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }
    fn pixel(&mut self, x: u32, y: u32) -> Option<&mut Vec3> {
        Some(self.get_mut(x, y))
    }
}

/// Rows `first_row .. first_row + film.height` of an image `height` rows
/// tall: lines and dots are placed as on the whole image, and only this
/// band's rows are written.
pub struct Band {
    /// The band's rows.
    pub film: Film,
    /// The image row of its first row.
    pub first_row: u32,
    /// The image's height.
    pub height: u32,
}

impl Band {
    /// A black band: rows `rows` of a `width` x `height` image.
    pub fn new(width: u32, rows: std::ops::Range<u32>, height: u32) -> Band {
        Band {
            film: Film::new(width, rows.len() as u32),
            first_row: rows.start,
            height,
        }
    }
}

impl Canvas for Band {
    fn size(&self) -> (u32, u32) {
        (self.film.width, self.height)
    }
    fn pixel(&mut self, x: u32, y: u32) -> Option<&mut Vec3> {
        let row = y.checked_sub(self.first_row)?;
        (row < self.film.height).then(|| self.film.get_mut(x, row))
    }
}

/// Draws a line from `a` to `b` (raster coordinates), its colour blending
/// linearly from `ca` to `cb`. Returns how many samples landed on the film.
pub fn line(film: &mut impl Canvas, a: Vec2, b: Vec2, ca: Vec3, cb: Vec3) -> usize {
    if !(a.is_finite() && b.is_finite()) {
        return 0;
    }
    let (a, b) = (a.as_dvec2(), b.as_dvec2());
    let margin = DVec2::splat(2.0);
    let (width, height) = film.size();
    let hi = DVec2::new(width as f64, height as f64) + margin;
    let Some((t0, t1)) = clip_segment_2d(a, b, -margin, hi) else {
        return 0;
    };
    let (p0, p1) = (a.lerp(b, t0).as_vec2(), a.lerp(b, t1).as_vec2());
    let steps = ((p1 - p0).length() * 4.0).ceil().max(1.0) as usize;
    let mut lit = 0;
    for s in 0..=steps {
        let f = s as f32 / steps as f32;
        let t = (t0 + (t1 - t0) * f as f64) as f32;
        lit += splat(film, p0.lerp(p1, f), ca.lerp(cb, t), 1.0);
    }
    lit
}

/// A filled dot of the given radius in pixels.
pub fn dot(film: &mut impl Canvas, centre: Vec2, radius: f32, color: Vec3) -> usize {
    if !centre.is_finite() {
        return 0;
    }
    let r = radius.max(0.5);
    let (x0, x1) = ((centre.x - r - 1.0).floor(), (centre.x + r + 1.0).ceil());
    let (y0, y1) = ((centre.y - r - 1.0).floor(), (centre.y + r + 1.0).ceil());
    let (width, height) = film.size();
    let mut lit = 0;
    for y in y0.max(0.0) as i64..y1.min(height as f32) as i64 {
        for x in x0.max(0.0) as i64..x1.min(width as f32) as i64 {
            let c = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let cover = (r + 0.5 - c.distance(centre)).clamp(0.0, 1.0);
            if cover > 0.0 {
                if let Some(p) = film.pixel(x as u32, y as u32) {
                    *p = p.max(color * cover);
                    lit += 1;
                }
            }
        }
    }
    lit
}

/// Lights the four pixel centres around `p` with tent weights.
fn splat(film: &mut impl Canvas, p: Vec2, color: Vec3, strength: f32) -> usize {
    let q = p - Vec2::splat(0.5);
    let (fx, fy) = (q.x.floor(), q.y.floor());
    let (width, height) = film.size();
    let mut lit = 0;
    for (dx, dy) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (fx + dx, fy + dy);
        if x < 0.0 || y < 0.0 || x >= width as f32 || y >= height as f32 {
            continue;
        }
        let w = (1.0 - (q.x - x).abs()) * (1.0 - (q.y - y).abs()) * strength;
        if let Some(px) = film.pixel(x as u32, y as u32) {
            *px = px.max(color * w.min(1.0));
            lit += 1;
        }
    }
    lit
}
