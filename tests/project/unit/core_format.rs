//! Unit tests of `src/core/format.rs`.

use raystep::core::format::*;

#[test]
fn counts_take_the_plural_except_one() {
    assert_eq!(format_count(0, "light"), "0 lights");
    assert_eq!(format_count(1, "exercise"), "1 exercise");
    assert_eq!(format_count(24, "exercise"), "24 exercises");
}

#[test]
fn numbers_read_well() {
    assert_eq!(format_number(0.0), "0");
    assert_eq!(format_number(1234.5678), "1235");
    assert_eq!(format_number(0.012346), "0.01235");
    assert_eq!(format_number(1.5e-7), "1.500e-7");
    assert_eq!(format_number(f64::INFINITY), "inf");
}
