//! Every chapter that exists, in lecture order. Front ends (the main binary,
//! the terminal UI) list chapters from here and nowhere else.

use crate::stage::Chapter;

/// All chapters, in order.
pub fn all() -> Vec<&'static dyn Chapter> {
    vec![
        &crate::projection::Projection,
        &crate::raster::RASTERIZATION,
        &crate::raytrace::RayTriangle,
        &crate::sphere_tracing::DEFAULT,
        &crate::reflection::DEFAULT,
        &crate::path_tracing::DEFAULT,
    ]
}
