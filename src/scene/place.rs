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
    /// (computed in f64, then rounded once). Point and spot intensities
    /// are multiplied by `scale²`, so that the irradiance they deliver at
    /// the scaled distances, and so the picture, stays the same; areas,
    /// radiances and directions are unchanged.
    pub fn placed(mut self, offset: DVec3, scale: f64) -> Scene {
        let place = |p: DVec3| p * scale + offset;
        for mesh in &mut self.meshes {
            for p in &mut mesh.positions {
                *p = place(p.as_dvec3()).as_vec3();
            }
        }
        self.camera.eye = place(self.camera.eye);
        self.camera.target = place(self.camera.target);
        let placed = |p: [f64; 3]| place(DVec3::from_array(p)).to_array();
        let brighter = |i: [f64; 3]| i.map(|c| c * scale * scale);
        for light in &mut self.lights {
            match light {
                LightSection::Point {
                    position,
                    intensity,
                }
                | LightSection::Spot {
                    position,
                    intensity,
                    ..
                } => {
                    *position = placed(*position);
                    *intensity = brighter(*intensity);
                }
                _ => {}
            }
        }
        for object in &mut self.sdfs {
            let shape = std::mem::replace(&mut object.sdf, Sdf::Union(Vec::new()));
            object.sdf = Sdf::Translate {
                offset: offset.as_vec3(),
                of: Box::new(Sdf::Scale {
                    factor: scale as f32,
                    of: Box::new(shape),
                }),
            };
        }
        self
    }
}

/// Where the chapters' placement cases put a scene (chapter 6's
/// `stability::placement`, chapter 5's): every offset of
/// 1e1 to 1e4 on one axis (y, x, z in turn) and scales 1e-3 to 1e3, which
/// must render like the box at the origin; then two placements past what
/// f32 can resolve (1e6 from the origin, where neighbouring values are
/// 0.06 apart; a box 2e-5 wide, below the fixed offset that spawned rays
/// use near the origin), reported but not required.
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

/// How many of [`PLACEMENTS`] are required to match (the rest are past
/// f32's reach).
pub const PLACEMENTS_REQUIRED: usize = 8;
