//! Unit tests of `src/core/plot.rs`.

use raystep::core::plot::*;

fn plot(series: Vec<Series>) -> LogLogPlot {
    LogLogPlot {
        title: "test".into(),
        x_label: "run time (s)".into(),
        y_label: "RMSE".into(),
        series,
        guide: Some(Guide {
            slope: -0.5,
            label: "slope −1/2".into(),
        }),
    }
}

fn at(px: &[u8], w: u32, x: u32, y: u32) -> (u8, u8, u8) {
    let i = ((y * w + x) * 3) as usize;
    (px[i], px[i + 1], px[i + 2])
}

#[test]
fn ticks_read_as_numbers() {
    assert_eq!(tick(0.001), "0.001");
    assert_eq!(tick(1.0), "1");
    assert_eq!(tick(100.0), "100");
    assert_eq!(tick(1e-5), "1e-5");
    assert_eq!(tick(1e6), "1e6");
}

#[test]
fn only_decades_are_labelled_on_long_axes() {
    let long = 1e-6..1.0;
    let short = 0.01..1.0;
    assert_eq!(labelled_tick(1e-3, &long), "0.001");
    assert_eq!(labelled_tick(2e-3, &long), "");
    assert_eq!(labelled_tick(0.05, &short), "0.05");
    assert_eq!(labelled_tick(0.03, &short), "");
}

#[test]
fn decades_round_outwards() {
    let (x, y) = decades([(2.0, 0.05), (30.0, 0.5)].into_iter());
    assert!((x.start - 1.0).abs() < 2e-3 && x.end == 100.0);
    assert!((y.start - 0.01).abs() < 2e-5 && (y.end - 1.0).abs() < 2e-3);
}

#[test]
fn the_guide_is_clipped_to_the_axes() {
    let s = Series {
        label: "a".into(),
        points: vec![(1.0, 1.0), (100.0, 0.1)],
        look: Look::nth(0),
    };
    let lines = vec![(&s, s.points.clone())];
    let seg = guide_segment(-0.5, &lines, 1.0..100.0, 0.1..1.0).unwrap();
    // From (1, 1) down to (100, 0.1): slope -1/2 over two decades.
    assert!((seg[0].0 - 1.0).abs() < 1e-9 && (seg[0].1 - 1.0).abs() < 1e-9);
    assert!((seg[1].0 - 100.0).abs() < 1e-6 && (seg[1].1 - 0.1).abs() < 1e-9);
}

#[test]
fn a_plot_draws_coloured_lines_and_text_on_white() {
    let series = vec![
        Series {
            label: "uniform".into(),
            points: vec![(0.01, 1.0), (0.1, 0.3), (1.0, 0.1)],
            look: Look::nth(0),
        },
        Series {
            label: "light".into(),
            points: vec![(0.01, 0.1), (0.1, 0.03), (1.0, 0.01), (0.0, 5.0)],
            look: Look {
                dashed: true,
                ..Look::nth(1)
            },
        },
    ];
    let (w, h) = (480, 320);
    let px = plot(series).draw(w, h).unwrap();
    assert_eq!(at(&px, w, 0, 0), (255, 255, 255));
    let count = |c: (u8, u8, u8)| {
        (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .filter(|&(x, y)| at(&px, w, x, y) == c)
            .count()
    };
    // Both series' colours show, and dark text (axis labels, ticks,
    // legend) is drawn.
    assert!(count(PALETTE[0]) > 100, "blue {}", count(PALETTE[0]));
    assert!(count(PALETTE[1]) > 50, "vermillion {}", count(PALETTE[1]));
    let dark = px.chunks(3).filter(|p| p.iter().all(|v| *v < 60)).count();
    assert!(dark > 500, "dark pixels {dark}");
}

#[test]
fn an_empty_plot_still_draws_its_axes() {
    let px = plot(vec![]).draw(200, 150).unwrap();
    assert!(px.chunks(3).any(|p| p == [0, 0, 0]));
}
