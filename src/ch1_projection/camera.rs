//! Chapter 1: the pinhole camera.
//!
//! The lecture's model comes first, literally: the pinhole sits at the origin,
//! the image plane is the plane z = -1, and a point (x, y, z) lands where the
//! ray from the pinhole through it meets that plane. [`project_pinhole`] is
//! that and nothing more. The general [`Camera`] then adds the three steps a
//! real renderer needs: placing the camera in the world (look-at), choosing
//! how much of the image plane we see (field of view and aspect), and mapping
//! the image plane to pixels (the viewport).
//!
//! Conventions: right-handed, the camera looks down -z, `+y` is up on the
//! image plane, raster coordinates grow right and *down* with pixel `(i, j)`
//! covering `[i, i+1) x [j, j+1)` and its centre at `(i + 0.5, j + 0.5)`.

use glam::{DVec3, Mat4, Vec2, Vec3, Vec4Swizzles};

use crate::core::error::{Error, Result};
pub use crate::scene::camera::CameraDesc;
use crate::scene::camera::MAX_RESOLUTION;
use crate::scene::Scene;

/// Projects a point given in camera space onto the image plane z = -1.
///
/// Returns `None` for points on or behind the camera plane (z ≥ 0): they
/// have no image, and dividing by their z would give infinities or a
/// mirrored picture.
// ANCHOR: pinhole
pub fn project_pinhole(p: Vec3) -> Option<Vec2> {
    // Only points in front of the pinhole (z < 0) reach the image plane.
    if p.z >= 0.0 || p.z.is_nan() {
        return None;
    }
    // Similar triangles: the ray through p meets z = -1 at p / (-z).
    let uv = Vec2::new(p.x / -p.z, p.y / -p.z);
    // A point a hair in front of the pinhole can still overflow f32.
    uv.is_finite().then_some(uv)
}
// ANCHOR_END: pinhole

/// The world-to-camera transform of a camera at `eye` looking at `target`
/// with `up` roughly up. Returns `None` when the three do not define a frame
/// (eye = target, or up parallel to the view direction).
// ANCHOR: look_at
pub fn camera_from_world_look_at(eye: Vec3, target: Vec3, up: Vec3) -> Option<Mat4> {
    // The camera looks down its -z axis, so +z points from target to eye.
    let back = (eye - target).try_normalize()?;
    // x is perpendicular to both the up hint and the view direction.
    let right = up.cross(back).try_normalize()?;
    // y completes the right-handed frame; it is unit length already.
    let true_up = back.cross(right);
    // The rows of the rotation are the camera axes in world coordinates;
    // translating by -eye first puts the pinhole at the origin.
    let world_from_camera = Mat4::from_cols(
        right.extend(0.0),
        true_up.extend(0.0),
        back.extend(0.0),
        eye.extend(1.0),
    );
    Some(world_from_camera.inverse())
}
// ANCHOR_END: look_at

/// A look-at pinhole camera with a vertical field of view and a viewport.
#[derive(Clone, Debug)]
pub struct Camera {
    /// The description the camera was built from.
    pub desc: CameraDesc,
    /// Maps world points to camera space (pinhole at the origin, looking down -z).
    pub camera_from_world: Mat4,
    /// Maps camera-space points to world space.
    pub world_from_camera: Mat4,
    /// tan(fov/2): half the height of the visible part of the image plane.
    pub tan_half_fov: f32,
    /// Width / height.
    pub aspect: f32,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// The camera's axes (right, up, back) in f64, for [`Camera::project_f64`].
    frame_f64: [DVec3; 3],
}

impl Camera {
    /// Builds and checks a camera. `at` names the scene key for errors.
    pub fn new(desc: CameraDesc) -> Result<Camera> {
        desc.check()?;
        let camera_from_world =
            camera_from_world_look_at(desc.eye.as_vec3(), desc.target.as_vec3(), desc.up.as_vec3())
                .ok_or_else(|| Error::Usage("camera: no frame (checked above)".into()))?;
        let back = (desc.eye - desc.target).normalize();
        let right = desc.up.cross(back).normalize();
        Ok(Camera {
            frame_f64: [right, back.cross(right), back],
            desc,
            camera_from_world,
            world_from_camera: camera_from_world.inverse(),
            tan_half_fov: (desc.fov_degrees.to_radians() * 0.5).tan() as f32,
            aspect: desc.width as f32 / desc.height as f32,
            width: desc.width,
            height: desc.height,
        })
    }

    /// The camera of a loaded scene. A scene checks its camera when it is
    /// loaded, with the same [`CameraDesc::check`] that [`Camera::new`]
    /// makes, so this cannot fail for a scene from [`Scene::load`] or
    /// [`Scene::parse`]; a description changed by hand afterwards falls
    /// back to a plain camera looking down -z.
    pub fn of(scene: &Scene) -> Camera {
        Camera::new(scene.camera).unwrap_or_else(|_| {
            Camera::new(CameraDesc {
                eye: DVec3::ZERO,
                target: DVec3::NEG_Z,
                up: DVec3::Y,
                fov_degrees: 45.0,
                width: scene.camera.width.clamp(1, MAX_RESOLUTION),
                height: scene.camera.height.clamp(1, MAX_RESOLUTION),
            })
            .expect("a camera at the origin looking down -z is valid")
        })
    }

    /// The same camera at another resolution.
    pub fn with_resolution(&self, width: u32, height: u32) -> Result<Camera> {
        Camera::new(self.desc.with_resolution(width, height)?)
    }

    /// World space to camera space.
    pub fn to_camera(&self, p_world: Vec3) -> Vec3 {
        (self.camera_from_world * p_world.extend(1.0)).xyz()
    }

    /// Image plane (u, v) to continuous raster coordinates (pixels, y down).
    // ANCHOR: viewport
    pub fn raster_from_image_plane(&self, uv: Vec2) -> Vec2 {
        // The visible window of the plane z = -1 is [-aspect·t, aspect·t] x [-t, t].
        let t = self.tan_half_fov;
        let ndc = Vec2::new(uv.x / (self.aspect * t), uv.y / t);
        // Map [-1, 1] to [0, width] and flip y so rows grow downwards.
        Vec2::new(
            (ndc.x + 1.0) * 0.5 * self.width as f32,
            (1.0 - ndc.y) * 0.5 * self.height as f32,
        )
    }
    // ANCHOR_END: viewport

    /// Continuous raster coordinates back to the image plane z = -1.
    pub fn image_plane_from_raster(&self, raster: Vec2) -> Vec2 {
        let t = self.tan_half_fov;
        let ndc = Vec2::new(
            raster.x / self.width as f32 * 2.0 - 1.0,
            1.0 - raster.y / self.height as f32 * 2.0,
        );
        Vec2::new(ndc.x * self.aspect * t, ndc.y * t)
    }

    /// World point to raster coordinates, or `None` if it has no image.
    // ANCHOR: project
    pub fn project(&self, p_world: Vec3) -> Option<Vec2> {
        let p_camera = self.to_camera(p_world);
        let uv = project_pinhole(p_camera)?;
        Some(self.raster_from_image_plane(uv))
    }
    // ANCHOR_END: project

    /// The f64 reference for [`Camera::project`]: the same steps in double
    /// precision from the scene's own numbers, used to measure f32 error.
    pub fn project_f64(&self, p_world: DVec3) -> Option<glam::DVec2> {
        let d = &self.desc;
        let [right, up, back] = self.frame_f64;
        let rel = p_world - d.eye;
        let p = DVec3::new(rel.dot(right), rel.dot(up), rel.dot(back));
        if p.z >= 0.0 {
            return None;
        }
        let t = (d.fov_degrees.to_radians() * 0.5).tan();
        let aspect = d.width as f64 / d.height as f64;
        let ndc = glam::DVec2::new(p.x / -p.z / (aspect * t), p.y / -p.z / t);
        Some(glam::DVec2::new(
            (ndc.x + 1.0) * 0.5 * d.width as f64,
            (1.0 - ndc.y) * 0.5 * d.height as f64,
        ))
    }
}
