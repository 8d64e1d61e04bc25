//! Exercise 6.3: the MIS weight (the power heuristic, β = 2).
//!
//! Multiple importance sampling: a direction drawn by strategy f (say, the
//! BRDF) could also have been drawn by strategy g (the light). Each sample
//! is weighted by how likely its own strategy was to draw it compared with
//! the other, so that each strategy counts most where it is the better one
//! and the two together count every direction exactly once.
//!
//! Contract (what the grader checks, to 10⁻⁶):
//! * return the power-heuristic weight w_f = pdf_f² / (pdf_f² + pdf_g²) of
//!   a sample of strategy f, whose density there is `pdf_f`, when strategy
//!   g has density `pdf_g` there;
//! * w_f + w_g = 1 wherever either strategy can sample (a two-strategy
//!   MIS estimate of ∫₀¹ 3x² dx must be unbiased, within 5 standard errors);
//! * 0 when `pdf_f` is 0 (also when both are 0);
//! * finite and right for densities as large as 10²⁰⁰ or as small as 10⁻²⁰⁰.
//!
//! Hints: `cargo grade --hint ch6/mis_weight`.
//! Grade it with: `cargo grade ch6`

/// The power-heuristic weight of strategy f.
pub fn mis_weight(pdf_f: f64, pdf_g: f64) -> f64 {
    // TODO: the power heuristic, safe at the extremes.
    todo!()
}
