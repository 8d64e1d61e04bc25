//! `s`: what the preview shows, saved as PNG and EXR, never overwriting.

use std::path::PathBuf;

use super::app::App;

/// Writes what the preview shows (with exposure, or a difference in its
/// false colour) as PNG and the same film without exposure as linear EXR
/// (a difference as its signed values, the non-finite view as its
/// counts) into `app.out_dir`; returns the paths.
/// Never overwrites: the name says what is saved ([`App::save_stem`]), and
/// when a file of that name is already there (the same state saved
/// before) the new one gets the first free suffix `-2`, `-3`, ….
pub fn save(app: &App) -> Result<Vec<PathBuf>, String> {
    let film = app.displayed().ok_or("nothing to save yet")?;
    let base = app.save_stem();
    let taken = |stem: &str| {
        ["png", "exr"]
            .iter()
            .any(|e| app.out_dir.join(format!("{stem}.{e}")).exists())
    };
    let stem = std::iter::once(base.clone())
        .chain((2..).map(|n| format!("{base}-{n}")))
        .find(|s| !taken(s))
        .expect("some suffix is free");
    std::fs::create_dir_all(&app.out_dir).map_err(|e| format!("{}: {e}", app.out_dir.display()))?;
    let png = app.out_dir.join(format!("{stem}.png"));
    let exr = app.out_dir.join(format!("{stem}.exr"));
    app.paint(&film)
        .write_png(&png)
        .map_err(|e| e.to_string())?;
    // A difference's EXR holds its signed values, the non-finite view's
    // its counts; a NaN or Inf never reaches a file (the PNG shows where
    // they were, in green).
    let mut values = match app.shows_caught() {
        true => app.main_film().map_or(film, |f| f.into_owned()),
        false => film,
    };
    values.scrub_nonfinite();
    values.write_exr(&exr).map_err(|e| e.to_string())?;
    Ok(vec![png, exr])
}
