//! Unit tests of `src/ch4_implicit_surfaces/render.rs`.

use raystep::ch1_projection::camera::Camera;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::ch4_implicit_surfaces::normal::NormalScheme;
use raystep::ch4_implicit_surfaces::render::*;

#[test]
fn a_pixels_march_steps_are_the_renders_march() {
    let scene = crate::common::shipped_scene("sdf-shapes", 16, 12);
    let camera = Camera::of(&scene);
    let m = March::default();
    let n = NormalScheme::Tetrahedron;
    let pixels = trace_image(
        &camera,
        0..camera.height,
        &scene.sdfs,
        &m,
        Method::Plain,
        n,
        None,
    );
    let mut hits = 0;
    for y in 0..12 {
        for x in 0..16 {
            let ray = pixel_ray(&camera, x, y);
            let s = march_steps(&ray, &scene.sdfs, &m, Method::Plain, n, None);
            let rendered = pixels[(y * 16 + x) as usize];
            assert_eq!(s.pixel, rendered);
            // One entry per evaluation, ending where the march stopped.
            assert_eq!(s.steps.len() as u32, rendered.trace.steps);
            if let Some(t) = rendered.trace.hit() {
                hits += 1;
                let (last_t, last_f) = *s.steps.last().unwrap();
                assert!((last_t - t).abs() <= 1e-4 * t.max(1.0), "{last_t} vs {t}");
                assert!(last_f.abs() < m.epsilon_at(ray.at(t)) * 2.0);
                // Sphere tracing steps by f: each step is the last f.
                for w in s.steps.windows(2).skip(1) {
                    assert!(((w[1].0 - w[0].0) - w[0].1).abs() < 1e-3 * w[1].0.max(1.0));
                }
            }
        }
    }
    assert!(hits > 10, "{hits}");
}
