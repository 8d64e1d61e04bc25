//! The structured fuzzer's OBJ files: a seed mesh, half the time with odd
//! edits (a byte-order mark, `l` and `p` lines, huge and negative indices,
//! a concave polygon, NaN and infinite coordinates, empty and short faces,
//! bad texture and normal indices, tens of thousands of collapsed or
//! overlapping triangles away from the origin, CRLF line endings), each
//! named in the case's list of edits.

use arbitrary::{Result, Unstructured};

use super::OBJ_SEEDS;

/// Lines an odd OBJ may gain.
const ODD_LINES: &[&str] = &[
    "l 1 2 3",
    "l 1 99999",
    "p 1",
    "p 1 2 3",
    "f 1 2 99999999999",
    "f 1 2 18446744073709551617",
    "f -1 -2 -99999",
    "f -1 -2 -3",
    "f 0 1 2",
    "v nan 0 0",
    "v inf 1 1",
    "v 0 -inf nan",
    "v 1e39 0 0",
    "v 0 0",
    "v 1 2 3 4 5",
    "f",
    "f 1",
    "f 1 2",
    "f 1/99/1 2/1/99 3",
    "vn nan nan nan",
    "vt 1e39 nan",
    "mtllib missing.mtl",
    "usemtl nothing",
    "s off",
    "g",
    "o",
];

/// A concave polygon (a star of ten corners) with relative indices.
const STAR: &str = "v 0 1 0\nv 0.2 0.2 0\nv 1 0 0\nv 0.2 -0.2 0\nv 0 -1 0\n\
v -0.2 -0.2 0\nv -1 0 0\nv -0.2 0.2 0\nv 0.5 0.5 0\nv -0.5 -0.5 0\n\
f -10 -9 -8 -7 -6 -5 -4 -3 -2 -1";

/// An OBJ file: a seed, half the time with odd edits.
pub(super) fn odd_obj(u: &mut Unstructured, edits: &mut Vec<String>) -> Result<String> {
    let seed = OBJ_SEEDS[u.choose_index(OBJ_SEEDS.len())?];
    if u.ratio(1u8, 2)? {
        return Ok(seed.to_string());
    }
    let mut lines: Vec<String> = seed.lines().map(str::to_string).collect();
    let (mut bom, mut crlf) = (false, false);
    for _ in 0..u.int_in_range(1..=4)? {
        let at = u.int_in_range(0..=lines.len())?;
        match u.int_in_range(0..=5u8)? {
            0 => bom = true,
            1 => crlf = true,
            2 => lines.insert(at, STAR.into()),
            // The same triangle many times, collapsed to a point or not,
            // away from the origin (up to the fuzzer's 1 MiB file limit).
            3 => {
                let n = [10usize, 1000, 20_000, 80_000][u.choose_index(4)?];
                let collapsed = u.ratio(1u8, 2)?;
                lines.extend(["v 5 5 5", "v 6 5 5", "v 5 6 5"].map(String::from));
                let face = if collapsed {
                    "f -1 -1 -1"
                } else {
                    "f -3 -2 -1"
                };
                lines.extend(std::iter::repeat_n(face.to_string(), n));
                let what = if collapsed {
                    "collapsed"
                } else {
                    "overlapping"
                };
                edits.push(format!("obj: {n} {what} triangles"));
            }
            _ => {
                let line = ODD_LINES[u.choose_index(ODD_LINES.len())?];
                edits.push(format!("obj: `{line}` at line {}", at + 1));
                lines.insert(at, line.into());
            }
        }
    }
    if bom {
        edits.push("obj: byte-order mark".into());
    }
    if crlf {
        edits.push("obj: CRLF".into());
    }
    let text = lines.join(if crlf { "\r\n" } else { "\n" });
    Ok(if bom { format!("\u{feff}{text}") } else { text })
}
