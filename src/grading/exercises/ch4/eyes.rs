//! Sphere tracing's drawn rays: a sphere's exact first hit, rays from one
//! eye one after another, as a camera shoots them, and oblique rays at a
//! sphere just beyond max_distance.

use glam::Vec3;

use super::TraceFn;
use crate::exercises::draws::{worst_drawn, Draws};
use crate::exercises::worse;

/// The first hit of the ray from `o` along `d` on the sphere (`c`, `r`),
/// worked out in f64, and how far a march with tolerance `eps` may stop
/// from it (2ε / cos θ, θ the angle of incidence, cos θ taken no smaller
/// than 10⁻³).
pub(super) fn sphere_hit(o: Vec3, d: Vec3, c: Vec3, r: f32, eps: f32) -> Option<(f64, f64)> {
    let (o, d, c) = (o.as_dvec3(), d.as_dvec3(), c.as_dvec3());
    let oc = o - c;
    let b = oc.dot(d);
    let disc = b * b - (oc.length_squared() - (r as f64).powi(2));
    (disc > 0.0 && -b - disc.sqrt() > 0.0).then(|| {
        let t = -b - disc.sqrt();
        let cos = ((o + d * t - c).normalize().dot(-d)).max(1e-3);
        (t, 2.0 * eps as f64 / cos)
    })
}

/// One eye, a large sphere ahead and a small one much nearer (each a
/// centre and a radius), and a ray from the eye.
struct EyeRay {
    eye: Vec3,
    far: (Vec3, f32),
    near: (Vec3, f32),
    dir: Vec3,
}

/// Rays from one eye, one after another, as a camera shoots them: a
/// large sphere ahead and a small one much nearer, the rays going to
/// either in turn (and some past both). Each march starts at t = 0,
/// whatever the rays before it found: after a far hit, the near sphere
/// lies well within half its distance. (ε is a ten-thousandth of the
/// large one's radius, and the eye within ten radii of the origin, so
/// that f32's rounding of the points stays far below ε.)
pub(super) fn eye_rays(f: TraceFn) -> (f64, String) {
    let mut draws = Draws::new(343);
    let mut rays = Vec::new();
    for _ in 0..draws.count(3, 6) {
        draws.next_case();
        let r_far = draws.decades(-2.0, 2.0);
        let eye = draws.place_for(r_far, 1.0);
        let ahead = draws.direction();
        let far = eye + ahead * r_far * draws.range(3.0, 10.0);
        let d_far = (far - eye).length();
        let r_near = r_far * draws.range(0.05, 0.2);
        // The near one beside the line to the far one, a tenth to a
        // quarter of the way there.
        let side = ahead.any_orthonormal_vector();
        let towards_near = (ahead + side * draws.range(0.6, 1.2)).normalize();
        let near = eye + towards_near * d_far * draws.range(0.1, 0.25);
        for k in 0..12 {
            let (c, r) = match k % 2 {
                0 => (far, r_far),
                _ => (near, r_near),
            };
            // A point on the sphere's half facing the eye, or past it.
            let aim = c + draws.in_cube() * r * 0.7 - eye;
            let dir = match draws.unit() < 0.15 {
                true => (aim + side * r * 4.0).normalize(),
                false => aim.normalize(),
            };
            rays.push(EyeRay {
                eye,
                far: (far, r_far),
                near: (near, r_near),
                dir,
            });
        }
    }
    // Not a ray that passes a sphere within a few ε of its surface: a right
    // march may stop there, within ε of it, where the ray itself misses.
    rays.retain(|ray| {
        let eps = ray.far.1 * 1e-4;
        [ray.far, ray.near]
            .into_iter()
            .all(|(c, r)| !(0.0..8.0 * eps as f64).contains(&miss_by(ray.eye, ray.dir, c, r)))
    });
    worst_drawn(rays.iter().map(|ray| eye_ray(f, ray)))
}

/// How far the ray from `o` along `d` passes outside the sphere (`c`,
/// `r`), worked out in f64: its closest approach to the centre (ahead of
/// `o`) less the radius; negative where it enters the sphere.
fn miss_by(o: Vec3, d: Vec3, c: Vec3, r: f32) -> f64 {
    let (oc, d) = ((c - o).as_dvec3(), d.as_dvec3());
    let along = oc.dot(d).max(0.0);
    (oc - d * along).length() - r as f64
}

/// One of [`eye_rays`]: its error (on the scale of the large sphere)
/// and what it asked.
fn eye_ray(f: TraceFn, ray: &EyeRay) -> (f64, String) {
    let EyeRay { eye, dir, .. } = *ray;
    let ((far, r_far), (near, r_near)) = (ray.far, ray.near);
    let sdf = |p: Vec3| ((p - far).length() - r_far).min((p - near).length() - r_near);
    let eps = r_far * 1e-4;
    let want = [
        sphere_hit(eye, dir, far, r_far, eps),
        sphere_hit(eye, dir, near, r_near, eps),
    ]
    .into_iter()
    .flatten()
    .min_by(|a, b| a.0.total_cmp(&b.0));
    let max_distance = 30.0 * r_far.max((far - eye).length());
    let got = f(&sdf, eye, dir, eps, 1 << 14, max_distance);
    let err = match (got, want) {
        (Some(g), Some((w, slack))) => worse((g as f64 - w).abs() - slack, 0.0) / r_far as f64,
        (None, None) => 0.0,
        _ => f64::INFINITY,
    };
    let what = format!(
        "one eye at {eye}, spheres of radius {r_far} at {far} and {r_near} at {near} (one \
         after another, each ray from t = 0), ray along {dir} (ε = {eps}, max_distance = \
         {max_distance}): got {got:?}, expected {:?}",
        want.map(|w| w.0)
    );
    (err, what)
}

/// Oblique rays (every component of the direction 0.34 to 0.77 of its
/// length) at a sphere 1.03 to 1.25 times max_distance away along the
/// ray, met off its centre, so that the march takes several steps and
/// passes max_distance before it comes within ε: a miss. (Only rays whose
/// step past the limit lands well past it, far from the surface, so that
/// every right tracer's rounding agrees.) t is what max_distance limits,
/// not a measure of p − o that is shorter on an oblique ray, such as its
/// largest coordinate, which reaches max_distance only past the sphere.
pub(super) fn beyond_limit(f: TraceFn) -> (f64, String) {
    let mut draws = Draws::new(443);
    worst_drawn((0..draws.count(8, 16)).filter_map(|_| {
        draws.next_case();
        let r = draws.decades(-2.0, 2.0);
        let centre = draws.place_for(r, 1.0);
        let mut slant = || draws.sign() * draws.range(0.6, 1.0);
        let dir = Vec3::new(slant(), slant(), slant()).normalize();
        let side = dir
            .cross(draws.direction())
            .normalize_or(dir.any_orthonormal_vector());
        let origin = centre - dir * r * draws.range(4.0, 10.0) + side * r * draws.range(0.4, 0.9);
        let eps = r * 1e-4;
        let (hit, _) = sphere_hit(origin, dir, centre, r, eps)?;
        let max_distance = (hit * draws.range(0.8, 0.97) as f64) as f32;
        let sdf = move |p: Vec3| (p - centre).length() - r;
        // The reference's march: where it passes the limit.
        let (mut t, mut steps) = (0.0f32, 0);
        let robust = loop {
            steps += 1;
            let v = sdf(origin + t * dir);
            if steps > 4096 {
                break false;
            }
            if v.abs() < eps {
                break false;
            }
            if t > max_distance {
                break v > 100.0 * eps && t > max_distance * (1.0 + 1e-4);
            }
            if t + v > max_distance && t > max_distance * (1.0 - 1e-4) {
                break false;
            }
            t += v;
        };
        if !robust {
            return None;
        }
        let got = f(&sdf, origin, dir, eps, 4096, max_distance);
        Some((
            if got.is_some() { f64::INFINITY } else { 0.0 },
            format!(
                "a sphere of radius {r} at {centre}, ray from {origin} along {dir} (ε = {eps}, \
                 max_distance = {max_distance}): the sphere is {hit:.4} away along the ray, and \
                 the march passes max_distance at t = {t} before it comes within ε: got {got:?}, \
                 expected None"
            ),
        ))
    }))
}
