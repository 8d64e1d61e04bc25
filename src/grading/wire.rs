//! The values that cross between the grader and the process that runs a
//! student's code, as bytes: each value written as its bits (a float's
//! exact bits, so that a NaN or a -0 arrives as it left), in a fixed
//! order, with nothing else. The grader reads back only values of the
//! types it asked for; a byte string that does not decode is an error,
//! never a value.

use glam::{DVec3, Mat4, Vec2, Vec3};

use crate::ch3_ray_triangle::triangle::Hit;
use crate::exercises::paths;

/// A value that can be written to bytes and read back exactly.
pub trait Wire: Sized {
    /// Appends this value's bytes to `out`.
    fn put(&self, out: &mut Vec<u8>);
    /// Reads one value from the front of `input`, advancing it; `None` when
    /// the bytes do not hold one.
    fn get(input: &mut &[u8]) -> Option<Self>;
}

/// The bytes of `value`.
pub fn to_bytes<T: Wire>(value: &T) -> Vec<u8> {
    let mut out = Vec::new();
    value.put(&mut out);
    out
}

/// `value` read from exactly `bytes` (nothing left over).
pub fn from_bytes<T: Wire>(mut bytes: &[u8]) -> Option<T> {
    let v = T::get(&mut bytes)?;
    bytes.is_empty().then_some(v)
}

fn take<'a>(input: &mut &'a [u8], n: usize) -> Option<&'a [u8]> {
    if input.len() < n {
        return None;
    }
    let (head, rest) = input.split_at(n);
    *input = rest;
    Some(head)
}

macro_rules! wire_number {
    ($($t:ty),*) => {$(
        impl Wire for $t {
            fn put(&self, out: &mut Vec<u8>) {
                out.extend_from_slice(&self.to_le_bytes());
            }
            fn get(input: &mut &[u8]) -> Option<Self> {
                let bytes = take(input, std::mem::size_of::<$t>())?;
                Some(<$t>::from_le_bytes(bytes.try_into().ok()?))
            }
        }
    )*};
}
wire_number!(u8, u32, u64, f32, f64);

impl Wire for bool {
    fn put(&self, out: &mut Vec<u8>) {
        out.push(u8::from(*self));
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        match u8::get(input)? {
            0 => Some(false),
            1 => Some(true),
            _ => None,
        }
    }
}

impl Wire for usize {
    fn put(&self, out: &mut Vec<u8>) {
        (*self as u64).put(out);
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        usize::try_from(u64::get(input)?).ok()
    }
}

impl Wire for String {
    fn put(&self, out: &mut Vec<u8>) {
        self.as_bytes().to_vec().put(out);
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        String::from_utf8(Vec::<u8>::get(input)?).ok()
    }
}

impl Wire for Vec2 {
    fn put(&self, out: &mut Vec<u8>) {
        self.to_array().put(out);
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        Some(Vec2::from_array(<[f32; 2]>::get(input)?))
    }
}

impl Wire for Vec3 {
    fn put(&self, out: &mut Vec<u8>) {
        self.to_array().put(out);
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        Some(Vec3::from_array(<[f32; 3]>::get(input)?))
    }
}

impl Wire for DVec3 {
    fn put(&self, out: &mut Vec<u8>) {
        self.to_array().put(out);
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        Some(DVec3::from_array(<[f64; 3]>::get(input)?))
    }
}

impl Wire for Mat4 {
    fn put(&self, out: &mut Vec<u8>) {
        self.to_cols_array().put(out);
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        Some(Mat4::from_cols_array(&<[f32; 16]>::get(input)?))
    }
}

impl<T: Wire, const N: usize> Wire for [T; N] {
    fn put(&self, out: &mut Vec<u8>) {
        self.iter().for_each(|v| v.put(out));
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        let items: Vec<T> = (0..N).map(|_| T::get(input)).collect::<Option<_>>()?;
        items.try_into().ok()
    }
}

impl<T: Wire> Wire for Vec<T> {
    fn put(&self, out: &mut Vec<u8>) {
        self.len().put(out);
        self.iter().for_each(|v| v.put(out));
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        let n = usize::get(input)?;
        // Every value takes at least one byte: a length beyond what is
        // left is a broken string, not a reason to allocate.
        if n > input.len() {
            return None;
        }
        (0..n).map(|_| T::get(input)).collect()
    }
}

impl<T: Wire> Wire for Option<T> {
    fn put(&self, out: &mut Vec<u8>) {
        match self {
            None => out.push(0),
            Some(v) => {
                out.push(1);
                v.put(out);
            }
        }
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        match u8::get(input)? {
            0 => Some(None),
            1 => Some(Some(T::get(input)?)),
            _ => None,
        }
    }
}

/// A hit as exercise 3.4 answers it.
impl Wire for Hit {
    fn put(&self, out: &mut Vec<u8>) {
        (self.t, self.u, self.v, self.triangle).put(out);
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        let (t, u, v, triangle) = <(f32, f32, f32, u32)>::get(input)?;
        Some(Hit { t, u, v, triangle })
    }
}

impl Wire for () {
    fn put(&self, _out: &mut Vec<u8>) {}
    fn get(_input: &mut &[u8]) -> Option<Self> {
        Some(())
    }
}

macro_rules! wire_tuple {
    ($($name:ident),+) => {
        impl<$($name: Wire),+> Wire for ($($name,)+) {
            #[allow(non_snake_case)]
            fn put(&self, out: &mut Vec<u8>) {
                let ($($name,)+) = self;
                $($name.put(out);)+
            }
            fn get(input: &mut &[u8]) -> Option<Self> {
                Some(($($name::get(input)?,)+))
            }
        }
    };
}
wire_tuple!(A);
wire_tuple!(A, B);
wire_tuple!(A, B, C);
wire_tuple!(A, B, C, D);
wire_tuple!(A, B, C, D, E);
wire_tuple!(A, B, C, D, E, F);
wire_tuple!(A, B, C, D, E, F, G);

impl Wire for paths::Tally {
    fn put(&self, out: &mut Vec<u8>) {
        let t = self;
        (t.bounces, t.vertices, t.light_samples, t.lights_found).put(out);
        t.lights_useful.put(out);
        (t.shadow_rays, t.below, t.over_budget).put(out);
        t.cosine_quarters.put(out);
        t.light_from_bounce_numbers.put(out);
        t.cosine_went_on.put(out);
        t.light_cells.put(out);
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        let (bounces, vertices, light_samples, lights_found) = Wire::get(input)?;
        let lights_useful = Wire::get(input)?;
        let (shadow_rays, below, over_budget) = Wire::get(input)?;
        let cosine_quarters = Wire::get(input)?;
        let light_from_bounce_numbers = Wire::get(input)?;
        let cosine_went_on = Wire::get(input)?;
        let light_cells = Wire::get(input)?;
        Some(paths::Tally {
            bounces,
            vertices,
            light_samples,
            lights_found,
            lights_useful,
            shadow_rays,
            below,
            over_budget,
            cosine_quarters,
            light_from_bounce_numbers,
            cosine_went_on,
            light_cells,
        })
    }
}

/// A buffer's values as the bits that a replay must reproduce.
pub(crate) trait Bits: Copy {
    /// Whether the two have the same bits.
    fn same(&self, other: &Self) -> bool;
    /// `h` with this value's bits hashed in (FNV-1a).
    fn hash_into(&self, h: u64) -> u64;
}

fn fnv(h: u64, word: u32) -> u64 {
    (h ^ u64::from(word)).wrapping_mul(0x100_0000_01b3)
}

impl Bits for f32 {
    fn same(&self, other: &Self) -> bool {
        self.to_bits() == other.to_bits()
    }
    fn hash_into(&self, h: u64) -> u64 {
        fnv(h, self.to_bits())
    }
}

impl Bits for Vec3 {
    fn same(&self, o: &Self) -> bool {
        self.x.same(&o.x) && self.y.same(&o.y) && self.z.same(&o.z)
    }
    fn hash_into(&self, h: u64) -> u64 {
        self.z.hash_into(self.y.hash_into(self.x.hash_into(h)))
    }
}

/// A hash of a buffer's bits, for comparing what a call was handed
/// without sending the whole buffer.
pub(crate) fn fingerprint<T: Bits>(values: &[T]) -> u64 {
    values
        .iter()
        .fold(0xcbf2_9ce4_8422_2325u64, |h, v| v.hash_into(h))
}

/// The entries of `after` whose bits differ from `before`'s.
pub(crate) fn changes<T: Bits>(before: &[T], after: &[T]) -> Vec<(u32, T)> {
    let mut out = Vec::new();
    for (i, (b, a)) in before.iter().zip(after).enumerate() {
        if !b.same(a) {
            out.push((i as u32, *a));
        }
    }
    out
}

/// Writes recorded changes into `buffer`; `false` when one is out of it.
pub(crate) fn apply<T: Copy>(buffer: &mut [T], changed: &[(u32, T)]) -> bool {
    changed
        .iter()
        .all(|(i, v)| match buffer.get_mut(*i as usize) {
            Some(slot) => {
                *slot = *v;
                true
            }
            None => false,
        })
}
