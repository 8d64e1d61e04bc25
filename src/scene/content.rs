//! A scene's content hash: one number for everything in a [`Scene`] that
//! changes its picture, so that a stored reference (chapter 6) is matched
//! to the scene it was rendered from by what the scene *is*, not by its
//! name. A user's own `cornell-box.toml` with other colours has another
//! hash, and gets no "RMSE against the stored reference" that would be
//! measured against a different picture.
//!
//! What is hashed, in this fixed order: the camera's eye, target, up and
//! field of view (not its resolution: a reference is found by size on its
//! own, and a larger render is compared with a downsampled one); every
//! mesh's vertex positions, triangles, vertex colours and material index;
//! every material's kind, reflectance, emission, sidedness, index of
//! refraction, exponent and specular weight; every light; every SDF
//! object's tree and material index. Names (scene, file, mesh, material,
//! object) and the file's path are not hashed, nor anything of the file's
//! text (key order, comments, spacing): only the scene it builds.
//!
//! Numbers are hashed as their IEEE bits (little-endian), integers as u64,
//! with 64-bit FNV-1a: the same value on every platform and every run (no
//! `std` hasher with a random state); the positions hashed are those the
//! scene builds, so an object placed with `rotate` goes through sin and
//! cos, whose last bit the platform's maths library decides (the shipped
//! Cornell box has no rotation). Lights and SDF trees are hashed as
//! their `Debug` text, which Rust formats itself (floats as the shortest
//! text that reads back to the same bits), the same on every platform; a
//! change of those types' fields changes the hashes, and the stored
//! references must then be annotated again (`ch6 --annotate-references`,
//! which a test would otherwise fail for).

use super::mesh::Mesh;
use super::{Material, Scene};

/// 64-bit FNV-1a over bytes fed in order.
struct Fnv1a(u64);

impl Fnv1a {
    const OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
    const PRIME: u64 = 0x0000_0100_0000_01b3;

    fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= b as u64;
            self.0 = self.0.wrapping_mul(Self::PRIME);
        }
    }

    fn u64(&mut self, v: u64) {
        self.bytes(&v.to_le_bytes());
    }

    fn f32s(&mut self, vs: &[f32]) {
        for v in vs {
            self.bytes(&v.to_bits().to_le_bytes());
        }
    }

    fn f64s(&mut self, vs: &[f64]) {
        for v in vs {
            self.bytes(&v.to_bits().to_le_bytes());
        }
    }

    /// A length-prefixed text, so that two texts never run together.
    fn text(&mut self, s: &str) {
        self.u64(s.len() as u64);
        self.bytes(s.as_bytes());
    }
}

/// The content hash of `scene` (see the module doc) as 16 hex digits.
pub fn content_hash(scene: &Scene) -> String {
    // Every field named, so that a new one must be placed in or out here.
    let Scene {
        name: _,
        source: _,
        camera,
        meshes,
        materials,
        lights,
        sdfs,
        origin,
        unit,
        // How lights are sampled changes the noise, not the image.
        light_sampling: _,
    } = scene;
    let mut h = Fnv1a(Fnv1a::OFFSET);
    h.text("camera");
    h.f64s(&camera.eye.to_array());
    h.f64s(&camera.target.to_array());
    h.f64s(&camera.up.to_array());
    h.f64s(&[camera.fov_degrees]);
    h.text("meshes");
    h.u64(meshes.len() as u64);
    for mesh in meshes {
        let Mesh {
            name: _,
            positions,
            triangles,
            colors,
            material,
        } = mesh;
        h.u64(positions.len() as u64);
        for p in positions {
            h.f32s(&p.to_array());
        }
        h.u64(triangles.len() as u64);
        for t in triangles {
            t.iter().for_each(|&i| h.u64(i as u64));
        }
        match colors {
            Some(colors) => {
                h.u64(colors.len() as u64);
                colors.iter().for_each(|c| h.f32s(&c.to_array()));
            }
            None => h.text("no colours"),
        }
        h.u64(*material as u64);
    }
    h.text("materials");
    h.u64(materials.len() as u64);
    for m in materials {
        let Material {
            name: _,
            kind,
            reflectance,
            emission,
            two_sided,
            ior,
            exponent,
            specular,
        } = m;
        h.text(&format!("{kind:?}"));
        h.f32s(&reflectance.to_array());
        h.f32s(&emission.to_array());
        h.u64(*two_sided as u64);
        h.f32s(&[*ior, *exponent, *specular]);
    }
    h.text("lights");
    h.u64(lights.len() as u64);
    for l in lights {
        h.text(&format!("{l:?}"));
    }
    h.text("sdfs");
    h.u64(sdfs.len() as u64);
    for s in sdfs {
        h.text(&format!("{:?}", s.sdf));
        h.u64(s.material as u64);
    }
    // Only a scene kept around its camera has an origin (the shipped
    // scenes' hashes stay as they were).
    if *origin != glam::DVec3::ZERO {
        h.text("origin");
        h.f64s(&origin.to_array());
    }
    if *unit != 1.0 {
        h.text("unit");
        h.f64s(&[*unit]);
    }
    format!("{:016x}", h.0)
}
