//! The course's solutions (`tests/project/solutions/`) whose bodies the
//! fresh sets' mutants and alternatives copy more than once, each written
//! once with knobs: a small `Copy` struct whose `Default` is the course's
//! solution exactly, one knob per departure a tester made, and the
//! solution taking it. A mutant is then a one-line call with its knobs
//! set by [`Knobs::with`] (as `Knobs` in `ch2.rs` does for the
//! rasterizer). The tests at the
//! end guard the defaults: with no knob turned, each passes its check.

use std::f32::consts::PI;

use glam::{Mat4, Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::ch6_global_illumination::layers::{
    LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND, SLOT_EMITTED,
};
use raystep::grading::counted::{intersect_watertight, Hit, NodeKind, ReadableBvh};
use raystep::grading::exercises::bounce_layers::{check_bounce_layers, Gathered, How};
use raystep::grading::exercises::paths::{self, PathScene};
use raystep::grading::exercises::{ch1, ch2, ch3, ch4, ch5};

use super::{passes_every, SEEDS};

/// A set of knobs: the course's solution by default, some knobs turned by
/// [`Knobs::with`] in one line, where a struct literal would take six.
pub trait Knobs: Default {
    /// The defaults with the knobs `turn` sets.
    fn with(turn: impl FnOnce(&mut Self)) -> Self {
        let mut k = Self::default();
        turn(&mut k);
        k
    }
}

impl Knobs for LookKnobs {}
impl Knobs for EdgeKnobs {}
impl Knobs for RasterKnobs {}
impl Knobs for InsideKnobs {}
impl Knobs for MollerKnobs {}
impl Knobs for BvhKnobs {}
impl Knobs for SahKnobs {}
impl Knobs for MarchKnobs {}
impl Knobs for SceneKnobs {}
impl Knobs for DirectKnobs {}
impl Knobs for PathKnobs {}
impl Knobs for LayersKnobs {}

// ---- 1.2 look_at ----------------------------------------------------------------

/// How a camera departs from the solution of look_at.
#[derive(Clone, Copy, Default)]
pub struct LookKnobs {
    /// `up` swapped for a world axis within 8° of the view.
    pub axis_near_parallel: bool,
    /// z normalised as v / (|v| + this).
    pub soft_normalise: Option<f32>,
    /// `up` itself (normalised) as y, and up × z as x, where |up · z| is
    /// under this.
    pub up_as_y_within: Option<f32>,
    /// x = the world's X where |up × z| is under this (a guard against a
    /// degenerate up that also takes a short one for it).
    pub side_floor: Option<f32>,
}

/// The solution of look_at, departing as `k` says.
pub fn look_at(k: LookKnobs, eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    let v = eye - target;
    let z = k
        .soft_normalise
        .map_or(v.normalize(), |e| v / (v.length() + e));
    let mut up = up;
    if k.axis_near_parallel && up.normalize().dot(z).abs() > 0.99 {
        up = if z.y.abs() < 0.9 { Vec3::Y } else { Vec3::X };
    }
    let u = up.normalize();
    let (x, y) = match k.up_as_y_within {
        Some(w) if u.dot(z).abs() < w => (u.cross(z), u),
        _ => {
            let side = up.cross(z);
            let x = match k.side_floor {
                Some(floor) if side.length() < floor => Vec3::X,
                _ => side.normalize(),
            };
            (x, z.cross(x))
        }
    };
    let rotation = Mat4::from_cols(
        x.extend(0.0),
        y.extend(0.0),
        z.extend(0.0),
        Vec3::ZERO.extend(1.0),
    )
    .transpose();
    rotation * Mat4::from_translation(-eye)
}

// ---- 1.3 draw_edges -------------------------------------------------------------

/// How the point where an edge meets the near plane is found, given the
/// ends and the first end's share s of the way.
#[derive(Clone, Copy, Default)]
pub enum Cut {
    /// from + (to - from) s, as the solution.
    #[default]
    Linear,
    /// glam's `lerp`, (1 - s) from + s to.
    Lerp,
}

/// How a clip departs from the solution of draw_edges.
#[derive(Clone, Copy, Default)]
pub struct EdgeKnobs {
    /// An edge of no length (a == b) drawn as nothing.
    pub zero_length_none: bool,
    /// How far past the near plane an end must be to count as behind it.
    pub behind: f32,
    /// How the cut is found.
    pub cut: Cut,
    /// An end nearer the pinhole than this, after the clip, gives None.
    pub min_depth: Option<f32>,
    /// The end behind kept as it is where the cut lies less than this
    /// share of the edge from it.
    pub keep_end_within: Option<f32>,
    /// The cut's share of the edge, from the end behind, capped at this.
    pub cut_at_most: Option<f32>,
    /// The cut's z interpolated like x and y, not set to -near.
    pub unsnapped_z: bool,
    /// The cut at the edge's middle where the ends' distances past the
    /// plane differ by less than this (an edge "parallel" to it).
    pub parallel_below: Option<f32>,
}

/// The solution of draw_edges, departing as `k` says.
pub fn draw_edges(
    k: EdgeKnobs,
    camera: &Camera,
    a: Vec3,
    b: Vec3,
    near: f32,
) -> Option<(Vec2, Vec2)> {
    if k.zero_length_none && a == b {
        return None;
    }
    let (a, b) = (camera.to_camera(a), camera.to_camera(b));
    let (da, db) = (a.z + near, b.z + near);
    let on_plane = |from: Vec3, to: Vec3, d_from: f32, d_to: f32| {
        let s = d_from / (d_from - d_to);
        let parallel = k.parallel_below.is_some_and(|g| (d_from - d_to).abs() < g);
        let s = if parallel { 0.5 } else { s };
        let s = k.cut_at_most.map_or(s, |most| s.min(most));
        let p = match k.cut {
            Cut::Linear => from + (to - from) * s,
            Cut::Lerp => from.lerp(to, s),
        };
        Vec3::new(p.x, p.y, if k.unsnapped_z { p.z } else { -near })
    };
    // The end behind, where the cut is within `keep_end_within` of it.
    let kept = |end: Vec3, d_end: f32, d_other: f32| {
        k.keep_end_within
            .filter(|&w| d_end / (d_end - d_other) < w)
            .map(|_| end)
    };
    let (a, b) = match (da > k.behind, db > k.behind) {
        (true, true) => return None,
        (true, false) => (kept(a, da, db).unwrap_or_else(|| on_plane(a, b, da, db)), b),
        (false, true) => (a, kept(b, db, da).unwrap_or_else(|| on_plane(a, b, da, db))),
        (false, false) => (a, b),
    };
    if k.min_depth.is_some_and(|d| -a.z < d || -b.z < d) {
        return None;
    }
    let raster = |p: Vec3| camera.raster_from_image_plane(Vec2::new(p.x / -p.z, p.y / -p.z));
    Some((raster(a), raster(b)))
}

// ---- 2.4 rasterize_triangle -----------------------------------------------------

fn edge(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)
}

fn top_left(a: Vec2, b: Vec2) -> bool {
    b.y < a.y || (b.y == a.y && b.x > a.x)
}

/// How the perspective-correct weights φ/z are formed from the edge
/// functions e, the corners' z and the doubled area.
#[derive(Clone, Copy, Default)]
pub enum Weights {
    /// Each edge function over its z, then over the area, as the solution.
    #[default]
    OverZFirst,
    /// The barycentric weights e / area first, each then over its z.
    BaryFirst,
    /// Affine (e / area over the corners' mean z) where the corners'
    /// depths are within 1 % of each other.
    AffineWhenFlat,
}

/// How a rasterizer departs from the solution of rasterize_triangle.
#[derive(Clone, Copy, Default)]
pub struct RasterKnobs {
    /// A triangle whose doubled area is under this draws nothing (the
    /// solution refuses only an area of 0).
    pub min_area: f32,
    /// A row stops at the first sample outside after a run inside.
    pub row_break: bool,
    /// How the weights are formed.
    pub weights: Weights,
    /// A sample nearer than this is not drawn.
    pub near: Option<f32>,
    /// The depth stored clamped to this.
    pub depth_clamp: Option<f32>,
    /// A sample counts as inside an edge that is neither top nor left
    /// only where its edge function exceeds this (the solution: 0).
    pub edge_slack: f32,
    /// The edge function as the shoelace sum of absolute coordinates'
    /// products, a × b + b × p + p × a.
    pub shoelace: bool,
    /// The (doubled) area the weights are divided by raised to at least
    /// this (the solution: 0).
    pub area_floor: f32,
    /// An edge function within this share of the (doubled) area taken as
    /// exactly on the edge, where the top-left rule decides (the
    /// solution: 0).
    pub relative_slack: f32,
    /// The edge functions computed at a row's first sample only, and
    /// stepped from there to each next sample by adding their change per
    /// pixel (the solution computes them at every sample).
    pub stepped: bool,
    /// The edge functions at the first column carried down from row to
    /// row by adding their change per row, and each sample's taken from
    /// its row's start plus the change per pixel times the columns
    /// between.
    pub carried_down: bool,
    /// The top-left rule decided on the corners' whole pixels (their
    /// coordinates truncated), where a nearly flat edge is flat (the
    /// twenty-eighth set).
    pub whole_pixel_rule: bool,
}

/// The solution of rasterize_triangle (corners not finite refused),
/// departing as `k` says.
pub fn rasterize(
    k: RasterKnobs,
    v: [Vec3; 3],
    colors: [Vec3; 3],
    (width, height): (u32, u32),
    depth: &mut [f32],
    image: &mut [Vec3],
) {
    let [p0, mut p1, mut p2] = v;
    let [c0, mut c1, mut c2] = colors;
    let area = edge(p0.truncate(), p1.truncate(), p2.truncate());
    if area == 0.0
        || area.abs() < k.min_area
        || !area.is_finite()
        || !v.iter().all(|p| p.is_finite())
    {
        return;
    }
    if area < 0.0 {
        std::mem::swap(&mut p1, &mut p2);
        std::mem::swap(&mut c1, &mut c2);
    }
    let area = area.abs().max(k.area_floor);
    let (a, b, c) = (p0.truncate(), p1.truncate(), p2.truncate());
    let min = a.min(b).min(c).max(Vec2::ZERO);
    let max = a.max(b).max(c).min(Vec2::new(width as f32, height as f32));
    let edges = [(b, c), (c, a), (a, b)];
    let corner = Vec2::new(min.x.floor() + 0.5, min.y.floor() + 0.5);
    let mut column = edges.map(|(s, t)| edge(s, t, corner));
    for y in min.y.floor() as u32..max.y.ceil() as u32 {
        let mut inside_run = false;
        let first = Vec2::new(min.x.floor() + 0.5, y as f32 + 0.5);
        let mut stepped = edges.map(|(s, t)| edge(s, t, first));
        let row_start = column;
        for (j, (s, t)) in edges.into_iter().enumerate() {
            column[j] += t.x - s.x;
        }
        for x in min.x.floor() as u32..max.x.ceil() as u32 {
            let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let e = |s: Vec2, t: Vec2| match k.shoelace {
                true => s.perp_dot(t) + t.perp_dot(p) + p.perp_dot(s),
                false => edge(s, t, p),
            };
            let whole = |q: Vec2| q.trunc();
            let rule = |s: Vec2, t: Vec2| match k.whole_pixel_rule {
                true => top_left(whole(s), whole(t)),
                false => top_left(s, t),
            };
            let mut w = edges.map(|(s, t)| (e(s, t), rule(s, t)));
            if k.stepped {
                for (j, (s, t)) in edges.into_iter().enumerate() {
                    w[j].0 = stepped[j];
                    stepped[j] += s.y - t.y;
                }
            }
            if k.carried_down {
                let dx = x as f32 - min.x.floor();
                for (j, (s, t)) in edges.into_iter().enumerate() {
                    w[j].0 = row_start[j] + (s.y - t.y) * dx;
                }
            }
            let inside = |&(e, tl): &(f32, bool)| {
                let on = e.abs() <= k.relative_slack * area;
                match tl {
                    true => e >= 0.0 || on,
                    false => e > k.edge_slack && !on,
                }
            };
            if !w.iter().all(inside) {
                if k.row_break && inside_run {
                    break;
                }
                continue;
            }
            inside_run = true;
            let (e, z) = (
                Vec3::new(w[0].0, w[1].0, w[2].0),
                Vec3::new(p0.z, p1.z, p2.z),
            );
            let q = match k.weights {
                Weights::OverZFirst => Vec3::new(e.x / z.x, e.y / z.y, e.z / z.z) / area,
                Weights::BaryFirst => e / area / z,
                Weights::AffineWhenFlat if z.max_element() <= 1.01 * z.min_element() => {
                    e / (area * (z.element_sum() / 3.0))
                }
                Weights::AffineWhenFlat => Vec3::new(e.x / z.x, e.y / z.y, e.z / z.z) / area,
            };
            let z = 1.0 / (q.x + q.y + q.z);
            let i = (y * width + x) as usize;
            if k.near.is_none_or(|near| z >= near) && z < depth[i] {
                depth[i] = k.depth_clamp.map_or(z, |most| z.min(most));
                image[i] = (c0 * q.x + c1 * q.y + c2 * q.z) * z;
            }
        }
    }
}

// ---- 3.2 barycentric_inside -----------------------------------------------------

/// How an inside test departs from the solution of barycentric_inside.
#[derive(Clone, Copy, Default)]
pub struct InsideKnobs {
    /// u and v tested by their sign bits (a -0 outside).
    pub sign_bits: bool,
    /// The cross products from absolute positions, p × e2 − p0 × e2.
    pub absolute: bool,
    /// A corner's (u, v) returned before the test for no area.
    pub corners_first: bool,
    /// u and v taken as inside down to −slack, u + v up to 1 + slack
    /// (the twenty-fourth set).
    pub slack: f32,
}

/// The solution of barycentric_inside, departing as `k` says.
pub fn inside(k: InsideKnobs, p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    if k.corners_first {
        let corner = (0..3).find(|&c| p == tri[c]);
        if let Some(c) = corner {
            return Some([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)][c]);
        }
    }
    let (e1, e2, q) = (tri[1] - tri[0], tri[2] - tri[0], p - tri[0]);
    let n = e1.cross(e2);
    let nn = n.dot(n);
    if nn == 0.0 {
        return None;
    }
    let (u, v) = match k.absolute {
        true => (
            n.dot(p.cross(e2) - tri[0].cross(e2)) / nn,
            n.dot(e1.cross(p) - e1.cross(tri[0])) / nn,
        ),
        false => (n.dot(q.cross(e2)) / nn, n.dot(e1.cross(q)) / nn),
    };
    let inside = match k.sign_bits {
        true => u.is_sign_positive() && v.is_sign_positive(),
        false => u >= -k.slack && v >= -k.slack,
    };
    (inside && u + v <= 1.0 + k.slack).then_some((u, v))
}

// ---- 3.3 moller_trumbore --------------------------------------------------------

/// When the determinant counts as zero.
#[derive(Clone, Copy, Default)]
pub enum Singular {
    /// Exactly 0, as the solution.
    #[default]
    Zero,
    /// Under this fraction of |e1| |e2| |d|.
    Relative(f32),
}

/// How a ray-triangle test departs from the solution of moller_trumbore.
#[derive(Clone, Copy, Default)]
pub struct MollerKnobs {
    /// When the determinant counts as zero.
    pub singular: Singular,
    /// Strict comparisons on u, v and u + v: the edges are outside.
    pub strict_edges: bool,
    /// t = 0 accepted.
    pub t_zero: bool,
    /// A hit farther than this along the ray refused.
    pub far: Option<f32>,
    /// t recomputed as the hit point's projection on d, over |d|².
    pub t_projected: bool,
    /// A hit at t up to this refused (the solution: 0).
    pub t_floor: f32,
    /// u and v tested by their sign bit (a -0 outside).
    pub sign_bits: bool,
}

/// The solution of moller_trumbore, departing as `k` says.
pub fn moller(k: MollerKnobs, o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let det3 = |a: Vec3, b: Vec3, c: Vec3| a.dot(b.cross(c));
    let (e1, e2, s) = (tri[1] - tri[0], tri[2] - tri[0], o - tri[0]);
    let det = det3(e1, e2, -d);
    let singular = match k.singular {
        Singular::Zero => det == 0.0,
        Singular::Relative(eps) => det.abs() < eps * e1.length() * e2.length() * d.length(),
    };
    if singular {
        return None;
    }
    let u = det3(s, e2, -d) / det;
    let v = det3(e1, s, -d) / det;
    let t = det3(e1, e2, s) / det;
    let outside = if k.sign_bits {
        u.is_sign_negative() || v.is_sign_negative() || u + v > 1.0
    } else if k.strict_edges {
        u <= 0.0 || v <= 0.0 || u + v >= 1.0
    } else {
        u < 0.0 || v < 0.0 || u + v > 1.0
    };
    let behind = if k.t_zero { t < 0.0 } else { t <= k.t_floor };
    if outside || behind || k.far.is_some_and(|far| t > far) {
        return None;
    }
    if k.t_projected {
        let p = tri[0] + (tri[1] - tri[0]) * u + (tri[2] - tri[0]) * v;
        return Some(((p - o).dot(d) / d.dot(d), u, v));
    }
    Some((t, u, v))
}

// ---- 3.4 bvh_traversal ----------------------------------------------------------

/// The t a leaf's triangles are tested from.
#[derive(Clone, Copy)]
pub enum TMin {
    /// This t (the solution: 0).
    Fixed(f32),
    /// The t at which the ray enters the leaf's box.
    BoxEntry,
}

/// How a traversal departs from the solution of bvh_traversal.
#[derive(Clone, Copy)]
pub struct BvhKnobs {
    /// The t a leaf's triangles are tested from.
    pub t_min: TMin,
    /// A later hit kept only where it is nearer than the best by more
    /// than this (the solution: any nearer one, 0).
    pub improve_by: f32,
    /// Only this many of a leaf's triangles tested.
    pub leaf_cap: Option<u32>,
    /// A direction's zero components made f32::EPSILON before 1/d.
    pub nudge_zero_dir: bool,
    /// 1/d from the bit trick and one Newton step (about 2.6·10⁻³ off).
    pub approx_recip: bool,
    /// Leaves opened at most, the rest passed by.
    pub leaf_budget: Option<u32>,
    /// A subtree passed by where the ray enters it at the best t so far,
    /// not only beyond it.
    pub prune_at_equal: bool,
    /// t_max asked of the root's box alone; below it, the search runs to
    /// infinity.
    pub t_max_at_root_only: bool,
}

impl Default for BvhKnobs {
    fn default() -> Self {
        BvhKnobs {
            t_min: TMin::Fixed(0.0),
            improve_by: 0.0,
            leaf_cap: None,
            nudge_zero_dir: false,
            approx_recip: false,
            leaf_budget: None,
            prune_at_equal: false,
            t_max_at_root_only: false,
        }
    }
}

/// The solution of bvh_traversal (recursive, the nearer child first),
/// departing as `k` says.
pub fn closest_hit(k: BvhKnobs, bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    fn visit(
        k: BvhKnobs,
        (bvh, ray, inv): (&ReadableBvh, &Ray, Vec3),
        node: u32,
        t_enter: f32,
        best: &mut (f32, Option<Hit>, u32),
    ) {
        if t_enter > best.0 || (k.prune_at_equal && t_enter == best.0) {
            return;
        }
        match bvh.nodes[node as usize].kind {
            NodeKind::Leaf { first, count } => {
                best.2 += 1;
                if k.leaf_budget.is_some_and(|most| best.2 > most) {
                    return;
                }
                let t_min = match k.t_min {
                    TMin::Fixed(t) => t,
                    TMin::BoxEntry => t_enter,
                };
                let count = k.leaf_cap.map_or(count, |cap| count.min(cap));
                for &id in &bvh.order[first as usize..(first + count) as usize] {
                    let kept = |hit: &Hit| {
                        k.improve_by == 0.0 || best.1.is_none() || hit.t < best.0 - k.improve_by
                    };
                    if let Some(hit) =
                        intersect_watertight(ray, bvh.tris[id as usize], t_min, best.0).filter(kept)
                    {
                        (best.0, best.1) = (
                            hit.t,
                            Some(Hit {
                                triangle: id,
                                ..hit
                            }),
                        );
                    }
                }
            }
            NodeKind::Inner { left, right } => {
                let tl = bvh.nodes[left as usize].bounds.enter(ray, inv, best.0);
                let tr = bvh.nodes[right as usize].bounds.enter(ray, inv, best.0);
                let mut kids = [(left, tl), (right, tr)];
                if tr.unwrap_or(f32::INFINITY) < tl.unwrap_or(f32::INFINITY) {
                    kids.swap(0, 1);
                }
                for (child, t) in kids {
                    if let Some(t) = t {
                        visit(k, (bvh, ray, inv), child, t, best);
                    }
                }
            }
        }
    }
    let dir = match k.nudge_zero_dir {
        true => Vec3::select(
            ray.dir.cmpeq(Vec3::ZERO),
            Vec3::splat(f32::EPSILON),
            ray.dir,
        ),
        false => ray.dir,
    };
    let approx = |x: f32| {
        let r = f32::from_bits(0x7EF3_11C7u32.wrapping_sub(x.abs().to_bits()));
        (r * (2.0 - x.abs() * r)).copysign(x)
    };
    let inv = match k.approx_recip {
        true => Vec3::new(approx(dir.x), approx(dir.y), approx(dir.z)),
        false => dir.recip(),
    };
    let t_root = bvh.nodes.first()?.bounds.enter(ray, inv, t_max)?;
    let limit = match k.t_max_at_root_only {
        true => f32::INFINITY,
        false => t_max,
    };
    let mut best = (limit, None, 0);
    visit(k, (bvh, ray, inv), 0, t_root, &mut best);
    best.1
}

// ---- 3.5 sah --------------------------------------------------------------------

/// The box's measure the costs are taken in.
#[derive(Clone, Copy, Default)]
pub enum Measure {
    /// Its surface area, as the solution.
    #[default]
    Surface,
    /// The half-perimeter dx + dy + dz.
    HalfPerimeter,
    /// The surface area as (dx + dy + dz)² − (dx² + dy² + dz²) in f32,
    /// which cancels for a needle.
    SquareIdentity,
    /// 2 d · (dy, dx, dz): the right area, up to a factor, where dz = 0 or
    /// the box is a cube (twenty-ninth set).
    Swizzled,
    /// The volume dx · dy · dz, which a box of no thickness has none of
    /// (thirty-seventh set).
    Volume,
}

/// The axes the sweep tries.
#[derive(Clone, Copy, Default)]
pub enum Axes {
    /// All three, as the solution.
    #[default]
    All,
    /// Only the one along which the centroids spread furthest.
    Longest,
}

/// Where the plane between two neighbouring centroids a < b goes.
#[derive(Clone, Copy, Default)]
pub enum Plane {
    /// At the upper centroid b, as the solution.
    #[default]
    Upper,
    /// Midway, at b where the midpoint rounds down to a.
    MidwaySafe,
    /// Midway, however it rounds.
    Midway,
}

/// How a sweep departs from the solution of sah.
#[derive(Clone, Copy)]
pub struct SahKnobs {
    /// The traversal's cost added to a split's (the solution: 1).
    pub trav_cost: f64,
    /// The box's measure.
    pub measure: Measure,
    /// The axes swept.
    pub axes: Axes,
    /// Where the plane goes.
    pub plane: Plane,
}

impl Default for SahKnobs {
    fn default() -> Self {
        SahKnobs {
            trav_cost: 1.0,
            measure: Measure::Surface,
            axes: Axes::All,
            plane: Plane::Upper,
        }
    }
}

/// The solution's surface area of the box lo..hi.
pub fn surface_area(lo: Vec3, hi: Vec3) -> f64 {
    let d = (hi - lo).max(Vec3::ZERO).as_dvec3();
    2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
}

/// The box around `boxes`.
pub fn bounds(boxes: &[[Vec3; 2]]) -> (Vec3, Vec3) {
    boxes
        .iter()
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(l, h), b| {
            (l.min(b[0]), h.max(b[1]))
        })
}

/// The solution of sah (a full sweep of the centroids sorted on each
/// axis, the leaf's cost the price to beat), departing as `k` says.
pub fn sah_sweep(k: SahKnobs, boxes: &[[Vec3; 2]], centroids: &[Vec3]) -> Option<(usize, f32)> {
    let area = |lo: Vec3, hi: Vec3| match k.measure {
        Measure::Surface => surface_area(lo, hi),
        Measure::HalfPerimeter => {
            let d = (hi - lo).max(Vec3::ZERO).as_dvec3();
            d.x + d.y + d.z
        }
        Measure::SquareIdentity => {
            let d = (hi - lo).max(Vec3::ZERO);
            let s = d.x + d.y + d.z;
            (s * s - d.length_squared()) as f64
        }
        Measure::Swizzled => {
            let d = (hi - lo).max(Vec3::ZERO).as_dvec3();
            2.0 * d.dot(glam::DVec3::new(d.y, d.x, d.z))
        }
        Measure::Volume => {
            let d = (hi - lo).max(Vec3::ZERO).as_dvec3();
            d.x * d.y * d.z
        }
    };
    let axes = match k.axes {
        Axes::All => 0..3,
        Axes::Longest => {
            let (cl, ch) = centroids
                .iter()
                .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(l, h), c| {
                    (l.min(*c), h.max(*c))
                });
            let ext = ch - cl;
            let long = if ext.x >= ext.y && ext.x >= ext.z {
                0
            } else if ext.y >= ext.z {
                1
            } else {
                2
            };
            long..long + 1
        }
    };
    let n = boxes.len();
    let (lo, hi) = bounds(boxes);
    let whole = area(lo, hi);
    let (mut best, mut split) = (n as f64, None);
    for axis in axes {
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| centroids[a][axis].total_cmp(&centroids[b][axis]));
        let mut right = vec![0.0; n + 1];
        let (mut rl, mut rh) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
        for i in (0..n).rev() {
            (rl, rh) = (rl.min(boxes[order[i]][0]), rh.max(boxes[order[i]][1]));
            right[i] = area(rl, rh);
        }
        let (mut ll, mut lh) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
        for i in 1..n {
            (ll, lh) = (
                ll.min(boxes[order[i - 1]][0]),
                lh.max(boxes[order[i - 1]][1]),
            );
            let (a, b) = (centroids[order[i - 1]][axis], centroids[order[i]][axis]);
            if a == b {
                continue;
            }
            let cost = k.trav_cost + (area(ll, lh) * i as f64 + right[i] * (n - i) as f64) / whole;
            if cost < best {
                let at = match k.plane {
                    Plane::Upper => b,
                    Plane::MidwaySafe => {
                        let m = 0.5 * (a + b);
                        if a < m {
                            m
                        } else {
                            b
                        }
                    }
                    Plane::Midway => 0.5 * (a + b),
                };
                (best, split) = (cost, Some((axis, at)));
            }
        }
    }
    split
}

// ---- 4.2 sphere_trace -----------------------------------------------------------

/// How a march departs from the solution of sphere_trace.
#[derive(Clone, Copy, Default)]
pub struct MarchKnobs {
    /// f < ε for |f| < ε: a point inside the surface is a hit.
    pub signed_hit: bool,
    /// t summed in f64, each step's point from t rounded to f32.
    pub t_f64: bool,
    /// The evaluation at t = 0 not tested for a hit (the first step is
    /// taken whatever it says).
    pub first_untested: bool,
    /// Gives up where |o + t d|, not t, is past max_distance.
    pub max_from_origin: bool,
    /// Unrolled by two: an odd budget loses its last evaluation.
    pub unrolled: bool,
    /// ε raised to at least this many f32 ε times t (the twenty-third set).
    pub eps_ulps_of_t: Option<f32>,
    /// A step that leaves t where it is taken as a hit (the twenty-third
    /// set).
    pub stall_hit: bool,
    /// Gives up at t = max_distance, not only beyond it (the
    /// twenty-fourth set).
    pub stop_at_max: bool,
    /// Gives up where p − o's largest |coordinate|, not t, is past
    /// max_distance (twenty-ninth set).
    pub travel_by_largest: bool,
    /// At the budget's last evaluation, tests the distance before the hit
    /// (thirtieth set: a loop whose last evaluation is tested after it).
    pub last_distance_first: bool,
    /// The point advanced by p += d·dir, not formed as o + t·d (the
    /// thirty-second set).
    pub advanced_point: bool,
}

/// The solution of sphere_trace, departing as `k` says.
pub fn sphere_trace(
    k: MarchKnobs,
    sdf: &dyn Fn(Vec3) -> f32,
    (origin, dir): (Vec3, Vec3),
    epsilon: f32,
    max_steps: u32,
    max_distance: f32,
) -> Option<f32> {
    // t holds an f32's value unless k.t_f64: each step is then the
    // solution's f32 sum.
    let mut t = 0.0f64;
    let steps = if k.unrolled {
        max_steps / 2 * 2
    } else {
        max_steps
    };
    let mut p = origin;
    for step in 0..steps {
        let tf = t as f32;
        let d = sdf(if k.advanced_point {
            p
        } else {
            origin + tf * dir
        });
        p += d * dir;
        let tested = !(k.first_untested && step == 0);
        if k.last_distance_first && step + 1 == steps && tf > max_distance {
            return None;
        }
        let eps = k
            .eps_ulps_of_t
            .map_or(epsilon, |n| epsilon.max(n * f32::EPSILON * tf));
        if tested && (if k.signed_hit { d } else { d.abs() }) < eps {
            return Some(tf);
        }
        let gone = match (k.max_from_origin, k.travel_by_largest) {
            (true, _) => (origin + tf * dir).length(),
            (_, true) => (tf * dir).abs().max_element(),
            _ => tf,
        };
        if gone > max_distance || (k.stop_at_max && gone == max_distance) {
            return None;
        }
        if k.stall_hit && tf + d == tf {
            return Some(tf);
        }
        t = if k.t_f64 {
            t + d as f64
        } else {
            (tf + d) as f64
        };
    }
    None
}

// ---- 4.4 trace_scene ------------------------------------------------------------

/// The tolerance that ends the march.
#[derive(Clone, Copy, Default)]
pub enum MarchEps {
    /// ε at the point, as the solution.
    #[default]
    AtPoint,
    /// ε at the point before the step.
    AtPointBefore,
    /// ε with |p| for p's largest coordinate.
    ByLength,
    /// ε with p's largest coordinate, not its largest |coordinate|
    /// (fourteenth set).
    SignedLargest,
    /// ε at the point, but never below 10⁻⁵ (twenty-eighth set).
    Floored,
}

/// Where the normal's difference step is taken.
#[derive(Clone, Copy, Default)]
pub enum NormalStep {
    /// ε at the hit, as the solution.
    #[default]
    AtHit,
    /// ε at the ray's origin.
    AtOrigin,
    /// The march's fixed ε.
    Fixed,
}

/// How a tracer departs from the solution of trace_scene.
#[derive(Clone, Copy)]
pub struct SceneKnobs {
    /// The tolerance that ends the march.
    pub eps: MarchEps,
    /// Where the normal's step is taken.
    pub h: NormalStep,
    /// The floor under the normal's step (the solution: 1e-4).
    pub h_floor: Option<f32>,
    /// A ceiling over it (the solution: none).
    pub h_cap: Option<f32>,
    /// The normal where the gradient vanishes is d, not -d.
    pub fallback_along: bool,
    /// The normal turned round only where n · d exceeds this (the
    /// solution: 0).
    pub flip_above: f32,
    /// -dir also where the gradient is shorter than this (the solution:
    /// only where it is zero).
    pub fallback_below: Option<f32>,
    /// Unrolled by two: an odd budget loses its last evaluation.
    pub unrolled: bool,
    /// The normal's differences taken forwards from the hit, f(p + h) - f(p).
    pub forward: bool,
    /// -dir where the gradient's largest component is 0, not where the
    /// gradient is zero (twenty-ninth set).
    pub zero_by_max_element: bool,
}

impl Default for SceneKnobs {
    fn default() -> Self {
        SceneKnobs {
            eps: MarchEps::AtPoint,
            h: NormalStep::AtHit,
            h_floor: Some(1e-4),
            h_cap: None,
            fallback_along: false,
            flip_above: 0.0,
            fallback_below: None,
            unrolled: false,
            forward: false,
            zero_by_max_element: false,
        }
    }
}

/// The solution of trace_scene, departing as `k` says.
pub fn trace_scene(
    k: SceneKnobs,
    sdf: &dyn Fn(Vec3) -> f32,
    origin: Vec3,
    dir: Vec3,
    march: &March,
) -> Option<(f32, Vec3)> {
    let (mut t, mut f, mut evaluations) = (0.0f32, sdf(origin), 1);
    let mut before = origin;
    let p = loop {
        let p = origin + t * dir;
        let eps = match k.eps {
            MarchEps::AtPoint => march.epsilon_at(p),
            MarchEps::AtPointBefore => march.epsilon_at(before),
            MarchEps::ByLength => march.epsilon.max(8.0 * f32::EPSILON * p.length()),
            MarchEps::SignedLargest => march.epsilon.max(8.0 * f32::EPSILON * p.max_element()),
            MarchEps::Floored => march.epsilon_at(p).max(1e-5),
        };
        if f.abs() < eps {
            break p;
        }
        let budget = match k.unrolled {
            true => march.max_steps / 2 * 2,
            false => march.max_steps,
        };
        if t > march.max_distance || evaluations >= budget {
            return None;
        }
        t += f;
        f = sdf(origin + t * dir);
        evaluations += 1;
        before = p;
    };
    let h = match k.h {
        NormalStep::AtHit => march.epsilon_at(p),
        NormalStep::AtOrigin => march.epsilon_at(origin),
        NormalStep::Fixed => march.epsilon,
    };
    let h = k.h_floor.map_or(h, |floor| h.max(floor));
    let h = k.h_cap.map_or(h, |cap| h.min(cap));
    let partial = |axis: Vec3| match k.forward {
        true => (sdf(p + axis * h) - f) / h,
        false => (sdf(p + axis * h) - sdf(p - axis * h)) / (2.0 * h),
    };
    let gradient = Vec3::new(partial(Vec3::X), partial(Vec3::Y), partial(Vec3::Z));
    let short = k.fallback_below.is_some_and(|l| gradient.length() < l)
        || (k.zero_by_max_element && gradient.max_element() == 0.0);
    let n = gradient
        .try_normalize()
        .filter(|_| !short)
        .unwrap_or(if k.fallback_along { dir } else { -dir });
    Some((t, if n.dot(dir) > k.flip_above { -n } else { n }))
}

// ---- 5.5 direct_light -----------------------------------------------------------

/// How a light sample's estimate departs from the solution of
/// direct_light.
#[derive(Clone, Copy, Default)]
pub struct DirectKnobs {
    /// "Below the plane" from the plane's equation in absolute
    /// coordinates, n · y ≤ n · p, in place of the test on cos θ.
    pub plane_equation: bool,
    /// An estimate under this in every channel is 0, without asking
    /// `visible`.
    pub cull_below: Option<f32>,
    /// The estimate clamped to this per channel.
    pub clamp: Option<f32>,
    /// Added to cos θl in the pdf "against division by 0".
    pub cos_light_plus: f32,
    /// The estimate from unnormalised cosines over d⁴ in f32 (which
    /// leaves f32's range at scales of 10¹⁰ and 10⁻¹⁰).
    pub over_d4: bool,
    /// The pdf per steradian raised to at least this "to keep the
    /// estimate finite".
    pub pdf_floor: Option<f32>,
}

/// The solution of direct_light, departing as `k` says (the surface
/// point, then the light point, as the exercise's arguments).
pub fn direct(
    k: DirectKnobs,
    (p, n, rho): (Vec3, Vec3, Vec3),
    (y, n_light, area, le): (Vec3, Vec3, f32, Vec3),
    visible: &dyn Fn(Vec3, Vec3) -> bool,
) -> Vec3 {
    if k.plane_equation && n.dot(y) <= n.dot(p) {
        return Vec3::ZERO;
    }
    let to = y - p;
    let d2 = to.length_squared();
    let wi = to / d2.sqrt();
    let cos = n.dot(wi);
    let cos_light = n_light.dot(-wi);
    if (!k.plane_equation && cos <= 0.0) || cos_light <= 0.0 {
        return Vec3::ZERO;
    }
    let f = rho / PI;
    let pdf = d2 / ((cos_light + k.cos_light_plus) * area);
    let pdf = k.pdf_floor.map_or(pdf, |floor| pdf.max(floor));
    let estimate = match k.over_d4 {
        true => f * le * n.dot(to) * -n_light.dot(to) / (d2 * d2) * area,
        false => f * le * cos / pdf,
    };
    if k.cull_below.is_some_and(|c| estimate.max_element() < c) || !visible(p, y) {
        return Vec3::ZERO;
    }
    k.clamp
        .map_or(estimate, |most| estimate.min(Vec3::splat(most)))
}

// ---- 6.6 bounce_layers ----------------------------------------------------------

/// How a path's layers depart from the solution of bounce_layers.
#[derive(Clone, Copy, Default)]
pub struct LayersKnobs {
    /// Contributions whose MIS weight is under this skipped.
    pub skip_weight_below: Option<f32>,
}

/// The solution of bounce_layers, departing as `k` says.
pub fn layers(k: LayersKnobs, path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
    let mut slots = [Vec3::ZERO; LAYER_SLOTS];
    for g in path {
        let k_bounce = match g.how {
            How::Found if g.vertex == 0 => None,
            How::Found => Some(g.vertex - 1),
            How::LightSample => Some(g.vertex),
        };
        let slot = match k_bounce {
            None => SLOT_EMITTED,
            Some(b) if b <= LAYERS_SHOWN => b as usize + 1,
            Some(_) => SLOT_BEYOND,
        };
        let c = g.value * g.weight;
        let skipped = k.skip_weight_below.is_some_and(|w| g.weight < w);
        if c.is_finite() && !skipped {
            slots[slot] += c;
        }
    }
    slots
}

// ---- 6.4 path_radiance ----------------------------------------------------------

/// How the roulette's survival probability q is taken (at most 1).
#[derive(Clone, Copy, Default)]
pub enum Survival {
    /// β's largest channel, as the solution.
    #[default]
    Largest,
    /// β's smallest channel.
    Smallest,
    /// β's largest channel before this bounce's factor.
    LargestBefore,
    /// This q, whatever β is.
    Fixed(f32),
    /// One channel of β.
    Channel(usize),
}

/// How the light sample's cosine is tested.
#[derive(Clone, Copy, Default)]
pub enum LightCos {
    /// Counted where it is positive, as the solution.
    #[default]
    Clamped,
    /// Counted with its sign, whatever it is.
    Unclamped,
    /// Its absolute value counted.
    Abs,
}

/// How a path loop departs from the solution of path_radiance.
#[derive(Clone, Copy)]
pub struct PathKnobs {
    /// How q is taken.
    pub q: Survival,
    /// The bounces after which the roulette plays (the solution: 1).
    pub roulette_after: u32,
    /// The roulette at the top of the loop, before the light sample.
    pub roulette_at_top: bool,
    /// How the light sample's cosine is tested.
    pub light_cos: LightCos,
    /// The weight of the light sample (the solution: 1).
    pub light_weight: f32,
    /// The emission a bounce finds added, with this weight.
    pub found_emission: Option<f32>,
    /// The roulette's number, known to be below q, used again as the next
    /// bounce's u.x.
    pub reuse_roulette_u: bool,
    /// What one light sample brings clamped to this, per channel.
    pub light_clamp: Option<f32>,
    /// A light sample that brings less than this counted without its
    /// shadow ray.
    pub lazy_below: Option<f32>,
    /// The emission the bounce finds added where the light sampler found
    /// no sample.
    pub found_emission_without_light: bool,
    /// Added to the bounce's pdf before dividing by it (the solution: 0).
    pub pdf_eps: f32,
    /// The path ends after this many bounces, roulette or not.
    pub max_bounces: Option<u32>,
    /// The roulette decided by the bounce's own u.x, not a number of its
    /// own.
    pub roulette_on_bounce_u: bool,
    /// The path ended, uncompensated, where roulette's q falls below this.
    pub dim_below: Option<f32>,
    /// Ends only where u > q: survives at u = q, also at q = 0 (thirty-first
    /// set).
    pub survive_at_q: bool,
    /// No end where the bounce's density is 0 (thirty-first set).
    pub no_pdf_guard: bool,
    /// The light sample's density floored at this (thirty-eighth set).
    pub light_pdf_floor: Option<f32>,
    /// The light sample's second number fixed at 1/2 (thirty-eighth set).
    pub light_v_half: bool,
}

impl Default for PathKnobs {
    fn default() -> Self {
        PathKnobs {
            q: Survival::Largest,
            roulette_after: 1,
            roulette_at_top: false,
            light_cos: LightCos::Clamped,
            light_weight: 1.0,
            found_emission: None,
            reuse_roulette_u: false,
            light_clamp: None,
            lazy_below: None,
            found_emission_without_light: false,
            pdf_eps: 0.0,
            max_bounces: None,
            roulette_on_bounce_u: false,
            dim_below: None,
            survive_at_q: false,
            no_pdf_guard: false,
            light_pdf_floor: None,
            light_v_half: false,
        }
    }
}

/// The solution of path_radiance (next-event estimation, Russian
/// roulette on the throughput), departing as `k` says.
pub fn path(
    k: PathKnobs,
    scene: &PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
) -> Vec3 {
    let q_of = |beta: Vec3, before: Vec3| match k.q {
        Survival::Largest => beta.max_element().min(1.0),
        Survival::Smallest => beta.min_element().min(1.0),
        Survival::LargestBefore => before.max_element().min(1.0),
        Survival::Fixed(q) => q,
        Survival::Channel(c) => beta[c].min(1.0),
    };
    let Some(mut hit) = scene.first_hit(origin, dir) else {
        return Vec3::ZERO;
    };
    let (mut radiance, mut beta, mut bounces) = (hit.emitted, Vec3::ONE, 0);
    let mut kept_u: Option<f32> = None;
    loop {
        if k.roulette_at_top && bounces > k.roulette_after {
            let q = q_of(beta, beta);
            if rng() >= q {
                break;
            }
            beta /= q;
        }
        let f = hit.albedo / PI;
        let u_light = Vec2::new(rng(), rng());
        let u_light = match k.light_v_half {
            true => Vec2::new(u_light.x, 0.5),
            false => u_light,
        };
        let light = scene.sample_light(&hit, u_light);
        let no_light = light.is_none();
        if let Some(mut ls) = light {
            ls.pdf = k.light_pdf_floor.map_or(ls.pdf, |floor| ls.pdf.max(floor));
            let cos = hit.n.dot(ls.wi);
            let (cos, counted) = match k.light_cos {
                LightCos::Clamped => (cos, cos > 0.0),
                LightCos::Unclamped => (cos, true),
                LightCos::Abs => (cos.abs(), cos.abs() > 0.0),
            };
            let brought = k.light_weight * beta * f * ls.li * cos / ls.pdf;
            let lazy = k.lazy_below.is_some_and(|l| brought.max_element() < l);
            if counted && ls.pdf > 0.0 && (lazy || scene.unoccluded(&hit, ls.wi, ls.dist)) {
                radiance += k
                    .light_clamp
                    .map_or(brought, |most| brought.min(Vec3::splat(most)));
            }
        }
        let ux = kept_u.take().unwrap_or_else(&mut *rng);
        let (wi, pdf) = scene.sample_cosine(&hit, Vec2::new(ux, rng()));
        if pdf <= 0.0 && !k.no_pdf_guard {
            break;
        }
        let before = beta;
        beta *= f * hit.n.dot(wi) / (pdf + k.pdf_eps);
        bounces += 1;
        if k.max_bounces.is_some_and(|most| bounces >= most) {
            break;
        }
        if !k.roulette_at_top && bounces > k.roulette_after {
            let q = q_of(beta, before);
            if k.dim_below.is_some_and(|dim| q < dim) {
                break;
            }
            let u = if k.roulette_on_bounce_u { ux } else { rng() };
            if u > q || (u == q && !k.survive_at_q) {
                break;
            }
            beta /= q;
            kept_u = k.reuse_roulette_u.then_some(u);
        }
        match scene.next_hit(&hit, wi) {
            Some(next) => {
                if let Some(weight) = k.found_emission {
                    radiance += weight * beta * next.emitted;
                }
                if k.found_emission_without_light && no_light {
                    radiance += beta * next.emitted;
                }
                hit = next;
            }
            None => break,
        }
    }
    radiance
}

// ---- the defaults are the course's solutions ------------------------------------

#[test]
fn look_at_defaults_pass() {
    passes_every(&SEEDS, "look_at's defaults", || {
        ch1::check_look_at(|e, t, u| look_at(LookKnobs::default(), e, t, u))
    });
}

#[test]
fn direct_defaults_pass() {
    passes_every(&SEEDS, "direct_light's defaults", || {
        ch5::check_direct_light(|p, n, rho, y, nl, a, le, v| {
            direct(DirectKnobs::default(), (p, n, rho), (y, nl, a, le), v)
        })
    });
}

#[test]
fn draw_edges_defaults_pass() {
    passes_every(&SEEDS, "draw_edges' defaults", || {
        ch1::check_draw_edges(|c, a, b, near| draw_edges(EdgeKnobs::default(), c, a, b, near))
    });
}

#[test]
fn rasterize_defaults_pass() {
    passes_every(&SEEDS, "rasterize_triangle's defaults", || {
        ch2::check_rasterize_triangle(|v, c, w, h, d, i| {
            rasterize(RasterKnobs::default(), v, c, (w, h), d, i)
        })
    });
}

#[test]
fn inside_defaults_pass() {
    passes_every(&SEEDS, "barycentric_inside's defaults", || {
        ch3::check_barycentric_inside(|p, t| inside(InsideKnobs::default(), p, t))
    });
}

#[test]
fn moller_defaults_pass() {
    passes_every(&SEEDS, "moller_trumbore's defaults", || {
        ch3::check_moller_trumbore(|o, d, tri| moller(MollerKnobs::default(), o, d, tri))
    });
}

#[test]
fn closest_hit_defaults_pass() {
    passes_every(&SEEDS, "bvh_traversal's defaults", || {
        ch3::check_bvh_traversal(|bvh, ray, t_max| {
            closest_hit(BvhKnobs::default(), bvh, ray, t_max)
        })
    });
}

#[test]
fn sah_sweep_defaults_pass() {
    passes_every(&SEEDS, "sah's defaults", || {
        ch3::check_sah(|b, c| sah_sweep(SahKnobs::default(), b, c))
    });
}

#[test]
fn sphere_trace_defaults_pass() {
    passes_every(&SEEDS, "sphere_trace's defaults", || {
        ch4::check_sphere_trace(|sdf, o, d, eps, steps, max| {
            sphere_trace(MarchKnobs::default(), sdf, (o, d), eps, steps, max)
        })
    });
}

#[test]
fn trace_scene_defaults_pass() {
    passes_every(&SEEDS, "trace_scene's defaults", || {
        ch4::check_trace_scene(|sdf, o, d, m| trace_scene(SceneKnobs::default(), sdf, o, d, m))
    });
}

/// The path loop's check traces 200,000 paths in a furnace per seed: its
/// defaults are tried under the first two seeds only, as the fresh sets'
/// path mutants are.
#[test]
fn path_defaults_pass() {
    passes_every(&SEEDS[..2], "path_radiance's defaults", || {
        paths::check_path_radiance(|s, o, d, rng| path(PathKnobs::default(), s, o, d, rng))
    });
}

#[test]
fn layers_defaults_pass() {
    passes_every(&SEEDS, "bounce_layers' defaults", || {
        check_bounce_layers(|path| layers(LayersKnobs::default(), path))
    });
}
