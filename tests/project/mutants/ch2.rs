//! Chapter 2's graders against plausible wrong solutions (each must fail
//! and name its mistake) and correct alternatives (each must pass).

use std::panic::catch_unwind;

use glam::{Vec2, Vec3};
use raystep::ch2_rasterization::triangle::rasterize_triangle;
use raystep::grading::exercise::{Check, Symptom};
use raystep::grading::exercises::ch2::{self, model::Model};

fn e(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)
}

fn top_left(s: Vec2, t: Vec2) -> bool {
    t.y < s.y || (t.y == s.y && t.x > s.x)
}

/// What a student's rasterizer may get wrong, one knob per mistake.
#[derive(Clone, Copy)]
struct Knobs {
    offset: f32,
    on_edge: fn(Vec2, Vec2) -> bool,
    swap: bool,
    swap_colours: bool,
    affine_colour: bool,
    affine_depth: bool,
    depth: fn(f32, f32) -> bool,
    store_depth: bool,
    colour_before_test: bool,
    clip_x: bool,
    guard_index: bool,
}

const RIGHT: Knobs = Knobs {
    offset: 0.5,
    on_edge: top_left,
    swap: true,
    swap_colours: true,
    affine_colour: false,
    affine_depth: false,
    depth: |z, d| z < d,
    store_depth: true,
    colour_before_test: false,
    clip_x: true,
    guard_index: true,
};

/// The capstone as a student writes it from the book, with knobs.
#[allow(clippy::too_many_arguments)]
fn student(
    v: [Vec3; 3],
    c: [Vec3; 3],
    w: u32,
    h: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
    k: Knobs,
) {
    let (mut v, mut c) = (v, c);
    let area = e(v[0].truncate(), v[1].truncate(), v[2].truncate());
    if area == 0.0 || !area.is_finite() || !v.iter().all(|q| q.is_finite()) {
        return;
    }
    if area < 0.0 && k.swap {
        v.swap(1, 2);
        if k.swap_colours {
            c.swap(1, 2);
        }
    }
    let area = area.abs();
    let [a, b, cc] = v.map(|p| p.truncate());
    let lo = a.min(b).min(cc).floor().max(Vec2::ZERO);
    let hi = a.max(b).max(cc).ceil();
    let x1 = if k.clip_x { hi.x.min(w as f32) } else { hi.x };
    for y in lo.y as u32..hi.y.min(h as f32) as u32 {
        for x in lo.x as u32..x1 as u32 {
            let p = Vec2::new(x as f32 + k.offset, y as f32 + k.offset);
            let edges = [(b, cc), (cc, a), (a, b)];
            let ws = edges.map(|(s, t)| e(s, t, p));
            if !(0..3).all(|i| ws[i] > 0.0 || (ws[i] == 0.0 && (k.on_edge)(edges[i].0, edges[i].1)))
            {
                continue;
            }
            let phi = Vec3::from(ws) / area;
            let zs = Vec3::new(v[0].z, v[1].z, v[2].z);
            let inv = phi / zs;
            let z = if k.affine_depth {
                phi.dot(zs)
            } else {
                1.0 / (inv.x + inv.y + inv.z)
            };
            let wt = if k.affine_colour {
                phi
            } else {
                inv / (inv.x + inv.y + inv.z)
            };
            let colour = c[0] * wt.x + c[1] * wt.y + c[2] * wt.z;
            let i = (y * w + x) as usize;
            if k.guard_index && i >= image.len() {
                continue; // (a guard against the panic, not against the wrap-around)
            }
            if k.colour_before_test {
                image[i] = colour;
            }
            if (k.depth)(z, depth[i]) {
                if k.store_depth {
                    depth[i] = z;
                }
                image[i] = colour;
            }
        }
    }
}

macro_rules! mutant {
    ($(#[$doc:meta])* $name:ident, $($field:ident: $value:expr),*) => {
        $(#[$doc])*
        fn $name(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
            student(v, c, w, h, d, i, Knobs { $($field: $value,)* ..RIGHT })
        }
    };
}

mutant!(
    /// The student's base solution with no knob turned: must pass.
    right,
);
mutant!(
    /// Affine colours: screen-space barycentrics used directly (the old
    /// grader's reference).
    affine, affine_colour: true, affine_depth: true
);
mutant!(
    /// Only the colours affine, the depth right.
    affine_colour_only, affine_colour: true
);
mutant!(
    /// Samples at the pixel's corner (x, y) instead of its centre.
    corner_samples, offset: 0.0
);
mutant!(
    /// Every sample on an edge counted: shared edges drawn twice.
    inclusive_edges, on_edge: |_, _| true
);
mutant!(
    /// No sample on an edge counted: cracks along shared edges.
    exclusive_edges, on_edge: |_, _| false
);
mutant!(
    /// The bottom-right rule: as wrong as none for this contract's y-down raster.
    bottom_right, on_edge: |s, t| !top_left(s, t)
);
mutant!(
    /// Never swaps the corners: clockwise triangles draw nothing.
    one_winding, swap: false
);
mutant!(
    /// Swaps the corners for the winding but not their colours.
    colours_stay, swap_colours: false
);
mutant!(
    /// Depth as Σ φ·z (screen-space), colours perspective-correct.
    affine_depth, affine_depth: true
);
mutant!(
    /// No depth test: the last triangle drawn wins.
    no_depth_test, depth: |_, _| true
);
mutant!(
    /// `<=`: a tie replaces what was drawn first.
    tie_replaces, depth: |z, d| z <= d
);
mutant!(
    /// Compares with the buffer but never stores the new depth.
    depth_not_stored, store_depth: false
);
mutant!(
    /// Writes the colour before the depth test decides.
    colour_first, colour_before_test: true
);
mutant!(
    /// No clip at the right border and no guard either: a pixel past the
    /// image's end is an index out of bounds (the grader reports the panic
    /// with its file and line).
    writes_past_the_end, clip_x: false, guard_index: false
);
mutant!(
    /// The bounding box not clipped at the right border: a column x >= width
    /// lands on the next row.
    wraps_around, clip_x: false
);

/// The top-left rule tested on the edges as given, with the winding fixed
/// by flipping the edge functions' sign instead of swapping corners: for a
/// clockwise triangle the rule then picks the bottom-right edges.
fn rule_before_orienting(
    v: [Vec3; 3],
    c: [Vec3; 3],
    w: u32,
    h: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
) {
    let [a, b, cc] = v.map(|p| p.truncate());
    let area = e(a, b, cc);
    if area == 0.0 || !area.is_finite() || !v.iter().all(|q| q.is_finite()) {
        return;
    }
    let s = area.signum();
    for y in 0..h {
        for x in 0..w {
            let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let edges = [(b, cc), (cc, a), (a, b)];
            let ws = edges.map(|(p0, p1)| s * e(p0, p1, p));
            if !(0..3).all(|i| ws[i] > 0.0 || (ws[i] == 0.0 && top_left(edges[i].0, edges[i].1))) {
                continue;
            }
            let inv = Vec3::from(ws) / area.abs() / Vec3::new(v[0].z, v[1].z, v[2].z);
            let sum = inv.x + inv.y + inv.z;
            let i = (y * w + x) as usize;
            if 1.0 / sum < depth[i] {
                depth[i] = 1.0 / sum;
                image[i] = (c[0] * inv.x + c[1] * inv.y + c[2] * inv.z) / sum;
            }
        }
    }
}

/// Correct, another formulation: no swap at all. The edge functions are
/// multiplied by the sign of the area, and the top-left rule is asked of
/// each edge in the direction that has the inside on its positive side
/// (reversed for a clockwise triangle); every pixel of the image is tested
/// (no bounding box: the work stays within the image all the same); the
/// depth is compared as 1/z (larger is nearer).
fn alternative_signed(
    v: [Vec3; 3],
    c: [Vec3; 3],
    w: u32,
    h: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
) {
    let [a, b, cc] = v.map(|p| p.truncate());
    let area = e(a, b, cc);
    if area == 0.0 || !area.is_finite() || !v.iter().all(|q| q.is_finite()) {
        return;
    }
    let s = area.signum();
    let edges = [(b, cc), (cc, a), (a, b)];
    let rule = edges.map(|(p0, p1)| {
        if s > 0.0 {
            top_left(p0, p1)
        } else {
            top_left(p1, p0)
        }
    });
    for y in 0..h {
        for x in 0..w {
            let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let ws = edges.map(|(p0, p1)| s * e(p0, p1, p));
            if !(0..3).all(|i| ws[i] > 0.0 || (ws[i] == 0.0 && rule[i])) {
                continue;
            }
            // Perspective-correct barycentrics first, then everything with them.
            let q = Vec3::from(ws) / Vec3::new(v[0].z, v[1].z, v[2].z);
            let bary = q / (q.x + q.y + q.z);
            let z = bary.x * v[0].z + bary.y * v[1].z + bary.z * v[2].z;
            let i = (y * w + x) as usize;
            if 1.0 / z > 1.0 / depth[i] {
                depth[i] = z;
                image[i] = c[0] * bary.x + c[1] * bary.y + c[2] * bary.z;
            }
        }
    }
}

/// Correct, another formulation: incremental edge functions (each steps by
/// a constant from one pixel to the next), the bounding box from rounding
/// the corners, in f64.
fn alternative_incremental(
    v: [Vec3; 3],
    c: [Vec3; 3],
    w: u32,
    h: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
) {
    let mut p = v.map(|q| q.as_dvec3());
    let mut c = c;
    let ed = |a: glam::DVec3, b: glam::DVec3, x: f64, y: f64| {
        (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)
    };
    let area = ed(p[0], p[1], p[2].x, p[2].y);
    if area == 0.0 || !area.is_finite() || !p.iter().all(|q| q.is_finite()) {
        return;
    }
    if area < 0.0 {
        p.swap(1, 2);
        c.swap(1, 2);
    }
    let area = area.abs();
    let edges = [(p[1], p[2]), (p[2], p[0]), (p[0], p[1])];
    let x0 = p
        .iter()
        .map(|q| q.x)
        .fold(f64::INFINITY, f64::min)
        .floor()
        .max(0.0) as u32;
    let y0 = p
        .iter()
        .map(|q| q.y)
        .fold(f64::INFINITY, f64::min)
        .floor()
        .max(0.0) as u32;
    let x1 = p
        .iter()
        .map(|q| q.x)
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil()
        .min(w as f64) as u32;
    let y1 = p
        .iter()
        .map(|q| q.y)
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil()
        .min(h as f64) as u32;
    for y in y0..y1 {
        let (px, py) = (x0 as f64 + 0.5, y as f64 + 0.5);
        let mut ws = edges.map(|(a, b)| ed(a, b, px, py));
        let step = edges.map(|(a, b)| -(b.y - a.y));
        for x in x0..x1 {
            let tl = |k: usize| {
                let (a, b) = edges[k];
                b.y < a.y || (b.y == a.y && b.x > a.x)
            };
            if (0..3).all(|k| ws[k] > 0.0 || (ws[k] == 0.0 && tl(k))) {
                let inv: [f64; 3] = std::array::from_fn(|k| ws[k] / area / p[k].z);
                let sum = inv[0] + inv[1] + inv[2];
                let z = (1.0 / sum) as f32;
                let i = (y * w + x) as usize;
                if z < depth[i] {
                    depth[i] = z;
                    let col = (c[0].as_dvec3() * inv[0]
                        + c[1].as_dvec3() * inv[1]
                        + c[2].as_dvec3() * inv[2])
                        / sum;
                    image[i] = col.as_vec3();
                }
            }
            for k in 0..3 {
                ws[k] += step[k];
            }
        }
    }
}

fn expect(check: Check, symptom: Symptom, what: &str) {
    super::fails_naming(check, symptom, &ch2::exercises(), what);
}

#[test]
fn a_rasterizer_writing_past_the_image_panics_in_the_check() {
    let r = catch_unwind(|| ch2::check_rasterize_triangle(writes_past_the_end));
    let message = r.map(|c| c.detail).unwrap_err();
    let message = message
        .downcast_ref::<String>()
        .cloned()
        .unwrap_or_default();
    assert!(message.contains("out of bounds"), "{message}");
}

#[test]
fn raster_mutants_fail_with_their_symptom() {
    let cases: [(ch2::RasterFn, Symptom, &str); 15] = [
        (affine, ch2::DEPTH_VALUE, "affine colour and depth"),
        (affine_colour_only, ch2::AFFINE, "affine colour"),
        (corner_samples, ch2::HALF_PIXEL, "samples at the corners"),
        (inclusive_edges, ch2::TOP_LEFT, "every edge sample"),
        (exclusive_edges, ch2::TOP_LEFT, "no edge sample"),
        (bottom_right, ch2::TOP_LEFT, "bottom-right rule"),
        (
            rule_before_orienting,
            ch2::TOP_LEFT,
            "the rule before orienting",
        ),
        (one_winding, ch2::WINDING, "one winding"),
        (wraps_around, ch2::OFF_IMAGE, "no clip at the right border"),
        (colours_stay, ch2::COLOUR_ORDER, "colours not swapped"),
        (affine_depth, ch2::DEPTH_VALUE, "Σφz depth"),
        (no_depth_test, ch2::DEPTH_TEST, "no depth test"),
        (tie_replaces, ch2::DEPTH_TIE, "<="),
        (depth_not_stored, ch2::DEPTH_TEST, "depth not stored"),
        (colour_first, ch2::DEPTH_TEST, "colour before the test"),
    ];
    for (f, symptom, what) in cases {
        expect(ch2::check_rasterize_triangle(f), symptom, what);
    }
}

fn passes(f: ch2::RasterFn, what: &str) {
    let check = ch2::check_rasterize_triangle(f);
    assert!(check.passed(), "{what}: {}", check.detail);
}

#[test]
fn raster_the_books_recipe_and_the_reference_pass() {
    passes(right, "the book's recipe");
    passes(rasterize_triangle, "the reference");
}

#[test]
fn raster_alternative_signed_passes() {
    passes(
        alternative_signed,
        "signed edge functions, whole image, 1/z compare",
    );
}

#[test]
fn raster_alternative_incremental_passes() {
    passes(alternative_incremental, "incremental edge functions in f64");
}

#[test]
fn the_model_without_mistakes_is_the_reference() {
    let mut tris: Vec<([Vec3; 3], [Vec3; 3])> = ch2::fill_rule_triangles()
        .into_iter()
        .map(|t| (t, [Vec3::X, Vec3::Y, Vec3::Z]))
        .collect();
    tris.push((
        [
            Vec3::new(2.3, 46.1, 1.0),
            Vec3::new(61.7, 45.4, 1.0),
            Vec3::new(39.6, 4.2, 8.0),
        ],
        [Vec3::X, Vec3::Y, Vec3::Z],
    ));
    let (w, h) = (64, 48);
    type Draw<'a> = &'a dyn Fn([Vec3; 3], [Vec3; 3], u32, u32, &mut [f32], &mut [Vec3]);
    let run = |g: Draw| {
        let mut depth = vec![f32::INFINITY; 64 * 48];
        let mut image = vec![Vec3::ZERO; 64 * 48];
        for (t, c) in &tris {
            g(*t, *c, w, h, &mut depth, &mut image);
        }
        (depth, image)
    };
    let m = Model::REFERENCE;
    assert_eq!(
        run(&rasterize_triangle),
        run(&|v, c, w, h, d, i| m.draw(v, c, w, h, d, i))
    );
}

#[test]
fn small_exercise_mutants_name_their_mistake() {
    use raystep::ch2_rasterization::edge;
    // The cross product the other way round.
    let check =
        ch2::check_edge_function(|a, b, p| (p.x - a.x) * (b.y - a.y) - (p.y - a.y) * (b.x - a.x));
    expect(check, ch2::EDGE_SIGN, "flipped edge function");
    // φi from the sub-triangle next to pi instead of opposite it.
    let check = ch2::check_barycentric(|pi, pj, pk, p| {
        let area = e(pi, pj, pk);
        (area != 0.0).then(|| Vec3::new(e(pi, pj, p), e(pj, pk, p), e(pk, pi, p)) / area)
    });
    expect(check, ch2::BARY_ORDER, "φ on the wrong corners");
    // Not divided by the whole triangle's area.
    let check = ch2::check_barycentric(|pi, pj, pk, p| {
        let area = e(pi, pj, pk);
        (area != 0.0).then(|| Vec3::new(e(pj, pk, p), e(pk, pi, p), e(pi, pj, p)))
    });
    expect(check, ch2::BARY_SCALE, "φ not divided by the area");
    // `<=`: a tie passes.
    let check = ch2::check_depth_test(|d, i, z| {
        let pass = z <= d[i];
        if pass {
            d[i] = z;
        }
        pass
    });
    expect(check, ch2::TIE, "<= depth test");
    // Right answers, but the buffer never changes.
    let check = ch2::check_depth_test(|d, i, z| z < d[i]);
    expect(check, ch2::NOT_STORED, "depth not stored");
    // The library's functions pass (they are the references).
    assert!(ch2::check_edge_function(edge::edge_function).passed());
}
