//! What the UI says: the names of things (the bounce selection, the
//! compare selection, the view, the estimator), the preview's title, the
//! status line, the key hints of the message line, and the names of saved
//! files. Each says what is shown, most important first, so a narrow
//! terminal drops the least important words.

use ratatui::text::{Line, Span};

use super::app::{bounce_name, App, BounceMode, Compare};
use super::gauge::short_number;
use crate::core::format::format_seconds;
use crate::core::text::escape;

impl App {
    /// The selected estimator or sampler's step on the ladder, in the
    /// lecture's words: "step 8/8: importance sampling according to …".
    pub fn variant_label(&self) -> Option<String> {
        let c = self.current_chapter()?;
        let v = c.info().variants.get(self.variant)?;
        Some(format!(
            "step {}/{}: {}",
            self.variant + 1,
            c.info().variants.len(),
            v.about
        ))
    }

    /// The compare selection's name: render, reference, difference, or
    /// student, reference, difference for the grader's images.
    pub fn compare_name(&self) -> &'static str {
        if self.grading.is_some() || self.student_render().is_some() {
            self.compare.grading_name()
        } else {
            self.compare.name()
        }
    }

    /// The name of the selected view.
    pub fn view_name(&self) -> &'static str {
        self.current_chapter()
            .and_then(|c| c.info().views.get(self.view))
            .map(|v| v.name)
            .unwrap_or("-")
    }

    /// The label of the bounce selection, in the lecture's words.
    pub fn bounce_label(&self) -> String {
        match self.bounce {
            None => "all bounces".into(),
            Some(k) => match self.bounce_mode {
                BounceMode::Exactly if k == 0 => "exactly 0 bounces: direct light alone".into(),
                BounceMode::Exactly => {
                    format!("{}: bounce {k} alone", self.bounce_short_words())
                }
                BounceMode::UpTo => format!("{}: {}", self.bounce_short_words(), bounce_name(k)),
            },
        }
    }

    /// The bounce selection in a few words: "all bounces", "up to 2
    /// bounces", "exactly 1 bounce".
    pub fn bounce_short_words(&self) -> String {
        match self.bounce {
            None => "all bounces".into(),
            Some(k) => {
                let noun = if k == 1 { "bounce" } else { "bounces" };
                format!("{} {noun}", self.bounce_short())
            }
        }
    }

    /// The bounce selection for the controls box: "all", "up to 2",
    /// "exactly 1".
    pub fn bounce_short(&self) -> String {
        match (self.bounce, self.bounce_mode) {
            (None, _) => "all".into(),
            (Some(k), BounceMode::UpTo) => format!("up to {k}"),
            (Some(k), BounceMode::Exactly) => format!("exactly {k}"),
        }
    }

    /// The base name of saved files for the current view.
    pub fn save_stem(&self) -> String {
        if let Some(g) = &self.grading {
            return format!("tui-grade-{}-{}", g.stem, self.compare_name());
        }
        if let Some(r) = self.student_render() {
            let id = r.id.replace('/', "-");
            return format!("tui-student-{id}-{}", self.compare_name());
        }
        let chapter = self.current_chapter().map(|c| c.info().number).unwrap_or(0);
        let scene = self
            .current_scene()
            .and_then(|s| s.scene.as_ref().ok())
            .map(|s| s.name.clone())
            .unwrap_or_else(|| "scene".into());
        let mut stem = format!("tui-ch{chapter}-{scene}-{}", self.view_name());
        if self.view == 0 && self.shows_bounces() {
            if let Some(k) = self.bounce {
                let mode = match self.bounce_mode {
                    BounceMode::Exactly => "exactly",
                    BounceMode::UpTo => "upto",
                };
                stem += &format!("-{mode}{k}");
            }
        }
        if self.view == 0 && self.shows_compare() && self.compare != Compare::Render {
            stem += &format!("-{}", self.compare.name());
        }
        let info = self.current_chapter().map(|c| c.info());
        if let Some(v) = info.and_then(|i| i.variants.get(self.variant)) {
            stem += &format!("-{}", v.name);
        }
        if let Some(snap) = self.snapshot.as_ref().filter(|s| s.samples > 0) {
            stem += &format!("-{}spp", snap.samples);
        }
        let ev = if self.shows_signed() {
            self.exposure
        } else {
            self.display_exposure()
        };
        if ev != 0 {
            stem += &format!("-ev{ev:+}");
        }
        stem
    }
}

/// What the preview shows, most important first, for its title: render,
/// reference or difference; which bounce layer ("up to k bounces" /
/// "exactly k bounces"); which estimator; then the view and the chapter,
/// the lecture's name for the layer, its share of the light and the
/// graphics protocol. [`fit_parts`] drops from the end what does not fit.
pub fn preview_title_parts(app: &App) -> Vec<String> {
    let Some(c) = app.current_chapter() else {
        return vec!["preview".into()];
    };
    let info = c.info();
    let mut parts = Vec::new();
    let variant = info.variants.get(app.variant).map(|v| v.name);
    if let Some(p) = app.pinned_here().filter(|_| app.shows_split()) {
        parts.push("split at equal time".into());
        parts.push(format!("left pinned {}", p.label));
        parts.push(format!("right {}", variant.unwrap_or("running")));
        parts.push(format!("ch{} {}", info.number, info.slug));
        return parts;
    }
    let layer = (app.view == 0 && app.shows_bounces())
        .then_some(app.bounce)
        .flatten();
    let main = app.view == 0;
    let compare = if main && app.shows_compare() {
        app.compare
    } else {
        Compare::Render
    };
    let layer_words = layer.map(|_| app.bounce_short_words());
    match compare {
        Compare::Render => {
            let what = if main { "render" } else { app.view_name() };
            parts.push(match &layer_words {
                Some(l) => format!("{what}, {l}"),
                None => what.to_string(),
            });
            if let Some(v) = variant {
                parts.push(format!("estimator {v}"));
            }
        }
        Compare::Reference => {
            // The stored reference has every bounce: say so when a layer
            // is selected, so the title never claims a layer it is not.
            parts.push(match layer {
                Some(_) => "reference, all bounces".into(),
                None => "reference".into(),
            });
        }
        Compare::Difference | Compare::Relative => {
            let render = match &layer_words {
                Some(l) => format!("render ({l}) - reference"),
                None => "render - reference".into(),
            };
            parts.push(match compare {
                Compare::Relative => format!("relative difference: ({render}) / reference"),
                _ => format!("difference: {render}"),
            });
            let (_, scale) = compare.scale(app.exposure);
            parts.push(format!("full colour at ±{scale}"));
            if let Some(v) = variant {
                parts.push(format!("estimator {v}"));
            }
        }
        Compare::Z => {
            parts.push(match &layer_words {
                Some(l) => format!("z: (render ({l}) - reference) / standard error"),
                None => "z: (render - reference) / standard error".into(),
            });
            let (_, scale) = compare.scale(app.exposure);
            parts.push(format!("full colour at ±{scale}"));
        }
    }
    // A pinned render stands in for the reference: say which.
    if let Some(p) = app.pinned_here().filter(|_| compare != Compare::Render) {
        parts[0] = parts[0].replace("reference", "pinned");
        parts.insert(1, format!("pinned {}", p.label));
    }
    if main {
        parts.push(app.view_name().to_string());
    }
    parts.push(format!("ch{} {}", info.number, info.slug));
    if let (Some(k), Compare::Render) = (layer, compare) {
        if app.bounce_mode == BounceMode::UpTo {
            parts.push(bounce_name(k));
        }
        if let Some(share) = app.bounce_share() {
            parts.push(format!("{:.1}% of the light", 100.0 * share));
        }
    }
    if app.zoom > 1 {
        // Right after what is shown: a zoomed picture must say so.
        parts.insert(1.min(parts.len()), format!("zoom {}x", app.zoom));
    }
    if super::placement::graphics_font(app).is_some() {
        parts.push(app.graphics.name().to_string());
    }
    parts
}

/// `parts` joined with " · ", the last ones dropped until the text fits
/// `width` cells (the first is always kept, cut if it must be).
pub fn fit_parts(parts: &[String], width: u16) -> String {
    let width = width as usize;
    let mut out = String::new();
    for (i, p) in parts.iter().enumerate() {
        let next = if i == 0 {
            p.clone()
        } else {
            format!("{out} · {p}")
        };
        if i > 0 && next.chars().count() > width {
            break;
        }
        out = next;
    }
    if out.chars().count() > width {
        out = out.chars().take(width).collect();
    }
    out
}

/// A rate in the status line: 1234567 → "1.23M".
pub fn format_rate(rate: f64) -> String {
    let (value, unit) = if rate >= 1e9 {
        (rate / 1e9, "G")
    } else if rate >= 1e6 {
        (rate / 1e6, "M")
    } else if rate >= 1e3 {
        (rate / 1e3, "k")
    } else {
        (rate, "")
    };
    let digits = if value >= 100.0 {
        0
    } else if value >= 10.0 {
        1
    } else {
        2
    };
    format!("{value:.digits$}{unit}")
}

/// The status line's parts, most important first: chapter, samples (or
/// passes), the error against the reference, then noise, scene, view,
/// resolution, time and rays per second.
pub fn status_parts(app: &App) -> Vec<String> {
    let mut parts: Vec<String> = Vec::new();
    if let Some(c) = app.current_chapter() {
        parts.push(format!("ch{} {}", c.info().number, c.info().slug));
    }
    // The scene's own name ("(built-in)" is in the scene list).
    let scene = app.current_scene().map(|s| match &s.scene {
        Ok(scene) => escape(&scene.name).into_owned(),
        Err(_) => escape(&s.name).into_owned(),
    });
    let view = app.view_name().to_string();
    let mut rest = Vec::new();
    if let Some(g) = &app.grading {
        let f = &g.student;
        parts.push(format!("grade {}", g.stem));
        parts.push(app.compare_name().to_string());
        rest.push(format!("{}x{}", f.width, f.height));
    } else if let Some(s) = &app.student {
        parts.push(format!("student {}", s.id));
        parts.push(escape(&s.status).into_owned());
        if let Some(r) = &s.render {
            parts.push(app.compare_name().to_string());
            rest.push(format!("{}x{}", r.student.width, r.student.height));
        }
    } else if let Some(snap) = &app.snapshot {
        match &snap.target {
            Some(t) => parts.push(format!("spp {}/{}", snap.samples, t.spp)),
            None => parts.push(format!("pass {}/{}", snap.progress.0, snap.progress.1)),
        }
        if let Some(e) = snap.rmse {
            parts.push(format!("rmse {}", short_number(e)));
        }
        if let Some(n) = snap.noise {
            parts.push(format!("noise {}", short_number(n)));
        }
        if let Some(f) = snap.views.first() {
            rest.push(format!("{}x{}", f.width, f.height));
        }
        rest.push(format_seconds(snap.elapsed.as_secs_f64()));
        if let Some(rate) = snap.rays_per_second() {
            rest.push(format!("{} rays/s", format_rate(rate)));
        }
    } else if app.failure.is_some() {
        parts.push("failed".into());
    } else if app.scene_to_read().is_some() {
        parts.push("reading the scene…".into());
    } else if app.problem().is_none() {
        parts.push("rendering…".into());
    }
    parts.extend(scene);
    parts.push(view);
    parts.extend(rest);
    parts
}

/// The whole status line ([`status_parts`] joined).
pub fn status_line(app: &App) -> Line<'static> {
    Line::from(Span::raw(status_parts(app).join(" │ ")))
}

/// The status line for a screen `width` cells wide: what does not fit is
/// dropped from the end, so chapter, samples and RMSE stay.
pub fn status_line_fit(app: &App, width: u16) -> Line<'static> {
    let parts = status_parts(app);
    let mut out = String::new();
    for (i, p) in parts.iter().enumerate() {
        let next = if i == 0 {
            p.clone()
        } else {
            format!("{out} │ {p}")
        };
        if i > 0 && next.chars().count() > width as usize {
            // The part that does not fit, cut, when there is room for
            // some of it.
            let room = (width as usize).saturating_sub(out.chars().count() + 4);
            if room >= 8 {
                let cut: String = p.chars().take(room - 1).collect();
                out = format!("{out} │ {cut}…");
            }
            break;
        }
        out = next;
    }
    Line::from(Span::raw(out))
}

/// The message line when there is no message: the pixel under the mouse
/// and its value, or the keys that matter in the current mode.
pub fn key_hints(app: &App) -> String {
    if let Some(text) = hover_text(app) {
        return text;
    }
    let mode = if app.trace.is_some() {
        "t next path · u d scroll · Esc close the path"
    } else if app.inspect.is_some() && app.traces_paths() {
        "arrows move · t trace a path · u d scroll · Esc close"
    } else if app.inspect.is_some() {
        "arrows move · u d scroll · Esc close"
    } else if app.grading.is_some() {
        "r student / reference / difference · g or Esc back"
    } else if app.student.is_some() {
        "r student / reference / difference · x or Esc back"
    } else if app.paused {
        "paused: space resumes"
    } else if app.shows_compare() {
        "i inspect · r compare · f flip · s save"
    } else {
        "i inspect · s save"
    };
    format!("{mode} · ? help · q quit")
}

/// "pixel (x, y): r g b" for the pixel under the mouse, as the preview
/// shows it (the view, layer and comparison selected, before exposure).
pub fn hover_text(app: &App) -> Option<String> {
    let (x, y) = app.hover?;
    if app.shows_caught() {
        let counts = app.snapshot.as_ref()?.views.get(app.view)?;
        return (x < counts.width && y < counts.height).then(|| {
            let n = counts.get(x, y).x;
            format!("pixel ({x}, {y}): {n} samples NaN or infinite, left out (under the mouse)")
        });
    }
    let film = app.displayed_ref()?;
    (x < film.width && y < film.height).then(|| {
        let v = film.get(x, y);
        let what = match app.compare {
            Compare::Difference if app.shows_signed() => "render − reference ",
            Compare::Relative if app.shows_signed() => "(render − reference) / reference ",
            Compare::Z if app.shows_signed() => "z = (render − reference) / standard error ",
            _ => "",
        };
        format!(
            "pixel ({x}, {y}): {what}{} (under the mouse; click to inspect)",
            crate::core::format::rgb(v)
        )
    })
}

/// A chapter's title in `room` characters: whole where it fits, else the
/// part before its colon ("Projection"), else cut at a word with "…".
pub fn fit_title(title: &str, room: usize) -> String {
    let len = |s: &str| s.chars().count();
    if len(title) <= room {
        return title.to_string();
    }
    if let Some((head, _)) = title.split_once(':') {
        if len(head) <= room {
            return head.to_string();
        }
    }
    let mut out = String::new();
    for word in title.split(' ') {
        let next = if out.is_empty() {
            word.to_string()
        } else {
            format!("{out} {word}")
        };
        if len(&next) + 1 > room {
            break;
        }
        out = next;
    }
    if out.is_empty() {
        out = title.chars().take(room.saturating_sub(1)).collect();
    }
    format!("{}…", out.trim_end_matches([',', ' ']))
}
