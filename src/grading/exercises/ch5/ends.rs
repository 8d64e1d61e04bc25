//! Exercise 5.2's two ends of the hemisphere and its finest scale, from
//! numbers of their own: the rim and the pole (shares that a map which
//! stops short of either gets wrong), and the largest gap that the drawn
//! directions leave in z² or around the azimuth (where a map that never
//! reaches some band of directions, however thin, shows it).

use glam::Vec2;

use crate::core::sampling::random;

/// How many numbers.
pub(super) const ENDS_N: u64 = 640_000;

/// How a gap's detail begins.
pub(super) const GAP: &str = "the largest gap between";

/// The ends' statistics of `f` from `ENDS_N` numbers drawn from `seed`,
/// each as (deviation, what it says), where a deviation above 5 fails:
///
/// * P(z < 0.03) = 0.03² (576 expected) and, for the cap about the pole,
///   P(x² + y² < s) = s with s = 2.5·10⁻⁴ (160 expected), in standard
///   errors;
/// * under cos θ / π, z² and the azimuth / 2π are uniform on [0, 1], so
///   the N values of each split [0, 1] (z² with its ends 0 and 1, the
///   azimuth as a circle) into gaps whose largest exceeds
///   g* = (ln(N + 1) + 16.1) / N (4.6·10⁻⁵) with probability at most
///   (N + 1) e^(−N g*) = 10⁻⁷. A floor on z at 0.005 leaves the gap
///   [0, 2.5·10⁻⁵] and more; an azimuth that stops short of 2π, by 0.003
///   (6.28 for 2π), the gap 5·10⁻⁴. The deviation is 5 g / g*.
pub(super) fn ends(f: impl Fn(Vec2) -> glam::Vec3, seed: u64) -> Vec<(f64, String)> {
    let n = ENDS_N as usize;
    let (mut rim, mut cap) = (0u64, 0u64);
    let (mut z2, mut turns) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for i in 0..ENDS_N {
        let u = Vec2::new(
            random(seed ^ 0x9a2e, i, 0, 0),
            random(seed ^ 0x9a2e, i, 0, 1),
        );
        let w = f(u);
        rim += u64::from(w.z < 0.03);
        cap += u64::from(w.x * w.x + w.y * w.y < 2.5e-4);
        let w = w.as_dvec3();
        z2.push((w.z * w.z).clamp(0.0, 1.0));
        if w.x != 0.0 || w.y != 0.0 {
            turns.push((w.y.atan2(w.x) / std::f64::consts::TAU).rem_euclid(1.0));
        }
    }
    let share = |count: u64, p: f64, what: &str, why: &str| {
        let got = count as f64 / ENDS_N as f64;
        let z = (got - p).abs() / (p * (1.0 - p) / ENDS_N as f64).sqrt();
        let detail =
            format!("{what} = {got:.6}, expected {p:.6} ({z:.1} standard errors off): {why}");
        (z, detail)
    };
    let bound = (((n + 1) as f64).ln() + 16.1) / n as f64;
    let gap = |what: &str, g: f64, at: f64, why: &str| {
        let detail = format!(
            "{GAP} the {what} of {n} directions is {g:.2e}, at {at:.6}; \
             a right map's is below {bound:.1e} but with probability 10⁻⁷: {why}"
        );
        (5.0 * g / bound, detail)
    };
    let (g, at) = largest_gap(z2, false);
    let (h, around) = largest_gap(turns, true);
    vec![
        share(rim, 0.0009, "P(z < 0.03)", "the directions must reach the rim"),
        share(
            cap,
            2.5e-4,
            "P(x² + y² < 0.00025)",
            "the directions about the pole must spread as cos θ / π too",
        ),
        gap(
            "values of z²",
            g,
            at,
            "under cos θ / π no band of z, however thin, is left out (not at the rim, not at the pole)",
        ),
        gap(
            "azimuths / 2π",
            h,
            around,
            "every azimuth must be reached (2π, not an approximation)",
        ),
    ]
}

/// The largest gap between the sorted values `v` in [0, 1] and where it
/// starts: with the ends 0 and 1 as values, or, `circle`, across the wrap
/// from the last value to the first.
fn largest_gap(mut v: Vec<f64>, circle: bool) -> (f64, f64) {
    v.sort_unstable_by(f64::total_cmp);
    let (Some(&first), Some(&last)) = (v.first(), v.last()) else {
        return (1.0, 0.0);
    };
    let mut best = match circle {
        true => (1.0 - last + first, last),
        false => (
            first.max(1.0 - last),
            if first > 1.0 - last { 0.0 } else { last },
        ),
    };
    for p in v.windows(2) {
        if p[1] - p[0] > best.0 {
            best = (p[1] - p[0], p[0]);
        }
    }
    best
}
