//! Exercise 6.3: the MIS weight (the power heuristic, β = 2).
//!
//! A sample drawn by strategy f, whose density there is `pdf_f`, could
//! also have come from strategy g with density `pdf_g`. Return its weight
//! w_f = pdf_f² / (pdf_f² + pdf_g²). The weights of the two strategies must
//! sum to one wherever either can sample; return 0 when `pdf_f` is 0.
//!
//! Grade it with: `cargo run --release --bin grade -- ch6`

/// The power-heuristic weight of strategy f.
pub fn mis_weight(pdf_f: f64, pdf_g: f64) -> f64 {
    // TODO: square both densities.
    // TODO: divide, and take care of pdf_f = 0 (and very large densities).
    todo!()
}
