//! The wrong pictures: what a plausible student bug looks like, rendered
//! by the project, beside the right picture of the same scene.

use std::path::Path;

use raystep::core::error::Result;

/// Every wrong picture and its right partner: (file name, what it
/// shows). Wrong ones end in `-wrong.png`, right ones in `-right.png`.
pub fn list() -> Vec<(&'static str, &'static str)> {
    Vec::new()
}

/// Renders every wrong picture and its right partner into `out`; returns
/// the file names written.
pub fn render_all(out: &Path) -> Result<Vec<String>> {
    let _ = out;
    Ok(Vec::new())
}
