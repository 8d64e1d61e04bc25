//! The warp view (`w`): chapter 5's sampling routines put to the test in
//! the terminal, after Nori's warptest. The directions a routine draws,
//! seen from above; how many fell in each cell of the sphere beside how
//! many its pdf predicts; and the χ² test's verdict
//! ([`crate::core::warp_test`]). The last routine is the student's own
//! (exercise 5.2), built and run in the grader's sandbox.

use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::canvas::{Canvas, Circle, Points};
use ratatui::widgets::{Block, Clear, Paragraph};
use ratatui::Frame;

use crate::chapters::{student_warp, warp_routines};
use crate::core::warp_test::{Drawn, WarpTest, COS_CELLS, DEFAULT_DRAWS, PHI_CELLS};

/// What the warp view shows: a routine, the seed of its numbers, and the
/// test's outcome.
#[derive(Clone, Debug)]
pub struct WarpView {
    /// Index into the routines: [`warp_routines`], then the student's
    /// ([`student_warp`]).
    pub index: usize,
    /// The seed of the draws (`n` takes the next).
    pub seed: u64,
    /// The outcome, or for the student's routine while it is being built
    /// and run (or could not be) what is happening.
    pub test: Result<WarpTest, String>,
    /// The student's routine is to be built and run with this seed: when
    /// it changes, `update` asks the event loop to
    /// ([`crate::effect::Effect::WarpStudent`]), which does it in a
    /// thread and answers with [`crate::app::Msg::WarpStudent`].
    pub student_requested: Option<u64>,
    /// A built-in routine is to be tested with this seed: `update` asks
    /// the event loop to ([`crate::effect::Effect::WarpBuiltin`]),
    /// which draws its directions in a thread, off the UI's, and answers
    /// with [`crate::app::Msg::WarpBuiltin`].
    pub pending: Option<u64>,
}

/// How many routines the view cycles through: the built-in ones and the
/// student's.
fn count() -> usize {
    warp_routines().len() + 1
}

impl WarpView {
    /// Runs routine `index` with `seed` (the student's is requested).
    pub fn new(index: usize, seed: u64) -> WarpView {
        let routines = warp_routines();
        let index = index % count();
        match routines.get(index) {
            Some(r) => WarpView {
                index,
                seed,
                test: Err(format!("drawing {DEFAULT_DRAWS} directions of {}…", r.name)),
                student_requested: None,
                pending: Some(seed),
            },
            None => WarpView {
                index,
                seed,
                test: Err(format!(
                    "building and running {} (chapters/{}.rs)…",
                    student_warp().name,
                    student_warp().id.replace('/', "-reflection/exercises/")
                )),
                student_requested: Some(seed),
                pending: None,
            },
        }
    }

    /// The routine's name.
    pub fn name(&self) -> &'static str {
        warp_routines()
            .get(self.index)
            .map_or(student_warp().name, |r| r.name)
    }

    /// The next (or, with `step` −1, previous) routine.
    pub fn step(&self, step: i64) -> WarpView {
        let n = count() as i64;
        WarpView::new((self.index as i64 + step).rem_euclid(n) as usize, self.seed)
    }

    /// The same routine with new numbers.
    pub fn reseeded(&self) -> WarpView {
        WarpView::new(self.index, self.seed + 1)
    }

    /// A built-in routine's test, drawn in a thread for routine `index`
    /// and `seed`; ignored unless the view still waits for it.
    pub fn builtin_done(&mut self, index: usize, seed: u64, test: WarpTest) {
        if self.index == index && self.seed == seed {
            self.test = Ok(test);
            self.pending = None;
        }
    }

    /// The student's draws (or why there are none) for seed `seed`,
    /// tested against the density the exercise's contract names; ignored
    /// unless the view still waits for them.
    pub fn student_drawn(&mut self, seed: u64, drawn: Result<Drawn, String>) {
        if self.index != warp_routines().len() || self.seed != seed {
            return;
        }
        self.student_requested = None;
        let pdf = student_warp().pdf;
        self.test = drawn.map(|d| d.test(student_warp().name, &pdf));
    }
}

/// Built-in routine `index`'s test with `seed` ([`DEFAULT_DRAWS`]
/// directions and the χ² test): what the event loop runs in a thread.
pub fn builtin_test(index: usize, seed: u64) -> Option<WarpTest> {
    warp_routines()
        .get(index)
        .map(|r| r.run(DEFAULT_DRAWS, seed))
}

/// The student's routine built and run as the grader runs it (in its
/// sandbox, under its time limit), drawing [`DEFAULT_DRAWS`] directions
/// with `seed`; or the one-line reason why not. Takes as long as the
/// build: the event loop calls it in a thread, one at a time, and sets
/// `cancel` when a newer request (or closing the view) makes it moot.
pub fn student_draws(
    out: &std::path::Path,
    seed: u64,
    cancel: &std::sync::atomic::AtomicBool,
) -> Result<Drawn, String> {
    let opts = crate::grading::live::LiveOptions::for_out_dir(out)?;
    crate::grading::live::live_warp(student_warp().id, DEFAULT_DRAWS, seed, &opts, Some(cancel))
        .map_err(|e| e.status())
}

/// The view's lines of text (title, verdict, keys), for tests and for
/// terminals too small for the pictures.
pub fn summary(w: &WarpView) -> Vec<String> {
    let draws = w.test.as_ref().map_or(DEFAULT_DRAWS, |t| t.draws);
    vec![
        format!(
            "warp test {}/{}: {} ({} draws, seed {})",
            w.index + 1,
            count(),
            w.name(),
            draws,
            w.seed
        ),
        match &w.test {
            Ok(t) => t.verdict(),
            Err(why) => why.clone(),
        },
        "←/→ routine · n new numbers · Esc close".into(),
    ]
}

/// Draws the view over `area`.
pub fn draw(w: &WarpView, color: bool, frame: &mut Frame, area: Rect) {
    frame.render_widget(Clear, area);
    let text = summary(w);
    let block = Block::bordered().title(text[0].clone());
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let [pictures, verdict, keys] = Layout::vertical([
        Constraint::Min(0),
        Constraint::Length(1),
        Constraint::Length(1),
    ])
    .areas(inner);
    let Ok(test) = &w.test else {
        frame.render_widget(Paragraph::new(text[1].clone()), verdict);
        frame.render_widget(Paragraph::new(text[2].clone()), keys);
        return;
    };
    let good = if test.passes() {
        Color::Green
    } else {
        Color::Red
    };
    let style = |c: Color| {
        if color {
            Style::default().fg(c)
        } else {
            Style::default()
        }
    };
    frame.render_widget(Paragraph::new(text[1].clone()).style(style(good)), verdict);
    frame.render_widget(Paragraph::new(text[2].clone()), keys);
    let histogram_width = 2 * PHI_CELLS as u16 + 2;
    let [points, histograms] = Layout::horizontal([
        Constraint::Min(10),
        Constraint::Length(histogram_width.min(pictures.width / 2)),
    ])
    .areas(pictures);
    draw_points(test, color, frame, points);
    let [observed, expected] =
        Layout::vertical([Constraint::Fill(1), Constraint::Fill(1)]).areas(histograms);
    let max = test
        .observed
        .iter()
        .chain(&test.expected)
        .fold(1.0f64, |m, v| m.max(*v));
    draw_histogram(
        "drawn per cell",
        &test.observed,
        max,
        color,
        frame,
        observed,
    );
    draw_histogram(
        "the pdf's prediction",
        &test.expected,
        max,
        color,
        frame,
        expected,
    );
}

/// The directions seen from above: (x, y) of each, upper hemisphere in
/// one colour, lower in another, inside the unit circle.
fn draw_points(test: &WarpTest, color: bool, frame: &mut Frame, area: Rect) {
    let upper: Vec<(f64, f64)> = test
        .points
        .iter()
        .filter(|p| p.z >= 0.0)
        .map(|p| (p.x as f64, p.y as f64))
        .collect();
    let lower: Vec<(f64, f64)> = test
        .points
        .iter()
        .filter(|p| p.z < 0.0)
        .map(|p| (p.x as f64, p.y as f64))
        .collect();
    let pick = |c: Color| if color { c } else { Color::Reset };
    let canvas = Canvas::default()
        .block(Block::bordered().title(format!(
            "{} directions from above (x, y){}",
            test.points.len(),
            if lower.is_empty() {
                String::new()
            } else {
                format!("; {} below the horizon", lower.len())
            }
        )))
        .marker(Marker::Braille)
        .x_bounds([-1.05, 1.05])
        .y_bounds([-1.05, 1.05])
        .paint(move |ctx| {
            ctx.draw(&Circle {
                x: 0.0,
                y: 0.0,
                radius: 1.0,
                color: pick(Color::DarkGray),
            });
            ctx.draw(&Points {
                coords: &upper,
                color: pick(Color::Cyan),
            });
            ctx.draw(&Points {
                coords: &lower,
                color: pick(Color::Red),
            });
        });
    frame.render_widget(canvas, area);
}

/// Counts per cell as a heat map: φ across, cos θ from 1 (top) to −1
/// (bottom), two cells per character cell (half blocks) in colour, shades
/// of ░▒▓█ without.
fn draw_histogram(
    title: &str,
    counts: &[f64],
    max: f64,
    color: bool,
    frame: &mut Frame,
    area: Rect,
) {
    let block = Block::bordered().title(format!("{title} (φ →, cos θ ↑)"));
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let level = |c: usize, p: usize| (counts[c * PHI_CELLS + p] / max).clamp(0.0, 1.0);
    // Two characters per φ cell where they fit, else one.
    let width = if inner.width as usize >= 2 * PHI_CELLS {
        2
    } else {
        1
    };
    let rows = (COS_CELLS / 2).min(inner.height as usize);
    let lines: Vec<Line> = (0..rows)
        .map(|r| {
            // Row r shows cos cells (top) 2r' + 1 and (bottom) 2r', counted
            // from the top of the sphere.
            let top = COS_CELLS - 1 - 2 * r;
            let bottom = top - 1;
            let spans: Vec<Span> = (0..PHI_CELLS)
                .map(|p| {
                    let (a, b) = (level(top, p), level(bottom, p));
                    if color {
                        let grey = |v: f64| {
                            let g = (v.sqrt() * 255.0) as u8;
                            Color::Rgb(g, g, g)
                        };
                        Span::styled("▀".repeat(width), Style::default().fg(grey(a)).bg(grey(b)))
                    } else {
                        let v = 0.5 * (a + b);
                        let shade = [" ", "░", "▒", "▓", "█"][(v.sqrt() * 4.0).round() as usize];
                        Span::raw(shade.repeat(width))
                    }
                })
                .collect();
            Line::from(spans)
        })
        .collect();
    frame.render_widget(Paragraph::new(lines), inner);
}
