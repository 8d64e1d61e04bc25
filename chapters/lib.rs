//! raystep's exercises: the files under `chN-…/exercises/`, one function
//! (or one algorithm) each, shipped as `todo!()` stubs. This crate is apart
//! from the renderer so that editing an exercise rebuilds only this crate,
//! and an exercise that does not compile is left out (see `build.rs`) while
//! the others are graded. Grade with `cargo run --release --bin grade`.

#![allow(unused_variables, unused_imports, dead_code, unreachable_code)]

use raystep::grading::exercises as checks;
use raystep::grading::runner::Registry;

include!(concat!(env!("OUT_DIR"), "/exercises.rs"));

/// Every exercise that compiled, with its check called on the student's
/// function. One entry per exercise; an exercise left out of the build
/// (`broken_chN_name`) is left out here too.
pub fn registry() -> Registry {
    let mut r: Registry = Vec::new();
    #[cfg(not(broken_ch1_project_point))]
    r.push(("ch1/project_point", || {
        checks::ch1::check_project_point(ch1::project_point::project_point)
    }));
    #[cfg(not(broken_ch1_look_at))]
    r.push(("ch1/look_at", || {
        checks::ch1::check_look_at(ch1::look_at::look_at)
    }));
    #[cfg(not(broken_ch1_draw_edges))]
    r.push(("ch1/draw_edges", || {
        checks::ch1::check_draw_edges(ch1::draw_edges::draw_edges)
    }));
    #[cfg(not(broken_ch2_edge_function))]
    r.push(("ch2/edge_function", || {
        checks::ch2::check_edge_function(ch2::edge_function::edge_function)
    }));
    #[cfg(not(broken_ch2_barycentric))]
    r.push(("ch2/barycentric", || {
        checks::ch2::check_barycentric(ch2::barycentric::barycentric)
    }));
    #[cfg(not(broken_ch2_depth_test))]
    r.push(("ch2/depth_test", || {
        checks::ch2::check_depth_test(ch2::depth_test::depth_test)
    }));
    #[cfg(not(broken_ch2_rasterize_triangle))]
    r.push(("ch2/rasterize_triangle", || {
        checks::ch2::check_rasterize_triangle(ch2::rasterize_triangle::rasterize_triangle)
    }));
    #[cfg(not(broken_ch3_ray_plane))]
    r.push(("ch3/ray_plane", || {
        checks::ch3::check_ray_plane(ch3::ray_plane::ray_plane)
    }));
    #[cfg(not(broken_ch3_barycentric_inside))]
    r.push(("ch3/barycentric_inside", || {
        checks::ch3::check_barycentric_inside(ch3::barycentric_inside::barycentric_inside)
    }));
    #[cfg(not(broken_ch3_moller_trumbore))]
    r.push(("ch3/moller_trumbore", || {
        checks::ch3::check_moller_trumbore(ch3::moller_trumbore::moller_trumbore)
    }));
    #[cfg(not(broken_ch3_bvh_traversal))]
    r.push(("ch3/bvh_traversal", || {
        checks::ch3::check_bvh_traversal(ch3::bvh_traversal::closest_hit)
    }));
    #[cfg(not(broken_ch4_sphere_sdf))]
    r.push(("ch4/sphere_sdf", || {
        checks::ch4::check_sphere_sdf(ch4::sphere_sdf::sphere_sdf)
    }));
    #[cfg(not(broken_ch4_sphere_trace))]
    r.push(("ch4/sphere_trace", || {
        checks::ch4::check_sphere_trace(ch4::sphere_trace::sphere_trace)
    }));
    #[cfg(not(broken_ch4_gradient_normal))]
    r.push(("ch4/gradient_normal", || {
        checks::ch4::check_gradient_normal(ch4::gradient_normal::gradient_normal)
    }));
    #[cfg(not(broken_ch4_trace_scene))]
    r.push(("ch4/trace_scene", || {
        checks::ch4::check_trace_scene(ch4::trace_scene::trace_scene)
    }));
    #[cfg(not(broken_ch5_lambert_brdf))]
    r.push(("ch5/lambert_brdf", || {
        checks::ch5::check_lambert_brdf(ch5::lambert_brdf::lambert_brdf)
    }));
    #[cfg(not(broken_ch5_cosine_hemisphere))]
    r.push(("ch5/cosine_hemisphere", || {
        checks::ch5::check_cosine_hemisphere(ch5::cosine_hemisphere::cosine_hemisphere)
    }));
    #[cfg(not(broken_ch5_point_light))]
    r.push(("ch5/point_light", || {
        checks::ch5::check_point_light(ch5::point_light::point_light_irradiance)
    }));
    #[cfg(not(broken_ch5_area_pdf))]
    r.push(("ch5/area_pdf", || {
        checks::ch5::check_area_pdf(ch5::area_pdf::area_to_solid_angle)
    }));
    #[cfg(not(broken_ch5_direct_light))]
    r.push(("ch5/direct_light", || {
        checks::ch5::check_direct_light(ch5::direct_light::direct_light)
    }));
    #[cfg(not(broken_ch6_mc_integral))]
    r.push(("ch6/mc_integral", || {
        checks::ch6::check_mc_integral(ch6::mc_integral::mc_integral)
    }));
    #[cfg(not(broken_ch6_russian_roulette))]
    r.push(("ch6/russian_roulette", || {
        checks::ch6::check_russian_roulette(ch6::russian_roulette::russian_roulette)
    }));
    #[cfg(not(broken_ch6_mis_weight))]
    r.push(("ch6/mis_weight", || {
        checks::ch6::check_mis_weight(ch6::mis_weight::mis_weight)
    }));
    #[cfg(not(broken_ch6_path_radiance))]
    r.push(("ch6/path_radiance", || {
        checks::paths::check_path_radiance(ch6::path_radiance::path_radiance)
    }));
    r
}
