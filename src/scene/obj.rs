//! Wavefront OBJ meshes through tobj.
//!
//! tobj does the loading. Before it runs, one quick pass over the text checks
//! what tobj would report without a line number (or not at all): coordinates
//! that are not finite numbers, faces that refer to vertices that do not
//! exist, faces with fewer than three corners, and files with no faces.

use glam::Vec3;

use crate::core::error::{Error, Result};
use crate::scene::mesh::Mesh;

/// Parses OBJ text into one mesh (all groups merged, polygons triangulated).
/// `file` names the source in errors. tobj loads each group (`o`/`g`) with
/// its own vertex array, so a vertex shared by two groups appears once per
/// group: mesh checks see the seam between groups as a boundary.
pub fn parse_obj(text: &str, file: &str) -> Result<Mesh> {
    parse_obj_limited(text, file, DEFAULT_MAX_TRIANGLES)
}

/// [`parse_obj`] with a limit on the number of triangles.
pub fn parse_obj_limited(text: &str, file: &str, max_triangles: usize) -> Result<Mesh> {
    // A UTF-8 byte order mark would glue itself to the first keyword (and
    // the first vertex would vanish).
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let text = normalize_line_endings(text);
    check_obj(text.as_ref(), file, max_triangles)?;
    let text = surfaces_only(text.as_ref());
    let text = text.as_ref();
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: false,
        ignore_points: true,
        ignore_lines: true,
    };
    let mut reader = std::io::BufReader::new(text.as_bytes());
    let (models, _) = tobj::load_obj_buf(&mut reader, &options, |_| {
        Ok((Vec::new(), Default::default()))
    })
    .map_err(|e| Error::Mesh {
        file: file.to_string(),
        line: None,
        message: format!("not a valid OBJ file: {e}"),
    })?;
    let mut mesh = Mesh::new(stem(file), Vec::new(), Vec::new());
    for model in models {
        let m = model.mesh;
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(
            m.positions
                .chunks_exact(3)
                .map(|p| Vec3::new(p[0], p[1], p[2])),
        );
        mesh.triangles.extend(
            m.indices
                .chunks_exact(3)
                .map(|t| [base + t[0], base + t[1], base + t[2]]),
        );
    }
    if mesh.triangles.is_empty() {
        return Err(Error::Mesh {
            file: file.to_string(),
            line: None,
            message: "the mesh has no triangles: expected at least one `f` line".into(),
        });
    }
    Ok(mesh)
}

/// The text with every polyline (`l`) and point (`p`) line blanked, after
/// [`check_obj`] has checked their indices: they are not surfaces, and
/// tobj would otherwise fill some of them in as triangles. Blanked, not
/// removed, so that line numbers stay.
fn surfaces_only(text: &str) -> std::borrow::Cow<'_, str> {
    let is_line = |l: &str| matches!(l.split_whitespace().next(), Some("l" | "p"));
    if !text.lines().any(is_line) {
        return text.into();
    }
    let mut out = String::with_capacity(text.len());
    for l in text.lines() {
        if !is_line(l) {
            out.push_str(l);
        }
        out.push('\n');
    }
    out.into()
}

fn stem(file: &str) -> String {
    std::path::Path::new(file)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| file.to_string())
}

/// The largest number of triangles one OBJ file may hold (after polygons
/// are split into triangles); raise it with `--max-triangles`. Peak memory
/// per triangle, measured on a 1,000,000-triangle grid (64x64 image,
/// `/usr/bin/time -f %M`): chapter 2 about 0.66 KB (its screen triangles;
/// 1.5 KB before their lists were joined per worker), chapters 3 to 6
/// about 0.38 KB, chapter 1 0.2 KB; at 20 million that is about 13 GB
/// (extrapolated, not run here).
pub const DEFAULT_MAX_TRIANGLES: usize = 20_000_000;

/// Line endings made `\n`: tobj splits lines at `\n` only, so a file with
/// old Mac (CR-only) endings would be one long line.
pub fn normalize_line_endings(text: &str) -> std::borrow::Cow<'_, str> {
    if text.contains('\r') {
        text.replace("\r\n", "\n").replace('\r', "\n").into()
    } else {
        text.into()
    }
}

/// The line-numbered checks tobj does not make: every number parses and is
/// finite in f32, every face index (vertex, texture and normal) exists, and
/// the triangle count stays within `max_triangles`.
fn check_obj(text: &str, file: &str, max_triangles: usize) -> Result<()> {
    let err = |line: usize, message: String| Error::Mesh {
        file: file.to_string(),
        line: Some(line),
        message,
    };
    let numbers = |line: usize, what: &str, words: &[&str]| -> Result<Vec<f32>> {
        words
            .iter()
            .map(|c| match c.parse::<f32>() {
                Ok(x) if x.is_finite() => Ok(x),
                Ok(_) => Err(err(
                    line,
                    format!("{what} `{c}` is not a finite number in f32"),
                )),
                Err(_) => Err(err(line, format!("{what} `{c}` is not a number"))),
            })
            .collect()
    };
    // Vertices, texture coordinates and normals defined so far.
    let mut counts = [0i64; 3];
    // The vertices, to tell a convex polygon (split into a fan of
    // triangles) from a concave one (which a fan would cover wrongly).
    let mut positions: Vec<Vec3> = Vec::new();
    let mut first_colour: Option<(bool, usize)> = None;
    let mut faces = 0usize;
    let mut triangles = 0usize;
    for (n, raw) in text.lines().enumerate() {
        let line = n + 1;
        let mut words = raw.split_whitespace();
        let Some(kind) = words.next() else { continue };
        let rest: Vec<&str> = words.collect();
        match kind {
            "v" => {
                let xyz = numbers(line, "vertex coordinate", &rest)?;
                match xyz.len() {
                    3 | 6 => {}
                    4 if xyz[3] != 0.0 && xyz[..3].iter().all(|c| (c / xyz[3]).is_finite()) => {}
                    4 => {
                        return Err(err(
                            line,
                            format!("the weight w = {} of `v x y z w` must be non-zero and keep x/w, y/w, z/w finite", xyz[3]),
                        ))
                    }
                    k => {
                        return Err(err(
                            line,
                            format!("a vertex is `v x y z`, `v x y z w` or `v x y z r g b`; got {k} numbers"),
                        ))
                    }
                }
                // tobj needs colours on every vertex or on none.
                let coloured = xyz.len() == 6;
                match first_colour {
                    None => first_colour = Some((coloured, line)),
                    Some((c, first)) if c != coloured => {
                        return Err(err(
                            line,
                            format!(
                                "vertex colours (`v x y z r g b`) must be on every vertex or none; line {first} {} one",
                                if c { "has" } else { "has no" }
                            ),
                        ))
                    }
                    Some(_) => {}
                }
                counts[0] += 1;
                let w = if xyz.len() == 4 { xyz[3] } else { 1.0 };
                positions.push(Vec3::new(xyz[0], xyz[1], xyz[2]) / w);
            }
            "vt" | "vn" => {
                let need = if kind == "vt" { 2 } else { 3 };
                let values = numbers(line, "coordinate", &rest)?;
                if values.len() < need || values.len() > 3 {
                    return Err(err(
                        line,
                        format!("`{kind}` takes {need} to 3 numbers, got {}", values.len()),
                    ));
                }
                counts[if kind == "vt" { 1 } else { 2 }] += 1;
            }
            "f" => {
                if rest.len() < 3 {
                    return Err(err(
                        line,
                        format!("a face needs at least 3 vertices, got {}", rest.len()),
                    ));
                }
                for c in &rest {
                    check_corner(c, &counts).map_err(|why| err(line, why))?;
                }
                if rest.len() > 3 {
                    let corners: Vec<Vec3> = rest
                        .iter()
                        .map(|c| {
                            let i: i64 = c.split('/').next().unwrap_or("").parse().unwrap_or(1);
                            let i = if i < 0 { counts[0] + i } else { i - 1 };
                            positions[i as usize]
                        })
                        .collect();
                    if !is_convex(&corners) {
                        return Err(err(
                            line,
                            format!(
                                "a concave or self-intersecting polygon of {} vertices: \
                                 a fan of triangles would cover the wrong area; split it into \
                                 triangles",
                                rest.len()
                            ),
                        ));
                    }
                }
                faces += 1;
                triangles += rest.len() - 2;
                if triangles > max_triangles {
                    return Err(err(
                        line,
                        format!("more than {max_triangles} triangles, the most this file may add (raise the limit with --max-triangles)"),
                    ));
                }
            }
            "l" | "p" => {
                // Polylines and points draw nothing, but their indices must
                // exist like a face's.
                for c in &rest {
                    check_corner(c, &counts)
                        .map_err(|why| err(line, format!("`{kind}` line: {why}")))?;
                }
            }
            _ => {}
        }
    }
    if faces == 0 {
        return Err(Error::Mesh {
            file: file.to_string(),
            line: None,
            message: format!(
                "the mesh has no triangles ({} vertices, no `f` lines): expected at least one face",
                counts[0]
            ),
        });
    }
    Ok(())
}

/// Whether a polygon is convex, so that the fan from its first corner
/// covers it exactly: its corners turn the same way all round (about its
/// Newell normal, collinear corners counting as either way) and turn once
/// round, not twice (a pentagram turns the same way at every corner). A
/// bow-tie's two halves cancel in the Newell normal: a polygon whose
/// normal vanishes is convex only if all its corners are on one line (a
/// zero-area face, harmless).
fn is_convex(corners: &[Vec3]) -> bool {
    let n = corners.len();
    let p: Vec<glam::DVec3> = corners.iter().map(|c| c.as_dvec3()).collect();
    let normal = (0..n).fold(glam::DVec3::ZERO, |acc, i| {
        let (a, b) = (p[i], p[(i + 1) % n]);
        acc + glam::DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        )
    });
    let scale = p
        .iter()
        .map(|q| (*q - p[0]).length_squared())
        .fold(0.0f64, f64::max);
    let turns = |i: usize| {
        let (a, b, c) = (p[i], p[(i + 1) % n], p[(i + 2) % n]);
        (b - a, c - b)
    };
    if normal.length() <= 1e-6 * scale {
        return (0..n).all(|i| {
            let (e1, e2) = turns(i);
            e1.cross(e2).length() <= 1e-6 * scale
        });
    }
    let unit = normal.normalize();
    let mut turning = 0.0;
    for i in 0..n {
        let (e1, e2) = turns(i);
        let cross = e1.cross(e2).dot(unit);
        if cross < -1e-6 * scale {
            return false;
        }
        if e1 != glam::DVec3::ZERO && e2 != glam::DVec3::ZERO {
            turning += cross.atan2(e1.dot(e2));
        }
    }
    turning < 3.0 * std::f64::consts::PI
}

/// One face corner `v`, `v/vt`, `v//vn` or `v/vt/vn`: every index given is
/// an integer that names an element defined before this line (negative ones
/// count back from the last).
fn check_corner(corner: &str, counts: &[i64; 3]) -> std::result::Result<(), String> {
    let parts: Vec<&str> = corner.split('/').collect();
    if parts.len() > 3 {
        return Err(format!(
            "face corner `{corner}` has more than three `/`-separated indices"
        ));
    }
    const NAMES: [&str; 3] = ["vertex", "texture coordinate", "normal"];
    const PLURALS: [&str; 3] = ["vertices", "texture coordinates", "normals"];
    for (k, part) in parts.iter().enumerate() {
        if part.is_empty() && k > 0 {
            continue;
        }
        let index: i64 = part.parse().map_err(|_| {
            format!(
                "face corner `{corner}`: `{part}` is not a {} index (an integer)",
                NAMES[k]
            )
        })?;
        let resolved = if index < 0 {
            counts[k] + index + 1
        } else {
            index
        };
        if resolved < 1 || resolved > counts[k] {
            return Err(format!(
                "face corner `{corner}` refers to {} {index}, but only {} {} are defined before this line",
                NAMES[k], counts[k], PLURALS[k]
            ));
        }
    }
    Ok(())
}
