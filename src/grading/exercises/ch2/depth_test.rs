//! Exercise 2.3, the depth test: a sequence of tests on a small buffer,
//! then a drawn run over every kind of depth (ties, neighbouring f32
//! numbers, zeros and infinities and NaNs of both signs, repeats).

use super::{worst_of, NOT_STORED, TIE};
use crate::exercise::Check;
use crate::exercises::draws::Draws;

/// Runs a sequence of depth tests on a small buffer against the expected
/// results and final contents.
pub fn check_depth_test(f: fn(&mut [f32], usize, f32) -> bool) -> Check {
    let inf = f32::INFINITY;
    // (index, z, passes)
    let steps = [
        (0, 5.0, true),
        (0, 7.0, false),
        (0, 5.0, false), // a tie keeps the first
        (1, 2.0, true),
        (0, 3.0, true),
        (1, f32::NAN, false),
        (2, f32::NAN, false), // NaN on an empty sample: nothing stored
        (2, inf, false),
        (0, 0.5, true),
    ];
    // A fourth sample holds a depth from before the first test, and no
    // test touches it: it must stay.
    let mut buffer = vec![inf, inf, inf, 9.0];
    let mut fails = Vec::new();
    let mut tie_passed = false;
    for (i, (index, z, want)) in steps.into_iter().enumerate() {
        let got = f(&mut buffer, index, z);
        tie_passed |= i == 2 && got;
        if got != want {
            fails.push((
                1.0,
                format!(
                    "step {i}: depth_test(index {index}, z {z}) returned {got}, expected {want}"
                ),
            ));
        }
    }
    let expected = [0.5, 2.0, inf, 9.0];
    if buffer != expected {
        fails.push((
            1.0,
            format!("buffer ends as {buffer:?}, expected {expected:?}"),
        ));
    }
    // A drawn run of tests on a drawn buffer: depths over twelve decades,
    // ties (-0 against 0 too), depths one f32 step either side of the
    // stored one, zeros, infinities of both signs and NaNs of both signs,
    // as many as the run draws.
    let mut draws = Draws::new(23);
    let size = draws.count(1, 64);
    let (mut theirs, mut ours) = (vec![inf; size], vec![inf; size]);
    // A third of the samples hold a depth before the first test.
    for (t, o) in theirs.iter_mut().zip(&mut ours) {
        if draws.unit() < 1.0 / 3.0 {
            *o = draws.decades(-6.0, 6.0);
            *t = *o;
        }
    }
    let mut last: Option<(usize, f32)> = None;
    for step in 0..draws.count(200, 2000) {
        draws.next_case();
        let mut index = draws.count(0, size - 1);
        // Now and then the last test again, exactly: now a tie at best.
        let again = match last {
            Some((i, z)) if draws.unit() < 0.1 => {
                index = i;
                Some(z)
            }
            _ => None,
        };
        // Next to the stored depth: one f32 step nearer or farther (a
        // nearer depth by the smallest amount is still nearer).
        let (stored, step_out) = (ours[index], draws.count(0, 14));
        let z = match step_out {
            0 => stored,
            1 => f32::NAN,
            2 => inf,
            3 => 0.0,
            4 if stored > 0.0 => stored.next_down(),
            5 if stored > 0.0 && stored < inf => stored.next_up(),
            6 if stored > 0.0 && stored < inf => stored * (1.0 - 4.0 * f32::EPSILON),
            // A NaN with its sign bit set, the other zero (a tie), -∞.
            7 => -f32::NAN,
            8 if stored == 0.0 => -stored,
            9 => -inf,
            // The largest finite depth, on an empty sample where there is
            // one: it passes.
            10 => {
                if let Some(empty) = ours.iter().position(|&d| d == inf) {
                    index = empty;
                }
                f32::MAX
            }
            _ => draws.decades(-6.0, 6.0),
        };
        let z = again.unwrap_or(z);
        last = Some((index, z));
        let want = z < ours[index];
        if want {
            ours[index] = z;
        }
        let got = f(&mut theirs, index, z);
        // The tested sample, then the others: as they were.
        let other = (0..size).find(|&i| theirs[i].to_bits() != ours[i].to_bits());
        let at = if got != want { Some(index) } else { other };
        if let Some(i) = at {
            let what = match i == index {
                true => "",
                false => " at another sample",
            };
            fails.push((
                1.0,
                format!(
                    "drawn step {step}: depth_test(index {index}, z {z}) returned {got} and left {}{what} \
                     (index {i}), expected {want} and {}",
                    theirs[i], ours[i]
                ),
            ));
            break;
        }
    }
    let check = worst_of(fails.into_iter(), 0.0, "every step matches");
    if check.passed() {
        check
    } else if buffer[..3] == [inf; 3] {
        check.with_symptom(NOT_STORED)
    } else if tie_passed {
        check.with_symptom(TIE)
    } else {
        check
    }
}
