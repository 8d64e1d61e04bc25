//! Inspect mode: a cursor on the preview (`i`, then the arrow keys or
//! `h j k l`; with Shift eight pixels at a time) and a panel with that
//! pixel's story: its value in every view of the chapter (for chapter 6
//! the mean radiance and its standard error), its light split by bounce
//! layer with each layer's share, and the reference and the difference
//! where there is one.

use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Block, Paragraph};
use ratatui::Frame;

use super::app::{bounce_name, App};
use super::gauge::short_number;
use crate::core::film::Film;

fn rgb(film: &Film, x: u32, y: u32) -> Option<String> {
    (x < film.width && y < film.height).then(|| {
        let p = film.get(x, y);
        format!(
            "{} {} {}",
            short_number(p.x as f64),
            short_number(p.y as f64),
            short_number(p.z as f64)
        )
    })
}

/// The panel's lines for the pixel under the cursor (empty when there is
/// no cursor or no picture).
pub fn inspect_lines(app: &App) -> Vec<String> {
    let (Some((x, y)), Some(snap), Some(chapter)) =
        (app.inspect, app.snapshot.as_ref(), app.current_chapter())
    else {
        return Vec::new();
    };
    let mut lines = vec![format!("pixel ({x}, {y})")];
    lines.extend(super::region::region_summary(app));
    // Radiance chapters' views hold values (radiance, its standard
    // error); the others' are colours made for showing (a depth as grey, a
    // normal as n/2 + 1/2), which the story below gives as numbers.
    let radiance = chapter.info().radiance;
    for (view, film) in chapter.info().views.iter().zip(&snap.views) {
        if view.name == crate::core::stage::CAUGHT_VIEW.name {
            // Said only where one was caught: most pixels catch none.
            let n = (x < film.width && y < film.height).then(|| film.get(x, y).x);
            if let Some(n) = n.filter(|n| *n > 0.0) {
                lines.push(format!("non-finite: {n} caught (left out)"));
            }
            continue;
        }
        if let Some(v) = rgb(film, x, y) {
            let name = match view.name {
                "stderr" => "± std error",
                other => other,
            };
            let shown = if radiance { "" } else { " (display colour)" };
            lines.push(format!("{name}{shown}: {v}"));
        }
    }
    if let (Some(layers), Some(image)) = (&snap.layers, snap.views.first()) {
        if x < image.width && y < image.height {
            let total = image.get(x, y).element_sum().max(1e-30);
            lines.push("by bounce (share of the pixel):".into());
            for (k, layer) in layers.iter().enumerate() {
                let v = layer.get(x, y);
                if v.element_sum() <= 0.0 {
                    continue;
                }
                let name = if k + 1 == layers.len() {
                    "beyond 16".to_string()
                } else if k == 0 {
                    "direct".to_string()
                } else {
                    bounce_name(k as u32).replace(" global illumination", "")
                };
                lines.push(format!(" {name}: {:.1}%", 100.0 * v.element_sum() / total));
            }
        }
    }
    if let Some((sx, sy, story)) = &app.story {
        if (*sx, *sy) == (x, y) {
            lines.extend(story.iter().cloned());
        }
    }
    if app.traces_paths() && app.trace.is_none() {
        lines.push("t: trace one path from here".into());
    }
    if let (Some(r), Some(image)) = (&snap.reference, snap.views.first()) {
        if (r.width, r.height) == (image.width, image.height) {
            if let Some(v) = rgb(r, x, y) {
                lines.push(format!("reference: {v}"));
                let d = image.get(x, y) - r.get(x, y);
                lines.push(format!(
                    "difference: {} {} {}",
                    short_number(d.x as f64),
                    short_number(d.y as f64),
                    short_number(d.z as f64)
                ));
            }
        }
    }
    lines
}

/// `lines` wrapped to `width` cells: at spaces where it can, a
/// continuation indented by two, a word longer than the width cut.
pub fn wrap_lines(lines: &[String], width: u16) -> Vec<String> {
    let width = (width as usize).max(4);
    let mut out = Vec::new();
    for line in lines {
        let mut cur: Vec<char> = Vec::new();
        for (i, word) in line.split(' ').enumerate() {
            let mut word: &[char] = &word.chars().collect::<Vec<_>>();
            let fits = cur.len() + usize::from(i > 0) + word.len() <= width;
            if i > 0 && !fits && cur.iter().any(|c| *c != ' ') {
                out.push(cur.iter().collect());
                cur = vec![' ', ' '];
            } else if i > 0 {
                cur.push(' ');
            }
            while cur.len() + word.len() > width {
                let take = width.saturating_sub(cur.len()).min(word.len());
                cur.extend_from_slice(&word[..take]);
                word = &word[take..];
                out.push(cur.iter().collect());
                cur = vec![' ', ' '];
            }
            cur.extend_from_slice(word);
        }
        out.push(cur.iter().collect());
    }
    out
}

/// How many lines of `lines` do not fit a bordered box `area`: how far it
/// can scroll.
pub fn overflow(lines: &[String], area: Rect) -> u16 {
    let shown = area.height.saturating_sub(2) as usize;
    let n = wrap_lines(lines, area.width.saturating_sub(2)).len();
    n.saturating_sub(shown).min(u16::MAX as usize) as u16
}

/// Draws `lines` into a bordered box `area` scrolled by `scroll` (clamped
/// to the end), with `title` on top and, below, where the view is and the
/// keys that apply.
fn draw_scrolled(
    frame: &mut Frame,
    area: Rect,
    lines: &[String],
    scroll: u16,
    title: String,
    keys: &str,
) {
    let wrapped = wrap_lines(lines, area.width.saturating_sub(2));
    let shown = area.height.saturating_sub(2) as usize;
    let max = wrapped.len().saturating_sub(shown);
    let at = (scroll as usize).min(max);
    let bottom = if max > 0 {
        format!(
            "{}-{} of {} · u d scroll · {keys}",
            at + 1,
            (at + shown).min(wrapped.len()),
            wrapped.len()
        )
    } else {
        keys.to_string()
    };
    let text: Vec<Line> = wrapped
        .into_iter()
        .skip(at)
        .take(shown)
        .map(Line::from)
        .collect();
    frame.render_widget(
        Paragraph::new(text).block(Block::bordered().title(title).title_bottom(bottom)),
        area,
    );
}

/// Draws the panel into `area`, scrolled by [`App::panel_scroll`].
pub fn draw_panel(app: &App, frame: &mut Frame, area: Rect) {
    draw_scrolled(
        frame,
        area,
        &inspect_lines(app),
        app.panel_scroll,
        "pixel".into(),
        "Esc: close",
    );
}

/// Marks the cell showing pixel (`x`, `y`) of a `width` x `height` film
/// drawn into `r` (half blocks: a cell is one pixel wide, two tall).
pub fn draw_cursor(frame: &mut Frame, r: Rect, (x, y): (u32, u32), width: u32, height: u32) {
    if r.width == 0 || r.height == 0 || x >= width || y >= height {
        return;
    }
    // The cell a click would map back to this pixel ([`cell_to_pixel`]),
    // when there is one (a zoomed picture has several cells per pixel);
    // else the cell the pixel falls in.
    let cell = |p: u32, cells: u16, pixels: u32| {
        (0..cells)
            .find(|c| cell_to_pixel(*c, cells, pixels) == p)
            .unwrap_or((p as u64 * cells as u64 / pixels as u64) as u16)
    };
    let cx = r.x + cell(x, r.width, width);
    let cy = r.y + cell(y, r.height, height);
    if let Some(cell) = frame.buffer_mut().cell_mut((cx, cy)) {
        cell.set_symbol("+").set_style(
            Style::default()
                .fg(Color::Black)
                .bg(Color::Yellow)
                .add_modifier(Modifier::BOLD),
        );
    }
}

/// The pixel (0 ..`pixels`) under cell `cell` of a picture `cells` wide
/// (or tall) showing `pixels`: the inverse of [`draw_cursor`]'s mapping, so
/// the cursor lands on the cell that was clicked.
pub fn cell_to_pixel(cell: u16, cells: u16, pixels: u32) -> u32 {
    let (c, n, p) = (cell as u64, cells.max(1) as u64, pixels as u64);
    let x = if n <= p {
        // Several pixels per cell: the first whose cell is this one.
        (c * p).div_ceil(n)
    } else {
        c * p / n
    };
    x.min(p.saturating_sub(1)) as u32
}

/// Draws the traced path's table into `area`, scrolled by
/// [`App::table_scroll`].
pub fn draw_table(app: &App, frame: &mut Frame, area: Rect) {
    let Some(t) = &app.trace else { return };
    let title = format!(
        "path: sample {} of pixel ({}, {})",
        t.sample, t.pixel.0, t.pixel.1
    );
    frame.render_widget(ratatui::widgets::Clear, area);
    draw_scrolled(
        frame,
        area,
        &t.lines,
        app.table_scroll,
        title,
        "t: next · Esc: close",
    );
}
