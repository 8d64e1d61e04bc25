//! The process that runs a student's exercise functions for the grader.
//!
//! It is handed one request on standard input, runs the exercise's check
//! with the student's functions in a sandbox, and sends back the
//! transcript of their calls (arguments, callbacks, answers), nothing
//! else: the grader replays the check on that transcript in its own
//! process and decides there (`raystep::grading::bridge`). This file only
//! connects the student's functions to the grader's types.

use glam::{Mat4, Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::triangle::Hit;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::ch6_global_illumination::layers::LAYER_SLOTS;
use raystep::grading::counted::ReadableBvh;
use raystep::grading::exercises::bounce_layers::Gathered;
use raystep::grading::exercises::paths::PathScene;
use raystep::grading::students::Students;
use raystep_grade_blocks as blocks;
use raystep_grade_student as student;

struct Student;

impl Students for Student {
    fn project_point(p: Vec3) -> Option<Vec2> {
        student::ch1::project_point::project_point(p)
    }
    fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
        student::ch1::look_at::look_at(eye, target, up)
    }
    fn draw_edges(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
        let camera = blocks::ch1_projection::camera::Camera::of(camera);
        student::ch1::draw_edges::draw_edges(&camera, a, b, near)
    }
    fn edge_function(a: Vec2, b: Vec2, p: Vec2) -> f32 {
        student::ch2::edge_function::edge_function(a, b, p)
    }
    fn barycentric(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
        student::ch2::barycentric::barycentric(pi, pj, pk, p)
    }
    fn depth_test(depth: &mut [f32], index: usize, z: f32) -> bool {
        student::ch2::depth_test::depth_test(depth, index, z)
    }
    fn rasterize_triangle(
        v: [Vec3; 3],
        colors: [Vec3; 3],
        width: u32,
        height: u32,
        depth: &mut [f32],
        image: &mut [Vec3],
    ) {
        student::ch2::rasterize_triangle::rasterize_triangle(v, colors, width, height, depth, image)
    }
    fn manifold_counts(triangles: &[[u32; 3]]) -> (usize, usize, usize, usize) {
        student::ch2::manifold::manifold_counts(triangles)
    }
    fn ray_plane(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
        student::ch3::ray_plane::ray_plane(o, d, n, c)
    }
    fn barycentric_inside(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
        student::ch3::barycentric_inside::barycentric_inside(p, tri)
    }
    fn moller_trumbore(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
        student::ch3::moller_trumbore::moller_trumbore(o, d, tri)
    }
    fn closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
        student::ch3::bvh_traversal::closest_hit(bvh, ray, t_max)
    }
    fn sah_split(boxes: &[[Vec3; 2]], centroids: &[Vec3]) -> Option<(usize, f32)> {
        student::ch3::sah::sah_split(boxes, centroids)
    }
    fn sphere_sdf(p: Vec3, center: Vec3, radius: f32) -> f32 {
        student::ch4::sphere_sdf::sphere_sdf(p, center, radius)
    }
    fn sphere_trace(
        sdf: &dyn Fn(Vec3) -> f32,
        origin: Vec3,
        dir: Vec3,
        epsilon: f32,
        max_steps: u32,
        max_distance: f32,
    ) -> Option<f32> {
        student::ch4::sphere_trace::sphere_trace(sdf, origin, dir, epsilon, max_steps, max_distance)
    }
    fn gradient_normal(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
        student::ch4::gradient_normal::gradient_normal(sdf, p, h)
    }
    fn trace_scene(
        sdf: &dyn Fn(Vec3) -> f32,
        origin: Vec3,
        dir: Vec3,
        march: &March,
    ) -> Option<(f32, Vec3)> {
        student::ch4::trace_scene::trace_scene(sdf, origin, dir, march)
    }
    fn lambert_brdf(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
        student::ch5::lambert_brdf::lambert_brdf(rho, wo, wi)
    }
    fn cosine_hemisphere(u: Vec2) -> (Vec3, f32) {
        student::ch5::cosine_hemisphere::cosine_hemisphere(u)
    }
    fn point_light_irradiance(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
        student::ch5::point_light::point_light_irradiance(intensity, light, p, n)
    }
    fn area_to_solid_angle(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
        student::ch5::area_pdf::area_to_solid_angle(pdf_area, x, y, n_light)
    }
    fn solid_angle(p: Vec3, tri: [Vec3; 3]) -> f32 {
        student::ch5::solid_angle::solid_angle(p, tri)
    }
    fn spot_power(intensity: Vec3, inner: f32, outer: f32) -> Vec3 {
        student::ch5::spot::spot_power(intensity, inner, outer)
    }
    fn direct_light(
        p: Vec3,
        n: Vec3,
        rho: Vec3,
        y: Vec3,
        n_light: Vec3,
        area: f32,
        le: Vec3,
        visible: &dyn Fn(Vec3, Vec3) -> bool,
    ) -> Vec3 {
        student::ch5::direct_light::direct_light(p, n, rho, y, n_light, area, le, visible)
    }
    fn mc_integral(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
        student::ch6::mc_integral::mc_integral(f, a, b, u)
    }
    fn russian_roulette(value: f64, q: f64, u: f64) -> f64 {
        student::ch6::russian_roulette::russian_roulette(value, q, u)
    }
    fn mis_weight(pdf_f: f64, pdf_g: f64) -> f64 {
        student::ch6::mis_weight::mis_weight(pdf_f, pdf_g)
    }
    fn path_radiance(
        scene: &PathScene,
        origin: Vec3,
        dir: Vec3,
        rng: &mut dyn FnMut() -> f32,
    ) -> Vec3 {
        student::ch6::path_radiance::path_radiance(scene, origin, dir, rng)
    }
    fn refract(d: Vec3, n: Vec3, eta_outside: f32, eta_inside: f32) -> Option<(Vec3, f32)> {
        student::ch6::refraction::refract(d, n, eta_outside, eta_inside)
    }
    fn bounce_layers(path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
        student::ch6::bounce_layers::bounce_layers(path)
    }
}

fn main() -> std::process::ExitCode {
    raystep::grading::runner::child_main::<Student>()
}
