//! Visibility with a depth buffer: every sample remembers the nearest
//! surface drawn so far, and a new one replaces it only if it is nearer.

/// The classic z-buffer test: if `z` is nearer than what `depth[index]`
/// holds, store it and return `true`. A NaN never passes, and a tie keeps
/// what was drawn first. (The renderer's own test, [`nearer`], compares 1/w
/// instead and breaks ties by triangle index, so that the result does not
/// depend on drawing order.)
// ANCHOR: depth_test
pub fn depth_test(depth: &mut [f32], index: usize, z: f32) -> bool {
    if z < depth[index] {
        depth[index] = z;
        true
    } else {
        false
    }
}
// ANCHOR_END: depth_test

/// What the renderer's depth buffer holds per sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// 1/w of the nearest surface so far (0: nothing, infinitely far).
    pub inv_w: f32,
    /// Index of its screen triangle, or `u32::MAX`.
    pub tri: u32,
}

impl Sample {
    /// A sample nothing covers yet.
    pub const EMPTY: Sample = Sample {
        inv_w: 0.0,
        tri: u32::MAX,
    };

    /// Whether some triangle covers it.
    pub fn is_covered(&self) -> bool {
        self.tri != u32::MAX
    }
}

/// Whether `new` is in front of `old`: larger 1/w is nearer; at equal 1/w
/// the lower triangle index wins, so coincident triangles give the same
/// image whatever order they are drawn in.
// ANCHOR: nearer
#[inline]
pub fn nearer(new: &Sample, old: &Sample) -> bool {
    new.inv_w > old.inv_w || (new.inv_w == old.inv_w && new.tri < old.tri)
}
// ANCHOR_END: nearer
