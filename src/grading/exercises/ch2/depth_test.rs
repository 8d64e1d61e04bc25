//! Exercise 2.3, the depth test: a sequence of tests on a small buffer,
//! then drawn runs on fresh buffers small and large over every kind of
//! depth (ties, neighbouring f32 numbers, subnormals, zeros and
//! infinities and NaNs of both signs, repeats).

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
        // Zeros of both signs: equal, so the second of each pair is a tie.
        (1, 0.0, true),
        (1, -0.0, false),
        (2, -0.0, true),
        (2, 0.0, false),
    ];
    let ties = [2, 10, 12];
    // A fourth sample holds a depth from before the first test, and no
    // test touches it: it must stay.
    let mut buffer = vec![inf, inf, inf, 9.0];
    let mut fails = Vec::new();
    let mut tie_passed = false;
    for (i, (index, z, want)) in steps.into_iter().enumerate() {
        let got = f(&mut buffer, index, z);
        tie_passed |= ties.contains(&i) && got;
        if got != want {
            fails.push((
                1.0,
                format!(
                    "step {i}: depth_test(index {index}, z {z}) returned {got}, expected {want}"
                ),
            ));
        }
    }
    // By bits: a tie of zeros keeps the zero drawn first.
    let expected: [f32; 4] = [0.5, 0.0, -0.0, 9.0];
    if buffer
        .iter()
        .map(|z| z.to_bits())
        .ne(expected.iter().map(|z| z.to_bits()))
    {
        fails.push((
            1.0,
            format!("buffer ends as {buffer:?}, expected {expected:?}"),
        ));
    }
    // The last passing step again, at the same index of a fresh buffer:
    // it passes there (nothing of the last buffer carries over).
    let mut fresh = vec![inf; 4];
    if !f(&mut fresh, 2, -0.0) || fresh[2].to_bits() != (-0.0f32).to_bits() {
        fails.push((
            1.0,
            format!(
                "on a fresh buffer of infinities, depth_test(index 2, z -0) after the steps above \
                 returned false or did not store -0 (the buffer: {fresh:?}): each test reads the \
                 buffer it is given"
            ),
        ));
    }
    // A buffer of 2^24 + 3 samples (a 4,096 x 4,097 image): its last
    // indices are as exact as the first, and a test there touches that
    // sample alone.
    let top = (1usize << 24) + 1;
    let mut large = vec![inf; top + 2];
    let passed = [f(&mut large, top, 2.0), f(&mut large, top + 1, 3.0)];
    if passed != [true, true]
        || large[top - 1..]
            .iter()
            .map(|z| z.to_bits())
            .ne([inf, 2.0, 3.0].map(f32::to_bits))
    {
        fails.push((
            1.0,
            format!(
                "on a buffer of 2^24 + 3 samples, depth_test(index 2^24 + 1, z 2) then (index 2^24 + 2, z 3) \
                 returned {passed:?} and left its last three samples {:?}, expected [true, true] and \
                 [inf, 2, 3]",
                &large[top - 1..]
            ),
        ));
    }
    drop(large);
    // Drawn runs of tests, each on a fresh drawn buffer: two small ones
    // and one of 2^16 to 2^17 samples (an index past 65,535 is an index
    // like any other). Each run starts with the last run's last passing
    // test again, on an empty sample: nothing of the last buffer may carry
    // over to the next.
    let mut draws = Draws::new(23);
    let mut last_pass = None;
    for run in 0..3 {
        let size = match run {
            1 => draws.count(1 << 16, 1 << 17),
            _ => draws.count(1, 64),
        };
        match drawn_run(f, &mut draws, size, last_pass) {
            Ok(pass) => last_pass = pass.or(last_pass),
            Err(fail) => {
                fails.push((1.0, format!("run {run} on {size} samples, {fail}")));
                break;
            }
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

/// One drawn run of tests on a drawn buffer of `size` samples (the first
/// test `first`, where it is given, on an empty sample): depths over
/// twelve decades of both signs, subnormal ones, ties (-0 against 0 too),
/// depths one f32 step either side of the stored one, zeros, infinities
/// and NaNs of both signs, repeats. Its last passing test, or what went
/// wrong.
fn drawn_run(
    f: fn(&mut [f32], usize, f32) -> bool,
    draws: &mut Draws,
    size: usize,
    first: Option<(usize, f32)>,
) -> Result<Option<(usize, f32)>, String> {
    let inf = f32::INFINITY;
    let (mut theirs, mut ours) = (vec![inf; size], vec![inf; size]);
    // A third of the samples hold a depth before the first test.
    for (t, o) in theirs.iter_mut().zip(&mut ours) {
        if draws.unit() < 1.0 / 3.0 {
            *o = draws.decades(-6.0, 6.0);
            *t = *o;
        }
    }
    let first = first.map(|(i, z)| (i % size, z));
    if let Some((i, _)) = first {
        (theirs[i], ours[i]) = (inf, inf);
    }
    let mut last_pass = None;
    // Every sample is compared after each test on a small buffer; on a
    // large one the tested sample after each, and all of them at the end.
    let small = size <= 64;
    let mut last: Option<(usize, f32)> = None;
    for step in 0..draws.count(200, 2000) {
        draws.next_case();
        let mut index = match (step, first) {
            (0, Some((i, _))) => i,
            _ => draws.count(0, size - 1),
        };
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
        let (stored, step_out) = (ours[index], draws.count(0, 17));
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
            // A subnormal depth of either sign: a depth like any other.
            11 => draws.sign() * f32::from_bits(draws.count(1, 0x007f_ffff) as u32),
            // A negative depth (behind the camera is not this test's
            // business: smaller is nearer).
            12 => -draws.decades(-6.0, 6.0),
            _ => draws.decades(-6.0, 6.0),
        };
        let z = match (step, first) {
            (0, Some((_, z))) => z,
            _ => again.unwrap_or(z),
        };
        last = Some((index, z));
        let want = z < ours[index];
        if want {
            ours[index] = z;
            last_pass = Some((index, z));
        }
        let got = f(&mut theirs, index, z);
        // The tested sample, then the others: as they were.
        let at = if got != want || first_difference(&theirs, &ours, index..index + 1).is_some() {
            Some(index)
        } else if small {
            first_difference(&theirs, &ours, 0..size)
        } else {
            None
        };
        if let Some(i) = at {
            let what = match i == index {
                true => "",
                false => " at another sample",
            };
            return Err(format!(
                "drawn step {step}: depth_test(index {index}, z {z}) returned {got} and left {}{what} \
                 (index {i}), expected {want} and {}",
                theirs[i], ours[i]
            ));
        }
    }
    match first_difference(&theirs, &ours, 0..size) {
        Some(i) => Err(format!(
            "after the run, sample {i} holds {}, expected {}",
            theirs[i], ours[i]
        )),
        None => Ok(last_pass),
    }
}

/// The first sample of `range` whose bits differ between the two buffers.
fn first_difference(theirs: &[f32], ours: &[f32], range: std::ops::Range<usize>) -> Option<usize> {
    range
        .into_iter()
        .find(|&i| theirs[i].to_bits() != ours[i].to_bits())
}
