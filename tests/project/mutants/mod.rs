//! Plausible wrong solutions of each capstone (each must fail, naming its
//! symptom) and other correct ones (each must pass), fed straight to the
//! checks.

pub mod ch3;
pub mod ch4;
