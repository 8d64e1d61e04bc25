//! The report every chapter prints: the three standing requirements in one
//! place.
//!
//! 1. *Error against run time*: a table of (variant, time, samples, error
//!    against a reference, efficiency, notes) with a log-log slope per series,
//!    also written as CSV next to the image.
//! 2. *Numerical stability*: each stiff or extreme case with its expected
//!    and measured outcome.
//! 3. *What the scene led the stage to build, and what it left out.*

use std::fmt::Write as _;
use std::path::Path;

use crate::core::error::Result;
use crate::core::figure::Figure;
use crate::core::film::write_atomically;
use crate::core::format::{format_number, format_seconds};
use crate::core::plot::{Guide, LogLogPlot, Look, Series};
pub use crate::core::table::{wrap, Table, COLUMNS};

/// One measured run of one variant.
#[derive(Clone, Debug, PartialEq)]
pub struct Measurement {
    /// Rows of the same series share a log-log slope (e.g. one estimator).
    pub series: String,
    /// What was run (e.g. "f32, depth 1e3" or "16 spp").
    pub variant: String,
    /// Wall-clock seconds.
    pub seconds: f64,
    /// Samples (points, rays, paths) the run took.
    pub samples: u64,
    /// Error against the reference (RMSE unless the header says otherwise).
    pub error: f64,
    /// Anything worth saying about the row.
    pub notes: String,
}

impl Measurement {
    /// Efficiency 1 / (MSE · time): higher is better; infinite when exact.
    pub fn efficiency(&self) -> f64 {
        1.0 / (self.error * self.error * self.seconds)
    }
}

/// The error-against-time study of a stage.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ErrorTime {
    /// What the error is measured against.
    pub reference: String,
    /// What the error column means (e.g. "max error (px)", "RMSE").
    pub error_name: String,
    /// The runs.
    pub rows: Vec<Measurement>,
    /// Whether a log-log slope per series means something (it does for
    /// Monte Carlo and supersampling; not for a precision sweep).
    pub show_slopes: bool,
}

impl ErrorTime {
    /// Least-squares slope of log(error) against log(time) for one series,
    /// over rows with non-zero error; `None` when [`ErrorTime::fit`] is.
    pub fn slope(&self, series: &str) -> Option<f64> {
        self.fit(series).map(|f| f.slope)
    }

    /// The least-squares line through one series on log-log axes: log
    /// error against log seconds. `None` unless the fit can be trusted:
    /// at least [`MIN_FIT_POINTS`] rows with non-zero error spanning at
    /// least [`MIN_FIT_SPAN`] times in run time (timing noise swamps a
    /// slope over a shorter span).
    pub fn fit(&self, series: &str) -> Option<LogLogFit> {
        let pts: Vec<(f64, f64)> = self
            .rows
            .iter()
            .filter(|r| r.series == series && r.error > 0.0 && r.seconds > 0.0)
            .map(|r| (r.seconds.ln(), r.error.ln()))
            .collect();
        LogLogFit::through(&pts).filter(LogLogFit::is_trustworthy)
    }

    /// The series names, in order of first appearance.
    pub fn series(&self) -> Vec<String> {
        let mut names: Vec<String> = Vec::new();
        for r in &self.rows {
            if !names.contains(&r.series) {
                names.push(r.series.clone());
            }
        }
        names
    }

    /// The table as CSV (times in seconds).
    pub fn to_csv(&self) -> String {
        let mut s = String::from("series,variant,seconds,samples,error,efficiency,notes\n");
        for r in &self.rows {
            let _ = writeln!(
                s,
                "{},{},{:e},{},{:e},{:e},{}",
                csv(&r.series),
                csv(&r.variant),
                r.seconds,
                r.samples,
                r.error,
                r.efficiency(),
                csv(&r.notes)
            );
        }
        s
    }
}

/// A slope is printed only from at least this many points...
pub const MIN_FIT_POINTS: usize = 3;
/// ... spanning at least this factor in run time.
pub const MIN_FIT_SPAN: f64 = 4.0;
/// A fitted line is read off (e.g. "time to reach RMSE 0.01") at most
/// this factor beyond the measured range; further out is a guess.
pub const MAX_EXTRAPOLATION: f64 = 10.0;

/// Slope of the least-squares line through (x, y) points.
pub fn log_log_slope(pts: &[(f64, f64)]) -> Option<f64> {
    LogLogFit::through(pts).map(|f| f.slope)
}

/// A straight line through points on log-log axes, ln y = a + slope · ln x,
/// with the range of ln x it was fitted over.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogLogFit {
    /// The slope (−1/2 for a Monte Carlo estimator against time).
    pub slope: f64,
    /// ln y at ln x = 0.
    pub intercept: f64,
    /// The smallest and largest ln x fitted.
    pub ln_x_range: (f64, f64),
    /// How many points.
    pub points: usize,
}

impl LogLogFit {
    /// The least-squares line through `(ln x, ln y)` points; `None` for
    /// fewer than two points or when all share one x.
    pub fn through(pts: &[(f64, f64)]) -> Option<LogLogFit> {
        if pts.len() < 2 {
            return None;
        }
        let n = pts.len() as f64;
        let (mx, my) = (
            pts.iter().map(|p| p.0).sum::<f64>() / n,
            pts.iter().map(|p| p.1).sum::<f64>() / n,
        );
        let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
        let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
        if sxx <= 0.0 {
            return None;
        }
        let slope = sxy / sxx;
        let lo = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
        let hi = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
        Some(LogLogFit {
            slope,
            intercept: my - slope * mx,
            ln_x_range: (lo, hi),
            points: pts.len(),
        })
    }

    /// Whether the fit spans enough to mean something: at least
    /// [`MIN_FIT_POINTS`] points over at least [`MIN_FIT_SPAN`] times in x.
    pub fn is_trustworthy(&self) -> bool {
        self.points >= MIN_FIT_POINTS
            && self.ln_x_range.1 - self.ln_x_range.0 >= MIN_FIT_SPAN.ln() - 1e-12
    }

    /// The x at which the line reaches `y`, and whether that lies outside
    /// the fitted range (an extrapolation); `None` unless the line falls,
    /// and `None` more than [`MAX_EXTRAPOLATION`] times beyond the range.
    pub fn x_at(&self, y: f64) -> Option<(f64, bool)> {
        if self.slope >= 0.0 || y.is_nan() || y <= 0.0 {
            return None;
        }
        let ln_x = (y.ln() - self.intercept) / self.slope;
        let (lo, hi) = self.ln_x_range;
        let reach = MAX_EXTRAPOLATION.ln();
        if ln_x < lo - reach || ln_x > hi + reach {
            return None;
        }
        Some((ln_x.exp(), ln_x < lo || ln_x > hi))
    }
}

fn csv(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// One stiff or extreme case and how the stage coped.
#[derive(Clone, Debug, PartialEq)]
pub struct StabilityCase {
    /// The case.
    pub name: String,
    /// What should happen.
    pub expected: String,
    /// What did happen.
    pub measured: String,
    /// Whether that is what should happen.
    pub ok: bool,
}

impl StabilityCase {
    /// A case with what should happen, what did, and whether they match.
    pub fn new(name: &str, expected: &str, measured: String, ok: bool) -> StabilityCase {
        StabilityCase {
            name: name.into(),
            expected: expected.into(),
            measured,
            ok,
        }
    }
}

/// A chapter's report.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Report {
    /// e.g. "ch1 projection: tetrahedron".
    pub title: String,
    /// Key facts: resolution, render time, counts.
    pub facts: Vec<(String, String)>,
    /// Stage-specific tables (projected coordinates, mesh checks, ...).
    pub tables: Vec<Table>,
    /// Requirement 1.
    pub error_vs_time: Option<ErrorTime>,
    /// Requirement 2.
    pub stability: Vec<StabilityCase>,
    /// Requirement 3: what the scene led the stage to build...
    pub built: Vec<String>,
    /// ... and what it left out.
    pub left_out: Vec<String>,
    /// NaN or Inf values caught before they reached an image.
    pub nonfinite_caught: u64,
    /// Pictures that come with the report (plots of its studies, strips,
    /// per-bounce layers); the runner writes them beside the images.
    pub figures: Vec<Figure>,
}

/// Whether printed reports show wall-clock times (snapshots hide them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Times {
    /// Print measured times.
    Show,
    /// Print `-` instead, so the text is the same on every run.
    Hide,
}

impl Report {
    /// The report as text.
    pub fn to_text(&self, times: Times) -> String {
        let mut s = format!("== {} ==\n", self.title);
        for (k, v) in &self.facts {
            s += &wrap(&format!("{k}: {v}"), "  ", "      ", COLUMNS);
        }
        s += &list("built", &self.built);
        s += &list("left out", &self.left_out);
        let _ = writeln!(
            s,
            "  NaN/Inf caught before the image: {}",
            self.nonfinite_caught
        );
        for t in &self.tables {
            s += "\n";
            s += &t.to_text();
        }
        if let Some(et) = &self.error_vs_time {
            s += "\n";
            s += &self.error_table(et, times).to_text();
            if et.show_slopes {
                s += "  log-log slope of error against time (— = fewer than 3 runs or under 4x in time):\n";
                for series in et.series() {
                    // Whether a slope can be trusted depends on the times
                    // too (their span): hidden with them.
                    let k = match (et.slope(&series), times) {
                        (_, Times::Hide) => "-".into(),
                        (Some(k), Times::Show) => format!("{k:.2}"),
                        (None, Times::Show) => "—".into(),
                    };
                    s += &wrap(&format!("{series}: {k}"), "    ", "      ", COLUMNS);
                }
            }
        }
        if !self.stability.is_empty() {
            let mut t = Table::new(
                "Stiff and extreme cases",
                &["case", "expected", "measured", "ok"],
            );
            for c in &self.stability {
                t.row(vec![
                    c.name.clone(),
                    c.expected.clone(),
                    c.measured.clone(),
                    if c.ok { "yes" } else { "NO" }.into(),
                ]);
            }
            s += "\n";
            s += &t.to_text();
        }
        s
    }

    fn error_table(&self, et: &ErrorTime, times: Times) -> Table {
        let title = format!("Error against run time (reference: {})", et.reference);
        let mut t = Table::new(
            &title,
            &[
                "series",
                "variant",
                "time",
                "samples",
                &et.error_name,
                "1/(MSE·time)",
                "notes",
            ],
        );
        for r in &et.rows {
            let (time, eff) = match times {
                Times::Show => (format_seconds(r.seconds), format_number(r.efficiency())),
                Times::Hide => ("-".into(), "-".into()),
            };
            t.row(vec![
                r.series.clone(),
                r.variant.clone(),
                time,
                r.samples.to_string(),
                format_number(r.error),
                eff,
                r.notes.clone(),
            ]);
        }
        t
    }

    /// Whether every stiff case came out as expected.
    pub fn all_stable(&self) -> bool {
        self.stability.iter().all(|c| c.ok)
    }

    /// Writes the error-against-time table (`stem.csv`) and the stability
    /// table (`stem-stability.csv`) into `dir`.
    pub fn write_csv(&self, dir: &Path, stem: &str) -> Result<()> {
        let write_text = |name: String, text: String| {
            write_atomically(&dir.join(name), |tmp| {
                std::fs::write(tmp, text).map_err(|e| e.to_string())
            })
        };
        if let Some(et) = &self.error_vs_time {
            write_text(format!("{stem}.csv"), et.to_csv())?;
        }
        if !self.stability.is_empty() {
            let mut s = String::from("case,expected,measured,ok\n");
            for c in &self.stability {
                let _ = writeln!(
                    s,
                    "{},{},{},{}",
                    csv(&c.name),
                    csv(&c.expected),
                    csv(&c.measured),
                    c.ok
                );
            }
            write_text(format!("{stem}-stability.csv"), s)?;
        }
        Ok(())
    }
}

/// `  name: nothing`, or `  name:` and one wrapped `- item` per line.
fn list(name: &str, items: &[String]) -> String {
    if items.is_empty() {
        return format!("  {name}: nothing\n");
    }
    let mut s = format!("  {name}:\n");
    for item in items {
        s += &wrap(item, "    - ", "      ", COLUMNS);
    }
    s
}

impl ErrorTime {
    /// The error-against-time plot of the series whose names start
    /// with `prefix` (the prefix is left out of the legend), each looked up
    /// in `look`; with the −1/2 guide when `et` shows slopes.
    pub fn plot(&self, prefix: &str, title: &str, look: impl Fn(&str) -> Look) -> LogLogPlot {
        let et = self;
        let series = et
            .series()
            .into_iter()
            .filter(|s| s.starts_with(prefix))
            .map(|s| Series {
                label: s[prefix.len()..].trim_matches([' ', ':', '/']).to_string(),
                look: look(&s),
                points: et
                    .rows
                    .iter()
                    .filter(|r| r.series == s)
                    .map(|r| (r.seconds, r.error))
                    .collect(),
            })
            .collect();
        LogLogPlot {
            title: title.into(),
            x_label: "run time (s)".into(),
            y_label: et.error_name.clone(),
            series,
            guide: et.show_slopes.then(|| Guide {
                slope: -0.5,
                label: "slope −1/2".into(),
            }),
        }
    }
}
