//! Chapter 3's diagrams.

use raystep::core::error::Result;

use crate::Diagram;

/// Chapter 3's diagrams, in the order the chapter shows them.
pub fn diagrams() -> Result<Vec<Diagram>> {
    Ok(Vec::new())
}
