//! Unit tests of `src/core/report.rs`.

use raystep::core::report::*;

#[test]
fn a_slope_needs_three_runs_over_four_times_in_time() {
    let row = |t: f64| Measurement {
        series: "mc".into(),
        variant: String::new(),
        seconds: t,
        samples: 1,
        error: 1.0 / t.sqrt(),
        notes: String::new(),
    };
    let et = |ts: &[f64]| ErrorTime {
        rows: ts.iter().map(|t| row(*t)).collect(),
        ..ErrorTime::default()
    };
    assert_eq!(et(&[1.0, 4.0]).slope("mc"), None);
    assert_eq!(et(&[1.0, 1.5, 3.9]).slope("mc"), None);
    assert!(et(&[1.0, 2.0, 4.0]).slope("mc").is_some());
    // Read off the line within 10x of the measured times only.
    let fit = et(&[1.0, 2.0, 4.0]).fit("mc").unwrap();
    let (t, extrapolated) = fit.x_at(0.25).unwrap(); // t = 16
    assert!((t - 16.0).abs() < 1e-9 && extrapolated);
    assert_eq!(fit.x_at(0.1), None); // t = 100: 25x beyond
    assert!(!fit.x_at(0.6).unwrap().1);
}

#[test]
fn slope_of_inverse_square_root_is_minus_half() {
    let mut et = ErrorTime::default();
    for k in 0..6 {
        let t = 2f64.powi(k);
        et.rows.push(Measurement {
            series: "mc".into(),
            variant: format!("{t}"),
            seconds: t,
            samples: 1,
            error: 0.3 / t.sqrt(),
            notes: String::new(),
        });
    }
    assert!((et.slope("mc").unwrap() + 0.5).abs() < 1e-12);
    assert_eq!(et.slope("other"), None);
}
