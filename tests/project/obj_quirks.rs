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
