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

use crate::ch3_ray_triangle::spawn::{FLOAT_SCALE, INT_SCALE, ORIGIN, STOP_SCALE};

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
    /// Whether roulette is played at this vertex.
    pub roulette: bool,
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
/// written): frame, light sample, MIS, next direction,
/// roulette. Each line is one pass over the lanes with selects in place of
/// branches.
#[inline(always)]
pub fn shade8(x: &In8, o: &mut Out8) {
    for j in 0..W {
        let (nx, ny, nz) = (x.n[0][j], x.n[1][j], x.n[2][j]);
        // Frame::from_normal (Duff et al.).
        let sign = 1.0f32.copysign(nz);
        let a = -1.0 / (sign + nz);
        let b = nx * ny * a;
        let s = [1.0 + sign * nx * nx * a, sign * b, -sign * nx];
        let t = [b, sign + ny * ny * a, -ny];
        let n = [nx, ny, nz];
        let local = |v: [f32; 3]| {
            [
                v[0] * s[0] + v[1] * s[1] + v[2] * s[2],
                v[0] * t[0] + v[1] * t[1] + v[2] * t[2],
                v[0] * n[0] + v[1] * n[1] + v[2] * n[2],
            ]
        };
        let wo = local([-x.d[0][j], -x.d[1][j], -x.d[2][j]]);
        o.valid[j] = wo[2] != 0.0;
        let flip = if wo[2] > 0.0 { 1.0 } else { -1.0 };
        for a in 0..3 {
            o.n_side[a][j] = n[a] * flip;
        }
        let p = [x.p[0][j], x.p[1][j], x.p[2][j]];
        let beta = [x.beta[0][j], x.beta[1][j], x.beta[2][j]];
        let f_rho = [
            x.rho[0][j] * FRAC_1_PI,
            x.rho[1][j] * FRAC_1_PI,
            x.rho[2][j] * FRAC_1_PI,
        ];

        // The light sample: a uniform point y on the chosen triangle.
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
        let wil = local(wi);
        let same = wo[2] * wil[2] > 0.0;
        let f = if same { f_rho } else { [0.0; 3] };
        let f_nonzero = (f[0] != 0.0) | (f[1] != 0.0) | (f[2] != 0.0);
        o.shadow[j] = o.valid[j] & has_sample & f_nonzero;
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
        for a in 0..3 {
            o.contribution[a][j] = beta[a] * f[a] * x.le[a][j] * cos_i * (weight / pdf);
        }

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
        let dir: [f32; 3] = std::array::from_fn(|a| s[a] * dx + t[a] * dy + n[a] * z);
        // Throughput and Russian roulette.
        let nb = [
            beta[0] * x.rho[0][j],
            beta[1] * x.rho[1][j],
            beta[2] * x.rho[2][j],
        ];
        let q = max_element(nb).min(1.0);
        let dies = x.roulette & (x.u[dim::ROULETTE][j] >= q);
        o.survives[j] = !dies;
        for a in 0..3 {
            o.beta[a][j] = if x.roulette { nb[a] / q } else { nb[a] };
        }

        // The two rays leaving this vertex, as `World::spawn` and
        // `World::unoccluded` make them.
        let next = spawn(p, n, dir);
        o.next_ok[j] = next.ok;
        for a in 0..3 {
            o.next_o[a][j] = next.origin[a];
            o.next_d[a][j] = next.dir[a];
        }
        let shadow = shadow_ray(p, n, wi, dist);
        o.shadow_trace[j] = shadow.ray.ok;
        o.shadow_free[j] = shadow.free;
        o.shadow_t[j] = shadow.t_max;
        for a in 0..3 {
            o.shadow_o[a][j] = shadow.ray.origin[a];
            o.shadow_d[a][j] = shadow.ray.dir[a];
        }
    }
}

/// glam's `Vec3::max_element`, in its order.
#[inline(always)]
fn max_element(v: [f32; 3]) -> f32 {
    let max = |a: f32, b: f32| if a > b { a } else { b };
    max(v[0], max(v[1], v[2]))
}

/// Chapter 3's [`offset_origin`](crate::ch3_ray_triangle::spawn::offset_origin)
/// for one coordinate, with a select in place of its early return (a test
/// checks that the bits agree).
#[inline(always)]
pub fn offset_coordinate(p: f32, n: f32) -> f32 {
    let near = p + FLOAT_SCALE * n;
    let ulps = truncate(INT_SCALE * n);
    let ulps = if p < 0.0 { ulps.wrapping_neg() } else { ulps };
    let far = f32::from_bits((p.to_bits() as i32).wrapping_add(ulps) as u32);
    if p.abs() < ORIGIN {
        near
    } else {
        far
    }
}

/// `x as i32`: x rounded towards zero, saturated to the `i32` range,
/// NaN giving 0. Written with integer steps on the bits (exponent and
/// mantissa, two shifts, selects), because the compiler turns Rust's
/// saturating cast into one scalar conversion per lane, and these steps
/// into vector instructions. A test checks it against `as i32`.
#[inline(always)]
pub fn truncate(x: f32) -> i32 {
    let bits = x.to_bits();
    let exponent = ((bits >> 23) & 0xff) as i32 - 127;
    let mantissa = (bits & 0x7f_ffff) | 0x80_0000;
    // |x| = mantissa · 2^(exponent - 23); below 1 the right shift of 31
    // leaves nothing.
    let right = (23 - exponent).clamp(0, 31) as u32;
    let left = (exponent - 23).clamp(0, 7) as u32;
    let magnitude = ((mantissa >> right) << left) as i32;
    let negative = (bits >> 31) != 0;
    let value = if negative {
        magnitude.wrapping_neg()
    } else {
        magnitude
    };
    let saturated = if negative { i32::MIN } else { i32::MAX };
    let nan = exponent == 128 && (bits & 0x7f_ffff) != 0;
    let out = if exponent >= 31 { saturated } else { value };
    if nan {
        0
    } else {
        out
    }
}

/// Chapter 3's [`stop_distance`](crate::ch3_ray_triangle::spawn::stop_distance),
/// with a select.
#[inline(always)]
pub fn stop_distance(y: [f32; 3]) -> f32 {
    let m = max_element([y[0].abs(), y[1].abs(), y[2].abs()]);
    let ulp = f32::from_bits(m.to_bits().wrapping_add(1)) - m;
    STOP_SCALE
        * if m < ORIGIN {
            FLOAT_SCALE
        } else {
            INT_SCALE * ulp
        }
}

/// A ray as `Ray::from_unit` makes it, for one lane; `ok` is false where
/// it gives `None`.
#[derive(Clone, Copy)]
pub struct LaneRay {
    /// Whether there is a ray.
    pub ok: bool,
    /// Its origin.
    pub origin: [f32; 3],
    /// Its unit direction.
    pub dir: [f32; 3],
}

/// `Ray::from_unit(origin, dir)`: `dir` as it is when its length is 1 to
/// within 10⁻⁵, else normalised (`Ray::new`); no ray for an origin that is
/// not finite or a direction that cannot be normalised.
#[inline(always)]
fn from_unit(origin: [f32; 3], dir: [f32; 3]) -> LaneRay {
    let len2 = dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2];
    let finite = (origin[0].abs() < f32::INFINITY)
        & (origin[1].abs() < f32::INFINITY)
        & (origin[2].abs() < f32::INFINITY);
    let unit = (len2 - 1.0).abs() <= 1e-5;
    let rcp = 1.0 / len2.sqrt();
    let normalisable = (rcp < f32::INFINITY) & (rcp > 0.0);
    LaneRay {
        ok: finite & (unit | normalisable),
        origin,
        dir: [
            if unit { dir[0] } else { dir[0] * rcp },
            if unit { dir[1] } else { dir[1] * rcp },
            if unit { dir[2] } else { dir[2] * rcp },
        ],
    }
}

/// `World::spawn(p, n, dir)` without SDFs: the origin moved off the
/// surface to the side `dir` leaves into.
#[inline(always)]
fn spawn(p: [f32; 3], n: [f32; 3], dir: [f32; 3]) -> LaneRay {
    let back = n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2] < 0.0;
    let s = if back { -1.0 } else { 1.0 };
    let origin = [
        offset_coordinate(p[0], n[0] * s),
        offset_coordinate(p[1], n[1] * s),
        offset_coordinate(p[2], n[2] * s),
    ];
    from_unit(origin, dir)
}

/// The shadow ray of `World::unoccluded(p, n, wi, dist)` without SDFs:
/// `ray.ok` when it must be traced (to `t_max`), `free` when the two ends
/// meet and nothing can lie between; neither: blocked (no origin).
struct ShadowRay {
    ray: LaneRay,
    t_max: f32,
    free: bool,
}

#[inline(always)]
fn shadow_ray(p: [f32; 3], n: [f32; 3], wi: [f32; 3], dist: f32) -> ShadowRay {
    let spawned = spawn(p, n, wi);
    let y = [
        p[0] + wi[0] * dist,
        p[1] + wi[1] * dist,
        p[2] + wi[2] * dist,
    ];
    let back = stop_distance(y);
    let to = [
        y[0] - wi[0] * back - spawned.origin[0],
        y[1] - wi[1] * back - spawned.origin[1],
        y[2] - wi[2] * back - spawned.origin[2],
    ];
    let t_max = (to[0] * to[0] + to[1] * to[1] + to[2] * to[2]).sqrt();
    let finite = t_max.abs() < f32::INFINITY;
    let infinite = !finite;
    let ahead = (t_max > 0.0) & (to[0] * wi[0] + to[1] * wi[1] + to[2] * wi[2] > 0.0);
    let aimed = from_unit(
        spawned.origin,
        [to[0] / t_max, to[1] / t_max, to[2] / t_max],
    );
    let ray = if infinite { spawned } else { aimed };
    ShadowRay {
        ray: LaneRay {
            ok: spawned.ok & (infinite | (ahead & aimed.ok)),
            ..ray
        },
        t_max: if infinite { f32::INFINITY } else { t_max },
        free: spawned.ok & !infinite & !(ahead & aimed.ok),
    }
}
