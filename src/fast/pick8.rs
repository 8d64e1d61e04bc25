//! An area light's choice of triangle ([`AreaLight::pick`]) for the eight
//! lanes of a round at once. Picking is a chain of steps that each wait
//! for the one before (count the running totals below the target, look up
//! two of them, divide), which one lane at a time the processor cannot
//! overlap much; for eight lanes that chose the same light, the same
//! steps go lane by lane over arrays, with selects in place of the
//! look-ups, and the compiler runs them in vector registers. A test
//! checks it against `pick` bit for bit.

use crate::ch5_reflection::light::area::AreaLight;

use super::lanes::W;
use super::shade8::{dim, In8};

/// Most triangles of a light picked in the lanes (more go one lane at a
/// time through `pick`'s bisection).
pub const MAX_TRIANGLES: usize = 8;

/// [`AreaLight::pick`] of `u[j]` for each lane j: the triangle and the
/// number left for the point on it, the same bits; `None` for a light of
/// more than [`MAX_TRIANGLES`] triangles.
// Lane loops index several arrays by lane, on purpose (vector code).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
pub fn pick8(light: &AreaLight, u: &[f32; W]) -> Option<([u32; W], [f32; W])> {
    let cdf = &light.cdf;
    if cdf.is_empty() || cdf.len() > MAX_TRIANGLES {
        return None;
    }
    let target: [f32; W] = std::array::from_fn(|j| u[j] * light.area);
    // The first triangle whose running total exceeds the target.
    let mut k = [0u32; W];
    for &c in cdf {
        for j in 0..W {
            k[j] += u32::from(c <= target[j]);
        }
    }
    let last = cdf.len() as u32 - 1;
    // Its running total and the one before it (0 for the first).
    let (mut lo, mut hi) = ([0.0f32; W], [0.0f32; W]);
    for (i, &c) in cdf.iter().enumerate() {
        for j in 0..W {
            k[j] = k[j].min(last);
            if k[j] == i as u32 {
                hi[j] = c;
            }
            if k[j] == i as u32 + 1 {
                lo[j] = c;
            }
        }
    }
    let mut ux = [0.0f32; W];
    for j in 0..W {
        let width = hi[j] - lo[j];
        let x = ((target[j] - lo[j]) / width).clamp(0.0, 1.0 - f32::EPSILON);
        ux[j] = if width > 0.0 { x } else { 0.0 };
    }
    Some((k, ux))
}

/// For eight lanes that all chose `light` (with probability `p_choose`):
/// the triangle [`pick8`] picks with the light's first number (`x.u[dim::LIGHT[0]]`), its corners and normal, and
/// the light's own numbers, written into the lanes' arrays with selects
/// (one pass per triangle) instead of one look-up per lane. False, and
/// nothing written, for a light of more than [`MAX_TRIANGLES`] triangles.
// Lane loops index several arrays by lane, on purpose (vector code).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
pub fn fill_light8(light: &AreaLight, p_choose: f32, x: &mut In8) -> bool {
    let Some((t, ux)) = pick8(light, &x.u[dim::LIGHT[0]]) else {
        return false;
    };
    x.ux = ux;
    // One select per lane and array, the lanes innermost, so that each
    // array is one vector blend per triangle.
    for (i, (corners, normal)) in light.triangles.iter().zip(&light.normals).enumerate() {
        let here: [bool; W] = std::array::from_fn(|j| t[j] == i as u32);
        for a in 0..3 {
            for (c, corner) in corners.iter().enumerate() {
                blend(&here, &mut x.tri[c][a], corner[a]);
            }
            blend(&here, &mut x.n_light[a], normal[a]);
        }
    }
    for a in 0..3 {
        x.le[a] = [light.le[a]; W];
    }
    x.inv_area = [light.inv_area; W];
    x.two_sided = [light.two_sided; W];
    x.p_choose = [p_choose; W];
    true
}

/// `to[j] = value` in the lanes `here`.
#[allow(clippy::needless_range_loop)]
#[inline(always)]
fn blend(here: &[bool; W], to: &mut [f32; W], value: f32) {
    for j in 0..W {
        to[j] = if here[j] { value } else { to[j] };
    }
}
