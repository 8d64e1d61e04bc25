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
    check_obj(text, file)?;
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

fn stem(file: &str) -> String {
    std::path::Path::new(file)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| file.to_string())
}

/// The line-numbered checks tobj does not make.
fn check_obj(text: &str, file: &str) -> Result<()> {
    let err = |line: usize, message: String| Error::Mesh {
        file: file.to_string(),
        line: Some(line),
        message,
    };
    let mut vertices: i64 = 0;
    let mut faces = 0usize;
    for (n, raw) in text.lines().enumerate() {
        let line = n + 1;
        let mut words = raw.split_whitespace();
        match words.next() {
            Some("v") => {
                let coords: Vec<&str> = words.collect();
                if coords.len() < 3 {
                    return Err(err(line, format!("a vertex needs x y z, got `{raw}`")));
                }
                for c in &coords[..3] {
                    match c.parse::<f32>() {
                        Ok(x) if x.is_finite() => {}
                        Ok(_) => {
                            return Err(err(
                                line,
                                format!("vertex coordinate `{c}` is not a finite number"),
                            ))
                        }
                        Err(_) => {
                            return Err(err(
                                line,
                                format!("vertex coordinate `{c}` is not a number"),
                            ))
                        }
                    }
                }
                vertices += 1;
            }
            Some("f") => {
                let corners: Vec<&str> = words.collect();
                if corners.len() < 3 {
                    return Err(err(
                        line,
                        format!("a face needs at least 3 vertices, got {}", corners.len()),
                    ));
                }
                for c in corners {
                    let first = c.split('/').next().unwrap_or("");
                    let index: i64 = first.parse().map_err(|_| {
                        err(
                            line,
                            format!("face corner `{c}` does not start with a vertex index"),
                        )
                    })?;
                    // OBJ indices are 1-based; negative ones count back from the last vertex.
                    let resolved = if index < 0 {
                        vertices + index + 1
                    } else {
                        index
                    };
                    if resolved < 1 || resolved > vertices {
                        return Err(err(
                            line,
                            format!(
                                "face refers to vertex {index}, but only {vertices} vertices are defined before this line"
                            ),
                        ));
                    }
                }
                faces += 1;
            }
            _ => {}
        }
    }
    if faces == 0 {
        return Err(Error::Mesh {
            file: file.to_string(),
            line: None,
            message: format!(
                "the mesh has no triangles ({vertices} vertices, no `f` lines): expected at least one face"
            ),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quads_are_triangulated_and_groups_merged() {
        let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\no a\nf 1 2 3 4\no b\nf -4 -2 -1\n";
        let m = parse_obj(text, "q.obj").unwrap();
        // tobj gives each group its own vertices: 4 for `a`, 3 for `b`.
        assert_eq!(m.positions.len(), 7);
        assert_eq!(m.triangles.len(), 3);
        let [i, j, k] = m.triangles[2];
        let corners = [i, j, k].map(|v| m.positions[v as usize].to_array());
        assert_eq!(corners, [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]]);
    }
}
