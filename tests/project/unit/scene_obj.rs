//! Unit tests of `src/scene/obj.rs`.

use raystep::scene::obj::*;

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
