pub mod ch1;
pub mod ch2;
