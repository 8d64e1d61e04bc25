//! Unit tests of `src/ch2_rasterization/clip.rs`.

use glam::DVec3;
use raystep::ch2_rasterization::clip::*;

fn v(x: f64, y: f64, z: f64, c: f64) -> ClipVertex {
    ClipVertex {
        p: DVec3::new(x, y, z),
        attr: [c, 0.0, 0.0, 0.0, 0.0, 0.0],
    }
}

#[test]
fn one_vertex_behind_gives_a_quad_with_interpolated_attributes() {
    // (0,0,-3) and (2,0,-3) in front, (0,0,1) behind; near = 1.
    let tri = [
        v(0.0, 0.0, -3.0, 0.0),
        v(2.0, 0.0, -3.0, 1.0),
        v(0.0, 0.0, 1.0, 2.0),
    ];
    let out = clip_near(&tri, 1.0);
    assert_eq!(out.len(), 4);
    assert!(out.iter().all(|v| v.p.z <= -1.0));
    // The cut on edge (2,0,-3)→(0,0,1) is half way: (1, 0, -1), colour 1.5.
    assert!(out
        .iter()
        .any(|q| q.p == DVec3::new(1.0, 0.0, -1.0) && q.attr[0] == 1.5));
    // On (0,0,-3)→(0,0,1), from the front end: half way, colour 1.
    assert!(out
        .iter()
        .any(|q| q.p == DVec3::new(0.0, 0.0, -1.0) && q.attr[0] == 1.0));
}

#[test]
fn all_behind_gives_nothing_and_nan_is_dropped() {
    let tri = [
        v(0.0, 0.0, 1.0, 0.0),
        v(1.0, 0.0, 2.0, 0.0),
        v(0.0, 1.0, 0.0, 0.0),
    ];
    assert!(clip_near(&tri, 1e-3).is_empty());
    let nan = [
        v(0.0, 0.0, f64::NAN, 0.0),
        v(1.0, 0.0, -2.0, 0.0),
        v(0.0, 1.0, -2.0, 0.0),
    ];
    assert!(clip_near(&nan, 1e-3).len() <= 2);
}

#[test]
fn shared_edges_are_cut_identically() {
    let (a, b) = (v(0.3, 0.1, -2.7, 0.0), v(-0.9, 0.4, 0.6, 1.0));
    let c1 = v(1.0, 1.0, -1.0, 0.0);
    let c2 = v(-1.0, -1.0, -5.0, 0.0);
    let t1 = clip_near(&[a, b, c1], 0.01);
    let t2 = clip_near(&[b, a, c2], 0.01);
    let d = |q: &ClipVertex| q.p.z + 0.01;
    let expected = a.lerp(&b, d(&a) / (d(&a) - d(&b))).p;
    assert!(t1
        .iter()
        .any(|q| q.p.x == expected.x && q.p.y == expected.y));
    assert!(t2
        .iter()
        .any(|q| q.p.x == expected.x && q.p.y == expected.y));
}
