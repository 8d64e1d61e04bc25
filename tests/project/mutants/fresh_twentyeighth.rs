//! The twenty-eighth fresh set (2026-11-30), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: defensive numerics (A, 50 wrong), code adapted from the
//! lesson's own functions (B, 49), and code fitted to the course's scenes
//! and examples (C, 51); 76 right alternatives, all of which pass. With
//! the grader of 22bd81a, 9 of the 150 wrong ones passed under seed 51 or
//! 52. The two that now fail under seeds 51 to 53 are here: a march whose
//! ε is floored at 10⁻⁵, and the top-left rule decided on the corners'
//! whole pixels. Of the other seven, two refuse an answer that is not
//! finite (project_point at a subnormal z, ray_plane at a t past f32's
//! range: the exact answer is not an f32 there), two decide roulette in
//! f32 or lift the disk without max(0) (right, as earlier sets rule), one
//! gives Fresnel's formula the indices unswapped for light from inside
//! (right: swapping them swaps r_s and r_p, whose mean stays), one
//! refuses a triangle whose |e1 × e2|² overflows (the course's own
//! solution squares it too), and one forms the edge function from p − a
//! and p − b (its rounding scales with |p − a|, within the contract).

use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch2, ch4};

use super::fails_every;
use super::knobs::{self, MarchEps, RasterKnobs, SceneKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn a_floored_epsilon_fails() {
    fails("trace_scene: ε at the point, never below 10⁻⁵", || {
        ch4::check_trace_scene(|sdf, o, d, m| {
            let k = SceneKnobs {
                eps: MarchEps::Floored,
                ..Default::default()
            };
            knobs::trace_scene(k, sdf, o, d, m)
        })
    });
}

#[test]
fn a_fill_rule_on_whole_pixels_fails() {
    fails(
        "rasterize_triangle: the top-left rule on the corners' whole pixels",
        || {
            ch2::check_rasterize_triangle(|v, c, w, h, depth, image| {
                let k = RasterKnobs {
                    whole_pixel_rule: true,
                    ..Default::default()
                };
                knobs::rasterize(k, v, c, (w, h), depth, image)
            })
        },
    );
}
