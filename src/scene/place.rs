//! The same scene somewhere else, or at another size: every mesh vertex,
//! the camera, the point and spot lights and the SDF objects moved by
//! `x → scale · x + offset`. A renderer's picture must not depend on
//! this (the lecture's "numerical stability on stiff and extreme cases"):
//! the chapters' placement tests render the Cornell box so moved and
//! compare it with the box at the origin.

use glam::DVec3;

use crate::scene::file::LightSection;
use crate::scene::sdf::Sdf;
use crate::scene::Scene;

impl Scene {
    /// This scene with every position `x` moved to `scale · x + offset`
    /// (computed in f64 from the positions as the file gives them, then
    /// rounded once, relative to the new [`Scene::origin`]). Point and spot
    /// intensities are multiplied by `scale²`, so that the irradiance they
    /// deliver at the scaled distances, and so the picture, stays the same;
    /// areas, radiances and directions are unchanged. A scene made tiny is
    /// then scaled up again by a power of two ([`Scene::normalized`]).
    pub fn placed(self, offset: DVec3, scale: f64) -> Scene {
        self.transformed(offset, scale).normalized()
    }

    /// A scene that reaches less than [`TINY`] from its camera (its
    /// farthest mesh vertex, or its target) scaled up by the power of two
    /// that brings that reach to between 1 and 2, with [`Scene::unit`]
    /// saying so. Ray offsets near the origin are fixed lengths (chapter
    /// 3's `offset_origin` moves a point within 1/32 of it by 1/65536):
    /// the size of the whole Cornell box scaled by 10⁻⁵. A power of two is
    /// exact in floating point, so the picture is the one of the scene at
    /// its own size, as it should be.
    pub fn normalized(self) -> Scene {
        let eye = self.camera.eye;
        let mut reach = (self.camera.target - eye).length();
        for m in &self.meshes {
            for p in &m.positions {
                reach = reach.max((p.as_dvec3() - eye).length());
            }
        }
        if !(reach > 0.0 && reach < TINY) {
            return self;
        }
        let k = (1.0 / reach).log2().floor() as i32;
        let scale = 2f64.powi(k);
        let unit = self.unit / scale;
        let mut scene = self.transformed(DVec3::ZERO, scale);
        scene.unit = unit;
        scene
    }

    fn transformed(mut self, offset: DVec3, scale: f64) -> Scene {
        let old = self.origin;
        let place = |p: DVec3| (p + old) * scale + offset;
        let eye = place(self.camera.eye);
        let target = place(self.camera.target);
        let origin = origin_for(eye, target);
        let here = |p: DVec3| place(p) - origin;
        for mesh in &mut self.meshes {
            for p in &mut mesh.positions {
                *p = here(p.as_dvec3()).as_vec3();
            }
        }
        (self.camera.eye, self.camera.target) = (eye - origin, target - origin);
        let placed = |p: [f64; 3]| here(DVec3::from_array(p)).to_array();
        let brighter = |i: [f64; 3]| i.map(|c| c * scale * scale);
        for light in &mut self.lights {
            if let LightSection::Point {
                position,
                intensity,
            }
            | LightSection::Spot {
                position,
                intensity,
                ..
            } = light
            {
                *position = placed(*position);
                *intensity = brighter(*intensity);
            }
        }
        // An SDF takes positions relative to the old origin: x here is
        // ((x + origin - offset) / scale) - old there.
        let shift = offset + old * scale - origin;
        for object in &mut self.sdfs {
            let shape = std::mem::replace(&mut object.sdf, Sdf::Union(Vec::new()));
            object.sdf = Sdf::Translate {
                offset: shift.as_vec3(),
                of: Box::new(Sdf::Scale {
                    factor: scale as f32,
                    of: Box::new(shape),
                }),
            };
        }
        self.origin = origin;
        self
    }

    /// The camera, lights and SDFs of a scene whose meshes were built
    /// relative to `origin` ([`origin_for`]) moved there too.
    pub(super) fn moved_to(mut self, origin: DVec3) -> Scene {
        if origin == DVec3::ZERO {
            return self;
        }
        self.camera.eye -= origin;
        self.camera.target -= origin;
        let moved = |p: [f64; 3]| (DVec3::from_array(p) - origin).to_array();
        for light in &mut self.lights {
            if let LightSection::Point { position, .. } | LightSection::Spot { position, .. } =
                light
            {
                *position = moved(*position);
            }
        }
        for object in &mut self.sdfs {
            let shape = std::mem::replace(&mut object.sdf, Sdf::Union(Vec::new()));
            object.sdf = match shape {
                // Folded into the shape's own move (in f64), so that its
                // distance is computed near the origin too.
                Sdf::Translate { offset, of } => Sdf::Translate {
                    offset: (offset.as_dvec3() - origin).as_vec3(),
                    of,
                },
                other => Sdf::Translate {
                    offset: (-origin).as_vec3(),
                    of: Box::new(other),
                },
            };
        }
        self.origin = origin;
        self
    }
}

/// Where a scene with this camera keeps its origin: the camera itself when
/// it is farther from the file's origin than [`FAR`] times its viewing
/// distance (eye to target), else the file's origin. Far from the origin
/// f32 spaces its numbers coarsely (at 10⁴, a millimetre apart), and every
/// hit point, offset and shadow ray would carry that error; near the
/// camera, where the picture is, they are as fine as at the origin. Every
/// position is computed in f64 and rounded once, relative to this origin,
/// so the picture does not depend on where the scene sits. The shipped
/// scenes are near their origin and are left as they are.
pub fn origin_for(eye: DVec3, target: DVec3) -> DVec3 {
    let view = (target - eye).length();
    if eye.length() > FAR * view {
        eye
    } else {
        DVec3::ZERO
    }
}

/// A scene that reaches less than this from its camera is scaled up
/// ([`Scene::normalized`]).
pub const TINY: f64 = 1.0 / 16.0;

/// A scene whose camera is farther from the origin than this many times
/// its viewing distance keeps its origin at the camera ([`origin_for`]).
pub const FAR: f64 = 8.0;

/// Where the chapters' placement cases put a scene (chapter 6's
/// `stability::placement`, chapter 5's): offsets of 1e1 to 1e6 on one axis
/// (y, x, z in turn) and scales 1e-5 to 1e3. Each must render like the box
/// at the origin: a far scene is kept around its camera ([`origin_for`]),
/// a tiny one scaled up ([`Scene::normalized`]).
pub const PLACEMENTS: [(&str, [f64; 3], f64); 10] = [
    ("+1e1 y", [0.0, 1e1, 0.0], 1.0),
    ("+1e2 x", [1e2, 0.0, 0.0], 1.0),
    ("-1e3 z", [0.0, 0.0, -1e3], 1.0),
    ("+1e4 y", [0.0, 1e4, 0.0], 1.0),
    ("x1e-3", [0.0; 3], 1e-3),
    ("x1e-2", [0.0; 3], 1e-2),
    ("x1e2", [0.0; 3], 1e2),
    ("x1e3", [0.0; 3], 1e3),
    ("+1e6 z", [0.0, 0.0, 1e6], 1.0),
    ("x1e-5", [0.0; 3], 1e-5),
];

/// How many of [`PLACEMENTS`] are required to match: all.
pub const PLACEMENTS_REQUIRED: usize = 10;
