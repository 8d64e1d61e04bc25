//! The clauses of chapter 4's sphere-tracing contract that a picture
//! cannot show: the step budget, the maximum distance, the
//! distance-scaled ε and the normal's three rules. Each is a ray against
//! a plain wall whose distance function the grader wraps to count every
//! evaluation ([`Probe`]), with the number of steps known exactly: the
//! walls' distance functions are exact dyadic numbers along the rays, so
//! every right tracer takes the same steps, bit for bit.

use glam::Vec3;

use crate::ch4_implicit_surfaces::march::March;

pub use super::probe::Probe;
use super::walls::*;

pub use super::clauses::{judge, Case, Clause};
pub use super::contract_symptoms::*;

/// The contract's cases, in the order they are checked.
pub fn cases() -> Vec<Case> {
    let m = March::default();
    let down = |z: f32| (Vec3::new(0.0, 0.0, z), -Vec3::Z);
    let case = |what, clause, sdf, (origin, dir): (Vec3, Vec3), march| Case {
        what,
        clause,
        sdf,
        origin,
        dir,
        march,
    };
    let budget = |n| March { max_steps: n, ..m };
    vec![
        case(
            "a wall 1 m below whose distance function is half the true distance (14 evaluations reach ε)",
            Clause::Budget,
            half_wall,
            down(1.0),
            budget(5),
        ),
        case(
            "the same wall, a budget of one evaluation too few",
            Clause::Budget,
            half_wall,
            down(1.0),
            budget(13),
        ),
        case(
            "the same wall, a budget of exactly the 14 evaluations needed",
            Clause::Budget,
            half_wall,
            down(1.0),
            budget(14),
        ),
        case(
            "the same wall with ε = 1e-7, a budget of exactly the 24 evaluations needed (f = 2^-24 \
             is the first below ε: a floor under ε stops short)",
            Clause::Budget,
            half_wall,
            down(1.0),
            March {
                epsilon: 1e-7,
                ..budget(24)
            },
        ),
        case(
            "the same wall from half as high, a budget of exactly the 13 evaluations needed (an odd budget)",
            Clause::Budget,
            half_wall,
            down(0.5),
            budget(13),
        ),
        case(
            "a wall 1 m below whose function is 2 % of the distance, a budget of 256 evaluations \
             (more than a byte counts)",
            Clause::Budget,
            slow_wall,
            down(1.0),
            budget(256),
        ),
        case(
            "a floor 2^-8 below the ray and a wall 0.75 m ahead, a budget of 256: 192 steps of 2^-8, \
             the hit at the 193rd evaluation (no budget of its own below the one given)",
            Clause::Budget,
            corridor,
            (Vec3::ZERO, Vec3::X),
            budget(256),
        ),
        case(
            "the same floor with the wall 8 m ahead, a budget of exactly the 2,049 evaluations \
             needed: 2,048 steps of 2^-8 (no cap of its own on a large budget)",
            Clause::Budget,
            long_corridor,
            (Vec3::ZERO, Vec3::X),
            budget(2_049),
        ),
        case(
            "an exact wall 3,000,000 m below, max_distance = 10⁷: a hit at t = 3·10⁶ (no distance \
             too far below the limit given)",
            Clause::MaxDistance,
            wall,
            down(3e6),
            March {
                max_distance: 1e7,
                ..m
            },
        ),
        case(
            "the same wall, a budget of u32::MAX evaluations (no limit to speak of)",
            Clause::Budget,
            half_wall,
            down(1.0),
            budget(u32::MAX),
        ),
        case(
            "the same wall 10⁻⁴ below, within ε at once: a budget of one evaluation is enough",
            Clause::Budget,
            half_wall,
            down(1e-4),
            budget(1),
        ),
        case(
            "the same wall 150 m below, max_distance = 100",
            Clause::MaxDistance,
            half_wall,
            down(150.0),
            m,
        ),
        case(
            "an exact wall 1 m below, max_distance = 1: the step lands on it exactly at max_distance, not beyond",
            Clause::MaxDistance,
            wall,
            down(1.0),
            March { max_distance: 1.0, ..m },
        ),
        case(
            "an exact wall 1 m below, max_distance = 0.5: the first step lands on it, beyond \
             max_distance; the point a step reaches is tested for a hit before the distance: a hit at t = 1",
            Clause::MaxDistance,
            wall,
            down(1.0),
            March { max_distance: 0.5, ..m },
        ),
        case(
            "the same wall 1 m below, max_distance = 0.5, a budget of exactly the two evaluations \
             it takes: the last one lands on it, beyond max_distance, and is tested for a hit \
             first too: a hit at t = 1",
            Clause::MaxDistance,
            wall,
            down(1.0),
            March {
                max_distance: 0.5,
                ..budget(2)
            },
        ),
        case(
            "the same wall 1 m below, max_distance = 0.9995: the 13th step goes past it (t = 1 - 2^-12) \
             without a hit; the next would hit, beyond the limit",
            Clause::MaxDistance,
            half_wall,
            down(1.0),
            March {
                max_distance: 0.9995,
                ..m
            },
        ),
        case(
            "a wall 1.5 m below whose function is its distance capped at 1, max_distance = 1: the \
             first step lands exactly at max_distance, short of the wall and not beyond the limit, \
             so the march goes on: a hit at t = 1.5",
            Clause::MaxDistance,
            capped_wall,
            down(1.5),
            March { max_distance: 1.0, ..m },
        ),
        case(
            "an exact wall ε = 2^-10 below: |f| = ε at t = 0 is not below ε, so one step of ε, \
             then the hit at t = 2^-10",
            Clause::Skim,
            wall,
            down(2f32.powi(-10)),
            March {
                epsilon: 2f32.powi(-10),
                ..m
            },
        ),
        case(
            "a floor skimmed at 1.2 ε on the way to a wall 2^-9 ahead: 16 steps with f just above ε, \
             then the hit",
            Clause::Skim,
            skimmed_floor,
            (Vec3::new(0.0, 0.0, 2f32.powi(-13)), Vec3::X),
            m,
        ),
        case(
            "a slab 0.05 thick 1,200 m along x whose function is half the distance: steps of f, however small, \
             far from the origin too",
            Clause::Skim,
            far_thin_slab,
            (Vec3::ZERO, Vec3::X),
            March {
                max_distance: 2000.0,
                ..m
            },
        ),
        case(
            "a wall 10 m below (exact): a hit at t = 10",
            Clause::Fresh,
            wall,
            down(10.0),
            m,
        ),
        case(
            "then a slab 0.5 thick 5 m below: a hit at t = 5, whatever the ray before found",
            Clause::Fresh,
            slab_below,
            down(10.0),
            m,
        ),
        case(
            "a wall 2·10²⁰ m below whose function is half the distance, max_distance = 1.2·10²⁰: past \
             it at the second step (a squared distance overflows there)",
            Clause::Fresh,
            very_far_half_wall,
            down(0.0),
            March {
                max_distance: 1.2e20,
                ..m
            },
        ),
        case(
            "the same wall 6,000 m from the world's origin, 1 m below the ray's origin",
            Clause::ScaledEpsilon,
            far_half_wall,
            down(6001.0),
            m,
        ),
        case(
            "the same wall seen from (6000, 6000, 6001): ε at p scales with p's largest coordinate, not its length",
            Clause::ScaledEpsilon,
            far_half_wall,
            (Vec3::new(6000.0, 6000.0, 6001.0), -Vec3::Z),
            m,
        ),
        case(
            "the same wall 6,000 m below the world's origin, seen from (0, 0, -5999): ε at p scales with \
             p's largest |coordinate|",
            Clause::ScaledEpsilon,
            far_half_floor,
            (Vec3::new(0.0, 0.0, -5999.0), -Vec3::Z),
            m,
        ),
        {
            // From a drawn point near the world's origin.
            let mut draws = crate::exercises::draws::Draws::new(42);
            let origin = Vec3::new(draws.range(-5.0, 5.0), draws.range(-5.0, 5.0), draws.range(0.0, 5.0));
            case(
                "a wall 6,000 m away seen from near the world's origin (max_distance = 10,000)",
                Clause::ScaledEpsilon,
                far_ahead_wall,
                (origin, Vec3::Z),
                March {
                    max_distance: 10_000.0,
                    ..m
                },
            )
        },
        case(
            "a wall whose distance overstates by 2^-16: the first step lands just behind it",
            Clause::Normal,
            eager_wall,
            down(1.0),
            m,
        ),
        case(
            "a floor whose distance function is 0 below z = 0.5: the first step lands where it is flat",
            Clause::Normal,
            flat_floor,
            down(1.0),
            m,
        ),
        case(
            "a floor flat below z = 0.5 that rises along x from 1.5e-4 on: flat over the \
             difference step h = 1e-4 at the hit, not over 2h, so the normal is -dir",
            Clause::Normal,
            flat_then_rising,
            down(1.0),
            m,
        ),
        case(
            "a floor that bends down at 45° from x = 5e-5 on, hit at the origin: the central \
             differences of h = 1e-4 straddle the bend, so the x slope is -0.25, not -0.5 (forwards \
             from p) or 0 (backwards)",
            Clause::Normal,
            bend_ahead,
            down(1.0),
            m,
        ),
        case(
            "a wall whose function is a quarter of the distance, seen obliquely: its gradient is \
             short, not zero, so the normal is the gradient's direction",
            Clause::Normal,
            quarter_wall,
            (Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.6, 0.0, -0.8)),
            m,
        ),
        case(
            "a wall whose function is 2^-50 of the distance, a ray from 1 m above it (within ε at \
             once) going down obliquely: a hit at t = 0 whose gradient, 2^-50 long, is tiny but \
             not zero, so the normal is its direction, +z (no threshold on its length)",
            Clause::Normal,
            faint_wall,
            (Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.6, 0.0, -0.8)),
            m,
        ),
        case(
            "a wall at x = 1 facing -x whose function is half the distance, seen obliquely: its \
             gradient (-1/2, 0, 0) has no component above 0 and is not zero, so the normal is \
             (-1, 0, 0)",
            Clause::Normal,
            west_wall,
            (Vec3::ZERO, Vec3::new(0.6, 0.0, 0.8)),
            m,
        ),
        case(
            "a ray starting on a wall and leaving it 5e-4 rad above its plane: a hit at t = 0 whose \
             gradient points along the ray, by a hair, so the normal turns round",
            Clause::Normal,
            wall,
            (Vec3::ZERO, Vec3::new(1.0, 0.0, 5e-4).normalize()),
            m,
        ),
        case(
            "a ray starting 2^-16 above a wall (within ε) and running along it: a hit at t = 0 whose \
             gradient is square to the ray (n · dir = 0), so the normal stays as it is, unit length",
            Clause::Normal,
            wall,
            (Vec3::new(0.0, 0.0, 2f32.powi(-16)), Vec3::X),
            m,
        ),
        case(
            "a wall 1,000 m along x whose function understates by 5e-7: ε is taken at each point the march reaches",
            Clause::ScaledEpsilon,
            understating_far_wall,
            (Vec3::ZERO, Vec3::X),
            March {
                max_distance: 2000.0,
                ..m
            },
        ),
        case(
            "a box at the origin seen from (1000, 0, 0), hit 5e-4 from an edge: h from ε at the hit, not at the ray's origin",
            Clause::Curved,
            box_at_origin,
            (
                Vec3::new(1000.0, 0.0, 0.0),
                (Vec3::new(0.5, 0.4995, 0.0) - Vec3::new(1000.0, 0.0, 0.0)).normalize(),
            ),
            March {
                max_distance: 2000.0,
                ..m
            },
        ),
        case(
            "a wall tilted 45° between x and y, 2^20 m along x (the coordinates' spacing 1/16 there): \
             the normal's difference step is ε at the hit, 1 m, not a fixed fraction of a metre",
            Clause::Normal,
            far_tilted_wall,
            (Vec3::new(1_048_512.0, 0.0, 0.0), Vec3::X),
            m,
        ),
        case(
            "a wall whose distance function overstates by half: the first step lands inside, at f = -0.75",
            Clause::Overshoot,
            overshooting_wall,
            down(1.0),
            m,
        ),
        case(
            "a ball of radius 1 at (6000, 0, 0), hit obliquely at (5999.2, 0.6, 0)",
            Clause::Curved,
            far_ball,
            (Vec3::new(5990.0, 0.6, 0.0), Vec3::X),
            m,
        ),
        case(
            "a ball of radius 4 at (0, 0, -4) with ε = 1e-7, hit near its top at (0.5, 0.3, -0.04)",
            Clause::Curved,
            low_ball,
            (Vec3::new(0.5, 0.3, 3.0), -Vec3::Z),
            March { epsilon: 1e-7, ..m },
        ),
        case(
            "a floor 2^-6 below the ray from 2^20 m along x on: one step to t = 2^20, then f = 2^-6 \
             while t + f rounds to t (f32's spacing there is 2^-3): with ε fixed at 1e-4 the march \
             stands still until the steps run out, a miss (with ε at p, 1 there, a hit)",
            Clause::Skim,
            stalling_floor,
            (Vec3::ZERO, Vec3::X),
            March {
                max_distance: 2_097_152.0,
                ..m
            },
        ),
    ]
}
