//! Region statistics: a box of pixels chosen with the mouse (drag on the
//! picture: [`App::drag_to`](super::screen)) or the keys (`b` at one corner, move the cursor, `b` at the
//! other; `b` again clears it), and what the pixel panel says of it:
//! its mean with the standard error of that mean, the reference's mean,
//! the relative MSE and the z of the difference, and a histogram of the
//! view.

use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::widgets::Block;
use ratatui::Frame;

use super::app::App;
use crate::core::film::Film;
use crate::core::zview::Z_MAX;

/// A box of pixels, corners included: (x0, y0, x1, y1).
pub type Region = (u32, u32, u32, u32);

/// The box spanned by two corners.
pub fn spanned(a: (u32, u32), b: (u32, u32)) -> Region {
    (a.0.min(b.0), a.1.min(b.1), a.0.max(b.0), a.1.max(b.1))
}

impl App {
    /// `b`: a first corner at the cursor, then the box to the cursor; with
    /// a box chosen, clears it.
    pub fn mark_region(&mut self) {
        if self.region.take().is_some() {
            self.region_anchor = None;
            return;
        }
        let Some(p) = self.inspect else {
            self.message = "b marks a region's corners at the inspect cursor (i), or drag".into();
            return;
        };
        match self.region_anchor.take() {
            Some(a) => self.region = Some(spanned(a, p)),
            None => self.region_anchor = Some(p),
        }
    }
}

/// What the inspect panel says of the region: its statistics and its
/// histogram, or where its first corner is while `b` waits for the second.
pub fn region_summary(app: &App) -> Vec<String> {
    if let (Some((x, y)), None) = (app.region_anchor, app.region) {
        return vec![format!("region: corner at ({x}, {y}); move, b again")];
    }
    let (Some(region), Some(film)) = (app.region, app.main_film()) else {
        return Vec::new();
    };
    let main = app.view == 0;
    let stderr = app
        .stderr_view()
        .filter(|s| main && (s.width, s.height) == (film.width, film.height));
    let reference = app
        .reference_pair()
        .filter(|(r, _)| main && (r.width, r.height) == (film.width, film.height))
        .map(|(r, err)| {
            (
                r,
                err.filter(|e| (e.width, e.height) == (r.width, r.height)),
            )
        });
    let mut lines = region_lines(region, &film, stderr, reference);
    let (x0, y0, x1, y1) = region;
    let (x1, y1) = (x1.min(film.width - 1), y1.min(film.height - 1));
    let mut crop = Film::new(x1 + 1 - x0, y1 + 1 - y0);
    for y in y0..=y1 {
        for x in x0..=x1 {
            *crop.get_mut(x - x0, y - y0) = film.get(x, y);
        }
    }
    lines.extend(histogram_line(&crop).map(|h| format!("histogram {h}")));
    lines
}

/// The statistics of `region` of `film` (with its per-pixel standard error
/// where known) against `reference` (with its own, where known), as lines
/// for the pixel panel; the z of the difference of the means comes with
/// its verdict, within noise up to [`Z_MAX`] (the grader's limit).
pub fn region_lines(
    region: Region,
    film: &Film,
    stderr: Option<&Film>,
    reference: Option<(&Film, Option<&Film>)>,
) -> Vec<String> {
    let (x0, y0, x1, y1) = region;
    let (x1, y1) = (x1.min(film.width - 1), y1.min(film.height - 1));
    let (mut sum, mut var, mut sum_ref, mut rel_mse, mut n) =
        (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let mut var_ref = 0.0f64;
    for y in y0..=y1 {
        for x in x0..=x1 {
            let v = f64::from(film.get(x, y).element_sum()) / 3.0;
            sum += v;
            if let Some(s) = stderr {
                // The channel mean's variance, channels taken as independent.
                var += f64::from(s.get(x, y).length_squared()) / 9.0;
            }
            if let Some((r, r_err)) = reference {
                let rv = f64::from(r.get(x, y).element_sum()) / 3.0;
                if let Some(e) = r_err {
                    var_ref += f64::from(e.get(x, y).length_squared()) / 9.0;
                }
                sum_ref += rv;
                rel_mse += (v - rv) * (v - rv) / (rv * rv + 0.01);
            }
            n += 1.0;
        }
    }
    let mean = sum / n;
    let n_px = (x1 + 1 - x0) * (y1 + 1 - y0);
    let mut lines = vec![format!(
        "region {}x{} at ({x0}, {y0}):",
        x1 + 1 - x0,
        y1 + 1 - y0
    )];
    let se = var.sqrt() / n;
    lines.push(match stderr {
        Some(_) => format!("mean {} ± {}", short(mean), short(se)),
        None => format!("mean {} ({n_px} px)", short(mean)),
    });
    if let Some((_, r_err)) = reference {
        let r = sum_ref / n;
        lines.push(format!("ref {} · rel MSE {}", short(r), short(rel_mse / n)));
        let sd = (var + var_ref).sqrt() / n;
        if stderr.is_some() && sd > 0.0 {
            let z = (mean - r) / sd;
            let verdict = if z.abs() <= Z_MAX {
                "within noise"
            } else {
                "biased"
            };
            let only = if r_err.is_some() {
                ""
            } else {
                " (render's noise only)"
            };
            lines.push(format!("z {z:+.1}: {verdict}{only}"));
        }
    }
    lines
}

fn short(x: f64) -> String {
    super::gauge::short_number(x)
}

/// A histogram of `film`'s channel means in 24 bins from 0 to its 99th
/// percentile, as one line of block characters (the tallest bin full),
/// with the range it covers.
pub fn histogram_line(film: &Film) -> Option<String> {
    let mut v: Vec<f32> = film
        .pixels
        .iter()
        .map(|p| p.element_sum() / 3.0)
        .filter(|v| v.is_finite())
        .collect();
    if v.is_empty() {
        return None;
    }
    v.sort_by(f32::total_cmp);
    let top = v[(v.len() - 1) * 99 / 100].max(f32::MIN_POSITIVE);
    const BINS: usize = 24;
    let mut bins = [0usize; BINS];
    for x in &v {
        bins[((x / top * BINS as f32) as usize).min(BINS - 1)] += 1;
    }
    let most = *bins.iter().max().unwrap_or(&1);
    let bars: String = bins
        .iter()
        .map(|&b| [' ', '▁', '▂', '▃', '▄', '▅', '▆', '▇', '█'][(b * 8).div_ceil(most.max(1))])
        .collect();
    Some(format!("{bars} 0–{}", short(f64::from(top))))
}

/// The chosen region in the coordinates of the zoom `window`, clamped to
/// it; `None` when there is none or it lies outside.
pub fn in_window(app: &App, window: &super::zoom::Window) -> Option<Region> {
    let (x0, y0, x1, y1) = app.region?;
    let (ax, ay) = (x0.max(window.x0), y0.max(window.y0));
    let (bx, by) = (
        x1.min(window.x0 + window.width - 1),
        y1.min(window.y0 + window.height - 1),
    );
    (ax <= bx && ay <= by).then(|| {
        (
            ax - window.x0,
            ay - window.y0,
            bx - window.x0,
            by - window.y0,
        )
    })
}

/// Outlines `region` (of a picture `width` x `height`) in yellow on
/// `image`, that picture scaled to the image's size.
pub fn outline(image: &mut image::RgbImage, region: Region, width: u32, height: u32) {
    let (iw, ih) = (image.width(), image.height());
    let sx = |x: u32| (u64::from(x) * u64::from(iw) / u64::from(width.max(1))) as u32;
    let sy = |y: u32| (u64::from(y) * u64::from(ih) / u64::from(height.max(1))) as u32;
    let (x0, y0) = (sx(region.0), sy(region.1));
    let (x1, y1) = (
        sx(region.2 + 1).clamp(x0 + 1, iw) - 1,
        sy(region.3 + 1).clamp(y0 + 1, ih) - 1,
    );
    let yellow = image::Rgb([255, 255, 0]);
    for x in x0..=x1 {
        image.put_pixel(x, y0, yellow);
        image.put_pixel(x, y1, yellow);
    }
    for y in y0..=y1 {
        image.put_pixel(x0, y, yellow);
        image.put_pixel(x1, y, yellow);
    }
}

/// Outlines `region` on the half-block picture drawn in `r` (cells) of a
/// film `width` x `height`.
pub fn draw_region(frame: &mut Frame, r: Rect, region: Region, width: u32, height: u32) {
    let (x0, y0, x1, y1) = region;
    let col = |x: u32| r.x + (u64::from(x) * u64::from(r.width) / u64::from(width.max(1))) as u16;
    let row = |y: u32| r.y + (u64::from(y) * u64::from(r.height) / u64::from(height.max(1))) as u16;
    let (c0, r0) = (col(x0), row(y0));
    let (c1, r1) = (col(x1 + 1).max(c0 + 2), row(y1 + 1).max(r0 + 2));
    let area = Rect::new(c0, r0, c1 - c0, r1 - r0).intersection(r);
    if area.width >= 2 && area.height >= 2 {
        frame.render_widget(
            Block::bordered().border_style(Style::default().fg(Color::Yellow)),
            area,
        );
    }
}
