//! `ch6 --bench`: the Cornell box at 256x256, 64 spp, up to 16 bounces,
//! MIS, on the current thread pool; seconds, paths/s, rays/s and RMSE
//! against the stored reference, for both samplers.
//!
//! The reference is smaller than 256x256, so the RMSE is taken after
//! box-downsampling the 256x256 render to the reference's resolution
//! (each reference pixel against the mean of the f x f render pixels it
//! covers, which has the same expectation). Averaging f² pixels divides
//! the noise variance by f², so this RMSE is lower than a per-pixel RMSE at
//! 256x256; the table also gives the latter's noise part, √(mean s²/n),
//! estimated from the render's own sample variance.

use crate::report::{format_number, Table};
use crate::scene::Scene;

use super::accumulate::downsample;
use super::integrator::PathSettings;
use super::reference::StoredReference;
use super::sampler::SamplerKind;
use super::studies::render;

/// Runs the benchmark and returns its table.
pub fn bench(spp: u32) -> crate::error::Result<Table> {
    let scene = Scene::builtin().with_resolution(256, 256)?;
    let reference = StoredReference::for_scene(&scene);
    let threads = rayon::current_num_threads();
    let mut t = Table::new(
        &format!(
            "ch6 benchmark: Cornell box 256x256, {spp} spp, up to 16 bounces, MIS, {threads} threads \
             (targets: > 3.5M paths/s; RMSE²·s < 3e-4)"
        ),
        &[
            "sampler",
            "seconds",
            "paths/s",
            "rays/s",
            "RMSE (at ref. res.)",
            "RMSE²·s",
            "noise RMSE at 256²",
        ],
    );
    for sampler in [SamplerKind::Independent, SamplerKind::Sobol] {
        let (acc, secs) = render(&scene, &PathSettings::default(), sampler, spp, 1, false);
        let var = acc.variance_of_mean();
        let noise = (var
            .pixels
            .iter()
            .map(|p| p.as_dvec3().element_sum())
            .sum::<f64>()
            / (3.0 * var.pixels.len() as f64))
            .sqrt();
        let rmse = reference.as_ref().map(|r| {
            let f = acc.width / r.mean.width;
            downsample(&acc.mean(), f).rmse(&r.mean)
        });
        t.row(vec![
            sampler.name().into(),
            format!("{secs:.3}"),
            format_number(acc.stats.paths as f64 / secs),
            format_number(acc.stats.rays as f64 / secs),
            rmse.map_or("no reference".into(), format_number),
            rmse.map_or("-".into(), |e| format_number(e * e * secs)),
            format_number(noise),
        ]);
    }
    Ok(t)
}
