//! Chapter 5's known answers: closed forms against independent integrals,
//! and the estimator against the closed forms.

use std::f64::consts::PI;

use glam::{DVec3, Vec3};
use raystep::ch4_implicit_surfaces::hit::Surface;
use raystep::ch5_reflection::direct::{Estimator, Strategy};
use raystep::ch5_reflection::radiometry::{
    cap_solid_angle, directional_irradiance, point_irradiance, polygon_irradiance,
    sphere_solid_angle, spot_flux, triangle_solid_angle,
};
use raystep::ch5_reflection::shading_events::Counters;
use raystep::ch5_reflection::studies::{area_problem, sky_problem};
use raystep::ch5_reflection::world::{Interaction, World};
use raystep::core::sampling::Sampler;
use raystep::scene::Scene;

fn world(text: &str) -> World {
    World::new(&Scene::from_text(text, "t").unwrap())
}

const FLOOR: &str = "[[materials]]\nname = \"floor\"\nreflectance = [0.5, 0.25, 1.0]\n[[objects]]\nshape = \"rectangle\"\nsize = [4, 4]\nmaterial = \"floor\"\n";

fn at_origin(w: &World) -> Interaction {
    Interaction {
        t: 1.0,
        p: Vec3::ZERO,
        n: Vec3::Z,
        material: w.mesh_material[0],
        surface: Surface::Mesh(0),
    }
}

fn shade(w: &World, strategy: Strategy, wo: Vec3, n: u32) -> Vec3 {
    let est = Estimator {
        strategy,
        max_mirror_bounces: 0,
        trace_light_rays: true,
    };
    let mut c = Counters::default();
    let it = at_origin(w);
    let sum: Vec3 = (0..n)
        .map(|i| est.reflected(w, &it, wo, &mut Sampler::new(1, 0, i as u64), &mut c))
        .sum();
    assert_eq!(c.nonfinite, 0);
    sum / n as f32
}

#[test]
fn solid_angles_agree_with_each_other() {
    // Eight octant triangles tile the sphere.
    let axes = [DVec3::X, DVec3::Y, -DVec3::X, -DVec3::Y];
    let mut total = 0.0;
    for i in 0..4 {
        for z in [DVec3::Z, -DVec3::Z] {
            total += triangle_solid_angle(axes[i], axes[(i + 1) % 4], z);
        }
    }
    assert!((total - 4.0 * PI).abs() < 1e-12, "{total}");
    // A small far triangle: Ω ≈ A cos / d².
    let d = 1000.0;
    let t = [
        DVec3::new(0.0, 0.0, d),
        DVec3::new(1.0, 0.0, d),
        DVec3::new(0.0, 1.0, d),
    ];
    let o = triangle_solid_angle(t[0], t[1], t[2]);
    assert!((o - 0.5 / (d * d)).abs() < 1e-3 * o, "{o}");
    // A sphere's solid angle is the cap with sin α = r/d, and 2π at contact.
    let (r, dist) = (1.0f64, 3.0f64);
    let cap = cap_solid_angle((r / dist).asin());
    assert!((sphere_solid_angle(r, dist) - cap).abs() < 1e-12);
    assert!((sphere_solid_angle(1.0, 1.0) - 2.0 * PI).abs() < 1e-12);
    // Far away, the cancellation-free form still gives π r²/d².
    let far = sphere_solid_angle(1.0, 1e6);
    assert!((far - PI * 1e-12).abs() < 1e-6 * far, "{far}");
}

#[test]
fn lamberts_polygon_formula_matches_an_integral_over_the_rectangle() {
    // E(p) = ∫ Le cos θ cos θl / d² dA over a 1 × 1 rectangle at height 1,
    // shifted off the normal, by a 400 × 400 midpoint rule.
    let corners = [
        DVec3::new(0.0, -0.25, 1.0),
        DVec3::new(1.0, -0.25, 1.0),
        DVec3::new(1.0, 0.75, 1.0),
        DVec3::new(0.0, 0.75, 1.0),
    ];
    let closed = polygon_irradiance(DVec3::ZERO, DVec3::Z, &corners, 1.0);
    let k = 400;
    let mut sum = 0.0;
    for i in 0..k {
        for j in 0..k {
            let y = DVec3::new(
                (i as f64 + 0.5) / k as f64,
                -0.25 + (j as f64 + 0.5) / k as f64,
                1.0,
            );
            let d2 = y.length_squared();
            let cos = y.z / d2.sqrt();
            sum += cos * cos / d2;
        }
    }
    let numeric = sum / (k * k) as f64;
    assert!((closed - numeric).abs() < 1e-5, "{closed} vs {numeric}");
    // A huge square right above: E → π Le (the whole hemisphere).
    let s = 1e4;
    let big = [
        DVec3::new(-s, -s, 1.0),
        DVec3::new(s, -s, 1.0),
        DVec3::new(s, s, 1.0),
        DVec3::new(-s, s, 1.0),
    ];
    let e = polygon_irradiance(DVec3::ZERO, DVec3::Z, &big, 1.0);
    assert!((e - PI).abs() < 1e-3, "{e}");
}

#[test]
fn every_strategy_converges_to_the_polygon_formula() {
    let p = area_problem();
    for s in Strategy::ALL {
        let n = 20_000;
        let (l, _) = p.estimate(s, n, 3, 0);
        let rel = ((l.x - p.truth.x) / p.truth.x).abs();
        // Uniform is noisiest: its relative σ at 20k samples is ~1.5%.
        assert!(rel < 0.05, "{s:?}: {} vs {}", l.x, p.truth.x);
    }
    // And light sampling is far better than uniform at equal samples.
    let (light, _) = p.rmse(Strategy::Light, 64, 32);
    let (uniform, _) = p.rmse(Strategy::Uniform, 64, 32);
    assert!(light < 0.5 * uniform, "{light} vs {uniform}");
}

#[test]
fn every_strategy_converges_to_the_sky_irradiance() {
    let p = sky_problem();
    for s in Strategy::ALL {
        let (l, _) = p.estimate(s, 20_000, 4, 0);
        let err = (l - p.truth).abs().max_element() / p.truth.max_element();
        assert!(err < 0.02, "{s:?}: {l} vs {}", p.truth);
    }
}

#[test]
fn a_lambertian_plane_under_a_constant_environment_reflects_rho_l_exactly() {
    let w = world(&format!(
        "{FLOOR}[[lights]]\ntype = \"environment\"\nradiance = [2, 3, 4]\n"
    ));
    let want = Vec3::new(0.5 * 2.0, 0.25 * 3.0, 1.0 * 4.0);
    for s in [Strategy::Bsdf, Strategy::Light, Strategy::Mis] {
        for wo in [Vec3::Z, Vec3::new(0.6, 0.0, 0.8)] {
            let l = shade(&w, s, wo, 8);
            assert!((l - want).abs().max_element() < 1e-5, "{s:?}: {l}");
        }
    }
    // Uniform sampling is right on average only.
    let l = shade(&w, Strategy::Uniform, Vec3::Z, 20_000);
    assert!((l - want).abs().max_element() < 0.03 * 4.0, "{l}");
}

#[test]
fn a_point_light_follows_the_inverse_square_and_cosine_laws() {
    let mut previous: Option<f64> = None;
    for d in [1.0f32, 2.0, 4.0, 8.0] {
        let w = world(&format!(
            "{FLOOR}[[lights]]\ntype = \"point\"\nposition = [0, 0, {d}]\nintensity = [5, 5, 5]\n"
        ));
        let l = shade(&w, Strategy::Mis, Vec3::Z, 1).x as f64;
        let want = 0.5 / PI * point_irradiance(5.0, d as f64, 1.0);
        assert!((l - want).abs() < 1e-5 * want, "{l} vs {want}");
        if let Some(p) = previous {
            assert!(((p / l) - 4.0f64).abs() < 1e-4, "doubling d quarters L");
        }
        previous = Some(l);
    }
    // Tilted: 2 m away at 60° from the normal.
    let (x, z) = (
        2.0 * 60f64.to_radians().sin(),
        2.0 * 60f64.to_radians().cos(),
    );
    let w = world(&format!(
        "{FLOOR}[[lights]]\ntype = \"point\"\nposition = [{x}, 0, {z}]\nintensity = [5, 5, 5]\n"
    ));
    let l = shade(&w, Strategy::Mis, Vec3::Z, 1).x as f64;
    let want = 0.5 / PI * point_irradiance(5.0, 2.0, 0.5);
    assert!((l - want).abs() < 1e-4 * want, "{l} vs {want}");
}

#[test]
fn a_directional_light_follows_lamberts_cosine_law() {
    for deg in [0.0f64, 30.0, 60.0, 85.0, 90.0, 120.0] {
        let t = deg.to_radians();
        let w = world(&format!(
            "{FLOOR}[[lights]]\ntype = \"directional\"\ndirection = [{}, 0, {}]\nirradiance = [2, 2, 2]\n",
            -t.sin(),
            -t.cos()
        ));
        let l = shade(&w, Strategy::Light, Vec3::Z, 1).x as f64;
        let want = 0.5 / PI * directional_irradiance(2.0, t.cos());
        assert!((l - want).abs() < 1e-5, "{deg}°: {l} vs {want}");
    }
}

#[test]
fn a_spot_light_is_a_point_light_inside_its_cone_and_dark_outside() {
    let spot = |x: f32| {
        world(&format!(
            "{FLOOR}[[lights]]\ntype = \"spot\"\nposition = [{x}, 0, 2]\ndirection = [0, 0, -1]\nintensity = [5, 5, 5]\ncone_degrees = 20\nfalloff_degrees = 5\n"
        ))
    };
    let inside = shade(&spot(0.2), Strategy::Mis, Vec3::Z, 1).x as f64;
    let d2: f64 = 0.04 + 4.0;
    let want = 0.5 / PI * point_irradiance(5.0, d2.sqrt(), 2.0 / d2.sqrt());
    assert!((inside - want).abs() < 1e-4 * want, "{inside} vs {want}");
    // tan 20° · 2 ≈ 0.73: at x = 1 the floor's centre is outside the cone.
    assert_eq!(shade(&spot(1.0), Strategy::Mis, Vec3::Z, 1), Vec3::ZERO);
}

/// A spot's power in closed form (exercise 5.7's reference) is its
/// falloff, the lesson's `Spot::falloff`, summed over the sphere: over a
/// million directions spread evenly (a Fibonacci lattice, each carrying
/// 4π/N sr), and by the grader's quadrature in cos θ.
#[test]
fn a_spot_lights_power_is_its_falloff_summed_over_the_sphere() {
    use raystep::ch5_reflection::light::spot::Spot;
    use raystep::grading::exercises::ch5::falloff_integral;
    let n = 1_000_000u32;
    let golden = PI * (3.0 - 5f64.sqrt());
    for (cone, soft) in [
        (30.0, 10.0),
        (45.0, 0.0),
        (90.0, 90.0),
        (120.0, 40.0),
        (180.0, 0.0),
        (180.0, 180.0),
    ] {
        let spot = Spot::new(Vec3::ZERO, Vec3::Z, Vec3::ONE, cone, soft);
        let sum: f64 = (0..n)
            .map(|k| {
                let z = 1.0 - (2.0 * k as f64 + 1.0) / n as f64;
                let r = (1.0 - z * z).sqrt();
                let phi = golden * k as f64;
                let w = DVec3::new(r * phi.cos(), r * phi.sin(), z).as_vec3();
                f64::from(spot.falloff(w))
            })
            .sum();
        let lattice = sum * 4.0 * PI / n as f64;
        let (inner, outer) = (
            f64::from(spot.cos_inner).acos(),
            f64::from(spot.cos_outer).acos(),
        );
        let closed = spot_flux(1.0, inner, outer);
        assert!(
            (lattice - closed).abs() < 1e-4 * closed,
            "{cone}°/{soft}°: {lattice} vs {closed}"
        );
        let quadrature = falloff_integral(inner as f32, outer as f32);
        assert!(
            (quadrature - closed).abs() < 1e-5 * closed,
            "{cone}°/{soft}°: {quadrature} vs {closed}"
        );
    }
    // The whole sphere at full intensity: 4π I.
    assert!((spot_flux(2.0, PI, PI) - 8.0 * PI).abs() < 1e-12);
}
