//! Capstone 4, solved as a student would.

use glam::Vec3;
use raystep::ch4_implicit_surfaces::march::March;

/// The first hit of the ray: `Some((t, normal))`, or `None` for a miss.
pub fn trace_scene(
    sdf: &dyn Fn(Vec3) -> f32,
    origin: Vec3,
    dir: Vec3,
    march: &March,
) -> Option<(f32, Vec3)> {
    let mut t = 0.0;
    let mut f = sdf(origin);
    let mut evaluations = 1;
    let p = loop {
        let p = origin + t * dir;
        if f.abs() < march.epsilon_at(p) {
            break p;
        }
        if t > march.max_distance || evaluations >= march.max_steps {
            return None;
        }
        t += f;
        f = sdf(origin + t * dir);
        evaluations += 1;
    };
    let h = march.epsilon_at(p).max(1e-4);
    let partial = |axis: Vec3| (sdf(p + axis * h) - sdf(p - axis * h)) / (2.0 * h);
    let gradient = Vec3::new(partial(Vec3::X), partial(Vec3::Y), partial(Vec3::Z));
    let n = gradient.try_normalize().unwrap_or(-dir);
    Some((t, if n.dot(dir) > 0.0 { -n } else { n }))
}
