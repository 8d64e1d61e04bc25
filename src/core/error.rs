//! One error type for everything a user can get wrong: scene files, meshes,
//! flags, output paths. Every message names the file and the key or line and
//! says what was expected, so a student can fix the input without reading code.
//! Displayed, every part that came from a file or flag has its control
//! characters escaped ([`crate::core::text`]).

use std::path::{Path, PathBuf};

use crate::core::text::{escape, escape_keep_newlines};

/// What went wrong, with enough context to find and fix it.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A scene file that does not parse or does not make sense. `at` is
    /// `line:column` or a key path such as `camera.fov` or `objects[2].mesh`.
    #[error("{}: {}: {}", escape(file), escape(at), escape_keep_newlines(message))]
    Scene {
        /// The scene file.
        file: String,
        /// Where in it: `line:column` or a key path.
        at: String,
        /// What is wrong and what was expected.
        message: String,
    },
    /// A mesh file that cannot be read or is malformed.
    #[error("{}{}: {}", escape(file), line.map(|l| format!(":{l}")).unwrap_or_default(), escape_keep_newlines(message))]
    Mesh {
        /// The OBJ file.
        file: String,
        /// The 1-based line, when one line is to blame.
        line: Option<usize>,
        /// What is wrong and what was expected.
        message: String,
    },
    /// Flags or settings that are out of range.
    #[error("{}", escape_keep_newlines(.0))]
    Usage(String),
    /// Reading or writing a file failed.
    #[error("{}: {}", escape(&path.display().to_string()), escape(&source.to_string()))]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Encoding an image failed.
    #[error("{}: {}", escape(&path.display().to_string()), escape_keep_newlines(message))]
    Image {
        /// The image file.
        path: PathBuf,
        /// Why.
        message: String,
    },
}

impl Error {
    /// An I/O error on `path`.
    pub fn io(path: &Path, source: std::io::Error) -> Self {
        Error::Io {
            path: path.to_path_buf(),
            source,
        }
    }
}

/// Shorthand for results in raystep.
pub type Result<T, E = Error> = std::result::Result<T, E>;
