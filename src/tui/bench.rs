//! `raystep --bench-ui`: how fast the UI starts and how much a redraw costs.
//!
//! Start-up is timed from the start of `main` to the first preview drawn:
//! scene list loaded, worker started, first pass of the first chapter on
//! the built-in scene received, and the UI drawn once. Redraws are timed on
//! a 200x60 test terminal, changing the exposure every frame so that every
//! preview cell changes and ratatui's diff has real work. The terminal
//! itself is not involved (a test backend), so the numbers are the UI's
//! own cost, not the terminal emulator's.

use std::io::Write;
use std::time::{Duration, Instant};

use ratatui::backend::TestBackend;
use ratatui::Terminal;

use super::app::{App, Msg};
use super::effect::Effect;
use super::scenes::scene_list;
use super::update::update;
use super::view::view;
use super::worker::{Progress, Worker};

/// Redraws timed per chapter.
pub const REDRAWS: usize = 200;

/// (mean, median, p95, max) in milliseconds. On a machine shared with
/// other work the median is the closest to the UI's own cost; p95 and max
/// also catch the moments the UI thread waited for a core.
fn stats(mut times: Vec<Duration>) -> (f64, f64, f64, f64) {
    times.sort();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let mean = times.iter().map(|d| ms(*d)).sum::<f64>() / times.len().max(1) as f64;
    let median = times.get(times.len() / 2).map_or(0.0, |d| ms(*d));
    let p95 = times.get(times.len() * 95 / 100).map_or(0.0, |d| ms(*d));
    let max = times.last().map_or(0.0, |d| ms(*d));
    (mean, median, p95, max)
}

/// Runs the benchmark and prints a table to `w`. `started` is the start of
/// `main`.
pub fn run(
    started: Instant,
    scenes_dir: &std::path::Path,
    w: &mut dyn Write,
) -> std::io::Result<()> {
    let chapters = crate::chapters::all();
    let scenes = scene_list(scenes_dir);
    let mut app = App::new(chapters.clone(), scenes, true);
    // The first chapter is selected already: its render is the first.
    let job = app.job();
    app.effects.extend(job.map(Effect::Start));
    let worker = Worker::spawn();
    let mut terminal = Terminal::new(TestBackend::new(200, 60))?;
    let mut rows = Vec::new();
    for (index, chapter) in chapters.iter().enumerate() {
        let t0 = if index == 0 { started } else { Instant::now() };
        app = update(app, Msg::ChapterNumber(chapter.info().number));
        // The chapter's scene read (here, in this thread), its job started
        // as update asks, and again on the scene it moves to if it refuses
        // the one it opened on; then the first pass of the job that runs.
        loop {
            if let Some((index, path)) = app.scene_to_read() {
                let read = super::scenes::read_scene(&path);
                app = update(app, Msg::SceneRead(index, path, read));
            }
            start_jobs(&worker, &mut app);
            if app.job().is_none() {
                break;
            }
            let p = worker
                .results
                .recv()
                .map_err(|e| std::io::Error::other(e.to_string()))?;
            let ours = p.generation() == app.generation;
            let failed = matches!(p, Progress::Failed { .. });
            app = update(app, Msg::Progress(p));
            if ours && (app.snapshot.is_some() || failed) {
                break;
            }
        }
        terminal.draw(|f| view(&app, f))?;
        let first = t0.elapsed();
        let mut times = Vec::with_capacity(REDRAWS);
        for i in 0..REDRAWS {
            app.exposure = if i % 2 == 0 { 1 } else { 0 };
            let t = Instant::now();
            terminal.draw(|f| view(&app, f))?;
            times.push(t.elapsed());
        }
        app.exposure = 0;
        let (mean, median, p95, max) = stats(times);
        let size = app
            .snapshot
            .as_ref()
            .and_then(|s| s.views.first())
            .map_or("-".to_string(), |f| format!("{}x{}", f.width, f.height));
        let scene = app
            .current_scene()
            .map_or(String::new(), |e| e.stem().to_string());
        let first = match (&app.snapshot, app.problem()) {
            (Some(_), _) => format!("{:.1}", first.as_secs_f64() * 1e3),
            (None, Some(why)) => format!("not rendered: {}", crate::core::text::escape(&why)),
            (None, None) => "not rendered".to_string(),
        };
        rows.push(format!(
            "| ch{} {} | {scene} | {size} | {first} | {mean:.2} | {median:.2} | {p95:.2} | {max:.2} |",
            chapter.info().number,
            chapter.info().slug,
        ));
    }
    worker.stop();
    writeln!(
        w,
        "UI benchmark: each chapter on the scene it opens on, 200x60 cells, {REDRAWS} redraws per chapter, {} threads",
        rayon::current_num_threads()
    )?;
    writeln!(
        w,
        "| chapter | scene | image | start to first preview (ms) | redraw mean (ms) | redraw median (ms) | redraw p95 (ms) | redraw max (ms) |"
    )?;
    writeln!(w, "|---|---|---|---|---|---|---|---|")?;
    for r in rows {
        writeln!(w, "{r}")?;
    }
    writeln!(
        w,
        "(start-up of ch1 counts from the start of main; later chapters from their selection)"
    )?;
    sixel_line(w)
}

/// Starts the renders `app` asks for; the benchmark asks nothing else of
/// the event loop's threads, so the other effects are dropped.
fn start_jobs(worker: &Worker, app: &mut App) {
    for effect in std::mem::take(&mut app.effects) {
        if let Effect::Start(job) = effect {
            worker.start(job);
        }
    }
}

/// The sixel picture is encoded on the UI thread whenever its pixels
/// change: the time for a 720 x 600 picture, what a 160 x 48 xterm shows.
fn sixel_line(w: &mut dyn Write) -> std::io::Result<()> {
    let img = image::RgbImage::from_fn(720, 600, |x, y| {
        let n = ((x * 7 + y * 13) % 40) as u8;
        image::Rgb([(x * 200 / 720) as u8 + n, (y * 200 / 600) as u8 + n, 80 + n])
    });
    let times: Vec<Duration> = (0..20)
        .map(|_| {
            let t = Instant::now();
            std::hint::black_box(super::sixel::encode(&img));
            t.elapsed()
        })
        .collect();
    let (mean, median, _, max) = stats(times);
    writeln!(
        w,
        "sixel encoding of a 720x600 picture: mean {mean:.2} ms, median {median:.2} ms, max {max:.2} ms"
    )
}
