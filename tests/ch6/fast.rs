//! The fast engine (`fast`) on every shipped scene: the same bytes on
//! every SIMD path this CPU has; the same bytes as the lesson's engine
//! where it runs the lesson's path loop, and the same paths up to the last
//! bits of a sine where it runs the wavefront (its polynomial sine); the
//! table-driven Sobol numbers equal the crate's; `unsafe` code only in the
//! one module that argues for it.

use std::path::Path;

use raystep::ch1_projection::camera::Camera;
use raystep::ch6_global_illumination::accumulate::Accumulator;
use raystep::ch6_global_illumination::engine::{PathEngine, PathLoop};
use raystep::ch6_global_illumination::integrator::{PathSettings, Strategy};
use raystep::ch6_global_illumination::sampler::{sobol_group, sobol_group_by_table, SamplerKind};
use raystep::fast::level::Level;
use raystep::fast::{wave, FastEngine};
use raystep::scene::Scene;

/// The fast engine with `level`'s instructions, or (`None`) the lesson's.
fn render(
    scene: &Scene,
    level: Option<Level>,
    path: &PathSettings,
    sampler: SamplerKind,
) -> Accumulator {
    let engine: Box<dyn PathEngine> = match level {
        Some(level) => Box::new(FastEngine::at(scene, level)),
        None => Box::new(PathLoop::new(scene)),
    };
    let camera = Camera::of(scene);
    let mut acc = Accumulator::new(camera.width, camera.height, true);
    acc.add_samples(&*engine, &camera, path, sampler, 3, 2);
    acc
}

fn shipped(name: &str) -> Scene {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    Scene::load(&root.join("scenes").join(name))
        .unwrap()
        .with_resolution(40, 30)
        .unwrap()
}

/// How far the fast engine's image is from the readable one's: the largest
/// per-pixel difference of the sums over the largest pixel sum, and the
/// share of pixels that differ by more than 10⁻⁴ of it.
fn distance(a: &Accumulator, b: &Accumulator) -> (f32, f64) {
    let scale = a.sum.iter().map(|p| p.max_element()).fold(0.0f32, f32::max);
    let diffs: Vec<f32> = a
        .sum
        .iter()
        .zip(&b.sum)
        .map(|(x, y)| (*x - *y).abs().max_element() / scale)
        .collect();
    let worst = diffs.iter().copied().fold(0.0f32, f32::max);
    let far = diffs.iter().filter(|d| **d > 1e-4).count() as f64 / diffs.len() as f64;
    (worst, far)
}

#[test]
fn both_engines_agree_on_every_scene_and_the_fast_one_on_every_simd_path() {
    let levels: Vec<Level> = Level::ALL.into_iter().filter(|l| l.available()).collect();
    assert!(levels.contains(&Level::Portable));
    let mut scenes = vec![Scene::builtin().with_resolution(40, 40).unwrap()];
    for name in [
        "cornell-glass.toml",
        "lights-gallery.toml",
        "bunny.toml",
        "brdf-row.toml",
        "interpenetrating.toml",
        "sdf-lit.toml",
        "tetrahedron.toml",
    ] {
        scenes.push(shipped(name));
    }
    let (mut compared, mut in_waves) = (0, 0);
    for scene in &scenes {
        // Each sampler's own roulette scale, and each with the other's
        // (and a larger one).
        for (strategy, sampler, rr_scale) in [
            (Strategy::Mis, SamplerKind::Sobol, None),
            (Strategy::Mis, SamplerKind::Independent, None),
            (Strategy::Mis, SamplerKind::Sobol, Some(1)),
            (Strategy::Mis, SamplerKind::Independent, Some(4)),
            (Strategy::Bsdf, SamplerKind::Independent, None),
            (Strategy::Light, SamplerKind::Sobol, None),
            (Strategy::Uniform, SamplerKind::Independent, None),
        ] {
            let path = PathSettings {
                strategy,
                rr_scale,
                ..PathSettings::default()
            };
            let readable = render(scene, None, &path, sampler);
            assert!(readable.stats.rays > 0, "{}", scene.name);
            // The lanes shade some vertices (then the images agree up to
            // the last bits of a sine), or the lesson's steps shade them
            // all (then the bytes are the readable engine's).
            let engine = FastEngine::new(scene);
            let waves = wave::supports(engine.world()) && wave::lanes_shade(engine.world(), &path);
            let first = render(scene, Some(Level::Portable), &path, sampler);
            for &level in &levels {
                let fast = render(scene, Some(level), &path, sampler);
                let what = format!(
                    "{} {} {} {rr_scale:?} on {}",
                    scene.name,
                    strategy.name(),
                    sampler.name(),
                    level.name()
                );
                // Every SIMD path: the same bytes.
                assert_eq!(fast.sum, first.sum, "{what}");
                assert_eq!(fast.sum_sq, first.sum_sq, "{what}");
                assert_eq!(fast.layers, first.layers, "{what}");
                assert_eq!(fast.stats, first.stats, "{what}");
                compared += 1;
            }
            if waves {
                // The wavefront loop: the same paths up to the last bits of
                // a sine (so the odd path turns differently).
                in_waves += 1;
                let (worst, far) = distance(&first, &readable);
                let what = format!(
                    "{} {} {} {rr_scale:?}",
                    scene.name,
                    strategy.name(),
                    sampler.name()
                );
                assert!(
                    far < 0.01 && worst < 0.05,
                    "{what}: worst {worst}, {far} of pixels"
                );
                let rays = |a: &Accumulator| a.stats.rays as f64;
                assert!(
                    (rays(&first) / rays(&readable) - 1.0).abs() < 1e-3,
                    "{what}"
                );
                assert_eq!(first.stats.paths, readable.stats.paths, "{what}");
                assert_eq!(first.stats.nonfinite, 0, "{what}");
            } else {
                // The lesson's loop over the eight-wide tree: the same bytes.
                let what = format!(
                    "{} {} {} {rr_scale:?}",
                    scene.name,
                    strategy.name(),
                    sampler.name()
                );
                assert_eq!(first.sum, readable.sum, "{what}");
                assert_eq!(first.sum_sq, readable.sum_sq, "{what}");
                assert_eq!(first.layers, readable.layers, "{what}");
                assert_eq!(first.stats, readable.stats, "{what}");
            }
        }
    }
    assert_eq!(compared, scenes.len() * 7 * levels.len());
    // The built-in box and the bunny at least go through the waves, with
    // both samplers and both scales.
    assert!(in_waves >= 8, "{in_waves}");
}

#[test]
fn a_level_the_cpu_lacks_falls_back_to_portable() {
    let scene = Scene::builtin();
    for level in Level::ALL {
        let engine = FastEngine::at(&scene, level);
        assert!(engine.world().queries.is_some());
        assert!(engine.tree().is_some_and(|t| t.level().available()));
    }
    assert!(Level::Portable.available());
}

#[test]
fn the_table_driven_sobol_numbers_are_the_crates() {
    for sample in (0..4096u64).chain([65_535]) {
        for (pixel_scramble, group) in [
            (0u64, 0u64),
            (0x1234_5678_9abc, 3),
            (u64::MAX, 17),
            (42, 1 << 40),
        ] {
            let a = sobol_group(sample, pixel_scramble, group);
            let b = sobol_group_by_table(sample, pixel_scramble, group);
            assert_eq!(
                a.map(f32::to_bits),
                b.map(f32::to_bits),
                "sample {sample} group {group}"
            );
        }
    }
}

#[test]
fn unsafe_code_lives_in_one_module() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut found = Vec::new();
    for p in crate::common::files_under(&src, "rs") {
        let text = std::fs::read_to_string(&p).unwrap();
        let code: String = text
            .lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .collect::<Vec<_>>()
            .join("\n");
        if code.contains("unsafe {") || code.contains("unsafe fn") {
            found.push(p.strip_prefix(&src).unwrap().display().to_string());
        }
    }
    found.sort();
    assert_eq!(
        found,
        [
            "fast/simd/avx.rs",
            "fast/simd/mod.rs",
            "fast/simd/numbers.rs"
        ]
    );
    // The crates' roots: only the fast engine's may allow it, in simd/.
    for (root, rule) in [
        ("lessons.rs", "#![forbid(unsafe_code)]"),
        ("lib.rs", "#![forbid(unsafe_code)]"),
        ("grading/mod.rs", "#![forbid(unsafe_code)]"),
        ("tui/mod.rs", "#![forbid(unsafe_code)]"),
        ("fast/mod.rs", "#![deny(unsafe_code)]"),
    ] {
        let text = std::fs::read_to_string(src.join(root)).unwrap();
        assert!(text.contains(rule), "src/{root} lacks {rule}");
    }
    // Each chapter forbids it outright (no `allow` can switch it back on).
    for chapter in crate::common::CHAPTER_MODULES {
        let m = std::fs::read_to_string(src.join(chapter).join("mod.rs")).unwrap();
        assert!(m.contains("#![forbid(unsafe_code)]"), "{chapter}");
    }
}

#[test]
fn the_engine_flag_chooses_the_tree_chapter_6_traces() {
    use raystep::core::stage::Settings;
    use std::sync::Arc;
    let scene = Arc::new(Scene::builtin().with_resolution(8, 8).unwrap());
    let settings = Settings {
        spp: 1,
        ..Settings::default()
    };
    for (readable, tree) in [(false, "8 wide"), (true, "4 wide")] {
        let ch6 = raystep::chapters::with_engine(readable)[5];
        assert_eq!(ch6.info().number, 6);
        let mut r = ch6.start(scene.clone(), &settings).unwrap();
        while !r.pass().complete {}
        let built = r.report().built.join("\n");
        assert!(built.contains(tree), "readable = {readable}: {built}");
    }
}

#[test]
fn the_owen_scramble_is_the_crates() {
    use raystep::ch6_global_illumination::sampler::owen_finish;
    use sobol_burley::parts::{hash_int4, owen_scramble_int4_rev, Int4};
    let mut x = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..20_000 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let (sobol, seed) = (
            [
                x as u32,
                (x >> 32) as u32,
                (x >> 7) as u32,
                (x >> 19) as u32,
            ],
            (x >> 11) as u32,
        );
        // The crate's own steps, as `sample_4d` takes them.
        let s = seed.wrapping_mul(0x9c8f2d3b);
        let scramble: Int4 = [
            s ^ 0x912f69ba,
            s ^ 0x174f18ab,
            s ^ 0x691e72ca,
            s ^ 0xb40cc1b8,
        ]
        .into();
        let expected = owen_scramble_int4_rev(sobol.into(), hash_int4(scramble))
            .reverse_bits()
            .to_f32_norm()
            .map(|u| u.min(1.0 - f32::EPSILON / 2.0));
        let got = owen_finish(sobol, seed);
        assert_eq!(got.map(f32::to_bits), expected.map(f32::to_bits));
    }
}

#[test]
fn the_lanes_offsets_are_chapter_3s_bit_for_bit() {
    use glam::Vec3;
    use raystep::ch3_ray_triangle::spawn::{offset_origin, stop_distance};
    use raystep::fast::lane_rays;
    let mut values = vec![
        0.0f32,
        -0.0,
        1.0 / 32.0,
        -1.0 / 32.0,
        0.031,
        1e-30,
        1e30,
        -1e30,
    ];
    let mut h = 0x9e37_79b9_7f4a_7c15u64;
    for _ in 0..20_000 {
        h = h
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let bits = (h >> 32) as u32;
        let v = f32::from_bits(bits);
        if v.is_finite() {
            values.push(v);
            values.push(v.fract());
        }
    }
    let normals = [-1.0f32, -0.7, -0.01, 0.0, 0.3, 1.0];
    for (i, &p) in values.iter().enumerate() {
        let n = normals[i % normals.len()];
        let want = offset_origin(Vec3::splat(p), Vec3::splat(n)).x;
        assert_eq!(
            lane_rays::offset_coordinate(p, n).to_bits(),
            want.to_bits(),
            "{p} {n}"
        );
        let y = [
            p,
            values[(i * 7) % values.len()],
            -values[(i * 13) % values.len()],
        ];
        let want = stop_distance(Vec3::from_array(y));
        assert_eq!(
            lane_rays::stop_distance(y).to_bits(),
            want.to_bits(),
            "{y:?}"
        );
    }
}

#[test]
fn the_lanes_truncation_is_rusts_cast() {
    use raystep::fast::lane_rays::truncate;
    let specials = [
        0.0f32,
        -0.0,
        0.5,
        -0.999,
        1.0,
        -1.0,
        8_388_607.5,
        16_777_217.0,
        2_147_483_520.0,
        2_147_483_648.0,
        -2_147_483_648.0,
        -2_147_483_904.0,
        f32::MAX,
        f32::MIN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        -f32::NAN,
        f32::from_bits(0x7f80_0001),
        f32::MIN_POSITIVE,
        1e-45,
        // Where the integer part's two halves meet, and where floors by
        // adding 2^23 round up.
        65_535.996,
        65_536.0,
        -65_536.5,
        131_071.99,
        0.499_999_97,
        1.5,
        -2.5,
        4_194_303.5,
        8_388_607.0,
        1_073_741_823.9,
    ];
    // Every 4099th bit pattern (both signs, every exponent), and the specials.
    let strided = (0..=u32::MAX / 4099).map(|i| f32::from_bits(i * 4099));
    for x in specials.into_iter().chain(strided) {
        assert_eq!(truncate(x), x as i32, "{x:e} ({:#x})", x.to_bits());
    }
}

#[test]
fn eight_paths_numbers_are_the_samplers_bit_for_bit() {
    use raystep::ch6_global_illumination::sampler::PathSampler;
    use raystep::fast::simd::independent8_at;
    use raystep::fast::sobol8::{independent8, sobol_group8, sobol_groups8};
    for kind in [SamplerKind::Sobol, SamplerKind::Independent] {
        for (pixel0, sample0) in [(0u64, 0u64), (12_345, 63), (7, 4_000)] {
            let samplers: Vec<PathSampler> = (0..8u64)
                .map(|j| PathSampler::new(kind, 42, pixel0 + j * 31, sample0 + j))
                .collect();
            for first in [4u64, 12, 132] {
                let lanes = match kind {
                    SamplerKind::Sobol => {
                        let sample = std::array::from_fn(|j| samplers[j].sobol_index().unwrap());
                        let scramble = std::array::from_fn(|j| samplers[j].pixel_scramble());
                        let (a, b) = (
                            sobol_group8(&sample, &scramble, first / 4),
                            sobol_group8(&sample, &scramble, first / 4 + 1),
                        );
                        // The two groups side by side (the wave loop's form)
                        // are the same numbers as one at a time.
                        let pair = sobol_groups8::<2>(&sample, &scramble, first / 4);
                        assert_eq!(
                            pair.map(|g| g.map(|d| d.map(f32::to_bits))),
                            [a, b].map(|g| g.map(|d| d.map(f32::to_bits)))
                        );
                        [a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]]
                    }
                    SamplerKind::Independent => {
                        let prefix =
                            std::array::from_fn(|j| samplers[j].independent_prefix().unwrap());
                        let lanes = independent8(&prefix, first);
                        // Every SIMD path (AVX-512's multiplies 64-bit
                        // lanes in one instruction) gives the same bits.
                        for level in Level::ALL.into_iter().filter(|l| l.available()) {
                            let at = independent8_at(level, &prefix, first);
                            assert_eq!(
                                at.map(|d| d.map(f32::to_bits)),
                                lanes.map(|d| d.map(f32::to_bits)),
                                "{level:?}"
                            );
                        }
                        lanes
                    }
                };
                for (j, s) in samplers.iter().enumerate() {
                    let want = s.eight_at(first);
                    for d in 0..8 {
                        assert_eq!(
                            lanes[d][j].to_bits(),
                            want[d].to_bits(),
                            "{kind:?} {first} {j} {d}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn the_lanes_triangle_pick_and_its_corners_are_the_lights() {
    use glam::Vec3;
    use raystep::ch5_reflection::light::area::AreaLight;
    use raystep::fast::pick8::{fill_light8, pick8, MAX_TRIANGLES};
    use raystep::fast::shade8::In8;
    let light = |areas: &[f32]| {
        let cdf: Vec<f32> = areas
            .iter()
            .scan(0.0f32, |sum, a| {
                *sum += a;
                Some(*sum)
            })
            .collect();
        let area = *cdf.last().unwrap();
        AreaLight {
            mesh: 0,
            // Corners and normals that tell the triangles apart.
            triangles: (0..areas.len())
                .map(|i| [0.0, 1.0, 2.0].map(|c| Vec3::new(i as f32, c, -(i as f32) - c)))
                .collect(),
            cdf,
            normals: (0..areas.len())
                .map(|i| Vec3::new(1.0, i as f32, 0.5).normalize())
                .collect(),
            area,
            inv_area: 1.0 / area,
            le: Vec3::ONE,
            two_sided: false,
            sampling: raystep::scene::LightSampling::Area,
        }
    };
    // Areas of every size, with zero-area triangles first, between and last.
    let mut lights = vec![
        light(&[1.0]),
        light(&[0.5, 0.5]),
        light(&[0.0, 2.0, 0.0, 1e-7, 3.0, 0.0]),
        light(&[1e-3, 1e3, 7.0, 0.1, 0.0, 2.5, 9.0, 1.0]),
    ];
    let mut state = 12345u64;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    for n in 1..=MAX_TRIANGLES {
        let areas: Vec<f32> = (0..n).map(|_| next() * 4.0).collect();
        lights.push(light(&areas));
    }
    for l in &lights {
        // Numbers across [0, 1), and the ones that land exactly on a
        // running total (and next to it).
        let mut us: Vec<f32> = (0..4000).map(|_| next()).collect();
        us.extend([0.0, 1.0 - f32::EPSILON, 0.5]);
        for c in &l.cdf {
            let u = c / l.area;
            us.extend([
                u,
                f32::from_bits(u.to_bits().saturating_sub(1)),
                f32::from_bits(u.to_bits() + 1),
            ]);
        }
        for group in us.chunks(8) {
            let u: [f32; 8] = std::array::from_fn(|j| group[j % group.len()]);
            let (t, ux) = pick8(l, &u).expect("at most eight triangles");
            // The lanes' arrays filled for that light, with selects.
            let mut x = In8::default();
            x.u[1] = u;
            assert!(fill_light8(l, 0.25, &mut x));
            for j in 0..8 {
                let (want_t, want_ux) = l.pick(u[j]);
                let corners = l.triangles[want_t];
                for a in 0..3 {
                    for (c, corner) in corners.iter().enumerate() {
                        assert_eq!(x.tri[c][a][j], corner[a], "corner {c} of {want_t}");
                    }
                    assert_eq!(x.n_light[a][j], l.normals[want_t][a]);
                    assert_eq!(x.le[a][j], l.le[a]);
                }
                assert_eq!(x.ux[j].to_bits(), want_ux.to_bits());
                assert_eq!(
                    (x.inv_area[j], x.two_sided[j], x.p_choose[j]),
                    (l.inv_area, l.two_sided, 0.25)
                );
                assert_eq!(t[j] as usize, want_t, "cdf {:?} u {}", l.cdf, u[j]);
                assert_eq!(
                    ux[j].to_bits(),
                    want_ux.to_bits(),
                    "cdf {:?} u {}",
                    l.cdf,
                    u[j]
                );
            }
        }
    }
    // More triangles than the lanes pick: left to `pick`.
    let many = light(&[1.0; MAX_TRIANGLES + 1]);
    assert!(pick8(&many, &[0.5; 8]).is_none());
    assert!(!fill_light8(&many, 1.0, &mut In8::default()));
}

#[test]
fn the_sobol_lanes_are_the_same_bits_on_every_simd_path() {
    use raystep::fast::simd::sobol_groups8_at;
    use raystep::fast::sobol8::sobol_groups8;
    // Sample indices across the tables' range (every bit of the shuffled
    // index in play), pixels and groups of all sizes.
    let mut next = crate::common::xorshift(0x2545_f491_4f6c_dd1d);
    let mut compared = 0;
    for round in 0..200u64 {
        let sample: [u32; 8] = std::array::from_fn(|_| (next() >> 48) as u32);
        let scramble: [u64; 8] = std::array::from_fn(|_| next());
        let group = round % 40;
        let one = sobol_groups8::<1>(&sample, &scramble, group);
        let two = sobol_groups8::<2>(&sample, &scramble, group);
        for level in Level::ALL.into_iter().filter(|l| l.available()) {
            let bits = |v: f32| v.to_bits();
            let got1 = sobol_groups8_at::<1>(level, &sample, &scramble, group);
            let got2 = sobol_groups8_at::<2>(level, &sample, &scramble, group);
            assert_eq!(
                got1.map(|g| g.map(|d| d.map(bits))),
                one.map(|g| g.map(|d| d.map(bits)))
            );
            assert_eq!(
                got2.map(|g| g.map(|d| d.map(bits))),
                two.map(|g| g.map(|d| d.map(bits)))
            );
            compared += 1;
        }
    }
    assert!(compared >= 200);
}

#[test]
fn numbers_made_only_where_wanted_are_the_same_bits_and_the_rest_zero() {
    use raystep::fast::simd::{independent8_wanted_at, sobol_groups8_wanted_at};
    use raystep::fast::sobol8::{independent8, sobol_groups8};
    let mut next = crate::common::xorshift(0x0123_4567_89ab_cdef);
    let mut compared = 0;
    for round in 0..100u64 {
        let sample: [u32; 8] = std::array::from_fn(|_| (next() >> 48) as u32);
        let scramble: [u64; 8] = std::array::from_fn(|_| next());
        let wanted = (next() & 0xff) as u8;
        let first = 4 + 8 * (round % 20);
        let all = sobol_groups8::<2>(&sample, &scramble, first / 4);
        let all_independent = independent8(&scramble, first);
        for level in Level::ALL.into_iter().filter(|l| l.available()) {
            let some =
                sobol_groups8_wanted_at::<2>(level, &sample, &scramble, first / 4, wanted.into());
            let some_independent = independent8_wanted_at(level, &scramble, first, wanted);
            for d in 0..8 {
                let (g, dd) = (d / 4, d % 4);
                let on = wanted >> d & 1 == 1;
                for j in 0..8 {
                    let want = if on { all[g][dd][j] } else { 0.0 };
                    assert_eq!(
                        some[g][dd][j].to_bits(),
                        want.to_bits(),
                        "{level:?} {d} {j}"
                    );
                    let want = if on { all_independent[d][j] } else { 0.0 };
                    assert_eq!(some_independent[d][j].to_bits(), want.to_bits());
                }
            }
            compared += 1;
        }
    }
    assert!(compared >= 100);
}

#[test]
fn vertices_the_lanes_do_not_shade_run_the_lessons_steps_to_the_bit() {
    // The lanes sample lights by area only: with
    // `--light-sampling solid-angle` every vertex of the wavefront runs
    // the lesson's own steps (`lesson_vertex`), and the fast engine makes
    // the readable engine's bytes; so it does with glass and mirrors and
    // the BSDF estimator, where no lane shades anything.
    let mut scene = Scene::builtin().with_resolution(24, 24).unwrap();
    let path = PathSettings::default();
    assert!(wave::lanes_shade(FastEngine::new(&scene).world(), &path));
    scene.light_sampling = raystep::scene::LightSampling::SolidAngle;
    let engine = FastEngine::new(&scene);
    assert!(wave::supports(engine.world()));
    assert!(!wave::lanes_shade(engine.world(), &path));
    let readable = render(&scene, None, &path, SamplerKind::Sobol);
    for level in Level::ALL.into_iter().filter(|l| l.available()) {
        let fast = render(&scene, Some(level), &path, SamplerKind::Sobol);
        assert_eq!(fast.sum, readable.sum, "{}", level.name());
        assert_eq!(fast.stats, readable.stats, "{}", level.name());
    }
}

#[test]
fn the_lane_mask_has_a_bit_for_each_true_lane() {
    // `mask` gathers eight booleans with one multiplication: every pattern
    // against the bits set one at a time.
    for bits in 0u32..256 {
        let lanes: [bool; 8] = std::array::from_fn(|i| bits >> i & 1 != 0);
        assert_eq!(raystep::fast::lanes::mask(lanes), bits, "{lanes:?}");
    }
}

#[test]
fn eight_camera_rays_at_once_are_the_lessons_bit_for_bit() {
    use glam::DVec3;
    use raystep::core::sampling::random;
    use raystep::fast::starts::rays8;
    use raystep::scene::camera::CameraDesc;
    // The project's own numbers, one dimension after another.
    let mut d = 0;
    let mut next = || {
        d += 1;
        f64::from(random(0x2545, 0, 0, d))
    };
    let mut checked = 0;
    for c in 0..200 {
        // Eyes from the origin to 10⁶ away, scenes from 10⁻³ to 10⁴ across,
        // fields of view from narrow to wide, odd image sizes.
        let far = 10f64.powf(6.0 * next() - 1.0);
        let size = 10f64.powf(7.0 * next() - 3.0);
        let mut v = || DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5);
        let eye = v() * far;
        let target = eye + v().normalize_or(DVec3::Z) * size;
        let desc = CameraDesc {
            eye,
            target,
            up: v(),
            fov_degrees: 0.5 + 170.0 * next(),
            width: 1 + (next() * 700.0) as u32,
            height: 1 + (next() * 500.0) as u32,
        };
        let Ok(camera) = Camera::new(desc) else {
            continue;
        };
        let (w, hh) = (camera.width as f64, camera.height as f64);
        // Raster positions anywhere on the image, on its edges, and one
        // exactly at each corner.
        let xs: [f32; 8] = std::array::from_fn(|j| match (c + j) % 5 {
            0 => 0.0,
            1 => w as f32,
            _ => (next() * w) as f32,
        });
        let ys: [f32; 8] = std::array::from_fn(|j| match (c + 2 * j) % 5 {
            0 => 0.0,
            1 => hh as f32,
            _ => (next() * hh) as f32,
        });
        let rays = rays8(&camera, &xs, &ys);
        for j in 0..8 {
            let want = camera.ray(glam::Vec2::new(xs[j], ys[j]));
            let bits = |v: glam::Vec3| v.to_array().map(f32::to_bits);
            assert_eq!(
                bits(rays[j].origin),
                bits(want.origin),
                "camera {c} lane {j}"
            );
            assert_eq!(bits(rays[j].dir), bits(want.dir), "camera {c} lane {j}");
            checked += 1;
        }
    }
    assert!(checked > 1000, "only {checked} rays checked");
}
