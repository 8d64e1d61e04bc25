//! Rays: the lecture's r(t) = o + t d.
//!
//! [`Ray::new`] refuses a direction that is zero, NaN or infinite, so no
//! later stage has to wonder; [`Ray::from_unit`] is its shortcut for
//! directions already of unit length. The camera builds its primary rays
//! directly ([`Camera::ray`]): their direction is never zero.

use glam::{Vec2, Vec3};

use crate::ch1_projection::camera::Camera;
use crate::core::error::{Error, Result};

/// A ray r(t) = origin + t · dir, for t in [0, ∞).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// o: where the ray starts.
    pub origin: Vec3,
    /// d: unit direction.
    pub dir: Vec3,
}

impl Ray {
    /// A ray from `origin` along `dir` (normalised here). Errors on a
    /// non-finite origin or a zero, NaN or infinite direction.
    pub fn new(origin: Vec3, dir: Vec3) -> Result<Ray> {
        if !origin.is_finite() {
            return Err(Error::Usage(format!("ray origin {origin} is not finite")));
        }
        let unit = dir
            .try_normalize()
            .ok_or_else(|| Error::Usage(format!("ray direction {dir} is zero or not finite")))?;
        Ok(Ray { origin, dir: unit })
    }

    /// A ray along `dir`, which should already be a unit vector (a
    /// sampled direction): normalised again only when its length is off by
    /// more than 10⁻⁵, which saves a square root and a division per ray.
    /// `None` where [`Ray::new`] errs.
    #[inline]
    pub fn from_unit(origin: Vec3, dir: Vec3) -> Option<Ray> {
        let len2 = dir.length_squared();
        if (len2 - 1.0).abs() <= 1e-5 && origin.is_finite() {
            Some(Ray { origin, dir })
        } else {
            Ray::new(origin, dir).ok()
        }
    }

    /// The point at parameter `t`.
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.dir
    }
}

impl Camera {
    /// The primary ray from the pinhole through the continuous raster
    /// position `raster` (pixel centres at +0.5), in world space.
    // ANCHOR: camera_ray
    pub fn ray(&self, raster: Vec2) -> Ray {
        // The point on the image plane z = -1, in camera space...
        let uv = self.image_plane_from_raster(raster);
        let dir_camera = Vec3::new(uv.x, uv.y, -1.0);
        // ... turned into world space; the origin is the eye.
        let origin = self.world_from_camera.transform_point3(Vec3::ZERO);
        let dir = self
            .world_from_camera
            .transform_vector3(dir_camera)
            .normalize();
        Ray { origin, dir }
    }
    // ANCHOR_END: camera_ray
}
