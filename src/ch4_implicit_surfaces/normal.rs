//! Normals of an implicit surface: the gradient ∇f, normalised, estimated
//! by finite differences of f around the hit point.

use glam::Vec3;

/// ∇f by central differences: six evaluations, error O(h²).
// ANCHOR: gradient_central
pub fn gradient_central(f: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    let dx = Vec3::new(h, 0.0, 0.0);
    let dy = Vec3::new(0.0, h, 0.0);
    let dz = Vec3::new(0.0, 0.0, h);
    Vec3::new(
        f(p + dx) - f(p - dx),
        f(p + dy) - f(p - dy),
        f(p + dz) - f(p - dz),
    ) / (2.0 * h)
}
// ANCHOR_END: gradient_central

/// ∇f from four evaluations at the corners of a tetrahedron around p:
/// k₀ = (1, −1, −1), k₁ = (−1, −1, 1), k₂ = (−1, 1, −1), k₃ = (1, 1, 1).
/// The kᵢ sum to zero and Σ kᵢ kᵢᵀ = 4 I, so Σ kᵢ f(p + h kᵢ) ≈ 4h ∇f.
// ANCHOR: gradient_tetrahedron
pub fn gradient_tetrahedron(f: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    const K: [Vec3; 4] = [
        Vec3::new(1.0, -1.0, -1.0),
        Vec3::new(-1.0, -1.0, 1.0),
        Vec3::new(-1.0, 1.0, -1.0),
        Vec3::new(1.0, 1.0, 1.0),
    ];
    K.iter().map(|k| *k * f(p + *k * h)).sum::<Vec3>() / (4.0 * h)
}
// ANCHOR_END: gradient_tetrahedron

/// Which finite-difference scheme to use for normals.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalScheme {
    /// Six taps.
    Central,
    /// Four taps.
    Tetrahedron,
}

/// The unit normal ∇f/‖∇f‖ at p, or `fallback` where the gradient is zero
/// or not finite (the centre of a sphere, a crease where the differences
/// cancel).
pub fn normal(
    f: &dyn Fn(Vec3) -> f32,
    p: Vec3,
    h: f32,
    scheme: NormalScheme,
    fallback: Vec3,
) -> Vec3 {
    let g = match scheme {
        NormalScheme::Central => gradient_central(f, p, h),
        NormalScheme::Tetrahedron => gradient_tetrahedron(f, p, h),
    };
    g.try_normalize().unwrap_or(fallback)
}
