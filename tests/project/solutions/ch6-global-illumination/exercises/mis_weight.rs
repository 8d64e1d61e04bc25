//! Exercise 6.3, solved: the power heuristic, divided through by pdf_f².

/// The power-heuristic weight of strategy f.
pub fn mis_weight(pdf_f: f64, pdf_g: f64) -> f64 {
    if pdf_f <= 0.0 {
        return 0.0;
    }
    let r = pdf_g / pdf_f;
    1.0 / (1.0 + r * r)
}
