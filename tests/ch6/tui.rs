//! Chapter 6 in the terminal UI's render worker: the real stage delivers
//! per-bounce layers whose "up to 16" sum is the image, a reference and a
//! live error series, pass after pass, for every estimator variant.

use std::sync::Arc;
use std::time::Duration;

use raystep::core::stage::Settings;
use raystep::scene::Scene;
use raystep::tui::app::{combine_layers, BounceMode};
use raystep::tui::worker::{Job, Progress, Worker};

#[test]
fn the_worker_renders_chapter_6_with_layers_reference_and_error_series() {
    let chapter = raystep::chapters::all()
        .into_iter()
        .find(|c| c.info().number == 6)
        .expect("chapter 6 is registered");
    let worker = Worker::spawn();
    // The reference's resolution, so the error series has a reference.
    let scene = Arc::new(Scene::builtin().with_resolution(64, 64).unwrap());
    for variant in [0, 7] {
        worker.start(Job {
            generation: variant as u64 + 1,
            chapter,
            scene: scene.clone(),
            settings: Settings {
                spp: 8,
                ..Settings::default()
            },
            variant,
            target: None,
        });
        let mut snapshots = 0;
        let last = loop {
            match worker
                .results
                .recv_timeout(Duration::from_secs(60))
                .unwrap()
            {
                Progress::State(s) if s.generation == variant as u64 + 1 => {
                    snapshots += 1;
                    if s.done {
                        break s;
                    }
                }
                Progress::State(_) | Progress::Inspected { .. } => {}
                Progress::Failed { message, .. } | Progress::Refused { message, .. } => {
                    panic!("{message}")
                }
            }
        };
        assert!(snapshots >= 2, "the first pass and the last are shown");
        assert_eq!(last.samples, 8);
        assert_eq!(last.progress, (4, 4), "passes of 1, 1, 2 and 4 spp");
        let layers = last.layers.as_ref().expect("chapter 6 has layers");
        assert_eq!(layers.len(), 18, "layer 0 (with E), 1..=16, beyond");
        let image = &last.views[0];
        let up_to_16 = combine_layers(layers, 16, BounceMode::UpTo, image);
        assert!(
            image.rmse(&up_to_16) < 1e-5,
            "the layers add up to the image"
        );
        // Direct light alone is darker than the whole image.
        let direct = combine_layers(layers, 0, BounceMode::UpTo, image);
        let sum =
            |f: &raystep::core::film::Film| f.pixels.iter().map(|p| p.element_sum()).sum::<f32>();
        assert!(sum(&direct) < 0.9 * sum(image));
        assert!(last.reference.is_some());
        assert_eq!(last.error_series.len(), 4, "one point per pass");
        assert!(last.error_series.iter().all(|(t, e)| *t >= 0.0 && *e > 0.0));
    }
}
