//! The lane half of the fast engine's wavefront loop ([`super::wave`]):
//! one vertex of eight paths shaded together. Every step is written as
//! one pass over eight lanes, with selects (`if` on values, `&` and `|` on
//! conditions) where the lesson's code branches, so the compiler turns the
//! whole function into vector instructions; [`super::simd`] compiles it a
//! second time for AVX2's eight-lane registers.
//!
//! Each lane runs the lesson's formulas in the lesson's order (the frame
//! of `Frame::from_normal`, `AreaLight::sample_li`, the power heuristic,
//! `cosine_hemisphere`), so a lane's numbers are the readable loop's bit
//! for bit except where the disk mapping's cosine and sine come from a
//! polynomial ([`sin_cos_quarter`]) instead of the C library.

// Lane loops index several arrays by lane, on purpose: that is the form
// the compiler turns into vector instructions.
#![allow(clippy::needless_range_loop)]

use std::f32::consts::{FRAC_1_PI, PI};

use super::lane_rays::{max_element, shadow_ray, spawn};
use super::lanes::W;

/// A vertex's random numbers by name: where each sits in [`In8::u`], in
/// the order the lesson's `trace_path` draws them.
pub mod dim {
    /// Which light to sample.
    pub const CHOOSE: usize = 0;
    /// The point on that light (two numbers).
    pub const LIGHT: [usize; 2] = [1, 2];
    /// Which lobe of the BSDF (a diffuse vertex leaves it unread).
    pub const LOBE: usize = 3;
    /// The next direction (two numbers).
    pub const DIRECTION: [usize; 2] = [4, 5];
    /// Russian roulette.
    pub const ROULETTE: usize = 6;
    /// Numbers per vertex (the last one unread).
    pub const PER_VERTEX: usize = 8;
}

/// What the lanes read: per lane the ray, the hit, the material, the
/// throughput, the vertex's random numbers and the light sample's
/// triangle (chosen by scalar code: a short search per lane). Vectors are
/// stored by coordinate: `d[axis][lane]`.
#[derive(Default)]
pub struct In8 {
    /// The ray's unit direction.
    pub d: [[f32; W]; 3],
    /// The hit point.
    pub p: [[f32; W]; 3],
    /// The surface's unit outward normal.
    pub n: [[f32; W]; 3],
    /// The diffuse reflectance ρ.
    pub rho: [[f32; W]; 3],
    /// The throughput β on arrival.
    pub beta: [[f32; W]; 3],
    /// The vertex's numbers, `u[dim][lane]` (see [`dim`]).
    pub u: [[f32; W]; dim::PER_VERTEX],
    /// The chosen light triangle's corners a, b, c: `tri[corner][axis]`.
    pub tri: [[[f32; W]; 3]; 3],
    /// Its unit normal.
    pub n_light: [[f32; W]; 3],
    /// The position inside the chosen triangle, rescaled from u_light.x.
    pub ux: [f32; W],
    /// 1 / the light's area.
    pub inv_area: [f32; W],
    /// The probability of having chosen that light.
    pub p_choose: [f32; W],
    /// The light's radiance.
    pub le: [[f32; W]; 3],
    /// Whether the light emits from both faces.
    pub two_sided: [bool; W],
    /// Whether roulette is played at this vertex...
    pub roulette: bool,
    /// ... and its scale s.
    pub rr_scale: f32,
}

/// What the lanes give back.
#[derive(Default)]
pub struct Out8 {
    /// wo.z ≠ 0: the ray is not in the surface's plane.
    pub valid: [bool; W],
    /// The normal on the side the path arrived from.
    pub n_side: [[f32; W]; 3],
    /// A shadow ray is cast (the light sample exists and f ≠ 0).
    pub shadow: [bool; W],
    /// The light it brings if nothing blocks it: β f Li |cos| w / pdf.
    pub contribution: [[f32; W]; 3],
    /// A next direction exists (pdf > 0, weight finite and non-zero).
    pub step: [bool; W],
    /// Its pdf.
    pub pdf: [f32; W],
    /// β after the step and roulette.
    pub beta: [[f32; W]; 3],
    /// Whether the path survived roulette.
    pub survives: [bool; W],
    /// Whether the next ray exists (`World::spawn` gives one).
    pub next_ok: [bool; W],
    /// Its origin, off the surface.
    pub next_o: [[f32; W]; 3],
    /// Its unit direction.
    pub next_d: [[f32; W]; 3],
    /// Whether the shadow ray must be traced (area lights)...
    pub shadow_trace: [bool; W],
    /// ... or its ends meet, so nothing blocks it (neither: blocked).
    pub shadow_free: [bool; W],
    /// The shadow ray's origin.
    pub shadow_o: [[f32; W]; 3],
    /// Its unit direction.
    pub shadow_d: [[f32; W]; 3],
    /// How far it is traced.
    pub shadow_t: [f32; W],
}

/// Cosine and sine of φ in [-π/4, π/4] (Cephes' minimax polynomials,
/// within a couple of units in the last place of `f32::sin_cos`).
// ANCHOR: sin_cos_quarter
#[inline(always)]
pub fn sin_cos_quarter(phi: f32) -> (f32, f32) {
    let z = phi * phi;
    let s = ((-1.951_529_6e-4 * z + 8.332_161e-3) * z - 1.666_665_5e-1) * z * phi + phi;
    let c = ((2.443_315_7e-5 * z - 1.388_731_6e-3) * z + 4.166_664_6e-2) * z * z - 0.5 * z + 1.0;
    (c, s)
}
// ANCHOR_END: sin_cos_quarter

/// One vertex of eight paths (into `o`, every field of every lane
/// written), step by step as the lesson's `trace_path` takes them: the
/// frame, the light sample with its MIS weight, the next direction,
/// roulette, and the two rays that leave. Each step is one pass over the
/// lanes with selects in place of branches (the steps are inlined into
/// one loop, which the compiler turns into vector instructions).
#[inline(always)]
pub fn shade8(x: &In8, o: &mut Out8) {
    for j in 0..W {
        let v = LaneVertex::at(x, j);
        o.valid[j] = v.wo[2] != 0.0;
        let flip = if v.wo[2] > 0.0 { 1.0 } else { -1.0 };
        for a in 0..3 {
            o.n_side[a][j] = v.n[a] * flip;
        }
        let light = light_sample(x, j, &v);
        o.shadow[j] = o.valid[j] & light.cast;
        for a in 0..3 {
            o.contribution[a][j] = light.contribution[a];
        }
        let dir = next_direction(x, j, &v, o);
        roulette(x, j, &v, o);

        // The two rays leaving this vertex, as `World::spawn` and
        // `World::unoccluded` make them.
        let next = spawn(v.p, v.n, dir);
        o.next_ok[j] = next.ok;
        for a in 0..3 {
            o.next_o[a][j] = next.origin[a];
            o.next_d[a][j] = next.dir[a];
        }
        let shadow = shadow_ray(v.p, v.n, light.wi, light.dist);
        o.shadow_trace[j] = shadow.ray.ok;
        o.shadow_free[j] = shadow.free;
        o.shadow_t[j] = shadow.t_max;
        for a in 0..3 {
            o.shadow_o[a][j] = shadow.ray.origin[a];
            o.shadow_d[a][j] = shadow.ray.dir[a];
        }
    }
}

/// Lane `j`'s vertex: the local frame of `Frame::from_normal` (Duff et
/// al.), the direction back along the ray in it, and what the steps read.
struct LaneVertex {
    s: [f32; 3],
    t: [f32; 3],
    n: [f32; 3],
    /// Towards where the path came from, local.
    wo: [f32; 3],
    p: [f32; 3],
    beta: [f32; 3],
    /// The Lambertian BRDF ρ / π.
    f_rho: [f32; 3],
}

impl LaneVertex {
    #[inline(always)]
    fn at(x: &In8, j: usize) -> LaneVertex {
        let (nx, ny, nz) = (x.n[0][j], x.n[1][j], x.n[2][j]);
        let sign = 1.0f32.copysign(nz);
        let a = -1.0 / (sign + nz);
        let b = nx * ny * a;
        let mut v = LaneVertex {
            s: [1.0 + sign * nx * nx * a, sign * b, -sign * nx],
            t: [b, sign + ny * ny * a, -ny],
            n: [nx, ny, nz],
            wo: [0.0; 3],
            p: [x.p[0][j], x.p[1][j], x.p[2][j]],
            beta: [x.beta[0][j], x.beta[1][j], x.beta[2][j]],
            f_rho: [
                x.rho[0][j] * FRAC_1_PI,
                x.rho[1][j] * FRAC_1_PI,
                x.rho[2][j] * FRAC_1_PI,
            ],
        };
        v.wo = v.local([-x.d[0][j], -x.d[1][j], -x.d[2][j]]);
        v
    }

    /// A world vector in the local frame.
    #[inline(always)]
    fn local(&self, v: [f32; 3]) -> [f32; 3] {
        let (s, t, n) = (self.s, self.t, self.n);
        [
            v[0] * s[0] + v[1] * s[1] + v[2] * s[2],
            v[0] * t[0] + v[1] * t[1] + v[2] * t[2],
            v[0] * n[0] + v[1] * n[1] + v[2] * n[2],
        ]
    }
}

/// A lane's light sample: the direction and distance to the point drawn
/// on the chosen triangle, whether a shadow ray is cast, and the light it
/// brings if nothing blocks it.
struct LaneLight {
    wi: [f32; 3],
    dist: f32,
    cast: bool,
    /// β f Li |cos| w / pdf.
    contribution: [f32; 3],
}

/// The light sample of `AreaLight::sample_li` (a uniform point on the
/// chosen triangle) and its MIS weight against the BSDF (the power
/// heuristic).
#[inline(always)]
fn light_sample(x: &In8, j: usize, v: &LaneVertex) -> LaneLight {
    let p = v.p;
    let sq = x.ux[j].sqrt();
    let b1 = 1.0 - sq;
    let b2 = x.u[dim::LIGHT[1]][j] * sq;
    let b0 = 1.0 - b1 - b2;
    let mut to = [0.0; 3];
    for a in 0..3 {
        let y = b0 * x.tri[0][a][j] + b1 * x.tri[1][a][j] + b2 * x.tri[2][a][j];
        to[a] = y - p[a];
    }
    let dist = (to[0] * to[0] + to[1] * to[1] + to[2] * to[2]).sqrt();
    let nl = [x.n_light[0][j], x.n_light[1][j], x.n_light[2][j]];
    let wi = [to[0] / dist, to[1] / dist, to[2] / dist];
    let cos_l = nl[0] * wi[0] + nl[1] * wi[1] + nl[2] * wi[2];
    let faces = x.two_sided[j] | (nl[0] * -wi[0] + nl[1] * -wi[1] + nl[2] * -wi[2] > 0.0);
    let c = cos_l.abs();
    let pdf_area = x.inv_area[j] * dist * dist / c;
    let pdf_light = if (c > 0.0) & (pdf_area.abs() < f32::INFINITY) {
        pdf_area
    } else {
        0.0
    };
    let li_nonzero = faces & ((x.le[0][j] != 0.0) | (x.le[1][j] != 0.0) | (x.le[2][j] != 0.0));
    let has_sample = (dist > 0.0)
        & (dist < f32::INFINITY)
        & ((nl[0] != 0.0) | (nl[1] != 0.0) | (nl[2] != 0.0))
        & (pdf_light > 0.0)
        & li_nonzero;
    let wil = v.local(wi);
    let same = v.wo[2] * wil[2] > 0.0;
    let f = if same { v.f_rho } else { [0.0; 3] };
    let f_nonzero = (f[0] != 0.0) | (f[1] != 0.0) | (f[2] != 0.0);
    let pdf = pdf_light * x.p_choose[j];
    let bsdf_pdf = if same {
        wil[2].abs().max(0.0) * FRAC_1_PI
    } else {
        0.0
    };
    let r = bsdf_pdf / pdf;
    // The power heuristic: 1 for an infinite pdf, 0 for NaN or ≤ 0.
    let heuristic = 1.0 / (1.0 + r * r);
    let weight = if pdf == f32::INFINITY {
        1.0
    } else if pdf > 0.0 {
        heuristic
    } else {
        0.0
    };
    let cos_i = wil[2].abs();
    LaneLight {
        wi,
        dist,
        cast: has_sample & f_nonzero,
        contribution: std::array::from_fn(|a| {
            v.beta[a] * f[a] * x.le[a][j] * cos_i * (weight / pdf)
        }),
    }
}

/// The next direction, cosine-weighted (`cosine_hemisphere`), into
/// `o.step` and `o.pdf`; returns it in world space.
#[inline(always)]
fn next_direction(x: &In8, j: usize, v: &LaneVertex, o: &mut Out8) -> [f32; 3] {
    let wo = v.wo;
    // ANCHOR: next_direction
    // The next direction: cosine-weighted (concentric disk, lifted).
    let ox = 2.0 * x.u[dim::DIRECTION[0]][j] - 1.0;
    let oy = 2.0 * x.u[dim::DIRECTION[1]][j] - 1.0;
    let wide = ox.abs() > oy.abs();
    let (r_disk, ratio) = if wide { (ox, oy / ox) } else { (oy, ox / oy) };
    let (cphi, sphi) = sin_cos_quarter(0.25 * PI * ratio);
    // θ = φ (wide) or π/2 − φ: cos θ and sin θ swap.
    let (cos_t, sin_t) = if wide { (cphi, sphi) } else { (sphi, cphi) };
    let zero = (ox == 0.0) & (oy == 0.0);
    let dx = if zero { 0.0 } else { r_disk * cos_t };
    let dy = if zero { 0.0 } else { r_disk * sin_t };
    let z = (1.0 - (dx * dx + dy * dy)).max(0.0).sqrt();
    let z = if wo[2] < 0.0 { -z } else { z };
    let step_pdf = if wo[2] * z > 0.0 {
        z.abs().max(0.0) * FRAC_1_PI
    } else {
        0.0
    };
    let rho_ok = ((x.rho[0][j] != 0.0) | (x.rho[1][j] != 0.0) | (x.rho[2][j] != 0.0))
        & (x.rho[0][j].abs() < f32::INFINITY)
        & (x.rho[1][j].abs() < f32::INFINITY)
        & (x.rho[2][j].abs() < f32::INFINITY);
    o.step[j] = o.valid[j] & (step_pdf > 0.0) & rho_ok;
    // ANCHOR_END: next_direction
    o.pdf[j] = step_pdf;
    let (s, t, n) = (v.s, v.t, v.n);
    std::array::from_fn(|a| s[a] * dx + t[a] * dy + n[a] * z)
}

/// Throughput and Russian roulette: β times f cos / pdf (ρ for a
/// cosine-sampled Lambertian step), then survive with q = min(1, s · max β)
/// (the lesson's `survival_probability`).
#[inline(always)]
fn roulette(x: &In8, j: usize, v: &LaneVertex, o: &mut Out8) {
    let beta = v.beta;
    let nb = [
        beta[0] * x.rho[0][j],
        beta[1] * x.rho[1][j],
        beta[2] * x.rho[2][j],
    ];
    let q = (max_element(nb) * x.rr_scale).min(1.0);
    let dies = x.roulette & (x.u[dim::ROULETTE][j] >= q);
    o.survives[j] = !dies;
    for a in 0..3 {
        o.beta[a][j] = if x.roulette { nb[a] / q } else { nb[a] };
    }
}
