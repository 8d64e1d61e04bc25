//! Unit tests of `src/ch3_ray_triangle/render.rs`.

use glam::Vec3;
use raystep::ch1_projection::camera::Camera;
use raystep::ch3_ray_triangle::geometry::{shade, Geometry};
use raystep::ch3_ray_triangle::render::*;
use raystep::core::film::Film;
use raystep::scene::Scene;

#[test]
fn a_pixels_hit_is_what_the_render_shaded() {
    // The four views of a one-sample render are `shade` of the hit:
    // the story's hit must shade to exactly the rendered values (its
    // t gives the depth view, its u, v the barycentrics view).
    let scene = Scene::builtin().with_resolution(20, 16).unwrap();
    let camera = Camera::of(&scene);
    let geometry = Geometry::new(&scene);
    let views = render_views(&camera, &geometry, 1, 3);
    let mut hits = 0;
    for y in 0..16 {
        for x in 0..20 {
            let h = pixel_hit(&camera, &geometry, (x, y), 1, 3, 0);
            let shaded = shade(&geometry, h.hit);
            for (v, film) in views.iter().enumerate() {
                assert_eq!(film.get(x, y), shaded[v], "view {v} at ({x}, {y})");
            }
            if let Some(hit) = h.hit {
                hits += 1;
                assert_eq!(film_bary(&views[2], x, y), hit.barycentrics());
                assert!(h.mesh.is_some());
            }
        }
    }
    assert!(hits > 100, "{hits}");
}

fn film_bary(f: &Film, x: u32, y: u32) -> Vec3 {
    f.get(x, y)
}
