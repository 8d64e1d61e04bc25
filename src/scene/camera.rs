//! What a scene file says about its camera, and the checks that make it a
//! camera chapter 1 can build.
//!
//! The scene only *describes* the camera (where it is, where it looks, its
//! field of view and image size); chapter 1 turns the description into the
//! matrices and maps that project points ([`crate::ch1_projection::camera`]).
//! Keeping the description here lets every chapter and the scene loader
//! share it without the foundation depending on a chapter.

use glam::{DVec3, Vec3};

use crate::core::error::{Error, Result};

/// What a scene says about its camera, kept in f64 so that reports can
/// compute an exact reference next to the f32 renderer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraDesc {
    /// Where the pinhole is, in world space.
    pub eye: DVec3,
    /// A point the camera looks at.
    pub target: DVec3,
    /// Which way is up (need not be perpendicular to the view direction).
    pub up: DVec3,
    /// Full vertical field of view in degrees, in (0, 180).
    pub fov_degrees: f64,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

/// Largest width or height raystep renders; larger requests are refused.
pub const MAX_RESOLUTION: u32 = 16384;

/// The narrowest field of view, in degrees: at 0.01° the rays of
/// neighbouring pixels of a 256-pixel-tall image are 7e-7 radians apart, a
/// few f32 ulps; much narrower, f32 cannot tell them apart (a field of
/// view of 1e-300 was accepted and gave a degenerate camera).
pub const MIN_FOV_DEGREES: f64 = 0.01;

impl CameraDesc {
    /// Whether chapter 1 can build a camera from this description: finite
    /// positions, a field of view strictly between 0° and 180°, a size
    /// [`check_resolution`] accepts, and an eye, target and up that define a
    /// frame in the renderer's f32 arithmetic (the same test the look-at
    /// construction makes). The message names the key at fault.
    pub fn check(&self) -> Result<()> {
        let bad = |m: String| Error::Usage(format!("camera: {m}"));
        for (name, v) in [("eye", self.eye), ("target", self.target), ("up", self.up)] {
            crate::scene::validate::position(&v.to_array())
                .map_err(|why| bad(format!("`{name}` {why}")))?;
        }
        if !(self.fov_degrees >= MIN_FOV_DEGREES && self.fov_degrees < 180.0) {
            return Err(bad(format!(
                "`fov` must be a vertical field of view in degrees from {MIN_FOV_DEGREES} to below 180, got {}",
                self.fov_degrees
            )));
        }
        check_resolution(self.width, self.height)?;
        let (eye, target, up) = (self.eye.as_vec3(), self.target.as_vec3(), self.up.as_vec3());
        let back = (eye - target).try_normalize();
        let why = match back {
            _ if self.eye == self.target => {
                format!("`eye` and `target` must differ, both are {}", self.eye)
            }
            None => format!(
                "`eye` {} and `target` {} are too close to tell apart in f32 (they give no \
                 view direction); move them further apart",
                self.eye, self.target
            ),
            Some(back) if up.cross(back).try_normalize().is_none() => format!(
                "`up` {} must not be parallel to the view direction from `eye` {} to `target` {}",
                self.up, self.eye, self.target
            ),
            Some(_) => return Ok(()),
        };
        Err(bad(why))
    }

    /// The same description at another image size (checked).
    pub fn with_resolution(&self, width: u32, height: u32) -> Result<CameraDesc> {
        check_resolution(width, height)?;
        Ok(CameraDesc {
            width,
            height,
            ..*self
        })
    }

    /// The eye in the renderer's f32.
    pub fn eye_f32(&self) -> Vec3 {
        self.eye.as_vec3()
    }
}

/// Refuses zero and absurd image sizes before anything is allocated.
pub fn check_resolution(width: u32, height: u32) -> Result<()> {
    for (name, v) in [("width", width), ("height", height)] {
        if v == 0 || v > MAX_RESOLUTION {
            return Err(Error::Usage(format!(
                "`{name}` must be between 1 and {MAX_RESOLUTION} pixels, got {v}"
            )));
        }
    }
    Ok(())
}
