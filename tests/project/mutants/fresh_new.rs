//! A second fresh set: plausible wrong solutions of the six exercises
//! added for #47 (manifold, sah, solid_angle, spot, refraction,
//! bounce_layers), written from their stubs' contracts before reading
//! their checks. Each must fail under every seed tried; the correct
//! solution written the same way must pass under every seed.

use std::collections::{HashMap, HashSet};
use std::f32::consts::PI;

use glam::Vec3;
use raystep::ch6_global_illumination::layers::{
    LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND, SLOT_EMITTED,
};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::bounce_layers::{Gathered, How};
use raystep::grading::exercises::{bounce_layers, ch2, ch3, ch5, refraction};

use super::under_seeds;

const SEEDS: [u64; 4] = [3, 0xfeed, 12_345, 0x51de];

/// A mutant that panics fails in the student's process; here the panic is
/// caught and counts as a failure too.
fn fails(what: &str, check: impl Fn() -> Check + std::panic::RefUnwindSafe) {
    let caught = || {
        std::panic::catch_unwind(&check).unwrap_or_else(|_| Check {
            error: f64::INFINITY,
            tolerance: 0.0,
            detail: "panicked".into(),
            images: None,
            symptom: None,
        })
    };
    for (seed, c) in under_seeds(&SEEDS, caught) {
        assert!(!c.passed(), "{what} passed under seed {seed}: {}", c.detail);
    }
}

fn passes(what: &str, check: impl Fn() -> Check) {
    for (seed, c) in under_seeds(&SEEDS, check) {
        assert!(c.passed(), "{what} failed under seed {seed}: {}", c.detail);
    }
}

// ---- 2.5 manifold ---------------------------------------------------------

/// The counts as the contract reads, with bug `B` switched in: 0 none,
/// 1 an edge with an odd number of triangles counted as boundary, 2 the
/// fan test by degree (a closed fan has as many edges as triangles, an
/// open one one more), 3 degenerate triangles kept, 4 only triangles with
/// three equal indices skipped, 5 edges with 3+ triangles also counted as
/// inconsistent when all walk one way, 6 vertices indexed in a table as
/// long as three per triangle.
fn manifold<const B: u8>(tris: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    let keep = |t: &&[u32; 3]| match B {
        3 => true,
        4 => !(t[0] == t[1] && t[1] == t[2]),
        _ => t[0] != t[1] && t[1] != t[2] && t[0] != t[2],
    };
    let tris: Vec<[u32; 3]> = tris.iter().filter(keep).copied().collect();
    if B == 6 {
        let mut seen = vec![0u8; tris.len() * 3];
        for t in &tris {
            for &v in t {
                seen[v as usize] = 1;
            }
        }
    }
    let mut edges: HashMap<(u32, u32), (usize, usize)> = HashMap::new();
    for t in &tris {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let e = edges.entry((a.min(b), a.max(b))).or_default();
            e.0 += 1;
            e.1 += usize::from(a < b);
        }
    }
    let boundary = edges
        .values()
        .filter(|e| if B == 1 { e.0 % 2 == 1 } else { e.0 == 1 })
        .count();
    let many = edges.values().filter(|e| e.0 >= 3).count();
    let inconsistent = edges
        .values()
        .filter(|e| (e.0 == 2 || (B == 5 && e.0 > 2)) && (e.1 == e.0 || e.1 == 0))
        .count();
    let mut at: HashMap<u32, Vec<usize>> = HashMap::new();
    for (i, t) in tris.iter().enumerate() {
        for &v in t {
            at.entry(v).or_default().push(i);
        }
    }
    let mut fans = 0;
    for (&v, ts) in &at {
        if B == 2 {
            let others: HashSet<u32> = ts
                .iter()
                .flat_map(|&i| tris[i])
                .filter(|&w| w != v)
                .collect();
            let (e, f) = (others.len(), ts.len());
            fans += usize::from(e != f && e != f + 1);
            continue;
        }
        let n = ts.len();
        let mut parent: Vec<usize> = (0..n).collect();
        fn find(p: &mut [usize], mut i: usize) -> usize {
            while p[i] != i {
                p[i] = p[p[i]];
                i = p[i];
            }
            i
        }
        for a in 0..n {
            for b in a + 1..n {
                let share = tris[ts[a]]
                    .iter()
                    .any(|&w| w != v && tris[ts[b]].contains(&w));
                if share {
                    let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
                    parent[ra] = rb;
                }
            }
        }
        let roots = (0..n).filter(|&i| find(&mut parent, i) == i).count();
        fans += usize::from(roots >= 2);
    }
    (boundary, many, fans, inconsistent)
}

#[test]
fn fresh_manifold_mistakes_fail() {
    passes("the counts as the contract reads", || {
        ch2::check_manifold(manifold::<0>)
    });
    fails("an odd number of triangles counted as boundary", || {
        ch2::check_manifold(manifold::<1>)
    });
    fails("fans judged by degree", || {
        ch2::check_manifold(manifold::<2>)
    });
    fails("degenerate triangles kept", || {
        ch2::check_manifold(manifold::<3>)
    });
    fails("only fully degenerate triangles skipped", || {
        ch2::check_manifold(manifold::<4>)
    });
    fails("3+ triangles walking one way counted inconsistent", || {
        ch2::check_manifold(manifold::<5>)
    });
    fails("vertices in a table three per triangle long", || {
        ch2::check_manifold(manifold::<6>)
    });
}

// ---- 3.5 sah ----------------------------------------------------------------

fn area(b: [Vec3; 2], bug: u8) -> f32 {
    let d = (b[1] - b[0]).max(Vec3::ZERO);
    match bug {
        5 => 2.0 * (d.x * d.y + d.y * d.z),
        6 => d.x * d.y * d.z,
        _ => 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x),
    }
}

fn join(a: [Vec3; 2], b: [Vec3; 2]) -> [Vec3; 2] {
    [a[0].min(b[0]), a[1].max(b[1])]
}

const EMPTY: [Vec3; 2] = [Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)];

/// A full sweep with bug `B`: 0 none, 1 the x axis only, 2 the children
/// weighed by their centroids' box, 4 a split whenever a plane exists,
/// 5 a face pair left out of the area, 6 volume, 7 the areas not divided
/// by the node's, 8 the plane at the last centroid of the left side.
fn sah<const B: u8>(boxes: &[[Vec3; 2]], centroids: &[Vec3]) -> Option<(usize, f32)> {
    let n = boxes.len();
    let whole = boxes.iter().fold(EMPTY, |a, b| join(a, *b));
    let a_node = if B == 7 { 1.0 } else { area(whole, B) };
    let mut best: Option<(f32, usize, f32)> = None;
    let axes = if B == 1 { 1 } else { 3 };
    for axis in 0..axes {
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&i, &j| centroids[i][axis].total_cmp(&centroids[j][axis]));
        let child_box = |i: usize| match B {
            2 => [centroids[i], centroids[i]],
            _ => boxes[i],
        };
        let mut right = vec![EMPTY; n + 1];
        for k in (0..n).rev() {
            right[k] = join(right[k + 1], child_box(order[k]));
        }
        let mut left = EMPTY;
        for k in 1..n {
            left = join(left, child_box(order[k - 1]));
            let (lo, hi) = (centroids[order[k - 1]][axis], centroids[order[k]][axis]);
            if lo >= hi {
                continue;
            }
            let cost =
                1.0 + (area(left, B) * k as f32 + area(right[k], B) * (n - k) as f32) / a_node;
            if best.is_none_or(|b| cost < b.0) {
                let at = if B == 8 { lo } else { hi };
                best = Some((cost, axis, at));
            }
        }
    }
    match best {
        Some((cost, axis, at)) if cost < n as f32 || B == 4 => Some((axis, at)),
        _ => None,
    }
}

#[test]
fn fresh_sah_mistakes_fail() {
    passes("a full sweep on three axes", || ch3::check_sah(sah::<0>));
    fails("the x axis only", || ch3::check_sah(sah::<1>));
    fails("children weighed by their centroids' box", || {
        ch3::check_sah(sah::<2>)
    });
    fails("a split whenever a plane exists", || {
        ch3::check_sah(sah::<4>)
    });
    fails("a face pair left out of the area", || {
        ch3::check_sah(sah::<5>)
    });
    fails("volume instead of area", || ch3::check_sah(sah::<6>));
    fails("areas not divided by the node's", || {
        ch3::check_sah(sah::<7>)
    });
    fails("the plane at the left side's last centroid", || {
        ch3::check_sah(sah::<8>)
    });
}

// ---- 5.7 spot -----------------------------------------------------------------

/// A spot's power with bug `B`: 0 none (half the band, by half-angle
/// sines), 1 the whole outer cone, 2 the inner cone only, 3 1 - cos in
/// f32, 4 the cone of the mean angle, 5 4π for 2π, 7 the half-angle form
/// doubled.
fn spot<const B: u8>(i: Vec3, inner: f32, outer: f32) -> Vec3 {
    let s2 = |a: f32| {
        let s = (0.5 * a).sin();
        s * s
    };
    let share = match B {
        1 => 2.0 * s2(outer),
        2 => 2.0 * s2(inner),
        3 => 1.0 - 0.5 * (inner.cos() + outer.cos()),
        4 => 2.0 * s2(0.5 * (inner + outer)),
        7 => 2.0 * (s2(inner) + s2(outer)),
        _ => s2(inner) + s2(outer),
    };
    let k = if B == 5 { 4.0 * PI } else { 2.0 * PI };
    i * k * share
}

#[test]
fn fresh_spot_mistakes_fail() {
    passes("the band's half, by half-angle sines", || {
        ch5::check_spot(spot::<0>)
    });
    fails("the outer cone, full", || ch5::check_spot(spot::<1>));
    fails("the inner cone only", || ch5::check_spot(spot::<2>));
    fails("1 - cos in f32 at tiny cones", || {
        ch5::check_spot(spot::<3>)
    });
    fails("the mean angle's cone", || ch5::check_spot(spot::<4>));
    fails("4π for the sphere's 2π", || ch5::check_spot(spot::<5>));
    fails("the half-angle form doubled", || ch5::check_spot(spot::<7>));
}

// ---- 5.6 solid angle ------------------------------------------------------------

/// Van Oosterom and Strackee's formula with bug `B`: 0 none, 1 A cos θ /
/// r² at the centroid, 2 atan of the quotient for atan2, 3 signed, 7 4π -
/// Ω for one winding, 8 the triple product of the three long vectors.
fn solid<const B: u8>(p: Vec3, tri: [Vec3; 3]) -> f32 {
    let [a, b, c] = tri.map(|v| v - p);
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    // The triple product from the triangle's own edges: a · (b × c) of
    // three long vectors cancels away every digit for a far triangle.
    let triple = match B {
        8 => a.dot(b.cross(c)),
        _ => a.dot((tri[1] - tri[0]).cross(tri[2] - tri[0])),
    };
    let den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    match B {
        1 => {
            let centre = (a + b + c) / 3.0;
            let n = (tri[1] - tri[0]).cross(tri[2] - tri[0]);
            0.5 * n.dot(centre).abs() / centre.length().powi(3)
        }
        2 => (2.0 * (triple.abs() / den).atan()).abs(),
        3 => 2.0 * triple.atan2(den),
        7 => {
            let o = 2.0 * triple.abs().atan2(den);
            if triple < 0.0 {
                4.0 * PI - o
            } else {
                o
            }
        }
        _ => 2.0 * triple.abs().atan2(den),
    }
}

#[test]
fn fresh_solid_angle_mistakes_fail() {
    passes("van Oosterom and Strackee", || {
        ch5::check_solid_angle(solid::<0>)
    });
    fails("A cos θ / r² at the centroid", || {
        ch5::check_solid_angle(solid::<1>)
    });
    fails("atan for atan2", || ch5::check_solid_angle(solid::<2>));
    fails("signed", || ch5::check_solid_angle(solid::<3>));
    fails("4π - Ω for one winding", || {
        ch5::check_solid_angle(solid::<7>)
    });
    fails("a · (b × c) of the long vectors in f32", || {
        ch5::check_solid_angle(solid::<8>)
    });
}

// ---- 6.5 refraction ---------------------------------------------------------------

/// Unpolarised Fresnel reflectance, with bug `B`: 4 the s-polarised part
/// alone, 5 cos θi and cos θt swapped in the p-polarised part.
fn fresnel<const B: u8>(ci: f32, ct: f32, ni: f32, nt: f32) -> f32 {
    let rs = (ni * ci - nt * ct) / (ni * ci + nt * ct);
    let rp = match B {
        5 => (nt * ct - ni * ci) / (nt * ct + ni * ci),
        _ => (nt * ci - ni * ct) / (nt * ci + ni * ct),
    };
    match B {
        4 => rs * rs,
        _ => 0.5 * (rs * rs + rp * rp),
    }
}

/// Refraction with bug `B`: 0 none, 1 the index ratio upside down, 2 the
/// normal never flipped for light from inside, 3 Schlick's Fresnel, 4 and
/// 5 as in [`fresnel`], 8 `d` taken as pointing away (the book's ωo),
/// 9 the normal flipped for light from inside but not the indices.
fn refract<const B: u8>(d: Vec3, n: Vec3, eo: f32, ei: f32) -> Option<(Vec3, f32)> {
    let d = if B == 8 { -d } else { d };
    let outside = d.dot(n) < 0.0 || B == 2;
    let (ns, ni, nt) = match (outside, B) {
        (true, _) => (n, eo, ei),
        (false, 9) => (-n, eo, ei),
        (false, _) => (-n, ei, eo),
    };
    let cos_i = (-d.dot(ns)).clamp(0.0, 1.0);
    let eta = if B == 1 { nt / ni } else { ni / nt };
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let t = (eta * d + (eta * cos_i - cos_t) * ns).normalize();
    let f = match B {
        3 => {
            let r0 = ((ni - nt) / (ni + nt)).powi(2);
            let c = if ni > nt { cos_t } else { cos_i };
            r0 + (1.0 - r0) * (1.0 - c).powi(5)
        }
        4 => fresnel::<4>(cos_i, cos_t, ni, nt),
        5 => fresnel::<5>(cos_i, cos_t, ni, nt),
        _ => fresnel::<0>(cos_i, cos_t, ni, nt),
    };
    Some((t, f))
}

#[test]
fn fresh_refraction_mistakes_fail() {
    passes("Snell's law in vector form, exact Fresnel", || {
        refraction::check_refraction(refract::<0>)
    });
    fails("the index ratio upside down", || {
        refraction::check_refraction(refract::<1>)
    });
    fails("the normal never flipped", || {
        refraction::check_refraction(refract::<2>)
    });
    fails("Schlick's approximation", || {
        refraction::check_refraction(refract::<3>)
    });
    fails("s-polarised reflectance only", || {
        refraction::check_refraction(refract::<4>)
    });
    fails("cosines swapped in rp", || {
        refraction::check_refraction(refract::<5>)
    });
    fails("d as the book's ωo", || {
        refraction::check_refraction(refract::<8>)
    });
    fails("the normal flipped, the indices not", || {
        refraction::check_refraction(refract::<9>)
    });
}

// ---- 6.6 bounce layers ------------------------------------------------------------

/// The slots with bug `B`: 0 none, 1 a light sample at vertex j filed at
/// bounce count j - 1, 2 emission found at vertex j filed at count j,
/// 3 emitters seen directly filed in layer 0, 4 the cap one lower,
/// 5 non-finite contributions kept, 6 the MIS weight left out, 7 the
/// finite channels of a non-finite contribution kept.
fn layers<const B: u8>(path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
    let mut out = [Vec3::ZERO; LAYER_SLOTS];
    for g in path {
        let k: Option<u32> = match g.how {
            How::Found if g.vertex == 0 && B != 3 => None,
            How::Found if g.vertex == 0 => Some(0),
            How::Found if B == 2 => Some(g.vertex),
            How::Found => Some(g.vertex - 1),
            How::LightSample if B == 1 => g.vertex.checked_sub(1),
            How::LightSample => Some(g.vertex),
        };
        let cap = if B == 4 {
            LAYERS_SHOWN - 1
        } else {
            LAYERS_SHOWN
        };
        let slot = match k {
            None => SLOT_EMITTED,
            Some(k) if k > cap => SLOT_BEYOND,
            Some(k) => k as usize + 1,
        };
        let c = if B == 6 { g.value } else { g.value * g.weight };
        if B == 7 {
            // Each channel on its own.
            let keep = Vec3::select(c.is_finite_mask(), c, Vec3::ZERO);
            out[slot] += keep;
        } else if c.is_finite() || B == 5 {
            out[slot] += c;
        }
    }
    out
}

#[test]
fn fresh_bounce_layer_mistakes_fail() {
    passes("the slots as the contract reads", || {
        bounce_layers::check_bounce_layers(layers::<0>)
    });
    fails("a light sample one bounce early", || {
        bounce_layers::check_bounce_layers(layers::<1>)
    });
    fails("found emission one bounce late", || {
        bounce_layers::check_bounce_layers(layers::<2>)
    });
    fails("emitters seen directly in layer 0", || {
        bounce_layers::check_bounce_layers(layers::<3>)
    });
    fails("the cap one lower", || {
        bounce_layers::check_bounce_layers(layers::<4>)
    });
    fails("non-finite contributions kept", || {
        bounce_layers::check_bounce_layers(layers::<5>)
    });
    fails("the MIS weight left out", || {
        bounce_layers::check_bounce_layers(layers::<6>)
    });
    fails(
        "the finite channels of a non-finite contribution kept",
        || bounce_layers::check_bounce_layers(layers::<7>),
    );
}
