//! What `ch6` writes besides the image: the bounce strip (the lecture's
//! direct, 1, 2, 4, 8, 16 bounce sequence), every layer as EXR, the
//! spp-doubling strip, and the strategy plot.

use crate::core::figure::{Figure, FigureContent};
use crate::core::film::Film;
use crate::core::plot::{LogLogPlot, Look};
use crate::core::report::ErrorTime;

use super::accumulate::Accumulator;
use super::engine::PathEngine;
use super::integrator::PathSettings;
use super::layers::{LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND};
use super::sampler::SamplerKind;
use crate::ch1_projection::camera::Camera;

/// The "up to k bounces" images of the lecture's sequence.
pub const STRIP_BOUNCES: [u32; 6] = [0, 1, 2, 4, 8, 16];

/// Their captions, as the lecture names them.
pub const STRIP_LABELS: [&str; 6] = [
    "direct",
    "one bounce",
    "two bounces",
    "four bounces",
    "eight bounces",
    "sixteen bounces",
];

/// Films side by side with a 2-pixel black gap.
pub fn side_by_side(films: &[Film]) -> Film {
    let gap = 2;
    let h = films.iter().map(|f| f.height).max().unwrap_or(1);
    let w = films.iter().map(|f| f.width).sum::<u32>() + gap * films.len().saturating_sub(1) as u32;
    let mut out = Film::new(w.max(1), h);
    let mut x0 = 0;
    for f in films {
        for y in 0..f.height {
            for x in 0..f.width {
                *out.get_mut(x0 + x, y) = f.get(x, y);
            }
        }
        x0 += f.width + gap;
    }
    out
}

/// The bounce strip (PNG, "up to k" = layer E plus layers 0..=k) and
/// every layer on its own as EXR, as figures named after `stem`. None
/// without layers.
pub fn layer_figures(acc: &Accumulator, stem: &str) -> Vec<Figure> {
    let mut figures = Vec::new();
    if acc.layers.is_none() {
        return figures;
    }
    let strip: Vec<(Film, String)> = STRIP_BOUNCES
        .iter()
        .zip(STRIP_LABELS)
        .filter_map(|(k, label)| Some((acc.prefix(*k as usize + 1)?, label.to_string())))
        .collect();
    figures.push(Figure {
        file: format!("{stem}-bounces.png"),
        content: FigureContent::Strip(strip),
    });
    for slot in 0..LAYER_SLOTS {
        let name = match slot {
            0 => "E".to_string(),
            SLOT_BEYOND => "beyond".to_string(),
            s => format!("{:02}", s - 1),
        };
        let mut f = acc.layer(slot).expect("layers kept");
        f.scrub_nonfinite();
        figures.push(Figure {
            file: format!("{stem}-layer-{name}.exr"),
            content: FigureContent::Exr(f),
        });
    }
    debug_assert_eq!(SLOT_BEYOND, LAYERS_SHOWN as usize + 2);
    figures
}

/// The spp-doubling figure: one render, its image after 1, 2, 4, … `max`
/// samples per pixel side by side, as `stem-spp.png`.
pub fn spp_figure(
    path: &PathSettings,
    sampler: SamplerKind,
    (engine, camera): (&dyn PathEngine, &Camera),
    seed: u64,
    max: u32,
    stem: &str,
) -> Figure {
    let mut acc = Accumulator::new(camera.width, camera.height, false);
    let mut films = Vec::new();
    let mut spp = 1;
    while spp <= max.max(1) {
        let count = spp - acc.samples;
        acc.add_samples(engine, camera, path, sampler, seed, count);
        let mut f = acc.mean();
        f.scrub_nonfinite();
        films.push((f, format!("{spp} spp")));
        spp *= 2;
    }
    Figure {
        file: format!("{stem}-spp.png"),
        content: FigureContent::Strip(films),
    }
}

/// How a series of the strategy plot looks: colour and marker by
/// estimator (as in chapter 5: uniform, BSDF, light, MIS), dashed for the
/// Sobol sampler, solid for independent numbers.
pub fn series_look(series: &str) -> Look {
    let estimator = ["uniform", "bsdf", "light", "mis"]
        .iter()
        .position(|e| series.split(' ').any(|w| w == *e))
        .unwrap_or(4);
    Look {
        dashed: series.contains("sobol"),
        ..Look::nth(estimator)
    }
}

/// The strategy plot of one scene of the study (`cornell` or `furnace`):
/// RMSE against run time, one line per estimator and sampler.
pub fn strategy_plot(et: &ErrorTime, scene: &str) -> LogLogPlot {
    let title = match scene {
        "cornell" => "Cornell box: error against time",
        "furnace" => "White furnace: error against time",
        other => other,
    };
    let mut plot = et.plot(scene, title, series_look);
    plot.y_label = "RMSE of the pixel radiance".into();
    plot
}
