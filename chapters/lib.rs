//! raystep's exercises: the files under `chN-…/exercises/`, one function
//! (or one algorithm) each, shipped as `todo!()` stubs. This crate is apart
//! from the renderer so that editing an exercise rebuilds only this crate,
//! and an exercise that does not compile is left out (see `build.rs`) while
//! the others are graded. Grade with `cargo run --release --bin grade`.

#![allow(unused_variables, unused_imports, dead_code, unreachable_code)]

use raystep::grading::exercises as checks;
use raystep::grading::runner::Registry;

/// A student's function, called through [`raystep::core::guard::student`]
/// (so that calling raystep's own solution of the exercise is caught) and
/// still a plain `fn` (a closure that captures nothing).
macro_rules! student {
    ($f:path, $($a:ident),*) => {
        |$($a),*| raystep::core::guard::student(|| $f($($a),*))
    };
}

include!(concat!(env!("OUT_DIR"), "/exercises.rs"));

/// Every exercise that compiled, with its check called on the student's
/// function. One entry per exercise; an exercise left out of the build
/// (`broken_chN_name`) is left out here too.
pub fn registry() -> Registry {
    let mut r: Registry = Vec::new();
    #[cfg(not(broken_ch1_project_point))]
    r.push(("ch1/project_point", || {
        checks::ch1::check_project_point(student!(ch1::project_point::project_point, a0))
    }));
    #[cfg(not(broken_ch1_look_at))]
    r.push(("ch1/look_at", || {
        checks::ch1::check_look_at(student!(ch1::look_at::look_at, a0, a1, a2))
    }));
    #[cfg(not(broken_ch1_draw_edges))]
    r.push(("ch1/draw_edges", || {
        checks::ch1::check_draw_edges(student!(ch1::draw_edges::draw_edges, a0, a1, a2, a3))
    }));
    #[cfg(not(broken_ch2_edge_function))]
    r.push(("ch2/edge_function", || {
        checks::ch2::check_edge_function(student!(ch2::edge_function::edge_function, a0, a1, a2))
    }));
    #[cfg(not(broken_ch2_barycentric))]
    r.push(("ch2/barycentric", || {
        checks::ch2::check_barycentric(student!(ch2::barycentric::barycentric, a0, a1, a2, a3))
    }));
    #[cfg(not(broken_ch2_depth_test))]
    r.push(("ch2/depth_test", || {
        checks::ch2::check_depth_test(student!(ch2::depth_test::depth_test, a0, a1, a2))
    }));
    #[cfg(not(broken_ch2_rasterize_triangle))]
    r.push(("ch2/rasterize_triangle", || {
        checks::ch2::check_rasterize_triangle(student!(
            ch2::rasterize_triangle::rasterize_triangle,
            a0,
            a1,
            a2,
            a3,
            a4,
            a5
        ))
    }));
    #[cfg(not(broken_ch3_ray_plane))]
    r.push(("ch3/ray_plane", || {
        checks::ch3::check_ray_plane(student!(ch3::ray_plane::ray_plane, a0, a1, a2, a3))
    }));
    #[cfg(not(broken_ch3_barycentric_inside))]
    r.push(("ch3/barycentric_inside", || {
        checks::ch3::check_barycentric_inside(student!(
            ch3::barycentric_inside::barycentric_inside,
            a0,
            a1
        ))
    }));
    #[cfg(not(broken_ch3_moller_trumbore))]
    r.push(("ch3/moller_trumbore", || {
        checks::ch3::check_moller_trumbore(student!(
            ch3::moller_trumbore::moller_trumbore,
            a0,
            a1,
            a2
        ))
    }));
    #[cfg(not(broken_ch3_bvh_traversal))]
    r.push(("ch3/bvh_traversal", || {
        checks::ch3::check_bvh_traversal(student!(ch3::bvh_traversal::closest_hit, a0, a1, a2))
    }));
    #[cfg(not(broken_ch4_sphere_sdf))]
    r.push(("ch4/sphere_sdf", || {
        checks::ch4::check_sphere_sdf(student!(ch4::sphere_sdf::sphere_sdf, a0, a1, a2))
    }));
    #[cfg(not(broken_ch4_sphere_trace))]
    r.push(("ch4/sphere_trace", || {
        checks::ch4::check_sphere_trace(student!(
            ch4::sphere_trace::sphere_trace,
            a0,
            a1,
            a2,
            a3,
            a4,
            a5
        ))
    }));
    #[cfg(not(broken_ch4_gradient_normal))]
    r.push(("ch4/gradient_normal", || {
        checks::ch4::check_gradient_normal(student!(
            ch4::gradient_normal::gradient_normal,
            a0,
            a1,
            a2
        ))
    }));
    #[cfg(not(broken_ch4_trace_scene))]
    r.push(("ch4/trace_scene", || {
        checks::ch4::check_trace_scene(student!(ch4::trace_scene::trace_scene, a0, a1, a2, a3))
    }));
    #[cfg(not(broken_ch5_lambert_brdf))]
    r.push(("ch5/lambert_brdf", || {
        checks::ch5::check_lambert_brdf(student!(ch5::lambert_brdf::lambert_brdf, a0, a1, a2))
    }));
    #[cfg(not(broken_ch5_cosine_hemisphere))]
    r.push(("ch5/cosine_hemisphere", || {
        checks::ch5::check_cosine_hemisphere(student!(
            ch5::cosine_hemisphere::cosine_hemisphere,
            a0
        ))
    }));
    #[cfg(not(broken_ch5_point_light))]
    r.push(("ch5/point_light", || {
        checks::ch5::check_point_light(student!(
            ch5::point_light::point_light_irradiance,
            a0,
            a1,
            a2,
            a3
        ))
    }));
    #[cfg(not(broken_ch5_area_pdf))]
    r.push(("ch5/area_pdf", || {
        checks::ch5::check_area_pdf(student!(ch5::area_pdf::area_to_solid_angle, a0, a1, a2, a3))
    }));
    #[cfg(not(broken_ch5_direct_light))]
    r.push(("ch5/direct_light", || {
        checks::ch5::check_direct_light(student!(
            ch5::direct_light::direct_light,
            a0,
            a1,
            a2,
            a3,
            a4,
            a5,
            a6,
            a7
        ))
    }));
    #[cfg(not(broken_ch6_mc_integral))]
    r.push(("ch6/mc_integral", || {
        checks::ch6::check_mc_integral(student!(ch6::mc_integral::mc_integral, a0, a1, a2, a3))
    }));
    #[cfg(not(broken_ch6_russian_roulette))]
    r.push(("ch6/russian_roulette", || {
        checks::ch6::check_russian_roulette(student!(
            ch6::russian_roulette::russian_roulette,
            a0,
            a1,
            a2
        ))
    }));
    #[cfg(not(broken_ch6_mis_weight))]
    r.push(("ch6/mis_weight", || {
        checks::ch6::check_mis_weight(student!(ch6::mis_weight::mis_weight, a0, a1))
    }));
    #[cfg(not(broken_ch6_path_radiance))]
    r.push(("ch6/path_radiance", || {
        checks::paths::check_path_radiance(student!(
            ch6::path_radiance::path_radiance,
            a0,
            a1,
            a2,
            a3
        ))
    }));
    r
}

/// The student's sampling routines the terminal UI's warp view can test
/// (`grade-student warp <id> …`): exercise 5.2's directions, tested
/// against the density its contract names, cos θ / π.
pub fn warps() -> raystep::grading::runner::Warps {
    let mut w: raystep::grading::runner::Warps = Vec::new();
    #[cfg(not(broken_ch5_cosine_hemisphere))]
    w.push((
        "ch5/cosine_hemisphere",
        raystep::core::warp_test::WarpRoutine {
            name: "your cosine_hemisphere (exercise 5.2)",
            sample: |u| {
                let f = student!(ch5::cosine_hemisphere::cosine_hemisphere, a0);
                Some(f(u).0)
            },
            pdf: |w| (w.z / std::f32::consts::PI).max(0.0),
        },
    ));
    w
}
