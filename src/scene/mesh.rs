//! Triangle meshes: the lecture's "vertices as triplets of coordinates,
//! triangles as triplets of indices", plus the procedural shapes scene files
//! can ask for (the lecture's tetrahedron, an icosphere, a rectangle, a box).

use std::collections::BTreeSet;

use glam::{Mat4, Vec3};

/// A triangle mesh in world space.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// A name for reports (the object's name or file stem).
    pub name: String,
    /// Vertex positions (x, y, z).
    pub positions: Vec<Vec3>,
    /// Triangles as triplets of vertex indices (i, j, k), counter-clockwise
    /// seen from the front.
    pub triangles: Vec<[u32; 3]>,
    /// Optional per-vertex colours (linear RGB) for attribute interpolation.
    pub colors: Option<Vec<Vec3>>,
    /// Index into the scene's materials.
    pub material: usize,
}

/// The lecture's tetrahedron table, exactly: vertices (x, y, z) ...
// ANCHOR: tetrahedron
pub const TETRAHEDRON_VERTICES: [[f32; 3]; 4] = [
    [-1.0, -1.0, -1.0], // 0
    [1.0, -1.0, 1.0],   // 1
    [1.0, 1.0, -1.0],   // 2
    [-1.0, 1.0, 1.0],   // 3
];
/// ... and triangles (i, j, k).
pub const TETRAHEDRON_TRIANGLES: [[u32; 3]; 4] = [
    [0, 2, 1], //
    [0, 3, 2],
    [3, 0, 1],
    [3, 1, 2],
];
// ANCHOR_END: tetrahedron

impl Mesh {
    /// A mesh from positions and triangles.
    pub fn new(name: impl Into<String>, positions: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> Mesh {
        Mesh {
            name: name.into(),
            positions,
            triangles,
            colors: None,
            material: 0,
        }
    }

    /// The lecture's tetrahedron, with one colour per vertex (red, green,
    /// blue, white) for interpolation.
    pub fn tetrahedron() -> Mesh {
        let mut m = Mesh::new(
            "tetrahedron",
            TETRAHEDRON_VERTICES
                .iter()
                .map(|v| Vec3::from(*v))
                .collect(),
            TETRAHEDRON_TRIANGLES.to_vec(),
        );
        m.colors = Some(vec![Vec3::X, Vec3::Y, Vec3::Z, Vec3::ONE]);
        m
    }

    /// A unit-radius sphere centred at the origin: an icosahedron whose
    /// triangles are split `subdivisions` times and pushed onto the sphere.
    /// It is closed and every edge is shared by exactly two triangles.
    pub fn icosphere(subdivisions: u32) -> Mesh {
        let t = (1.0 + 5f32.sqrt()) / 2.0;
        let mut positions: Vec<Vec3> = [
            [-1.0, t, 0.0],
            [1.0, t, 0.0],
            [-1.0, -t, 0.0],
            [1.0, -t, 0.0],
            [0.0, -1.0, t],
            [0.0, 1.0, t],
            [0.0, -1.0, -t],
            [0.0, 1.0, -t],
            [t, 0.0, -1.0],
            [t, 0.0, 1.0],
            [-t, 0.0, -1.0],
            [-t, 0.0, 1.0],
        ]
        .iter()
        .map(|p| Vec3::from(*p).normalize())
        .collect();
        let mut triangles: Vec<[u32; 3]> = vec![
            [0, 11, 5],
            [0, 5, 1],
            [0, 1, 7],
            [0, 7, 10],
            [0, 10, 11],
            [1, 5, 9],
            [5, 11, 4],
            [11, 10, 2],
            [10, 7, 6],
            [7, 1, 8],
            [3, 9, 4],
            [3, 4, 2],
            [3, 2, 6],
            [3, 6, 8],
            [3, 8, 9],
            [4, 9, 5],
            [2, 4, 11],
            [6, 2, 10],
            [8, 6, 7],
            [9, 8, 1],
        ];
        for _ in 0..subdivisions {
            let mut midpoint = std::collections::HashMap::new();
            let mut mid = |a: u32, b: u32, positions: &mut Vec<Vec3>| -> u32 {
                *midpoint.entry((a.min(b), a.max(b))).or_insert_with(|| {
                    let p = (positions[a as usize] + positions[b as usize]).normalize();
                    positions.push(p);
                    positions.len() as u32 - 1
                })
            };
            let mut next = Vec::with_capacity(triangles.len() * 4);
            for [a, b, c] in triangles {
                let ab = mid(a, b, &mut positions);
                let bc = mid(b, c, &mut positions);
                let ca = mid(c, a, &mut positions);
                next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
            }
            triangles = next;
        }
        Mesh::new("sphere", positions, triangles)
    }

    /// A `w` x `h` rectangle in the plane z = 0, centred at the origin,
    /// facing +z.
    pub fn rectangle(w: f32, h: f32) -> Mesh {
        let (x, y) = (w / 2.0, h / 2.0);
        Mesh::new(
            "rectangle",
            vec![
                Vec3::new(-x, -y, 0.0),
                Vec3::new(x, -y, 0.0),
                Vec3::new(x, y, 0.0),
                Vec3::new(-x, y, 0.0),
            ],
            vec![[0, 1, 2], [0, 2, 3]],
        )
    }

    /// An axis-aligned box of the given size centred at the origin, faces
    /// pointing outwards, 8 shared vertices (so the mesh is closed).
    pub fn cuboid(size: Vec3) -> Mesh {
        let h = size / 2.0;
        let positions = (0..8)
            .map(|i| {
                Vec3::new(
                    if i & 1 == 0 { -h.x } else { h.x },
                    if i & 2 == 0 { -h.y } else { h.y },
                    if i & 4 == 0 { -h.z } else { h.z },
                )
            })
            .collect();
        let quads = [
            [0, 2, 3, 1], // -z
            [4, 5, 7, 6], // +z
            [0, 1, 5, 4], // -y
            [2, 6, 7, 3], // +y
            [0, 4, 6, 2], // -x
            [1, 3, 7, 5], // +x
        ];
        let triangles = quads
            .iter()
            .flat_map(|[a, b, c, d]| [[*a, *b, *c], [*a, *c, *d]])
            .collect();
        Mesh::new("box", positions, triangles)
    }

    /// Applies `world_from_object` to every vertex.
    pub fn transform(&mut self, world_from_object: &Mat4) {
        for p in &mut self.positions {
            *p = world_from_object.transform_point3(*p);
        }
    }

    /// Every undirected edge once, as (smaller index, larger index), sorted.
    pub fn edges(&self) -> Vec<[u32; 2]> {
        let set: BTreeSet<[u32; 2]> = self
            .triangles
            .iter()
            .flat_map(|&[a, b, c]| [[a, b], [b, c], [c, a]])
            .map(|[a, b]| [a.min(b), a.max(b)])
            .collect();
        set.into_iter().collect()
    }
}
