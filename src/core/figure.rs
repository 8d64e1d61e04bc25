//! Pictures that come with a report: plots of its studies, strips,
//! per-bounce layers. A stage describes them ([`Figure`]); the runner
//! writes them beside the images.

use std::path::Path;

use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::plot::{write_captioned_strip, LogLogPlot};

/// A picture that comes with a report: its file name (no folder) and what
/// to draw there. A stage describes it; the runner writes it
/// ([`Figure::write`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// The file name, e.g. `ch5-error-time-area.png`.
    pub file: String,
    /// What the file holds.
    pub content: FigureContent,
}

/// What a [`Figure`] holds.
#[derive(Clone, Debug, PartialEq)]
pub enum FigureContent {
    /// An image, tone-mapped to an sRGB PNG.
    Png(Film),
    /// An image as linear HDR EXR.
    Exr(Film),
    /// Images side by side with a caption under each (a PNG).
    Strip(Vec<(Film, String)>),
    /// A log-log plot (a PNG of this size in pixels).
    Plot(LogLogPlot, u32, u32),
}

impl Figure {
    /// Writes the figure into `dir`; returns the path written.
    pub fn write(&self, dir: &Path) -> Result<std::path::PathBuf> {
        let path = dir.join(&self.file);
        match &self.content {
            FigureContent::Png(film) => film.write_png(&path)?,
            FigureContent::Exr(film) => film.write_exr(&path)?,
            FigureContent::Strip(images) => {
                let captioned: Vec<(&Film, &str)> =
                    images.iter().map(|(f, l)| (f, l.as_str())).collect();
                write_captioned_strip(&captioned, &path)?;
            }
            FigureContent::Plot(plot, w, h) => plot.write_png(&path, *w, *h)?,
        }
        Ok(path)
    }
}
