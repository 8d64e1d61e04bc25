//! Exercise 3.5's hand-made nodes: boxes and centroids given directly,
//! as a node passes them to the split, each with the axis it must be split
//! on, or none where it must stay a leaf.

use glam::Vec3;

use crate::exercises::draws::Draws;

/// A hand-made node: what it is, its boxes and centroids, and the axis
/// it must be split on (`None`: it must stay a leaf).
pub(super) type HandNode = (&'static str, Vec<[Vec3; 2]>, Vec<Vec3>, Option<usize>);

/// The hand-made nodes. Boxes are given directly, as the node passes them.
pub(super) fn hand_nodes() -> Vec<HandNode> {
    let v = Vec3::new;
    // Four triangles whose boxes are all the unit cube: any split costs
    // 1 + 4, the leaf 4.
    let cube = [v(0.0, 0.0, 0.0), v(1.0, 1.0, 1.0)];
    let spread = vec![
        v(0.2, 0.5, 0.4),
        v(0.6, 0.3, 0.5),
        v(0.4, 0.7, 0.6),
        v(0.8, 0.4, 0.3),
    ];
    let mut nodes = vec![(
        "four triangles whose boxes are all the unit cube",
        vec![cube; 4],
        spread,
        None,
    )];
    // Two small triangles far apart along each axis: a split on it.
    for (axis, what) in [
        (0, "two small triangles 10 apart along x"),
        (1, "two small triangles 10 apart along y"),
        (2, "two small triangles 10 apart along z"),
    ] {
        let mut far = Vec3::ZERO;
        far[axis] = 10.0;
        let b = |c: Vec3| [c - 0.1, c + 0.1];
        nodes.push((
            what,
            vec![b(Vec3::ZERO), b(far)],
            vec![Vec3::ZERO, far],
            Some(axis),
        ));
    }
    // One centroid, three different boxes: no plane separates them.
    nodes.push((
        "three triangles with one centroid",
        vec![
            [v(-1.0, -0.1, -0.1), v(1.0, 0.1, 0.1)],
            [v(-0.1, -1.0, -0.1), v(0.1, 1.0, 0.1)],
            [v(-0.1, -0.1, -1.0), v(0.1, 0.1, 1.0)],
        ],
        vec![Vec3::ZERO; 3],
        None,
    ));
    // Three cubes at x = 10, 0, 0, in that order: the two equal centroids
    // are neighbours only once sorted (a split between 0 and 10 pays).
    let cube = |x: f32| [v(x - 0.5, -0.5, -0.5), v(x + 0.5, 0.5, 0.5)];
    nodes.push((
        "three unit cubes at x = 10, 0 and 0, in that order",
        vec![cube(10.0), cube(0.0), cube(0.0)],
        vec![v(10.0, 0.0, 0.0), Vec3::ZERO, Vec3::ZERO],
        Some(0),
    ));
    // Six long boxes reaching left from x = 10⁶ and six reaching right
    // from the next f32 up (their centroids): the one plane that parts
    // them is that next float itself (a plane halfway, 10⁶ + 2⁻⁵, rounds
    // to 10⁶, which parts nothing).
    let (x0, x1) = (1.0e6f32, 1.0e6f32.next_up());
    let thin = |lo: f32, hi: f32| [v(lo, -0.1, -0.1), v(hi, 0.1, 0.1)];
    nodes.push((
        "six boxes with centroids at x = 10^6 and six at the next float up",
        [thin(x0 - 10.0, x0); 6]
            .into_iter()
            .chain([thin(x1, x1 + 10.0); 6])
            .collect(),
        [v(x0, 0.0, 0.0); 6]
            .into_iter()
            .chain([v(x1, 0.0, 0.0); 6])
            .collect(),
        Some(0),
    ));
    let mut d = Draws::new(38);
    // Two unit cubes s apart along x (s from 0.2 to 0.9, drawn): the
    // children's areas over the node's are 12 / (6 + 4s), between 1 and
    // 2, so the split costs more than the leaf only with C_trav counted.
    let s = d.range(0.2, 0.9);
    let at = d.place_for(1.0, 2.0);
    nodes.push((
        "two unit cubes overlapping along x (a split saves less than C_trav)",
        vec![
            [at, at + 1.0],
            [at + v(s, 0.0, 0.0), at + v(1.0 + s, 1.0, 1.0)],
        ],
        vec![at + 0.5, at + v(0.5 + s, 0.5, 0.5)],
        None,
    ));
    // A needle: twelve boxes half a step long, a step apart along x
    // (steps from 10⁻² to 10³, drawn), 10⁻⁹ of a step thick. Splitting
    // it pays; its area, 4 · length · thickness, cancels to 0 if taken
    // as a square of the sum of extents less the sum of their squares.
    let step = d.decades(-2.0, 3.0);
    let w = step * 1e-9;
    let needle: Vec<[Vec3; 2]> = (0..12)
        .map(|i| {
            let x = i as f32 * step;
            [v(x, 0.0, 0.0), v(x + 0.5 * step, w, w)]
        })
        .collect();
    let centres = needle.iter().map(|[lo, hi]| (*lo + *hi) * 0.5).collect();
    nodes.push((
        "a needle of twelve boxes along x, 10^-9 of a step thick",
        needle,
        centres,
        Some(0),
    ));
    nodes
}
