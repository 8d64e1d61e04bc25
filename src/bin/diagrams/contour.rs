//! Level sets of a function of the plane, by marching squares: the
//! outlines and contour lines of chapter 4's slices through an SDF. The
//! crossings are found on a grid of samples of the real function and
//! chained into polylines, so the lines are what the function says.

use std::collections::BTreeMap;

/// Samples of `f` on a grid over `[x0, x1] x [y0, y1]`.
pub struct Grid {
    origin: (f64, f64),
    cell: (f64, f64),
    nx: usize,
    ny: usize,
    values: Vec<f64>,
}

impl Grid {
    /// `f` sampled at `(nx + 1) x (ny + 1)` nodes over `world` =
    /// `[x0, x1, y0, y1]`.
    pub fn sample(f: &dyn Fn(f64, f64) -> f64, world: [f64; 4], nx: usize, ny: usize) -> Grid {
        let [x0, x1, y0, y1] = world;
        let cell = ((x1 - x0) / nx as f64, (y1 - y0) / ny as f64);
        let mut values = Vec::with_capacity((nx + 1) * (ny + 1));
        for j in 0..=ny {
            for i in 0..=nx {
                values.push(f(x0 + i as f64 * cell.0, y0 + j as f64 * cell.1));
            }
        }
        Grid {
            origin: (x0, y0),
            cell,
            nx,
            ny,
            values,
        }
    }

    fn at(&self, i: usize, j: usize) -> f64 {
        self.values[j * (self.nx + 1) + i]
    }

    fn node(&self, i: usize, j: usize) -> (f64, f64) {
        (
            self.origin.0 + i as f64 * self.cell.0,
            self.origin.1 + j as f64 * self.cell.1,
        )
    }

    /// The grid with its outer ring of samples raised to at least `floor`,
    /// so that the region below `floor` closes along the border (the
    /// outline of a solid that leaves the picture).
    pub fn closed(&self, floor: f64) -> Grid {
        let mut values = self.values.clone();
        for j in 0..=self.ny {
            for i in 0..=self.nx {
                if i == 0 || j == 0 || i == self.nx || j == self.ny {
                    let k = j * (self.nx + 1) + i;
                    values[k] = values[k].max(floor);
                }
            }
        }
        Grid { values, ..*self }
    }

    /// The end points of a grid edge, by id: horizontal edges first.
    fn edge(&self, id: usize) -> ((usize, usize), (usize, usize)) {
        let horizontal = self.nx * (self.ny + 1);
        if id < horizontal {
            let (i, j) = (id % self.nx, id / self.nx);
            ((i, j), (i + 1, j))
        } else {
            let k = id - horizontal;
            let (i, j) = (k % (self.nx + 1), k / (self.nx + 1));
            ((i, j), (i, j + 1))
        }
    }

    /// Where the level crosses edge `id` (linear between its samples).
    fn crossing(&self, id: usize, level: f64) -> (f64, f64) {
        let (a, b) = self.edge(id);
        let (va, vb) = (self.at(a.0, a.1), self.at(b.0, b.1));
        let w = ((level - va) / (vb - va)).clamp(0.0, 1.0);
        let (pa, pb) = (self.node(a.0, a.1), self.node(b.0, b.1));
        (pa.0 + w * (pb.0 - pa.0), pa.1 + w * (pb.1 - pa.1))
    }

    /// The level set `f = level` as polylines (closed ones end where they
    /// start).
    pub fn level(&self, level: f64) -> Vec<Vec<(f64, f64)>> {
        let (nx, horizontal) = (self.nx, self.nx * (self.ny + 1));
        let h = |i: usize, j: usize| j * nx + i;
        let v = |i: usize, j: usize| horizontal + j * (nx + 1) + i;
        let mut segments: Vec<(usize, usize)> = Vec::new();
        for j in 0..self.ny {
            for i in 0..self.nx {
                let inside = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                    .map(|(a, b)| self.at(a, b) < level);
                // Bottom, right, top, left.
                let edges = [h(i, j), v(i + 1, j), h(i, j + 1), v(i, j)];
                let crossed: Vec<usize> = (0..4)
                    .filter(|&k| inside[k] != inside[(k + 1) % 4])
                    .collect();
                match crossed.len() {
                    2 => segments.push((edges[crossed[0]], edges[crossed[1]])),
                    4 => {
                        let centre = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                            .iter()
                            .map(|&(a, b)| self.at(a, b))
                            .sum::<f64>()
                            / 4.0;
                        if (centre < level) == inside[0] {
                            segments.push((edges[0], edges[1]));
                            segments.push((edges[2], edges[3]));
                        } else {
                            segments.push((edges[3], edges[0]));
                            segments.push((edges[1], edges[2]));
                        }
                    }
                    _ => {}
                }
            }
        }
        let mut at_edge: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        for (k, &(a, b)) in segments.iter().enumerate() {
            at_edge.entry(a).or_default().push(k);
            at_edge.entry(b).or_default().push(k);
        }
        let mut used = vec![false; segments.len()];
        let mut lines = Vec::new();
        // Open lines start at an end (an edge with one segment); what is
        // left afterwards are loops.
        let ends: Vec<usize> = at_edge
            .iter()
            .filter(|(_, s)| s.len() == 1)
            .map(|(e, _)| *e)
            .collect();
        let starts = ends
            .into_iter()
            .chain(segments.iter().map(|s| s.0))
            .collect::<Vec<_>>();
        for start in starts {
            let mut edge = start;
            let mut line = vec![self.crossing(edge, level)];
            while let Some(&k) = at_edge[&edge].iter().find(|&&k| !used[k]) {
                used[k] = true;
                let (a, b) = segments[k];
                edge = if a == edge { b } else { a };
                line.push(self.crossing(edge, level));
            }
            if line.len() > 1 {
                lines.push(line);
            }
        }
        lines
    }
}
