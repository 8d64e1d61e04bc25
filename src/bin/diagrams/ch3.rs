//! Chapter 3's diagrams: a ray meeting a plane ([`ray_plane`]), a hit's
//! (u, v) on a triangle ([`intersect_moller_trumbore`]), the slab test
//! ([`Aabb::enter`]); the BVH's boxes are in [`crate::ch3_bvh`].

use glam::{Vec2, Vec3};
use raystep::ch2_rasterization::edge::barycentric;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::readable_bvh::Aabb;
use raystep::ch3_ray_triangle::triangle::{
    barycentric_inside, intersect_moller_trumbore, ray_plane,
};
use raystep::core::error::{Error, Result};

use crate::svg::{
    Anchor, Stroke, Svg, BLUE, FILL_BLUE, FILL_GREEN, FILL_ORANGE, GREEN, GREY, INK, ORANGE, RED,
};
use crate::Diagram;

/// Chapter 3's diagrams, in the order the chapter shows them.
pub fn diagrams() -> Result<Vec<Diagram>> {
    Ok(vec![
        Diagram {
            name: "ch3-ray-plane-diagram",
            what: "the ray r(t) = o + t d meeting the plane Nᵀx = c at the t that ray_plane computes",
            svg: ray_meets_plane()?,
        },
        Diagram {
            name: "ch3-ray-triangle-diagram",
            what: "a hit p = p0 + u e1 + v e2 with the (u, v) of intersect_moller_trumbore, and a miss barycentric_inside rejects",
            svg: ray_triangle()?,
        },
        Diagram {
            name: "ch3-slab-diagram",
            what: "the slab test in 2D: each slab's interval along a ray, and the overlap Aabb::enter finds (or not)",
            svg: slabs()?,
        },
        crate::ch3_bvh::diagram()?,
    ])
}

fn xy(v: Vec3) -> (f64, f64) {
    (v.x as f64, v.y as f64)
}

fn no(what: &str) -> Error {
    Error::Usage(format!("ch3 diagram: {what}"))
}

/// A side view in the plane z = 0 (the plane Nᵀx = c is a line there): the
/// origin of the coordinates, the plane's unit normal N at distance c, and
/// a ray whose parameter t is ticked off up to the hit; a second ray runs
/// parallel to the plane (Nᵀd = 0, no t).
fn ray_meets_plane() -> Result<Svg> {
    // A unit normal and a direction along the plane whose dot product is
    // exactly 0 in f32 (the products are the same two numbers).
    let n = Vec3::new(-0.28, 0.96, 0.0);
    let c = 1.6f32;
    let ray = Ray::new(Vec3::new(0.4, 5.6, 0.0), Vec3::new(1.0, -0.75, 0.0))?;
    let t = ray_plane(ray.origin, ray.dir, n, c).ok_or_else(|| no("the ray misses the plane"))?;
    let parallel = Ray {
        origin: Vec3::new(-0.6, 3.3, 0.0),
        dir: Vec3::new(n.y, -n.x, 0.0),
    };
    if ray_plane(parallel.origin, parallel.dir, n, c).is_some() {
        return Err(no("the parallel ray meets the plane"));
    }
    let mut s = Svg::new(620.0, [-1.6, 9.4, -0.5, 6.3]);
    // The plane: the points c N + s (N rotated a quarter turn).
    let foot = n * c;
    let along = Vec3::new(n.y, -n.x, 0.0);
    s.area(
        &[
            xy(foot - 1.2 * along),
            xy(foot + 10.6 * along),
            xy(foot + 10.6 * along - 0.3 * n),
            xy(foot - 1.2 * along - 0.3 * n),
        ],
        FILL_BLUE,
    );
    s.line(
        xy(foot - 1.2 * along),
        xy(foot + 10.6 * along),
        Stroke::solid(INK, 2.2),
    );
    s.text(
        xy(foot + 8.4 * along),
        (0.0, 28.0),
        "Nᵀx = c",
        15.0,
        Anchor::Middle,
        INK,
        false,
    );
    // The origin, the offset c along N, and N itself.
    s.dot((0.0, 0.0), 4.5, GREY);
    s.text(
        (0.0, 0.0),
        (-6.0, 16.0),
        "0",
        14.0,
        Anchor::End,
        GREY,
        false,
    );
    s.line((0.0, 0.0), xy(foot), Stroke::dashed(GREY, 1.2));
    let c_label = format!("c = {c:.1}");
    s.text(
        xy(foot * 0.5),
        (-8.0, 0.0),
        &c_label,
        14.0,
        Anchor::End,
        GREY,
        false,
    );
    s.arrow(xy(foot), xy(foot + 1.2 * n), Stroke::solid(GREEN, 2.4));
    s.text(
        xy(foot + 1.2 * n),
        (-6.0, 0.0),
        "N",
        15.0,
        Anchor::End,
        GREEN,
        true,
    );
    // The parallel ray.
    s.arrow(
        xy(parallel.origin),
        xy(parallel.at(5.2)),
        Stroke::dashed(GREY, 1.6),
    );
    s.text(
        xy(parallel.at(5.2)),
        (-4.0, -12.0),
        "Nᵀd = 0: no t",
        13.0,
        Anchor::End,
        GREY,
        false,
    );
    // The ray, ticked at t = 1, 2, ...
    let end = t + 1.3;
    s.arrow(xy(ray.origin), xy(ray.at(end)), Stroke::solid(BLUE, 2.2));
    let tick = Vec3::new(-ray.dir.y, ray.dir.x, 0.0) * 0.12;
    for k in 1..=t.floor() as i32 {
        let p = ray.at(k as f32);
        s.line(xy(p - tick), xy(p + tick), Stroke::solid(BLUE, 1.6));
        let label = format!("{k}");
        s.text(xy(p), (7.0, -6.0), &label, 12.0, Anchor::Start, BLUE, false);
    }
    s.dot(xy(ray.origin), 5.0, INK);
    s.text(
        xy(ray.origin),
        (0.0, -10.0),
        "o",
        16.0,
        Anchor::Middle,
        INK,
        true,
    );
    s.text(
        xy(ray.at(0.5)),
        (-8.0, 14.0),
        "d",
        16.0,
        Anchor::End,
        BLUE,
        true,
    );
    s.dot(xy(ray.at(t)), 6.0, RED);
    let hit = format!("r(t) at t = {t:.2}");
    s.text(
        xy(ray.at(t)),
        (12.0, 6.0),
        &hit,
        15.0,
        Anchor::Start,
        RED,
        false,
    );
    s.caption(&format!(
        "t = (c − Nᵀo) / (Nᵀd) = ({c:.2} − {:.2}) / ({:.2}) = {t:.2}",
        n.dot(ray.origin),
        n.dot(ray.dir)
    ));
    Ok(s)
}

/// The triangle seen along the rays (they run down −z onto the plane
/// z = 0): e1 and e2 from p0, a hit at p = p0 + u e1 + v e2 with the (u, v)
/// Möller–Trumbore returns, and a miss, outside because u + v > 1.
fn ray_triangle() -> Result<Svg> {
    let tri = [
        Vec3::new(0.6, 0.6, 0.0),
        Vec3::new(8.4, 1.2, 0.0),
        Vec3::new(2.6, 6.0, 0.0),
    ];
    let [p0, p1, p2] = tri;
    let down = Vec3::new(0.0, 0.0, -1.0);
    let hit_ray = Ray::new(Vec3::new(4.2, 2.6, 5.0), down)?;
    let miss_ray = Ray::new(Vec3::new(7.4, 5.0, 5.0), down)?;
    let hit = intersect_moller_trumbore(&hit_ray, tri, 0.0, f32::INFINITY)
        .ok_or_else(|| no("the hit ray misses"))?;
    if intersect_moller_trumbore(&miss_ray, tri, 0.0, f32::INFINITY).is_some()
        || barycentric_inside(miss_ray.at(5.0), tri).is_some()
    {
        return Err(no("the miss ray hits"));
    }
    // The miss's (u, v), from chapter 2's barycentrics in the plane.
    let flat = |v: Vec3| Vec2::new(v.x, v.y);
    let q = miss_ray.at(5.0);
    let phi = barycentric(flat(p0), flat(p1), flat(p2), flat(q))
        .ok_or_else(|| no("degenerate triangle"))?;
    let (e1, e2) = (p1 - p0, p2 - p0);
    let p = hit.point(tri);
    let mut s = Svg::new(600.0, [-0.4, 10.0, -0.2, 6.9]);
    s.polyline(
        &[xy(p0), xy(p1), xy(p2)],
        Stroke::solid(INK, 2.0),
        Some(FILL_GREEN),
    );
    s.arrow(xy(p0), xy(p1), Stroke::solid(BLUE, 2.2));
    s.arrow(xy(p0), xy(p2), Stroke::solid(ORANGE, 2.2));
    s.text(
        xy(p0 + 0.82 * e1),
        (0.0, 18.0),
        "e1 = p1 − p0",
        14.0,
        Anchor::Middle,
        BLUE,
        false,
    );
    s.text(
        xy(p0 + 0.8 * e2),
        (-8.0, 0.0),
        "e2 = p2 − p0",
        14.0,
        Anchor::End,
        ORANGE,
        false,
    );
    // p reached as u e1, then v e2.
    let corner = p0 + hit.u * e1;
    s.line(xy(p0), xy(corner), Stroke::solid(BLUE, 4.0));
    s.arrow(xy(corner), xy(p), Stroke::solid(ORANGE, 2.4));
    s.line(xy(p0 + hit.v * e2), xy(p), Stroke::dashed(GREY, 1.2));
    s.text(
        xy(p0 + 0.5 * hit.u * e1),
        (0.0, -8.0),
        "u e1",
        14.0,
        Anchor::Middle,
        BLUE,
        true,
    );
    s.text(
        xy(corner + 0.5 * hit.v * e2),
        (8.0, 4.0),
        "v e2",
        14.0,
        Anchor::Start,
        ORANGE,
        true,
    );
    s.dot(xy(p), 6.0, GREEN);
    let label = format!(
        "p: u = {:.2}, v = {:.2}, 1 − u − v = {:.2}",
        hit.u,
        hit.v,
        1.0 - hit.u - hit.v
    );
    s.text(
        xy(p),
        (10.0, -8.0),
        &label,
        14.0,
        Anchor::Start,
        GREEN,
        false,
    );
    s.dot(xy(q), 6.0, RED);
    let label = format!("miss: u = {:.2}, v = {:.2}", phi.y, phi.z);
    s.text(
        xy(q),
        (0.0, -30.0),
        &label,
        14.0,
        Anchor::Middle,
        RED,
        false,
    );
    let label = format!("u + v = {:.2} > 1", phi.y + phi.z);
    s.text(
        xy(q),
        (0.0, -13.0),
        &label,
        14.0,
        Anchor::Middle,
        RED,
        false,
    );
    for (v, name, offset) in [
        (p0, "p0", (-8.0, 14.0)),
        (p1, "p1", (8.0, 5.0)),
        (p2, "p2", (0.0, -10.0)),
    ] {
        s.dot(xy(v), 4.5, INK);
        let anchor = if offset.0 > 0.0 {
            Anchor::Start
        } else {
            Anchor::Middle
        };
        s.text(xy(v), offset, name, 15.0, anchor, INK, true);
    }
    s.caption("seen along the rays: inside exactly when u, v and 1 − u − v are all ≥ 0");
    Ok(s)
}

/// A box [min, max] in the plane z = 0, its x slab and y slab drawn as
/// bands, and two rays: one whose two intervals overlap (it enters the box
/// at the t [`Aabb::enter`] returns and leaves at the smaller far value),
/// and one whose intervals do not overlap (`enter` returns `None`).
fn slabs() -> Result<Svg> {
    let bounds = Aabb {
        min: Vec3::new(3.0, 2.0, -1.0),
        max: Vec3::new(7.0, 4.6, 1.0),
    };
    let (x0, x1, y0, y1) = (0.0, 10.4, 0.0, 7.0);
    let mut s = Svg::new(640.0, [x0, x1, y0, y1]);
    let (bx0, bx1) = (bounds.min.x as f64, bounds.max.x as f64);
    let (by0, by1) = (bounds.min.y as f64, bounds.max.y as f64);
    s.area(&[(bx0, y0), (bx1, y0), (bx1, y1), (bx0, y1)], FILL_BLUE);
    s.area(&[(x0, by0), (x1, by0), (x1, by1), (x0, by1)], FILL_ORANGE);
    s.area(
        &[(bx0, by0), (bx1, by0), (bx1, by1), (bx0, by1)],
        FILL_GREEN,
    );
    s.polyline(
        &[(bx0, by0), (bx1, by0), (bx1, by1), (bx0, by1)],
        Stroke::solid(INK, 2.0),
        Some("none"),
    );
    s.text(
        (bx1, y0),
        (-6.0, -8.0),
        "x slab",
        14.0,
        Anchor::End,
        BLUE,
        false,
    );
    s.text(
        (x1, by0),
        (-6.0, -8.0),
        "y slab",
        14.0,
        Anchor::End,
        ORANGE,
        false,
    );
    let rays = [
        (Vec3::new(0.4, 0.7, 0.0), Vec3::new(1.0, 0.5, 0.0)),
        (Vec3::new(0.4, 3.6, 0.0), Vec3::new(1.0, 0.45, 0.0)),
    ];
    for (origin, dir) in rays {
        let ray = Ray::new(origin, dir)?;
        let inv = ray.dir.recip();
        let entered = bounds.enter(&ray, inv, f32::INFINITY);
        // Each slab's interval along the ray: the same sums as the test.
        let slab = |axis: usize| {
            let t0 = (bounds.min[axis] - ray.origin[axis]) * inv[axis];
            let t1 = (bounds.max[axis] - ray.origin[axis]) * inv[axis];
            (t0.min(t1).max(0.0), t0.max(t1))
        };
        let (x_in, y_in) = (slab(0), slab(1));
        let (near, far) = (x_in.0.max(y_in.0), x_in.1.min(y_in.1));
        if entered != (near <= far).then_some(near) {
            return Err(no("the slab intervals disagree with Aabb::enter"));
        }
        // Where the ray leaves the picture (both rays go up and right).
        let t_end = ((x1 as f32 - 0.2 - ray.origin.x) / ray.dir.x)
            .min((y1 as f32 - 0.2 - ray.origin.y) / ray.dir.y);
        s.arrow(xy(ray.origin), xy(ray.at(t_end)), Stroke::solid(GREY, 1.4));
        s.dot(xy(ray.origin), 4.5, INK);
        s.text(
            xy(ray.origin),
            (0.0, 18.0),
            "o",
            15.0,
            Anchor::Middle,
            INK,
            true,
        );
        // Each slab's interval, just beside the ray.
        let side = Vec3::new(-ray.dir.y, ray.dir.x, 0.0) * 0.14;
        s.line(
            xy(ray.at(x_in.0) + side),
            xy(ray.at(x_in.1) + side),
            Stroke::solid(BLUE, 3.0),
        );
        s.line(
            xy(ray.at(y_in.0) - side),
            xy(ray.at(y_in.1) - side),
            Stroke::solid(ORANGE, 3.0),
        );
        match entered {
            Some(t_near) => {
                s.line(
                    xy(ray.at(t_near)),
                    xy(ray.at(far)),
                    Stroke::solid(GREEN, 4.0),
                );
                s.dot(xy(ray.at(t_near)), 5.0, GREEN);
                s.dot(xy(ray.at(far)), 5.0, GREEN);
                let label = format!("enters at t = {t_near:.2}");
                s.text(
                    xy(ray.at(t_near)),
                    (-4.0, 18.0),
                    &label,
                    13.0,
                    Anchor::Start,
                    GREEN,
                    false,
                );
                let label = format!("leaves at t = {far:.2}");
                s.text(
                    xy(ray.at(far)),
                    (8.0, 12.0),
                    &label,
                    13.0,
                    Anchor::Start,
                    GREEN,
                    false,
                );
            }
            None => {
                for (line, text) in [
                    format!("upper ray: in the y slab until t = {:.2},", y_in.1),
                    format!("in the x slab from t = {:.2}: a miss", x_in.0),
                ]
                .iter()
                .enumerate()
                {
                    let dy = 18.0 + 17.0 * line as f64;
                    s.text((x0, y1), (8.0, dy), text, 13.0, Anchor::Start, RED, false);
                }
            }
        }
    }
    s.caption("in the box from the largest near t to the smallest far t of the slabs");
    Ok(s)
}
