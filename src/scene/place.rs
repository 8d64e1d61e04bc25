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
