//! The predict questions (`chapters/questions.toml`) and the student's
//! sheet (`chapters/predictions.toml`): the bank is well formed and cites
//! what exists, its answers are the renderer's own where the renderer can
//! say, the shipped sheet is the bank without its answers, and `grade
//! --predict` marks a sheet right, wrong or unreadable with a clear word.

use glam::{DVec3, Vec2, Vec3};
use raystep::grading::predict::{self, Answer, Mark};

use super::grader_hints::{book_headings, cited, slide_list};
use super::grading::{copy_exercises, grade};
use crate::common;

fn bank() -> &'static predict::Bank {
    predict::bank().unwrap()
}

fn question(id: &str) -> &'static predict::Question {
    bank().question.iter().find(|q| q.id == id).unwrap()
}

fn number(id: &str) -> f64 {
    match question(id).answer {
        Answer::Number(x) => x,
        _ => panic!("{id} is not a number question"),
    }
}

#[test]
fn the_bank_is_well_formed_with_two_questions_a_chapter() {
    let problems = predict::problems(bank());
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert!(bank().question.len() >= 12);
    for chapter in 1..=6 {
        let n = bank()
            .question
            .iter()
            .filter(|q| q.chapter == chapter)
            .count();
        assert!(n >= 2, "chapter {chapter} has {n} predict questions");
    }
    // And the check finds what is wrong with a bank that is.
    let broken = predict::TEXT.replacen("answer = \"bc\"", "answer = \"bx\"", 1)
        + "\n[[question]]\nid = \"ch9/Bad\"\nchapter = 9\nask = \"?\"\nanswer = 1\n\
           tolerance = -1.0\nexplain = \".\"\n";
    let found = predict::problems(&predict::parse_bank(&broken).unwrap());
    for expected in [
        "\"ch1/no-image\": its answer: `x` is not an option",
        "\"ch9/Bad\": expected an id chN/short-name",
        "\"ch9/Bad\": tolerance must be 0 or more",
    ] {
        assert!(
            found.iter().any(|p| p.contains(expected)),
            "{expected}: {found:?}"
        );
    }
    let e = predict::parse_bank("[[question]]\nid = 3\n").unwrap_err();
    assert!(e.starts_with("chapters/questions.toml: line 2:"), "{e}");
}

#[test]
fn every_explanation_cites_a_real_slide_or_book_section() {
    let (slides, headings) = (slide_list(), book_headings());
    for q in &bank().question {
        let (s, b) = (cited(&q.explain, "slide"), cited(&q.explain, "book"));
        assert!(!(s.is_empty() && b.is_empty()), "{} cites nothing", q.id);
        for title in s {
            assert!(slides.contains(title), "{}: slide \"{title}\"", q.id);
        }
        for heading in b {
            assert!(headings.contains(heading), "{}: book \"{heading}\"", q.id);
        }
    }
}

/// The shipped sheet is the bank's questions without their answers.
/// `RAYSTEP_UPDATE_SHEET=1` writes it again after the bank changed (and
/// `chapters/predictions.toml`, which a clean clone ships the same).
#[test]
fn the_shipped_sheet_is_the_bank_without_answers() {
    let blank = predict::blank_sheet(bank());
    if std::env::var_os("RAYSTEP_UPDATE_SHEET").is_some() {
        for path in [
            "src/grading/shipped/predictions.toml",
            "chapters/predictions.toml",
        ] {
            std::fs::write(common::root().join(path), &blank).unwrap();
        }
    }
    assert_eq!(
        predict::SHIPPED,
        blank,
        "the questions changed: RAYSTEP_UPDATE_SHEET=1 cargo test --test all -- predict"
    );
    for q in &bank().question {
        assert!(
            !blank.contains(&q.explain[..40]),
            "{} explains itself",
            q.id
        );
    }
}

/// Marks `sheet` (the text of a predictions file) in a fresh folder.
fn marks_of(sheet: &str, name: &str) -> Result<predict::Sheet, String> {
    let dir = common::temp_dir(name);
    std::fs::write(dir.join(predict::SHEET), sheet).unwrap();
    predict::read_sheet(&dir, bank())
}

#[test]
fn the_solved_sheet_is_all_right_and_the_blank_one_unanswered() {
    let solved =
        std::fs::read_to_string(common::root().join("tests/project/solutions/predictions.toml"))
            .unwrap();
    let sheet = marks_of(&solved, "predict-solved").unwrap();
    let wrong: Vec<_> = sheet
        .marks
        .iter()
        .filter(|(_, m)| *m != Mark::Right)
        .collect();
    assert!(wrong.is_empty(), "{wrong:?}");
    assert!(sheet.strays.is_empty(), "{:?}", sheet.strays);
    let blank = marks_of(predict::SHIPPED, "predict-blank").unwrap();
    assert_eq!(blank.counts(), (0, 0));
}

#[test]
fn near_misses_and_partial_choices_are_wrong() {
    for q in &bank().question {
        let wrong: Vec<toml::Value> = match &q.answer {
            Answer::Number(x) => {
                let off = (q.tolerance * 3.0).max(0.01) * x.abs().max(1.0);
                vec![
                    (x + off).into(),
                    (x - off).into(),
                    (-x).into(),
                    (x * 10.0).into(),
                ]
            }
            // Each right letter alone where several are right, every
            // letter, and each wrong letter.
            Answer::Letters(l) => {
                let n = q.choices.len();
                let all: String = (0..n).map(|i| (b'a' + i as u8) as char).collect();
                let mut v: Vec<toml::Value> = vec![all.clone().into()];
                if l.len() > 1 {
                    v.extend(l.chars().map(|c| c.to_string().into()));
                }
                v.extend(
                    all.chars()
                        .filter(|c| !l.contains(*c))
                        .map(|c| c.to_string().into()),
                );
                v
            }
        };
        for w in wrong {
            assert_eq!(predict::mark(q, &w), Mark::Wrong, "{} given {w}", q.id);
        }
    }
}

#[test]
fn a_bad_sheet_is_named_by_file_and_line() {
    let e = marks_of("[ch1.twice-as-far]\nanswer = \n", "predict-syntax")
        .err()
        .unwrap();
    assert!(e.contains("predictions.toml: line 2:"), "{e}");
    let e = marks_of("[ch1.twice-as-far]\nanwser = 0.1\n", "predict-key")
        .err()
        .unwrap();
    assert!(
        e.contains("predictions.toml") && e.contains("anwser"),
        "{e}"
    );
    let sheet = marks_of(
        "[ch1.no-image]\nanswer = \"bz\"\n\n[ch1.twice-as-far]\nanswer = [1]\n\
         \n[ch1.twice-as-fat]\nanswer = 0.1\n",
        "predict-values",
    )
    .unwrap();
    let mark = |id: &str| {
        sheet
            .marks
            .iter()
            .find(|(q, _)| q.id == id)
            .unwrap()
            .1
            .clone()
    };
    let Mark::Unreadable(why) = mark("ch1/no-image") else {
        panic!()
    };
    assert!(
        why.contains("line 2: `z` is not an option: expected letters a to d"),
        "{why}"
    );
    let Mark::Unreadable(why) = mark("ch1/twice-as-far") else {
        panic!()
    };
    assert!(why.contains("line 5: expected a number"), "{why}");
    assert!(
        sheet.strays[0].contains("line 8: no question `ch1/twice-as-fat`"),
        "{:?}",
        sheet.strays
    );
    // No sheet at all, or not a file: said, never a hang.
    let dir = common::temp_dir("predict-none");
    let e = predict::read_sheet(&dir, bank()).err().unwrap();
    assert!(
        e.contains("predictions.toml") && e.contains("git checkout"),
        "{e}"
    );
    std::fs::create_dir(dir.join(predict::SHEET)).unwrap();
    let e = predict::read_sheet(&dir, bank()).err().unwrap();
    assert!(e.contains("expected a text file"), "{e}");
}

#[test]
fn grade_predict_explains_only_what_was_answered() {
    let dir = copy_exercises(common::temp_dir("predict-grade"));
    let at = predict::SHIPPED.find("[ch6.halve-error]").unwrap();
    let (head, tail) = predict::SHIPPED.split_at(at);
    let sheet = head.to_string() + &tail.replacen("answer = \"\"", "answer = 128", 1);
    std::fs::write(dir.join(predict::SHEET), sheet).unwrap();
    let d = dir.to_str().unwrap();
    let (run, text, _) = grade(
        &["--predict", "--exercises", d],
        &common::temp_dir("predict-out"),
    );
    assert_eq!(run.status.code(), Some(0), "{text}");
    assert!(
        text.contains("ch6/halve-error not quite: the answer is 256"),
        "{text}"
    );
    assert!(
        text.contains(&question("ch6/halve-error").explain[..30]),
        "{text}"
    );
    assert!(
        text.contains("ch6/roulette-weight not answered yet"),
        "{text}"
    );
    assert!(
        !text.contains(&question("ch6/roulette-weight").explain[..30]),
        "{text}"
    );
    assert!(
        text.contains("1 of 15 questions answered, 0 right"),
        "{text}"
    );
    std::fs::write(dir.join(predict::SHEET), "[ch1]\nx = \n").unwrap();
    let (run, _, _) = grade(
        &["--predict", "--exercises", d],
        &common::temp_dir("predict-out2"),
    );
    let err = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2));
    assert!(err.contains("predictions.toml: line 2:"), "{err}");
}

// The answers, as raystep's own code computes them.

#[test]
fn chapter_1_answers_are_the_cameras() {
    let width = |z: f32| {
        let a = raystep::ch1_projection::camera::project_pinhole(Vec3::new(-1.0, 0.0, z)).unwrap();
        let b = raystep::ch1_projection::camera::project_pinhole(Vec3::new(1.0, 0.0, z)).unwrap();
        f64::from(b.x - a.x)
    };
    assert!((width(-10.0) - 0.2).abs() < 1e-6);
    assert!((width(-20.0) - number("ch1/twice-as-far")).abs() < 1e-6);
    let points = [
        Vec3::new(0.0, 0.0, -0.001),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 0.0, 5.0),
        Vec3::new(100.0, 0.0, -1.0),
    ];
    let none: String = points
        .iter()
        .zip('a'..)
        .filter(|(p, _)| raystep::ch1_projection::camera::project_pinhole(**p).is_none())
        .map(|(_, c)| c)
        .collect();
    assert_eq!(Answer::Letters(none), question("ch1/no-image").answer);
}

/// The unit cube with its corner at `at`: the scene's closed box
/// (`Mesh::cuboid`, vertex i at bit 1 x, bit 2 y, bit 4 z), moved there.
fn cube(at: Vec3) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let m = raystep::scene::mesh::Mesh::cuboid(Vec3::ONE);
    let p = m.positions.iter().map(|p| *p + at + 0.5).collect();
    (p, m.triangles)
}

fn check(p: Vec<Vec3>, t: Vec<[u32; 3]>) -> raystep::ch2_rasterization::mesh_check::MeshCheck {
    raystep::ch2_rasterization::mesh_check::check_mesh(&raystep::scene::mesh::Mesh::new("m", p, t))
}

#[test]
fn chapter_2_answers_are_the_mesh_check_and_the_edge_function() {
    let (p, t) = cube(Vec3::ZERO);
    let closed = check(p.clone(), t.clone());
    assert_eq!(closed.euler() as f64, number("ch2/euler"));
    // b: a second cube whose edge x = 1, y = 1 is the first one's (it
    // shares those two vertices, 3 and 7, and nothing else).
    let (mut p2, t2) = cube(Vec3::new(1.0, 1.0, 0.0));
    let shift = p.len() as u32;
    let same = |i: u32| match i {
        0 => Some(3),
        4 => Some(7),
        _ => None,
    };
    let mut tb = t.clone();
    tb.extend(
        t2.iter()
            .map(|tri| tri.map(|i| same(i).unwrap_or(i + shift))),
    );
    let mut pb = p.clone();
    pb.append(&mut p2);
    // c: one triangle gone; d: two tetrahedra on one vertex.
    let tc = t[1..].to_vec();
    let tet = [[0u32, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    let pd = vec![
        Vec3::ZERO,
        Vec3::X,
        Vec3::Y,
        Vec3::Z,
        -Vec3::X,
        -Vec3::Y,
        -Vec3::Z,
    ];
    let mut td = tet.to_vec();
    td.extend(
        tet.iter()
            .map(|tri| tri.map(|i| if i == 0 { 0 } else { i + 3 })),
    );
    let manifold: String = [
        check(p.clone(), t),
        check(pb, tb),
        check(p, tc),
        check(pd, td),
    ]
    .iter()
    .zip('a'..)
    .filter(|(m, _)| m.is_manifold())
    .map(|(_, c)| c)
    .collect();
    assert_eq!(
        Answer::Letters(manifold),
        question("ch2/which-manifold").answer
    );
    let e = raystep::ch2_rasterization::edge::edge_function;
    let (a, b, q) = (
        Vec2::new(1.0, 2.0),
        Vec2::new(7.0, 3.0),
        Vec2::new(2.0, 9.0),
    );
    let ratio = e(2.0 * a, 2.0 * b, 2.0 * q) / e(a, b, q);
    assert_eq!(f64::from(ratio), number("ch2/edge-scale"));
}

#[test]
fn chapter_3_5_and_6_answers_are_the_lessons() {
    let tri = [
        DVec3::new(-1.0, -1.0, -5.0),
        DVec3::new(1.0, -1.0, -5.0),
        DVec3::new(0.0, 1.0, -5.0),
    ];
    let d = DVec3::new(0.0, 0.0, -2.0);
    let (t, _, _) =
        raystep::ch3_ray_triangle::triangle::intersect_f64(DVec3::ZERO, d, tri).unwrap();
    assert!((t - 2.5).abs() < 1e-12);
    assert_eq!(t * d.length(), number("ch3/t-units"));
    let e = |r: f64| raystep::ch5_reflection::radiometry::point_irradiance(1.0, r, 1.0);
    assert!((e(4.0) / e(2.0) - number("ch5/point-light-distance")).abs() < 1e-12);
    let hemisphere =
        raystep::ch5_reflection::radiometry::cap_solid_angle(std::f64::consts::FRAC_PI_2);
    assert!((hemisphere - number("ch5/hemisphere")).abs() < 1e-5 * hemisphere);
    let w = raystep::ch5_reflection::mis::power_heuristic(3.0, 1.0);
    assert!((f64::from(w) - number("ch6/mis-weight")).abs() < 1e-6);
}
