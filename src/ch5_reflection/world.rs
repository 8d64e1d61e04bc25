//! The scene as the shading chapters (5 and 6) see it: one `intersect`
//! and one shadow-ray test over meshes (chapter 3's BVH, in the 4-wide form
//! of [`crate::ch3_ray_triangle::wide_bvh`]) and SDF objects
//! (chapter 4's sphere tracing), each surface's BSDF, and the lights.
//!
//! Nothing is built for what the scene lacks: no BVH without meshes, no
//! marching without SDFs, no light tables without lights.

use glam::Vec3;

use crate::ch3_ray_triangle::obvhs_bvh::Triangles;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::spawn::{offset_origin, stop_distance};
use crate::ch3_ray_triangle::triangle::unit_normal;
use crate::ch3_ray_triangle::wide_bvh::WideBvh;
use crate::ch4_implicit_surfaces::bounds::{reach, unit_of_reach};
use crate::ch4_implicit_surfaces::distance::{scene_distance, SdfObject};
use crate::ch4_implicit_surfaces::hit::Surface;
use crate::ch4_implicit_surfaces::march::{sphere_trace, March};
use crate::ch4_implicit_surfaces::normal::{normal, NormalScheme};
use crate::ch5_reflection::light::area::emitted_towards;
use crate::ch5_reflection::light::{Light, Lights};
use crate::ch5_reflection::material::Bsdf;
use crate::scene::{Material, Scene};

/// A ray's first hit, with what shading needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interaction {
    /// Distance along the ray.
    pub t: f32,
    /// The hit point.
    pub p: Vec3,
    /// The unit *outward* normal (a mesh's winding normal, an SDF's
    /// gradient), whichever side the ray came from.
    pub n: Vec3,
    /// Index into [`World::materials`] and [`World::bsdfs`].
    pub material: usize,
    /// Which surface was hit.
    pub surface: Surface,
}

/// The two ray queries over the scene's triangles, for a BVH other than
/// chapter 3's four-wide one to answer them ([`World::queries`]).
pub trait RayQueries: Send + Sync {
    /// The closest hit in (0, t_max); `Hit::triangle` indexes
    /// [`World::triangles`].
    fn closest(&self, ray: &Ray, t_max: f32) -> Option<crate::ch3_ray_triangle::triangle::Hit>;
    /// Whether anything is hit in (0, t_max).
    fn occluded(&self, ray: &Ray, t_max: f32) -> bool;
    /// What it is, for reports ("8 wide, 12 nodes, ...").
    fn describe(&self) -> String;
}

/// A [`RayQueries`] as [`World`] holds it (a world stays safe to use
/// after a caught panic, as the grader needs).
pub type Queries = dyn RayQueries + std::panic::RefUnwindSafe + std::panic::UnwindSafe;

impl RayQueries for WideBvh {
    fn closest(&self, ray: &Ray, t_max: f32) -> Option<crate::ch3_ray_triangle::triangle::Hit> {
        WideBvh::closest(self, ray, t_max)
    }
    fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        WideBvh::occluded(self, ray, t_max)
    }
    fn describe(&self) -> String {
        format!(
            "chapter 3's BVH, 4 wide ({} nodes, {} leaves)",
            self.node_count(),
            self.leaf_count()
        )
    }
}

/// Meshes, SDFs, materials and lights, ready for shading.
pub struct World {
    /// Every triangle of the scene's meshes (empty without meshes).
    pub triangles: Triangles,
    /// Chapter 3's BVH over them in its 4-wide form, which `intersect` and
    /// `unoccluded` trace through; `None` for a scene without meshes.
    pub wide: Option<WideBvh>,
    /// Another BVH over the same triangles that answers the ray queries
    /// instead of `wide` (a faster engine's tree); `None`: `wide` does.
    pub queries: Option<Box<Queries>>,
    /// The unit outward (winding) normal of each triangle.
    pub normals: Vec<Vec3>,
    /// The material of each scene mesh.
    pub mesh_material: Vec<usize>,
    /// SDF objects (empty: nothing is marched).
    pub sdfs: Vec<SdfObject>,
    /// How SDFs are marched.
    pub march: March,
    /// The scene's materials.
    pub materials: Vec<Material>,
    /// One BSDF per material.
    pub bsdfs: Vec<Bsdf>,
    /// Every light.
    pub lights: Lights,
}

impl World {
    /// Builds what `scene` needs.
    pub fn new(scene: &Scene) -> World {
        World::with_queries(scene, |_| None)
    }

    /// Builds what `scene` needs, with the ray queries over its triangles
    /// answered by what `queries` builds over them; where it builds
    /// nothing, by chapter 3's tree in its four-wide form (then built).
    pub fn with_queries(
        scene: &Scene,
        queries: impl FnOnce(&[[Vec3; 3]]) -> Option<Box<Queries>>,
    ) -> World {
        let triangles = Triangles::from_meshes(&scene.meshes);
        let queries = queries(&triangles.tris);
        let wide = match queries {
            Some(_) => None,
            None => WideBvh::build(&triangles.tris),
        };
        let normals = triangles
            .tris
            .iter()
            .map(|tri| unit_normal(*tri).unwrap_or(Vec3::Z))
            .collect();
        // Nothing can be hit beyond twice the reach of the camera to every
        // mesh vertex and bounded SDF (at least the scaled default).
        let reach = reach(scene);
        let unit = unit_of_reach(reach);
        let march = March {
            max_distance: (2.0 * reach as f32).max(100.0 * unit),
            ..March::default().scaled(unit)
        };
        World {
            triangles,
            wide,
            queries,
            normals,
            mesh_material: scene.meshes.iter().map(|m| m.material).collect(),
            sdfs: scene.sdfs.clone(),
            march,
            materials: scene.materials.clone(),
            bsdfs: scene.materials.iter().map(Bsdf::from_material).collect(),
            lights: Lights::new(scene),
        }
    }

    /// What answers the ray queries over the meshes, for reports; `None`
    /// without meshes.
    pub fn mesh_queries(&self) -> Option<&dyn RayQueries> {
        match (&self.queries, &self.wide) {
            (Some(q), _) => Some(q.as_ref() as &dyn RayQueries),
            (None, Some(w)) => Some(w),
            (None, None) => None,
        }
    }

    /// The closest mesh hit in (0, t_max), from `queries` or `wide`.
    #[inline]
    fn closest_mesh(
        &self,
        ray: &Ray,
        t_max: f32,
    ) -> Option<crate::ch3_ray_triangle::triangle::Hit> {
        match (&self.queries, &self.wide) {
            (Some(q), _) => q.closest(ray, t_max),
            (None, Some(w)) => w.closest(ray, t_max),
            (None, None) => None,
        }
    }

    /// Whether a mesh is hit in (0, t_max), from `queries` or `wide`.
    #[inline]
    fn occluded_mesh(&self, ray: &Ray, t_max: f32) -> bool {
        match (&self.queries, &self.wide) {
            (Some(q), _) => q.occluded(ray, t_max),
            (None, Some(w)) => w.occluded(ray, t_max),
            (None, None) => false,
        }
    }

    /// The first surface along `ray`, meshes and SDFs alike.
    pub fn intersect(&self, ray: &Ray) -> Option<Interaction> {
        self.intersect_within(ray, f32::INFINITY)
    }

    /// The first surface along `ray` before `t_max`.
    pub fn intersect_within(&self, ray: &Ray, t_max: f32) -> Option<Interaction> {
        let mut best: Option<Interaction> = None;
        if let Some(hit) = self.closest_mesh(ray, t_max) {
            let k = hit.triangle as usize;
            let mesh = self.triangles.mesh[k] as usize;
            best = Some(Interaction {
                t: hit.t,
                p: hit.point(self.triangles.tris[k]),
                n: self.normals[k],
                material: self.mesh_material[mesh],
                surface: Surface::Mesh(mesh),
            });
        }
        if !self.sdfs.is_empty() {
            let f = |p: Vec3| scene_distance(&self.sdfs, p).0;
            let m = March {
                max_distance: self.march.max_distance.min(best.map_or(t_max, |b| b.t)),
                ..self.march
            };
            if let Some(t) = sphere_trace(&f, ray, &m).hit() {
                if best.is_none_or(|b| t < b.t) {
                    let p = ray.at(t);
                    let object = scene_distance(&self.sdfs, p).1;
                    let h = m.epsilon_at(p).max(m.epsilon);
                    best = Some(Interaction {
                        t,
                        p,
                        n: normal(&f, p, h, NormalScheme::Central, -ray.dir),
                        material: self.sdfs[object].material,
                        surface: Surface::Sdf(object),
                    });
                }
            }
        }
        best
    }

    /// A ray leaving the surface point `p` (outward normal `n`) along
    /// `dir`, started far enough off the surface not to hit it again:
    /// chapter 3's offset in ulps, plus a few marching ε when the scene has
    /// SDFs (a march that starts on the surface stops at once).
    pub fn spawn(&self, p: Vec3, n: Vec3, dir: Vec3) -> Option<Ray> {
        let side = if n.dot(dir) < 0.0 { -n } else { n };
        let mut origin = offset_origin(p, side);
        if !self.sdfs.is_empty() {
            origin += side * 4.0 * self.march.epsilon_at(p);
        }
        Ray::from_unit(origin, dir)
    }

    /// Whether nothing blocks the segment from the surface point `p`
    /// (outward normal `n`) to the point `dist` away along the unit
    /// direction `wi` (`dist` = ∞: to infinity). The ray starts at the
    /// spawned origin and is aimed at the far point moved back towards `p`
    /// by [`stop_distance`]: both ends sit off their surfaces by amounts
    /// that scale with the coordinates, so neither surface blocks the
    /// segment wherever the scene sits and whatever its size (aiming from
    /// the moved origin along the old direction and length would meet the
    /// light's own surface at grazing angles).
    pub fn unoccluded(&self, p: Vec3, n: Vec3, wi: Vec3, dist: f32) -> bool {
        let Some(spawned) = self.spawn(p, n, wi) else {
            return false;
        };
        let y = p + wi * dist;
        let to = y - wi * stop_distance(y) - spawned.origin;
        let t_max = to.length();
        let (ray, t_max) = if !t_max.is_finite() {
            // A light at infinity (or as good as).
            (spawned, f32::INFINITY)
        } else if t_max > 0.0 && to.dot(wi) > 0.0 {
            match Ray::from_unit(spawned.origin, to / t_max) {
                Some(ray) => (ray, t_max),
                None => return true,
            }
        } else {
            // The two ends meet: nothing lies between them.
            return true;
        };
        if self.occluded_mesh(&ray, t_max) {
            return false;
        }
        if !self.sdfs.is_empty() {
            let f = |q: Vec3| scene_distance(&self.sdfs, q).0;
            let m = March {
                max_distance: self.march.max_distance.min(t_max),
                ..self.march
            };
            if sphere_trace(&f, &ray, &m).hit().is_some() {
                return false;
            }
        }
        true
    }

    /// Radiance the surface at `it` emits towards the unit direction `wo`
    /// (pointing away from the surface): Le on an emitting face, else 0.
    pub fn emitted(&self, it: &Interaction, wo: Vec3) -> Vec3 {
        let m = &self.materials[it.material];
        if !m.is_emissive() {
            return Vec3::ZERO;
        }
        emitted_towards(m.emission, m.two_sided, it.n, wo)
    }

    /// The area light of the surface `it` hit, if it is one that
    /// [`Lights`] samples (emissive meshes; emissive SDFs are only found by
    /// BSDF sampling).
    pub fn area_light(
        &self,
        it: &Interaction,
    ) -> Option<(usize, &crate::ch5_reflection::light::area::AreaLight)> {
        let Surface::Mesh(m) = it.surface else {
            return None;
        };
        let index = self.lights.area_of_mesh.get(m).copied().flatten()?;
        match &self.lights.lights[index] {
            Light::Area(a) => Some((index, a)),
            _ => None,
        }
    }
}
