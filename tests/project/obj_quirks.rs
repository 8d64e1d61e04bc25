//! OBJ files as editors write them: a UTF-8 byte order mark (it used to
//! drop the first vertex silently), polylines (`l`, which used to come out
//! as filled triangles, and whose bad indices had no line number), and
//! polygons of more than three corners (a concave one used to be split
//! into a wrong fan without a word).

use raystep::scene::obj::parse_obj;

#[test]
fn a_byte_order_mark_keeps_the_first_vertex() {
    let text = "\u{feff}v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    let mesh = parse_obj(text, "bom.obj").unwrap();
    assert_eq!(mesh.positions.len(), 3);
    assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
}

#[test]
fn polylines_draw_nothing_and_their_indices_are_checked() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nl 1 2 3 4\nl 2 4\n";
    let mesh = parse_obj(text, "lines.obj").unwrap();
    assert_eq!(mesh.triangles.len(), 1, "{:?}", mesh.triangles);
    let bad = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 9\n";
    let m = parse_obj(bad, "lines.obj").unwrap_err().to_string();
    assert!(
        m.contains("lines.obj") && m.contains("lines.obj:5:") && m.contains("`l` line"),
        "{m}"
    );
}

#[test]
fn convex_polygons_are_fanned_and_concave_ones_refused_with_their_line() {
    // A convex quad and pentagon: 2 + 3 triangles.
    let convex = "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 1 3 0\nf 1 2 3 4\nf 1 2 3 5 4\n";
    assert_eq!(parse_obj(convex, "c.obj").unwrap().triangles.len(), 5);
    // An arrowhead: its fan from the first corner covers the notch.
    let concave = "v 0 0 0\nv 2 1 0\nv 0 2 0\nv 1 1 0\nf 1 2 3 4\n";
    let m = parse_obj(concave, "arrow.obj").unwrap_err().to_string();
    assert!(m.contains("arrow.obj:5:") && m.contains("concave"), "{m}");
    // The same corners in the order that starts at the reflex corner
    // would fan correctly, but the polygon is still concave: refused.
    let turned = "v 0 0 0\nv 2 1 0\nv 0 2 0\nv 1 1 0\nf 4 1 2 3\n";
    assert!(parse_obj(turned, "arrow.obj").is_err());
}

/// Issue 48: a bow-tie quad (its two halves cancel in the Newell normal)
/// and a pentagram (it turns the same way at every corner, twice round)
/// were accepted and fanned over the wrong area; a convex polygon given in
/// either winding, a degenerate one on a line, and a convex one of many
/// corners still are accepted.
#[test]
fn self_intersecting_polygons_are_refused() {
    let corners = |points: &[(f64, f64)]| {
        let mut obj = String::new();
        for (x, y) in points {
            obj.push_str(&format!("v {x} {y} 0.5\n"));
        }
        obj.push('f');
        for k in 1..=points.len() {
            obj.push_str(&format!(" {k}"));
        }
        obj.push('\n');
        obj
    };
    let refused = |points: &[(f64, f64)]| {
        let m = parse_obj(&corners(points), "p.obj")
            .unwrap_err()
            .to_string();
        assert!(m.contains("self-intersecting"), "{points:?}: {m}");
    };
    refused(&[(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)]);
    refused(&[(0.0, 0.0), (3.0, 1.0), (3.0, 0.0), (0.0, 1.0)]);
    let star: Vec<(f64, f64)> = (0..5)
        .map(|k| {
            let a = std::f64::consts::TAU * (2 * k) as f64 / 5.0;
            (a.cos(), a.sin())
        })
        .collect();
    refused(&star);
    let mut square = vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
    assert_eq!(
        parse_obj(&corners(&square), "q.obj")
            .unwrap()
            .triangles
            .len(),
        2
    );
    square.reverse();
    assert_eq!(
        parse_obj(&corners(&square), "q.obj")
            .unwrap()
            .triangles
            .len(),
        2
    );
    let line = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0)];
    assert_eq!(
        parse_obj(&corners(&line), "l.obj").unwrap().triangles.len(),
        2
    );
    let round: Vec<(f64, f64)> = (0..1000)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 1000.0;
            (a.cos(), a.sin())
        })
        .collect();
    assert_eq!(
        parse_obj(&corners(&round), "r.obj")
            .unwrap()
            .triangles
            .len(),
        998
    );
}
