//! The view: draws an [`App`] into a ratatui frame. Pure: the same state
//! and terminal size always give the same cells, which the layout
//! snapshots rely on.
//!
//! ```text
//! ┌ chapters ─┐┌ preview ──────────────┐
//! │ scenes    ││                       │
//! │ controls  ││  (the film, two       │
//! │ error/time││   pixels per cell)    │
//! └───────────┘└───────────────────────┘
//!  status line · progress gauge · message
//! ```

use crate::core::text::{escape, escape_keep_newlines};
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{
    Axis, Block, Chart, Clear, Dataset, GraphType, List, ListItem, ListState, Paragraph, Wrap,
};
use ratatui::Frame;

use super::app::{App, Focus};
use super::gauge::draw_gauge;
pub use super::gauge::{gauge_state, short_number};
use super::keys::KEYS;
pub use super::labels::{
    fit_parts, format_rate, key_hints, preview_title_parts, status_line, status_line_fit,
    status_parts,
};
use super::readouts::fg;
pub use super::screen::{areas, pixel_at, sidebar_width, Areas};
use super::shown::{draw_film, Content};
use crate::core::format::format_seconds;

/// The focused list's box: bold, its title reversed (readable on light
/// and dark backgrounds alike, where a yellow or grey border is not).
fn block<'a>(app: &App, title: &'a str, focused: bool) -> Block<'a> {
    let b = Block::bordered().title(title);
    if focused && app.color {
        b.border_style(Style::default().add_modifier(Modifier::BOLD))
            .title_style(Style::default().add_modifier(Modifier::REVERSED))
    } else if focused {
        b.border_style(Style::default().add_modifier(Modifier::BOLD))
    } else {
        b
    }
}

/// Draws the whole UI.
pub fn view(app: &App, frame: &mut Frame) {
    let area = frame.area();
    let Areas {
        side,
        preview,
        table,
        panel,
        lines: [status, gauge, message],
        too_small,
    } = areas(app, area);
    if too_small {
        draw_too_small(frame, area);
        return;
    }
    match panel {
        Some(p) => super::inspect::draw_panel(app, frame, p),
        None => draw_sidebar(app, frame, side),
    }
    if preview.width > 0 {
        draw_preview(app, frame, preview);
    }
    if let Some(t) = table {
        super::inspect::draw_table(app, frame, t);
    }
    frame.render_widget(Paragraph::new(status_line_fit(app, status.width)), status);
    draw_gauge(app, frame, gauge);
    // The message in the terminal's own colours (grey on a light
    // background is unreadable), else the keys of the current mode.
    let line = if app.message.is_empty() {
        Line::from(key_hints(app))
    } else {
        Line::from(escape(&app.message).into_owned())
            .style(Style::default().add_modifier(Modifier::BOLD))
    };
    frame.render_widget(Paragraph::new(line), message);
    if let Some(w) = &app.warp {
        super::warp::draw(w, app.color, frame, area);
    }
    if app.help {
        draw_help(app, frame, area);
    }
}

/// The notice on a screen below [`MIN_SIZE`](super::screen::MIN_SIZE).
fn draw_too_small(frame: &mut Frame, area: Rect) {
    let (w, h) = super::screen::MIN_SIZE;
    let text = format!(
        "raystep needs a terminal of at least {w}x{h}; this one is {}x{}. Enlarge it, or q quits.",
        area.width, area.height
    );
    frame.render_widget(Paragraph::new(text).wrap(Wrap { trim: true }), area);
}

fn draw_sidebar(app: &App, frame: &mut Frame, area: Rect) {
    let chapter = app.current_chapter();
    let has_chart = app
        .snapshot
        .as_ref()
        .is_some_and(|s| s.error_series.len() >= 2);
    let controls = control_lines(app);
    let scene_rows: u16 = app
        .scenes
        .iter()
        .enumerate()
        .map(|(i, _)| 1 + u16::from(chapter.is_some() && app.scene_problem(i).is_some()))
        .sum();
    // Chapters first, then the controls, then (on a terminal of 30 rows or
    // more) up to ten rows for the chart, and the scene list gets what is
    // left (at least three rows; it scrolls to the selection).
    let total = area.height;
    let ch_h = (app.chapters.len() as u16 + 2).min(total);
    let ctrl_h = (controls.len() as u16 + 2).min(total.saturating_sub(ch_h + 3));
    let left = total.saturating_sub(ch_h + ctrl_h);
    let chart_h = if has_chart && total >= 30 {
        10.min(left.saturating_sub(3))
    } else {
        0
    };
    let sc_h = (scene_rows + 2).min(left - chart_h);
    let [chapters, scenes, ctrl, rest] = Layout::vertical([
        Constraint::Length(ch_h),
        Constraint::Length(sc_h),
        Constraint::Length(ctrl_h),
        Constraint::Fill(1),
    ])
    .areas(area);

    let items: Vec<ListItem> = app
        .chapters
        .iter()
        .map(|c| {
            // The box's inner width, less the "> " of the selection.
            let room = chapters.width.saturating_sub(6) as usize;
            let title = super::labels::fit_title(c.info().title, room);
            ListItem::new(format!("{} {title}", c.info().number))
        })
        .collect();
    let highlight = Style::default().add_modifier(Modifier::BOLD);
    let list = List::new(items)
        .block(block(app, "chapters", app.focus == Focus::Chapters))
        .highlight_symbol("> ")
        .highlight_style(highlight);
    let mut state = ListState::default().with_selected(Some(app.chapter));
    frame.render_stateful_widget(list, chapters, &mut state);

    let items: Vec<ListItem> = app
        .scenes
        .iter()
        .enumerate()
        .map(|(i, s)| match chapter.and_then(|_| app.scene_problem(i)) {
            None => ListItem::new(escape(&s.name).into_owned()),
            Some(why) => ListItem::new(vec![
                Line::from(format!("✗ {}", escape(&s.name))).style(fg(app, Color::Red)),
                Line::from(format!("  {}", escape(&why.to_string()))),
            ]),
        })
        .collect();
    let list = List::new(items)
        .block(block(app, "scenes", app.focus == Focus::Scenes))
        .highlight_symbol("> ")
        .highlight_style(highlight);
    let mut state = ListState::default().with_selected(Some(app.scene));
    frame.render_stateful_widget(list, scenes, &mut state);

    frame.render_widget(
        Paragraph::new(controls).block(Block::bordered().title("controls")),
        ctrl,
    );
    if has_chart && rest.height >= 6 {
        draw_chart(app, frame, rest);
    }
}

/// The lines of the controls box: only the controls this render has.
pub fn control_lines(app: &App) -> Vec<Line<'static>> {
    let mut lines = Vec::new();
    if let Some(c) = app.current_chapter() {
        lines.push(Line::from(format!(
            "view {}/{}: {}",
            app.view + 1,
            c.info().views.len(),
            app.view_name()
        )));
    }
    lines.push(Line::from(if app.auto_exposure_on() {
        format!("exposure {:+} stops (auto)", app.display_exposure())
    } else {
        format!("exposure {:+} stops", app.exposure)
    }));
    lines.extend(super::readouts::noise_scale(app));
    lines.extend(super::readouts::caught_lines(app));
    lines.extend(app.split_lines());
    if app.shows_bounces() {
        lines.push(Line::from(format!("bounces {}", app.bounce_short())));
        if let Some(share) = app.bounce_share() {
            lines.push(Line::from(format!(
                "  {:.1}% of the total light",
                100.0 * share
            )));
        }
    }
    if app.shows_compare() {
        lines.push(Line::from(format!("compare: {}", app.compare_name())));
        if app.compare.is_difference() {
            lines.push(difference_legend(app));
        }
        lines.extend(super::readouts::compare_lines(app));
    }
    if let Some(c) = app.current_chapter() {
        if let Some(v) = c.info().variants.get(app.variant) {
            lines.push(Line::from(format!(
                "estimator {}/{}: {}",
                app.variant + 1,
                c.info().variants.len(),
                v.name
            )));
        }
    }
    lines.extend(super::readouts::efficiency_lines(app));
    lines
}

/// The error against time on log-log axes, whole decades, with the slope
/// −1/2 guide of a Monte Carlo estimate through the running render's last
/// point (the same as the reports' plots): a render on the guide converges
/// as it should. Every estimator's kept curve of this chapter and scene is
/// drawn beside it, in its own colour: the controls box's efficiency lines
/// are its legend (ratatui's own would cover the curves).
fn draw_chart(app: &App, frame: &mut Frame, area: Rect) {
    let curves = app.curves();
    let Some(current) = curves.iter().find(|c| c.current) else {
        return;
    };
    let LogLog {
        guide,
        mut x,
        mut y,
        ..
    } = log_log(&current.series);
    let all: Vec<LogLog> = curves.iter().map(|c| log_log(&c.series)).collect();
    for l in &all {
        (x, y) = (
            (x.0.min(l.x.0), x.1.max(l.x.1)),
            (y.0.min(l.y.0), y.1.max(l.y.1)),
        );
    }
    let guide = extend_guide(&guide, x);
    let label = |e: f64| format!("1e{}", e as i32);
    let mut sets = vec![Dataset::default()
        .name("slope −1/2")
        .marker(Marker::Braille)
        .graph_type(GraphType::Line)
        .style(Style::default())
        .data(&guide)];
    for (c, l) in curves.iter().zip(&all) {
        sets.push(
            Dataset::default()
                .name(c.name.clone())
                .marker(Marker::Braille)
                .graph_type(GraphType::Line)
                .style(fg(app, c.colour))
                .data(&l.data),
        );
    }
    let chart = Chart::new(sets)
        .block(Block::bordered().title("error vs time; plain line −1/2"))
        // The controls box's efficiency lines are the legend: ratatui's
        // own, drawn over the chart, hid the curves it names.
        .legend_position(None)
        .x_axis(Axis::default().bounds([x.0, x.1]).labels([
            format_seconds(10f64.powf(x.0)),
            format_seconds(10f64.powf(x.1)),
        ]))
        .y_axis(
            Axis::default()
                .bounds([y.0, y.1])
                .labels([label(y.0), label(y.1)]),
        );
    frame.render_widget(chart, area);
}

/// The −1/2 guide (two points) stretched to the x bounds `x`.
fn extend_guide(guide: &[(f64, f64)], x: (f64, f64)) -> Vec<(f64, f64)> {
    match guide {
        [(x0, y0), (x1, y1)] if x1 > x0 => {
            let slope = (y1 - y0) / (x1 - x0);
            vec![
                (x.0, y0 + slope * (x.0 - x0)),
                (x.1, y0 + slope * (x.1 - x0)),
            ]
        }
        _ => guide.to_vec(),
    }
}

/// An error series ready for log-log axes.
#[derive(Clone, Debug, PartialEq)]
pub struct LogLog {
    /// The points as (log10 seconds, log10 error).
    pub data: Vec<(f64, f64)>,
    /// The slope −1/2 guide through the last point, edge to edge.
    pub guide: Vec<(f64, f64)>,
    /// The x axis' bounds, whole decades.
    pub x: (f64, f64),
    /// The y axis' bounds, whole decades.
    pub y: (f64, f64),
}

/// An error series as log10 points, the −1/2 guide through its last
/// point, and the axes' bounds in whole decades (points that are not
/// positive and finite are left out).
pub fn log_log(series: &[(f64, f64)]) -> LogLog {
    let data: Vec<(f64, f64)> = series
        .iter()
        .filter(|(t, e)| *t > 0.0 && *e > 0.0 && t.is_finite() && e.is_finite())
        .map(|(t, e)| (t.log10(), e.log10()))
        .collect();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in &data {
        (x0, x1, y0, y1) = (x0.min(*x), x1.max(*x), y0.min(*y), y1.max(*y));
    }
    if data.is_empty() {
        (x0, x1, y0, y1) = (-1.0, 0.0, -2.0, -1.0);
    }
    let x = (x0.floor(), x1.ceil().max(x0.floor() + 1.0));
    let y = (y0.floor(), y1.ceil().max(y0.floor() + 1.0));
    let guide = match data.last() {
        Some(&(lx, ly)) => vec![(x.0, ly + 0.5 * (lx - x.0)), (x.1, ly - 0.5 * (x.1 - lx))],
        None => Vec::new(),
    };
    LogLog { data, guide, x, y }
}

fn draw_preview(app: &App, frame: &mut Frame, area: Rect) {
    let title = match (&app.grading, app.current_chapter()) {
        (Some(g), _) => format!("grade · {} · {}", g.stem, app.compare_name()),
        (None, _) if app.student.is_some() => student_title(app),
        (None, Some(_)) => fit_parts(&preview_title_parts(app), area.width.saturating_sub(4)),
        (None, None) => "preview".into(),
    };
    let block = Block::bordered().title(title);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let note = |text: String, color: Color| {
        Paragraph::new(escape_keep_newlines(&text).into_owned())
            .style(fg(app, color))
            .wrap(Wrap { trim: true })
    };
    match super::shown::content(app) {
        Content::Film(film) => draw_film(app, frame, &film, inner),
        Content::Note(text, color) => frame.render_widget(note(text, color), inner),
    }
}

/// The preview's title in student mode: `student · ch1/draw_edges ·
/// reference`.
fn student_title(app: &App) -> String {
    let id = app.student.as_ref().map_or("", |s| s.id.as_str());
    match app.student_render() {
        Some(_) => format!("student · {id} · {}", app.compare_name()),
        None => format!("student · {id}"),
    }
}

/// The difference views' legend: which colour is which sign, on which
/// scale.
fn difference_legend(app: &App) -> Line<'static> {
    let (_, scale) = app.compare.scale(app.exposure);
    Line::from(vec![
        Span::styled(format!("−{scale}"), fg(app, Color::LightBlue)),
        Span::raw(" blue · 0 · "),
        Span::styled(format!("+{scale}"), fg(app, Color::Red)),
        Span::raw(" red"),
    ])
}

fn draw_help(app: &App, frame: &mut Frame, area: Rect) {
    let w = 78.min(area.width);
    let h = (KEYS.len() as u16 + 2).min(area.height);
    let r = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    // Where the terminal is too short for every key, the last row says
    // how many more there are and how to scroll to them.
    let rows = h.saturating_sub(2) as usize;
    let first = app
        .help_scroll
        .min(super::keys::help_scroll_max(area.height));
    let hidden = KEYS.len().saturating_sub(rows);
    let shown = if hidden > 0 {
        rows.saturating_sub(1)
    } else {
        rows
    };
    let mut lines: Vec<Line> = KEYS[first..(first + shown).min(KEYS.len())]
        .iter()
        .map(|(k, what)| {
            Line::from(vec![
                Span::styled(
                    format!("{k:>15}  "),
                    Style::default().add_modifier(Modifier::BOLD),
                ),
                Span::raw(*what),
            ])
        })
        .collect();
    if hidden > 0 {
        let below = KEYS.len().saturating_sub(first + shown);
        lines.push(Line::from(format!(
            "… {below} more keys below, {first} above: ↑ ↓ scroll"
        )));
    }
    frame.render_widget(Clear, r);
    frame.render_widget(
        Paragraph::new(lines).block(Block::bordered().title("keys (Esc or any key closes)")),
        r,
    );
}
