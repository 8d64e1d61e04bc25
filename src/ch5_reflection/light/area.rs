//! Area lights: emissive meshes of radiance Le, sampled by area or by
//! solid angle.
//!
//! By area, a point y is drawn uniformly over the mesh's surface (a
//! triangle by its share of the area, then a uniform point in it): pdf_A =
//! 1 / A. The reflection equation integrates over solid angle at the
//! shading point x, and dω = |cos θl| dA / d², so the same sample has
//! pdf_ω = pdf_A · d² / |cos θl| ([`solid_angle_pdf`], the one place this
//! conversion is made).
//!
//! By solid angle (`--light-sampling solid-angle`), a triangle is picked by
//! its share of the solid angle the light covers at x, then a direction in
//! it ([`super::spherical`]): pdf_ω = 1 / Ω, the same for every direction
//! that reaches the light. A light of more than
//! [`SOLID_ANGLE_MAX_TRIANGLES`] triangles, and one that covers less than
//! [`SOLID_ANGLE_MIN`] at x, is sampled by area all the same.

use glam::{Vec2, Vec3};

use super::spherical::sample_spherical_triangle;
use super::LightSample;
use crate::ch3_ray_triangle::spawn::offset_distance;
use crate::ch5_reflection::radiometry::triangle_solid_angle;
use crate::ch5_reflection::warp::uniform_triangle;
use crate::scene::mesh::Mesh;
use crate::scene::LightSampling;

/// The most triangles a light sampled by solid angle may have: every
/// sample weighs the solid angle of each, so a larger emitter is sampled
/// by area.
pub const SOLID_ANGLE_MAX_TRIANGLES: usize = 16;

/// Below this solid angle (sr) at the shading point, a light is sampled by
/// area: it looks like a point there, where area sampling's 1/d² and
/// cos θl hardly vary across it.
pub const SOLID_ANGLE_MIN: f64 = 1e-6;

/// An emissive mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct AreaLight {
    /// The scene mesh it came from.
    pub mesh: usize,
    /// Its triangles in world space.
    pub triangles: Vec<[Vec3; 3]>,
    /// Cumulative triangle areas, for picking a triangle by area.
    pub cdf: Vec<f32>,
    /// Each triangle's unit normal (its winding's), computed once.
    pub normals: Vec<Vec3>,
    /// Total area A.
    pub area: f32,
    /// 1 / A, the density of a uniformly chosen point (computed once).
    pub inv_area: f32,
    /// Emitted radiance Le.
    pub le: Vec3,
    /// Whether it emits from both faces (else only the front face, the
    /// side its triangles wind counter-clockwise towards).
    pub two_sided: bool,
    /// How it is sampled ([`AreaLight::sampled_by`]).
    pub sampling: LightSampling,
}

/// pdf_A (per unit area at the light) → pdf_ω (per steradian at the
/// shading point): multiply by d² / |cos θl|. Zero at grazing angles, where
/// the light shows no area at all.
// ANCHOR: solid_angle_pdf
pub fn solid_angle_pdf(pdf_area: f32, dist: f32, cos_light: f32) -> f32 {
    let c = cos_light.abs();
    if c <= 0.0 {
        return 0.0;
    }
    let pdf = pdf_area * dist * dist / c;
    if pdf.is_finite() {
        pdf
    } else {
        0.0
    }
}
// ANCHOR_END: solid_angle_pdf

impl AreaLight {
    /// The area light of `mesh` (index `index` in the scene); `None` when
    /// the mesh has no area.
    pub fn new(mesh: &Mesh, index: usize, le: Vec3, two_sided: bool) -> Option<AreaLight> {
        let triangles: Vec<[Vec3; 3]> = mesh
            .triangles
            .iter()
            .map(|t| t.map(|i| mesh.positions[i as usize]))
            .collect();
        let mut cdf = Vec::with_capacity(triangles.len());
        let mut normals = Vec::with_capacity(triangles.len());
        let mut area = 0.0f32;
        for [a, b, c] in &triangles {
            let cross = (*b - *a).cross(*c - *a);
            area += 0.5 * cross.length();
            cdf.push(area);
            normals.push(cross.normalize_or_zero());
        }
        (area > 0.0 && area.is_finite()).then_some(AreaLight {
            mesh: index,
            triangles,
            cdf,
            normals,
            area,
            inv_area: 1.0 / area,
            le,
            two_sided,
            sampling: LightSampling::Area,
        })
    }

    /// The same light sampled by `sampling`; by area if it has more than
    /// [`SOLID_ANGLE_MAX_TRIANGLES`] triangles.
    pub fn sampled_by(mut self, sampling: LightSampling) -> AreaLight {
        let few = self.triangles.len() <= SOLID_ANGLE_MAX_TRIANGLES;
        self.sampling = if few { sampling } else { LightSampling::Area };
        self
    }

    /// Radiance leaving the light at a point with unit outward normal
    /// `n_light` towards direction `w` (unit, away from the light).
    pub fn emitted(&self, n_light: Vec3, w: Vec3) -> Vec3 {
        emitted_towards(self.le, self.two_sided, n_light, w)
    }

    /// The triangle a sample with first number `u_x` lies in, chosen by
    /// area, and `u_x` rescaled to [0, 1) inside its share, to place the
    /// point in it.
    #[inline]
    pub fn pick(&self, u_x: f32) -> (usize, f32) {
        let target = u_x * self.area;
        // The first triangle whose running total exceeds the target: by
        // counting for a few triangles (no branch to mispredict), by
        // bisection for many; the same index either way.
        let below = if self.cdf.len() <= 8 {
            self.cdf.iter().map(|c| (*c <= target) as usize).sum()
        } else {
            self.cdf.partition_point(|c| *c <= target)
        };
        let k = below.min(self.cdf.len() - 1);
        // The running total before triangle k (0 for the first), as a
        // product rather than a branch: prev · 1 = prev, prev · 0 = 0.
        let lo = self.cdf[k.saturating_sub(1)] * f32::from(u8::from(k > 0));
        let width = self.cdf[k] - lo;
        let ux = if width > 0.0 {
            ((target - lo) / width).clamp(0.0, 1.0 - f32::EPSILON)
        } else {
            0.0
        };
        (k, ux)
    }

    /// A point on the light seen from `p`, as a direction with a
    /// solid-angle pdf.
    pub fn sample_li(&self, p: Vec3, u: Vec2) -> Option<LightSample> {
        if let Some((omega, total)) = self.solid_angles(p) {
            return self.sample_by_solid_angle(p, u, &omega, total);
        }
        let (k, ux) = self.pick(u.x);
        let [a, b, c] = self.triangles[k];
        let bary = uniform_triangle(Vec2::new(ux, u.y));
        let y = bary.x * a + bary.y * b + bary.z * c;
        let n_light = self.normals[k];
        let to = y - p;
        let dist = to.length();
        if !(dist > 0.0 && dist.is_finite()) || n_light == Vec3::ZERO {
            return None;
        }
        let wi = to / dist;
        let li = self.emitted(n_light, -wi);
        let pdf = solid_angle_pdf(self.inv_area, dist, n_light.dot(wi));
        (pdf > 0.0 && li != Vec3::ZERO).then_some(LightSample {
            wi,
            li,
            pdf,
            dist,
            delta: false,
        })
    }

    /// The solid-angle pdf with which [`AreaLight::sample_li`] would return
    /// the point `y` (normal `n_light`) seen from `p`: for MIS, when a BSDF
    /// sample happened to hit this light.
    pub fn pdf_li(&self, p: Vec3, y: Vec3, n_light: Vec3) -> f32 {
        if let Some((_, total)) = self.solid_angles(p) {
            // Every point of a triangle that faces p has density 1/Ω.
            let faces_p = self.faces(p, n_light.dot(p - y));
            return if faces_p { (1.0 / total) as f32 } else { 0.0 };
        }
        let to = y - p;
        let dist = to.length();
        match to.try_normalize() {
            Some(wi) => solid_angle_pdf(self.inv_area, dist, n_light.dot(wi)),
            None => 0.0,
        }
    }
}

impl AreaLight {
    /// Whether a triangle whose plane lies at signed distance `h` from `p`
    /// (positive on its front) shows p a face that emits. A point closer
    /// to the plane than chapter 3's offset may lie on the light itself,
    /// rounded to either side, and sees it edge-on: not at all.
    fn faces(&self, p: Vec3, h: f32) -> bool {
        let h = if self.two_sided { h.abs() } else { h };
        h > offset_distance(p)
    }

    /// Where the light is sampled by solid angle at `p`: the solid angle of
    /// each triangle (zero for one that does not face p, [`Self::faces`])
    /// and their sum Ω; `None` where it is sampled by area.
    fn solid_angles(&self, p: Vec3) -> Option<([f64; SOLID_ANGLE_MAX_TRIANGLES], f64)> {
        if self.sampling != LightSampling::SolidAngle {
            return None;
        }
        let mut omega = [0.0; SOLID_ANGLE_MAX_TRIANGLES];
        let mut total = 0.0;
        for (k, [a, b, c]) in self.triangles.iter().enumerate() {
            if self.faces(p, self.normals[k].dot(p - *a)) {
                let [a, b, c] = [*a - p, *b - p, *c - p].map(|v| v.as_dvec3());
                omega[k] = triangle_solid_angle(a, b, c);
                total += omega[k];
            }
        }
        (total >= SOLID_ANGLE_MIN && total.is_finite()).then_some((omega, total))
    }

    /// [`AreaLight::sample_li`] by solid angle: a triangle by its share
    /// `omega[k]` of the total Ω (`u.x` rescaled inside that share), a
    /// direction uniformly in it, and where that direction meets it. Each
    /// triangle is picked with probability Ω_k / Ω and then gives density
    /// 1 / Ω_k, so every direction has pdf_ω = 1 / Ω.
    // ANCHOR: sample_by_solid_angle
    fn sample_by_solid_angle(
        &self,
        p: Vec3,
        u: Vec2,
        omega: &[f64],
        total: f64,
    ) -> Option<LightSample> {
        let (k, ux) = pick_share(&omega[..self.triangles.len()], total, u.x)?;
        let [a, b, c] = self.triangles[k];
        let corners = [a, b, c].map(|v| (v - p).as_dvec3().normalize_or_zero());
        let w = sample_spherical_triangle(corners, Vec2::new(ux, u.y))?;
        // How far along w the triangle's plane is.
        let n = self.normals[k].as_dvec3();
        let dist = (n.dot((a - p).as_dvec3()) / n.dot(w)) as f32;
        if !(dist > 0.0 && dist.is_finite()) {
            return None;
        }
        let wi = w.as_vec3();
        let li = self.emitted(self.normals[k], -wi);
        (li != Vec3::ZERO).then_some(LightSample {
            wi,
            li,
            pdf: (1.0 / total) as f32,
            dist,
            delta: false,
        })
    }
    // ANCHOR_END: sample_by_solid_angle
}

/// The triangle whose share of `total` (the running sum of `omega`) the
/// number `u_x` falls in, and `u_x` rescaled to [0, 1) inside that share;
/// `None` if only rounding led to a triangle of no share.
fn pick_share(omega: &[f64], total: f64, u_x: f32) -> Option<(usize, f32)> {
    let target = u_x as f64 * total;
    let mut k = 0;
    let mut below = 0.0;
    while k + 1 < omega.len() && below + omega[k] <= target {
        below += omega[k];
        k += 1;
    }
    if omega[k] <= 0.0 {
        return None;
    }
    let ux = (((target - below) / omega[k]) as f32).clamp(0.0, 1.0 - f32::EPSILON);
    Some((k, ux))
}

/// The one emission rule of every emitting surface (an area light, or an
/// emissive surface a path hits): radiance `le` leaves the face its unit
/// normal `n` points out of, towards the unit direction `w`; a two-sided
/// emitter also lights the other side; else nothing.
#[inline]
pub fn emitted_towards(le: Vec3, two_sided: bool, n: Vec3, w: Vec3) -> Vec3 {
    if two_sided || n.dot(w) > 0.0 {
        le
    } else {
        Vec3::ZERO
    }
}
