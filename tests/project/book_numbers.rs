//! Every measured number in the book comes from the run of
//! `bash book/figures.sh` that made its figures. Tables are included from
//! files that script writes (a part of a report, cut out by its `section`
//! function, or a benchmark's output); the few numbers and claims the text
//! states in its own sentences are checked here against those same files,
//! so regenerating the figures shows at once which sentence no longer
//! holds. Tables are read by their column headers, never by position.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use raystep::ch2_rasterization::mesh_check::check_mesh;
use raystep::scene::Scene;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

fn figure(name: &str) -> String {
    let path = root().join("book/src/figures").join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A page of the book with every run of white space made one space, so
/// that a phrase matches wherever the lines of the page break.
fn page(name: &str) -> String {
    let path = root().join("book/src").join(name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

#[track_caller]
fn says(page_name: &str, phrase: &str) {
    let text = page(page_name);
    assert!(
        text.contains(phrase),
        "{page_name} should say `{phrase}` (the number is measured: from a file in \
         book/src/figures, or by the test itself; write what the new run measured)"
    );
}

/// `x` with `n` significant digits, as the book writes it.
fn sig(x: f64, n: i32) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let decimals = (n - 1 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.decimals$}")
}

/// 12345 as "12,345".
fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

fn num(cell: &str) -> f64 {
    let s = cell.trim().trim_end_matches('x');
    s.parse()
        .unwrap_or_else(|_| panic!("`{cell}` is not a number"))
}

/// "249.7 µs", "1.2 ms", "1.97 s" in seconds.
fn seconds(cell: &str) -> f64 {
    let (v, unit) = cell
        .trim()
        .split_once(' ')
        .unwrap_or_else(|| panic!("`{cell}`"));
    let scale = match unit {
        "ns" => 1e-9,
        "µs" => 1e-6,
        "ms" => 1e-3,
        "s" => 1.0,
        _ => panic!("unit of `{cell}`"),
    };
    num(v) * scale
}

/// One row of a report table: header → cell (a header printed twice gets
/// " #2" on its second copy), plus the `name: value` lines printed under
/// the row (such as `notes:`).
type Row = BTreeMap<String, String>;

/// The table whose title line starts with `title`, read by the columns its
/// dashed line marks out.
fn table(report: &str, title: &str) -> Vec<Row> {
    let lines: Vec<&str> = report.lines().collect();
    let start = lines
        .iter()
        .position(|l| l.trim_start().starts_with(title))
        .unwrap_or_else(|| panic!("no table `{title}`"));
    let dashes = (start..lines.len())
        .find(|&i| {
            let t = lines[i].trim();
            !t.is_empty() && t.chars().all(|c| c == '-' || c == ' ')
        })
        .unwrap_or_else(|| panic!("table `{title}` has no dashed line"));
    let dash: Vec<char> = lines[dashes].chars().collect();
    let mut spans = Vec::new();
    for i in 0..dash.len() {
        if dash[i] == '-' && (i == 0 || dash[i - 1] == ' ') {
            spans.push(i);
        }
    }
    let cut = |line: &str| -> Vec<String> {
        let c: Vec<char> = line.chars().collect();
        (0..spans.len())
            .map(|k| {
                let a = spans[k].min(c.len());
                let b = spans.get(k + 1).copied().unwrap_or(c.len()).min(c.len());
                c[a..b].iter().collect::<String>().trim().to_string()
            })
            .collect()
    };
    let mut headers = Vec::new();
    for h in cut(lines[dashes - 1]) {
        let name = if headers.contains(&h) {
            format!("{h} #2")
        } else {
            h
        };
        headers.push(name);
    }
    let mut rows: Vec<Row> = Vec::new();
    for line in &lines[dashes + 1..] {
        let indent = line.len() - line.trim_start().len();
        if line.trim().is_empty() || (indent <= 2 && line.trim_start().starts_with("log-log")) {
            break;
        }
        if indent >= 4 {
            if let (Some(row), Some((k, v))) = (rows.last_mut(), line.trim().split_once(": ")) {
                row.insert(k.to_string(), v.to_string());
            }
            continue;
        }
        rows.push(headers.iter().cloned().zip(cut(line)).collect());
    }
    rows
}

/// The row whose `column` is `value`, and the others given.
fn row<'a>(rows: &'a [Row], keys: &[(&str, &str)]) -> &'a Row {
    rows.iter()
        .find(|r| {
            keys.iter()
                .all(|(k, v)| r.get(*k).map(String::as_str) == Some(*v))
        })
        .unwrap_or_else(|| panic!("no row {keys:?}"))
}

/// The slopes printed under an error-against-time table, by series.
fn slopes(report: &str) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    let mut on = false;
    for line in report.lines() {
        if line.trim_start().starts_with("log-log slope") {
            on = true;
        } else if on {
            match line.trim().rsplit_once(": ") {
                Some((k, v)) if line.starts_with("    ") => {
                    out.insert(k.to_string(), v.to_string());
                }
                _ => break,
            }
        }
    }
    out
}

/// The stiff cases of a report: (case, measured, ok).
fn stiff(report: &str) -> Vec<(String, String, String)> {
    let mut out = Vec::new();
    let mut field = String::new();
    for line in report.lines() {
        let t = line.trim();
        if let Some(case) = t.strip_prefix("- case: ") {
            out.push((case.to_string(), String::new(), String::new()));
            field = "case".into();
        } else if let Some(m) = t.strip_prefix("measured: ") {
            out.last_mut().unwrap().1 = m.into();
            field = "measured".into();
        } else if let Some(ok) = t.strip_prefix("ok: ") {
            out.last_mut().unwrap().2 = ok.into();
            field = "ok".into();
        } else if t.starts_with("expected: ") {
            field = "expected".into();
        } else if line.starts_with("        ") && field == "measured" {
            let m = &mut out.last_mut().unwrap().1;
            m.push(' ');
            m.push_str(t);
        }
    }
    out
}

/// The included part of a report is the report's own text, and the script
/// that makes the figures writes every file a page includes (the
/// comparison with Mitsuba: book/side-by-side.sh, which CI never runs).
#[test]
fn every_included_figure_file_is_made_by_figures_sh() {
    let read = |f: &str| std::fs::read_to_string(root().join(f)).unwrap();
    let script = read("book/figures.sh") + &read("book/side-by-side.sh");
    let mut problems = Vec::new();
    let mut pages: Vec<PathBuf> = std::fs::read_dir(root().join("book/src"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    pages.sort();
    for p in pages {
        let text = std::fs::read_to_string(&p).unwrap();
        for part in text.split("{{#include figures/").skip(1) {
            let name = part.split("}}").next().unwrap();
            // The terminal UI's captures are made by the tests of tui::.
            if name.starts_with("tui") {
                continue;
            }
            if !script.contains(&format!("$out/{name}\"")) {
                problems.push(format!(
                    "{}: figures/{name} is not written by book/figures.sh or book/side-by-side.sh",
                    p.display()
                ));
                continue;
            }
            // A part of a report: `section "$out/REPORT" "PREFIX" "$out/NAME"`
            // or `part "$out/REPORT" "FROM" "UPTO" "$out/NAME"`.
            let made = script.lines().find(|l| {
                (l.starts_with("section ") || l.starts_with("part "))
                    && l.ends_with(&format!("\"$out/{name}\""))
            });
            if let Some(line) = made {
                let report = line.split('"').nth(1).unwrap().trim_start_matches("$out/");
                if !figure(report).contains(&figure(name)) {
                    problems.push(format!("figures/{name} is not a part of figures/{report}"));
                }
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_bunny_counts_are_the_meshes() {
    let bunny = Scene::load(&root().join("scenes/bunny.toml")).unwrap();
    let c = check_mesh(&bunny.meshes[0]);
    let (v, e, t) = (
        thousands(c.vertices as u64),
        thousands(c.edges as u64),
        thousands(c.triangles as u64),
    );
    says("ch1-projection.md", &format!("the bunny's {v} vertices"));
    says(
        "ch1-projection.md",
        &format!("The Stanford bunny, {t} triangles"),
    );
    says(
        "ch2-rasterization.md",
        &format!("({v} vertices, {e} edges, {t} triangles)"),
    );
}

#[test]
fn chapter_1_numbers_match_its_report() {
    let report = figure("ch1-tetrahedron-report.txt");
    let rows = table(&report, "Error against run time");
    let f32_err = |depth: &str| {
        num(&row(&rows, &[("series", "f32 camera"), ("variant", depth)])["max error (px)"])
    };
    // "within about 10⁻⁵ pixel at ordinary depths"
    for d in [
        "depth 1e0",
        "depth 1e1",
        "depth 1e3",
        "depth 1e5",
        "depth 1e7",
    ] {
        assert!((3e-6..3e-5).contains(&f32_err(d)), "{d}: {}", f32_err(d));
    }
    // "about a hundredth of a pixel at 10⁻³"
    assert!((3e-3..3e-2).contains(&f32_err("depth 1e-3")));
    // "The `f64` path takes about twice as long": the ratio at every depth.
    let time = |s: &str, d: &str| seconds(&row(&rows, &[("series", s), ("variant", d)])["time"]);
    for d in ["depth 1e-3", "depth 1e0", "depth 1e3", "depth 1e7"] {
        let ratio = time("f64 reference", d) / time("f32 camera", d);
        assert!(
            (1.6..3.0).contains(&ratio),
            "{d}: f64 / f32 time {ratio}, not about twice"
        );
    }
    says(
        "ch1-projection.md",
        "The `f64` path takes about twice as long",
    );
    // "the picture is off by tens of pixels"
    let far = stiff(&report)
        .into_iter()
        .find(|c| c.0.contains("coordinates 1e7"))
        .unwrap();
    let px = num(far
        .1
        .trim_start_matches("max error ")
        .trim_end_matches(" px"));
    assert!((10.0..100.0).contains(&px), "{px}");
    says("ch1-projection.md", "the picture is off by tens of pixels");
}

#[test]
fn chapter_2_numbers_match_its_report() {
    let checker = figure("ch2-checker.txt");
    let before_affine = &checker[..checker.find("%) affine").expect("the affine share")];
    let affine = num(before_affine.rsplit_once('(').unwrap().1);
    assert!((35.0..50.0).contains(&affine), "affine wrong on {affine}%");
    let perspective = checker
        .split("ray cast on")
        .nth(1)
        .unwrap()
        .split_whitespace()
        .next()
        .unwrap();
    assert_eq!(perspective, "0", "{checker}");
    says(
        "ch2-rasterization.md",
        "affine gets almost half of the floor's pixels wrong",
    );

    let rows = table(&figure("ch2-error-time.txt"), "Error against run time");
    let rmse =
        |s: &str, v: &str| num(&row(&rows, &[("series", s), ("variant", v)])["RMSE of coverage"]);
    let drop = rmse("stratified", "4 spp") / rmse("stratified", "64 spp");
    says(
        "ch2-rasterization.md",
        &format!("it drops by a factor of {drop:.1} rather than 4"),
    );
    says(
        "ch2-rasterization.md",
        &format!(
            "4 stratified samples give {} against {} for 8 jittered ones, 16 give {} against {} for 32",
            sig(rmse("stratified", "4 spp"), 2),
            sig(rmse("uniform jitter", "8 spp"), 2),
            sig(rmse("stratified", "16 spp"), 2),
            sig(rmse("uniform jitter", "32 spp"), 2),
        ),
    );
}

#[test]
fn chapter_3_numbers_match_its_report() {
    let tests = table(
        &figure("ch3-three-tests.txt"),
        "The three ray-triangle tests",
    );
    assert_eq!(tests.len(), 3);
    for t in &tests {
        let agree = &t["agree with f64 on hit/miss"];
        let (a, b) = agree.split_once(" of ").unwrap();
        assert_eq!(a, b, "{t:?}");
    }
    let fastest = tests
        .iter()
        .min_by(|a, b| num(&a["ns per test"]).total_cmp(&num(&b["ns per test"])))
        .unwrap();
    assert!(
        fastest["test"].starts_with("Möller–Trumbore"),
        "{fastest:?}"
    );
    says("ch3-ray-triangle.md", "All three agree with f64 on every hit and miss. Möller–Trumbore, which changes no coordinates, is the fastest");

    let leaks = table(&figure("ch3-leaks.txt"), "Leaks:");
    let mut one_in = Vec::new();
    for l in &leaks {
        let (rays, n) = (num(&l["rays"]), num(&l["leaks"]));
        if l["test"].starts_with("watertight") {
            assert_eq!(n, 0.0, "{l:?}");
        } else {
            one_in.push((rays / n).round() as u64);
        }
    }
    let (lo, hi) = (one_in.iter().min().unwrap(), one_in.iter().max().unwrap());
    says(
        "ch3-ray-triangle.md",
        &format!("the other two lose between one ray in {hi} and one in {lo}"),
    );

    let naive = table(&figure("ch3-naive-bvh.txt"), "Naive loop against BVH");
    assert!(naive
        .iter()
        .all(|r| r["same image"] == "yes" || r["same image"] == "-"));
    assert_eq!(naive.last().unwrap()["same image"], "-");
    says(
        "ch3-ray-triangle.md",
        "The images agree in every row where both ran",
    );

    let report = figure("ch3-bunny-report.txt");
    let fixed = |at: &str| -> u64 {
        let case = stiff(&report)
            .into_iter()
            .find(|c| c.0.contains("secondary rays leaving a sphere at") && c.0.ends_with(at))
            .unwrap();
        assert!(case.1.starts_with("scaled offset: 0;"), "{case:?}");
        num(case.1.rsplit_once(": ").unwrap().1) as u64
    };
    says(
        "ch3-ray-triangle.md",
        &format!(
            "hit it again 0 times with this offset, and {} times",
            thousands(fixed("1e5"))
        ),
    );
    says(
        "ch3-ray-triangle.md",
        &format!("(at 1e6: 0 and {};", thousands(fixed("1e6"))),
    );

    let aa = table(&report, "Error against run time");
    let rmse =
        |v: &str| num(&row(&aa, &[("series", "anti-aliasing (BVH)"), ("variant", v)])["RMSE"]);
    says(
        "ch3-ray-triangle.md",
        &format!(
            "RMSE falls from {} at 1 spp to {} at 64 spp",
            sig(rmse("1 spp"), 3),
            sig(rmse("64 spp"), 2)
        ),
    );
    let slope = num(&slopes(&report)["anti-aliasing (BVH)"]);
    assert!((-0.6..-0.35).contains(&slope), "{slope}");

    let t_err = table(&figure("ch3-t-error.txt"), "Relative error of t");
    let worst = t_err
        .iter()
        .flat_map(|r| {
            r.iter()
                .filter(|(k, _)| *k != "distance D")
                .map(|(_, v)| num(v))
        })
        .fold(0.0, f64::max);
    assert!(worst < 4e-7, "{worst}");
    says("ch3-ray-triangle.md", "(below 4e-7 for all three tests");
}

#[test]
fn chapter_4_numbers_match_its_report() {
    let report = figure("ch4-error-time.txt");
    let rows = table(&report, "Error against run time");
    let get = |s: &str, v: &str| row(&rows, &[("series", s), ("variant", v)]);
    let evals = |s: &str, v: &str| num(&get(s, v)["samples"]);
    // "saves about 6 to 8% of the evaluations ... once ε is 10⁻³ or smaller"
    for eps in ["ε = 0.001000", "ε = 1.000e-4", "ε = 1.000e-5"] {
        let saved =
            100.0 * (1.0 - evals("over-relaxed ω = 1.6, ε", eps) / evals("sphere tracing, ε", eps));
        assert!((6.0..8.5).contains(&saved), "{eps}: {saved}%");
    }
    says(
        "ch4-sphere-tracing.md",
        "saves about 6 to 8% of the evaluations",
    );
    // "the 0.32 maximum up to Δ = 0.05"
    for d in ["Δ = 0.2", "Δ = 0.1", "Δ = 0.05"] {
        assert!(
            get("fixed step, Δ", d)["notes"].starts_with("max 0.3167;"),
            "{d}"
        );
    }
    says("ch4-sphere-tracing.md", "(the 0.32 maximum up to Δ = 0.05");
    // "17 to 29 times the evaluations of sphere tracing for the same error"
    let a = evals("fixed step, Δ", "Δ = 0.025") / evals("sphere tracing, ε", "ε = 1.000e-4");
    let b = evals("fixed step, Δ", "Δ = 0.0125") / evals("sphere tracing, ε", "ε = 1.000e-5");
    says(
        "ch4-sphere-tracing.md",
        &format!(
            "It needs {} to {} times the evaluations",
            a.round(),
            b.round()
        ),
    );
    // The ε series get no slope, and their error falls by four orders of magnitude.
    let s = slopes(&report);
    assert_eq!(s["sphere tracing, ε"], "—");
    assert_eq!(s["over-relaxed ω = 1.6, ε"], "—");
    let rmse = |v: &str| num(&get("sphere tracing, ε", v)["RMSE of hit distance"]);
    let orders = (rmse("ε = 0.1000") / rmse("ε = 1.000e-5")).log10();
    assert!((4.0..5.0).contains(&orders), "{orders}");
    says(
        "ch4-sphere-tracing.md",
        "while their error falls by four orders of magnitude",
    );
    assert!(stiff(&figure("ch4-stiff.txt")).iter().all(|c| c.2 == "yes"));
}

#[test]
fn chapter_5_numbers_match_its_report() {
    let report = figure("ch5-lambert-sphere-report.txt");
    for (series, slope) in slopes(&report) {
        assert!((num(&slope) + 0.5).abs() <= 0.1, "{series}: {slope}");
    }
    says(
        "ch5-reflection.md",
        "within 0.1 of it in the run that drew these plots",
    );
    let rows = table(&report, "Error against run time");
    let get = |s: &str, n: &str| row(&rows, &[("series", s), ("variant", n)]);
    for n in [
        "4 samples",
        "16 samples",
        "64 samples",
        "256 samples",
        "1024 samples",
    ] {
        let rmse = |s: &str| num(&get(s, n)["RMSE"]);
        let eff = |s: &str| num(&get(s, n)["1/(MSE·time)"]);
        for blind in ["area: uniform", "area: bsdf"] {
            for aimed in ["area: light", "area: mis"] {
                let r = rmse(blind) / rmse(aimed);
                assert!((5.0..10.0).contains(&r), "{n}: {blind} / {aimed} = {r}");
            }
        }
        for aimed in ["area: light", "area: mis"] {
            let r = eff(aimed) / eff("area: uniform");
            assert!(
                (10.0..100.0).contains(&r),
                "{n}: efficiency {aimed} / uniform = {r}"
            );
        }
        for strategy in ["light", "mis"] {
            let r = rmse(&format!("area: {strategy}"))
                / rmse(&format!("area: {strategy} by solid angle"));
            assert!(
                (2.5..5.0).contains(&r),
                "{n}: {strategy} by area / by solid angle = {r}"
            );
        }
        let most_efficient = ["uniform", "bsdf", "light", "mis"]
            .into_iter()
            .map(|s| format!("area: {s}"))
            .chain(["area: mis by solid angle".to_string()])
            .all(|s| eff(&s) < eff("area: light by solid angle"));
        assert!(most_efficient, "{n}");
        let best = ["uniform", "bsdf", "light", "mis"]
            .into_iter()
            .min_by(|a, b| {
                rmse(&format!("environment: {a}")).total_cmp(&rmse(&format!("environment: {b}")))
            })
            .unwrap();
        assert_eq!(best, "bsdf", "{n}");
    }
    says(
        "ch5-reflection.md",
        "Light sampling and MIS sit five to ten times below uniform and BSDF sampling",
    );
    says(
        "ch5-reflection.md",
        "are roughly 10 to 100 times as efficient as uniform sampling",
    );
    says(
        "ch5-reflection.md",
        "Here the cosine-weighted BRDF sampling is best",
    );
    says(
        "ch5-reflection.md",
        "at equal samples it cuts the error 2.5 to 5 times, for light sampling and for MIS alike",
    );
    says(
        "ch5-reflection.md",
        "light sampling by solid angle is the most efficient row of the area problem at every N",
    );
    assert!(stiff(&report).iter().all(|c| c.2 == "yes"));
}

#[test]
fn chapter_6_numbers_match_its_report() {
    let strategies = figure("ch6-strategies.txt");
    let rows = table(&strategies, "Strategies:");
    let get = |s: &str| row(&rows, &[("series", s)]);
    let rmse = |s: &str| num(&get(s)["RMSE"]);
    says(
        "ch6-global-illumination.md",
        &format!(
            "light sampling's RMSE is {:.3} against BSDF sampling's {:.3} and the uniform walk's {:.3}",
            rmse("cornell light independent"),
            rmse("cornell bsdf independent"),
            rmse("cornell uniform independent"),
        ),
    );
    let alike = rmse("cornell mis independent") / rmse("cornell light independent");
    assert!((alike - 1.0).abs() < 0.05, "{alike}");
    says(
        "ch6-global-illumination.md",
        "MIS and light sampling alone are nearly the same here",
    );
    let eff = |s: &str| num(&get(s)["1/(MSE·time)"]);
    assert!(eff("cornell light independent") >= 2.0 * eff("cornell bsdf independent"));
    says(
        "ch6-global-illumination.md",
        "its efficiency is several times BSDF sampling's",
    );
    let slope = |s: &str| num(&get(s)["slope"]);
    let shallowest = rows
        .iter()
        .filter(|r| r["series"].starts_with("furnace"))
        .max_by(|a, b| num(&a["slope"]).total_cmp(&num(&b["slope"])))
        .unwrap();
    assert_eq!(shallowest["series"], "furnace light independent");
    says(
        "ch6-global-illumination.md",
        "light sampling alone with independent numbers has the shallowest slope of all",
    );
    for s in ["furnace mis independent", "furnace mis sobol"] {
        assert!(slope(s) <= -0.4, "{s}");
    }
    let (sobol, ind) = (
        rmse("cornell light sobol"),
        rmse("cornell light independent"),
    );
    assert!(
        (0.2..0.32).contains(&(sobol / ind)),
        "about a quarter: {}",
        sobol / ind
    );
    assert!(slope("cornell light sobol") < slope("cornell light independent"));
    says(
        "ch6-global-illumination.md",
        &format!(
            "at 64 spp their RMSE is {} against {}, about a quarter, and their slope is steeper",
            sig(sobol, 3),
            sig(ind, 3)
        ),
    );
    assert!(stiff(&figure("ch6-stiff.txt")).iter().all(|c| c.2 == "yes"));
}

#[test]
fn the_appendix_statements_match_the_benchmarks() {
    // ch3 --bench, as a Markdown table.
    let md = figure("ch3-bench.md");
    let mut lines = md.lines();
    let cells = |l: &str| -> Vec<String> {
        l.trim()
            .trim_matches('|')
            .split('|')
            .map(|c| c.trim().to_string())
            .collect()
    };
    let headers = cells(lines.next().unwrap());
    let rows: Vec<Row> = lines
        .skip(1)
        .map(|l| headers.iter().cloned().zip(cells(l)).collect())
        .collect();
    assert!(rows.len() >= 4);
    for r in &rows {
        let stage = num(&r["stage"]);
        if r["mesh"] == "bunny" {
            let gain = stage / num(&r["stage, readable watertight"]);
            assert!((1.3..1.9).contains(&gain), "{r:?}");
        }
        // "the stage is ahead in every row"
        let ratio = num(&r["stage / obvhs"]);
        assert!((1.0..2.0).contains(&ratio), "{r:?}");
        if r["readable BVH"] != "-" {
            let share = num(&r["readable BVH"]) / stage;
            assert!((0.35..0.65).contains(&share), "{r:?}");
        }
        let builds: Vec<f64> = r["build (stage / obvhs / readable)"]
            .split(" / ")
            .map(seconds)
            .collect();
        assert!(builds[2] < builds[1] && builds[2] < builds[0], "{r:?}");
    }
    says(
        "making-it-fast.md",
        "the stage is about one and a half times as fast",
    );
    // "On the wavy grids ... the gain is smaller"
    let mean_gain = |mesh: &str| {
        let gains: Vec<f64> = rows
            .iter()
            .filter(|r| r["mesh"] == mesh)
            .map(|r| num(&r["stage"]) / num(&r["stage, readable watertight"]))
            .collect();
        gains.iter().sum::<f64>() / gains.len() as f64
    };
    assert!(mean_gain("wavy grid") < mean_gain("bunny"));
    says(
        "making-it-fast.md",
        "On the wavy grids the traversal takes a larger share, and the gain is smaller",
    );
    says(
        "making-it-fast.md",
        "The readable BVH builds its median-split tree fastest",
    );
    says("making-it-fast.md", "the stage is ahead in every row");
    says(
        "making-it-fast.md",
        "traces at about two fifths to three fifths of the stage's speed",
    );

    // ch6 --bench.
    let bench = figure("ch6-bench.txt");
    let rows = table(&bench, "ch6 benchmark");
    let get = |s: &str| row(&rows, &[("engine sampler", s)]);
    let (ind, sobol) = (get("fast independent"), get("fast sobol"));
    let per_pixel = |r: &Row| num(&r["RMSE per pixel"]);
    let paths = |r: &Row| num(&r["paths/s"]);
    // The engines make the same images: the same RMSEs and noise.
    for s in ["independent", "sobol"] {
        let (f, r) = (get(&format!("fast {s}")), get(&format!("readable {s}")));
        for column in [
            "RMSE per pixel",
            "RMSE 64²",
            "noise from variance",
            "rays/path",
        ] {
            assert_eq!(f[column], r[column], "{s} {column}");
        }
    }
    says(
        "making-it-fast.md",
        "The two engines' rows have the same RMSEs to the last digit",
    );
    assert!((0.25..0.5).contains(&(per_pixel(sobol) / per_pixel(ind))));
    assert!(num(&sobol["RMSE²·s"]) < num(&ind["RMSE²·s"]));
    says(
        "making-it-fast.md",
        "Per pixel, Sobol points give less than half the error of independent numbers",
    );
    let noise = |r: &Row| num(&r["noise from variance"]);
    assert!((noise(sobol) / noise(ind) - 1.0).abs() < 0.1);
    assert!((noise(ind) / per_pixel(ind) - 1.0).abs() < 0.15);
    assert!(noise(sobol) > 1.5 * per_pixel(sobol));
    says(
        "making-it-fast.md",
        "predicts about the same noise for both samplers",
    );
    says(
        "making-it-fast.md",
        "right for independent numbers, too much for Sobol points",
    );
    // What random numbers cost: in the readable engine a Sobol path costs
    // more, in the fast engine about the same; Sobol is the more efficient
    // in both.
    let (r_ind, r_sobol) = (get("readable independent"), get("readable sobol"));
    assert!(paths(r_sobol) < paths(r_ind), "{r_ind:?} {r_sobol:?}");
    says(
        "making-it-fast.md",
        "In the readable engine a Sobol path costs more than an independent one",
    );
    for (i, s) in [(ind, sobol), (r_ind, r_sobol)] {
        assert!(num(&s["RMSE²·s"]) < num(&i["RMSE²·s"]), "{i:?} {s:?}");
    }
    says("making-it-fast.md", "the lower RMSE²·s, in both engines");
    let rays = |r: &Row| paths(r) * num(&r["rays/path"]);
    let same_speed = rays(sobol) / rays(ind);
    assert!((0.8..1.25).contains(&same_speed), "{same_speed}");
    assert!(num(&sobol["rays/path"]) > num(&ind["rays/path"]));
    says(
        "making-it-fast.md",
        "In the fast engine the two samplers cast about the same rays per second",
    );
    says("making-it-fast.md", "Sobol paths are longer");
    let over = noise(sobol) / per_pixel(sobol);
    assert!((1.5..2.5).contains(&over), "{over}");
    says(
        "running.md",
        "With Sobol numbers the estimate is about twice the true error",
    );
    for r in [ind, sobol] {
        assert!(num(&r["RMSE²·s #2"]) < 3e-4, "{r:?}");
    }
    // "both its rows are above it, both of the readable engine's below"
    assert!(paths(ind).min(paths(sobol)) > 3.5e6, "{ind:?} {sobol:?}");
    for s in ["readable independent", "readable sobol"] {
        assert!(paths(get(s)) < 3.5e6, "{s}");
    }
    assert!(num(&sobol["RMSE²·s"]) < 3e-4, "{sobol:?}");
    let readable_sobol = get("readable sobol");
    assert!(num(&readable_sobol["RMSE²·s"]) < 3e-4, "{readable_sobol:?}");
    says(
        "making-it-fast.md",
        "holds against the 64x64 reference for both samplers; per pixel at 256x256 both Sobol rows reach it",
    );
    says(
        "making-it-fast.md",
        "The speed target (3.5 M paths/s) is reached only by the fast engine: both its rows are above it, both of the readable engine's below.",
    );
    let queries = table(&bench, "ray queries");
    assert_eq!(queries.len(), 2);
    for q in &queries {
        assert!(
            num(&q["4-wide (readable)"]) > num(&q["binary BVH (ch3)"]),
            "{q:?}"
        );
    }
    says(
        "making-it-fast.md",
        "The four-wide tree answers more queries per second than the binary tree",
    );
    // "somewhat more ... not twice as many" for closest hits; shadow
    // rays gain more.
    let gain = |q: &Row| num(&q["8-wide (fast)"]) / num(&q["4-wide (readable)"]);
    let closest = row(&queries, &[("query", "closest hit (bounce rays)")]);
    let shadow = row(&queries, &[("query", "occlusion (shadow rays)")]);
    assert!((1.0..2.0).contains(&gain(closest)), "{closest:?}");
    assert!(gain(shadow) > gain(closest), "{shadow:?} {closest:?}");
    says(
        "making-it-fast.md",
        "For closest hits the eight-wide tree answers somewhat more queries per second than the four-wide one, not twice as many",
    );
    says("making-it-fast.md", "Shadow rays gain more");

    // Roulette after the first scattering against after the third, by
    // rays per path (rays/s over paths/s of one render) and RMSE.
    let late = table(&figure("ch6-bench-rr-after-3.txt"), "ch6 benchmark");
    let rays_per_path = |r: &Row| num(&r["rays/path"]);
    for s in ["fast independent", "fast sobol"] {
        let (now, later) = (get(s), row(&late, &[("engine sampler", s)]));
        assert!(rays_per_path(later) > rays_per_path(now), "{s}");
        assert!(per_pixel(later) < per_pixel(now), "{s}");
        let cost = |r: &Row| per_pixel(r).powi(2) * rays_per_path(r);
        assert!(
            cost(now) < cost(later),
            "{s}: {} against {}",
            cost(now),
            cost(later)
        );
    }
    says(
        "making-it-fast.md",
        "a path casts more rays and the RMSE is a little lower, but not by enough",
    );
    says(
        "making-it-fast.md",
        "is lower for the default with both samplers",
    );

    // Roulette's scale: each sampler's default (the bench's own rows) is
    // the one of the two scales with the lower RMSE² times rays per path.
    let scaled = |s: u32| {
        table(
            &figure(&format!("ch6-bench-rr-scale-{s}.txt")),
            "ch6 benchmark",
        )
    };
    let (one, two) = (scaled(1), scaled(2));
    for (sampler, best, other) in [("independent", &one, &two), ("sobol", &two, &one)] {
        let name = format!("fast {sampler}");
        let of = |t: &Vec<Row>| row(t, &[("engine sampler", &name)]).clone();
        let cost = |r: &Row| per_pixel(r).powi(2) * rays_per_path(r);
        let (b, o) = (of(best), of(other));
        assert!(
            cost(&b) < cost(&o),
            "{sampler}: {} against {}",
            cost(&b),
            cost(&o)
        );
        assert_eq!(
            get(&name)["RMSE per pixel"],
            b["RMSE per pixel"],
            "{sampler}"
        );
    }
    says(
        "making-it-fast.md",
        "s = 1 is lower for independent numbers and s = 2 for Sobol points",
    );

    // Both engines on three scenes: the wavefront lesson's table.
    let scenes = table(
        &figure("ch6-bench-scenes.txt"),
        "paths per second by scene and engine",
    );
    assert_eq!(scenes.len(), 3);
    for s in &scenes {
        assert!(num(&s["paths/s fast"]) > num(&s["readable"]), "{s:?}");
        assert!(num(&s["ratio"]) > 1.0, "{s:?}");
    }
    says(
        "making-it-fast.md",
        "The fast engine is ahead on every scene",
    );

    // The glass-ball box: the lesson's path loop in both engines.
    let glass_text = figure("ch6-bench-glass.txt");
    let glass = table(&glass_text, "ch6 benchmark");
    let on_glass = |s: &str| row(&glass, &[("engine sampler", s)]);
    for s in ["independent", "sobol"] {
        let (f, r) = (
            on_glass(&format!("fast {s}")),
            on_glass(&format!("readable {s}")),
        );
        for column in ["RMSE per pixel", "noise from variance", "rays/path"] {
            assert_eq!(f[column], r[column], "glass {s} {column}");
        }
    }
    assert!(
        glass_text.contains("diffuse hits shaded eight at once, the others by the lesson's steps"),
        "{glass_text}"
    );
    says(
        "making-it-fast.md",
        "lanes shade the walls and the lesson's steps the glass",
    );
    let glass_gain = paths(on_glass("fast independent")) / paths(on_glass("readable independent"));
    let box_gain = paths(get("fast independent")) / paths(get("readable independent"));
    assert!(
        (1.7..2.5).contains(&glass_gain) && glass_gain > 0.6 * box_gain && glass_gain < box_gain,
        "{glass_gain} {box_gain}"
    );
    says(
        "making-it-fast.md",
        "runs about twice the readable engine's paths per second, most of its",
    );
}

/// The prose of a page: its sentences without fenced blocks, include
/// lines, inline code (commands and flags) and link targets.
fn prose(text: &str) -> String {
    let mut out = String::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced || line.trim_start().starts_with("{{#") {
            continue;
        }
        let no_code: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
        let mut rest = no_code.as_str();
        while let Some(at) = rest.find("](") {
            out.push_str(&rest[..at]);
            rest = rest[at..].split_once(')').map_or("", |(_, r)| r);
        }
        out.push_str(rest);
        out.push('\n');
    }
    out
}

/// The numbers written in `text`: each run of digits with its decimal
/// point, thousands commas and exponent ("0.02667", "16,384", "3e-4"),
/// except where it is part of a name ("f64", "ch6", "x86-64", "AVX-512",
/// "pbrt-v3") or a chapter's number ("chapter 3").
fn numbers(text: &str) -> Vec<String> {
    let c: Vec<char> = text.chars().collect();
    let digit = |i: usize| c.get(i).is_some_and(|x| x.is_ascii_digit());
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        if !digit(i) {
            i += 1;
            continue;
        }
        let start = i;
        while digit(i) || (matches!(c.get(i), Some('.' | ',')) && digit(i + 1)) {
            i += 1;
        }
        if matches!(c.get(i), Some('e' | 'E')) {
            let sign = matches!(c.get(i + 1), Some('-' | '+')) as usize;
            if digit(i + 1 + sign) {
                i += 1 + sign;
                while digit(i) {
                    i += 1;
                }
            }
        }
        let before = |k: usize| start.checked_sub(k).map(|j| c[j]);
        let named = before(1).is_some_and(|x| x.is_alphanumeric() || x == '_')
            || (before(1) == Some('-') && before(2).is_some_and(char::is_alphanumeric));
        let head: String = c[start.saturating_sub(8)..start].iter().collect();
        if !named && !head.to_lowercase().ends_with("chapter ") {
            out.push(c[start..i].iter().collect());
        }
    }
    out
}

/// The appendix states no number of its own: every number in its
/// sentences is written in a figure file it includes or links to, so a new
/// run of `book/figures.sh` cannot leave a retyped measurement behind.
#[test]
fn every_number_in_the_appendix_is_in_a_figure_it_shows() {
    // The checker itself: retyped measurements are found, names are not.
    assert_eq!(
        numbers(
            "leaf tests 1.57 → 1.33 in chapter 3 on x86-64 with AVX-512, f32, 3e-4 and 16,384."
        ),
        ["1.57", "1.33", "3e-4", "16,384"]
    );
    let name = "making-it-fast.md";
    let text = std::fs::read_to_string(root().join("book/src").join(name)).unwrap();
    let mut shown = Vec::new();
    for part in text.split("figures/").skip(1) {
        let file: String = part
            .chars()
            .take_while(|c| c.is_alphanumeric() || matches!(c, '-' | '_' | '.'))
            .collect();
        let file = file.trim_end_matches('.').to_string();
        if !shown.contains(&file) {
            shown.push(file);
        }
    }
    assert!(shown.len() >= 3, "{name} shows only {shown:?}");
    let measured: Vec<String> = shown.iter().flat_map(|f| numbers(&figure(f))).collect();
    let unbacked: Vec<String> = numbers(&prose(&text))
        .into_iter()
        .filter(|n| !measured.contains(n))
        .collect();
    assert!(
        unbacked.is_empty(),
        "{name} writes numbers that no figure file it includes holds: {unbacked:?} \
         (quote the included file, or let the table say it)"
    );
}

/// Chapter 6 and the grading page quote the furnace's noise: how close
/// the grader's 200,000 paths of the reference loop come, and how many
/// standard errors a 2% bias is.
#[test]
fn the_furnace_noise_the_book_quotes_is_measured() {
    use raystep::grading::exercises::paths::{
        reference_path, trace_furnace, PathScene, FURNACE_ALBEDO, FURNACE_LE, FURNACE_PATHS,
    };
    let scene = PathScene::furnace(FURNACE_ALBEDO, FURNACE_LE);
    let run = trace_furnace(reference_path, &scene, FURNACE_PATHS, 611);
    let n = FURNACE_PATHS as f64;
    let mean = run.sum.x / n;
    let variance = run.sum_sq.x / n - mean * mean;
    let relative = (variance / n).sqrt() / mean;
    let paths = thousands(FURNACE_PATHS);
    let z = (0.02 / relative).round();
    says(
        "ch6-global-illumination.md",
        &format!(
            "{paths} paths estimate the answer to {:.2}%, and a 2% bias is {z} standard errors",
            100.0 * relative
        ),
    );
    says("grading.md", &format!("{paths} paths must agree with it"));
    says(
        "grading.md",
        &format!("which a 2 % bias misses by about {z} ("),
    );
}

/// The numbers `prose` gives as measurements: each followed by a unit of
/// time or speed, or by "times faster" and the like.
fn measured(prose: &str) -> Vec<String> {
    const UNITS: [&str; 19] = [
        "ns",
        "µs",
        "ms",
        "s",
        "seconds",
        "second",
        "minutes",
        "minute",
        "hours",
        "hour",
        "paths/s",
        "rays/s",
        "Mrays/s",
        "M paths/s",
        "x faster",
        "times faster",
        "times slower",
        "times as fast",
        "× faster",
    ];
    let mut out = Vec::new();
    for n in numbers(prose) {
        let mut rest = prose;
        while let Some(i) = rest.find(n.as_str()) {
            let whole = !rest[..i].ends_with(|c: char| c.is_ascii_digit() || c == '.' || c == ',')
                && !rest[i + n.len()..].starts_with(|c: char| c.is_ascii_digit());
            let after = rest[i + n.len()..].trim_start();
            let unit = whole
                && UNITS.iter().any(|u| {
                    after.starts_with(u)
                        && !after[u.len()..].starts_with(|c: char| c.is_alphanumeric())
                });
            if unit && !out.contains(&n) {
                out.push(n.clone());
            }
            rest = &rest[i + n.len()..];
        }
    }
    out
}

/// Every page, not only the appendix: a number the prose gives as a
/// measurement (a time, a speed, a speed-up) is in a figure file the page
/// includes or links to, or in a phrase a test above checks against one;
/// a limit or default the code sets is in the source (`from_secs(20)`),
/// and a figure from the lecture (Coco's 50 hours) is in the lecture.
#[test]
fn every_measured_number_on_every_page_is_backed() {
    assert_eq!(
        measured("the build takes 17.3 ms, 2.4 times faster, on 16 cores and 3 scenes"),
        ["17.3", "2.4"]
    );
    let this = std::fs::read_to_string(root().join("tests/project/book_numbers.rs")).unwrap();
    let lecture = std::fs::read_to_string(root().join("../shared/lecture-11-rendering.txt"))
        .unwrap_or_default();
    let mut source = String::new();
    for f in crate::common::files_under(&root().join("src"), "rs") {
        source.push_str(&std::fs::read_to_string(f).unwrap());
    }
    let literal = |n: &str| {
        source.match_indices(n).any(|(i, _)| {
            let before = source[..i].chars().next_back();
            let after = source[i + n.len()..].chars().next();
            !before.is_some_and(|c| c.is_alphanumeric() || c == '.')
                && !after.is_some_and(|c| c.is_ascii_digit() || c == '.')
        })
    };
    let mut unbacked = Vec::new();
    let mut checked = 0;
    for entry in std::fs::read_dir(root().join("book/src")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "md") {
            continue;
        }
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(&path).unwrap();
        let mut shown = String::new();
        for part in text.split("figures/").skip(1) {
            let file: String = part
                .chars()
                .take_while(|c| c.is_alphanumeric() || matches!(c, '-' | '_' | '.'))
                .collect();
            let file = root()
                .join("book/src/figures")
                .join(file.trim_end_matches('.'));
            if let Ok(t) = std::fs::read_to_string(file) {
                shown.push_str(&t);
            }
        }
        let prose = prose(&text)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        for n in measured(&prose) {
            checked += 1;
            let backed = numbers(&shown).contains(&n)
                || this.contains(&format!("\"{n}"))
                || this.contains(&format!(" {n} "))
                || lecture.contains(&n)
                || literal(&n);
            if !backed {
                unbacked.push(format!("{name}: {n}"));
            }
        }
    }
    assert!(
        checked >= 5,
        "only {checked} measured numbers found in the book"
    );
    assert!(
        unbacked.is_empty(),
        "measured numbers that no figure file, checked phrase, source constant or the lecture \
         holds (retyped?): {unbacked:?}"
    );
}

/// One table of book/side-by-side.sh: each configuration's median
/// seconds and RMSE, and the two ratios.
struct SideBySide {
    rows: BTreeMap<String, (f64, f64)>,
    throughput: f64,
    efficiency: f64,
}

fn side_by_side(name: &str) -> SideBySide {
    let text = figure(name);
    let ratio = |prefix: &str| {
        let line = text.lines().find(|l| l.starts_with(prefix)).unwrap();
        let after = line.split("): ").nth(1).unwrap();
        num(after.split_whitespace().next().unwrap())
    };
    let rows = text
        .lines()
        .filter(|l| l.starts_with("raystep-") || l.starts_with("mitsuba-"))
        .map(|l| {
            let cells: Vec<&str> = l.split_whitespace().collect();
            (cells[0].to_string(), (num(cells[1]), num(cells[3])))
        })
        .collect();
    SideBySide {
        rows,
        throughput: ratio("throughput ratio"),
        efficiency: ratio("efficiency ratio"),
    }
}

#[test]
fn the_comparison_with_mitsuba_says_what_its_tables_show() {
    let page = "against-mitsuba.md";
    let cornell = side_by_side("sbs-cornell.txt");
    let rr5 = side_by_side("sbs-cornell-rr5.txt");
    let portable = side_by_side("sbs-cornell-portable.txt");
    let glass = side_by_side("sbs-glass.txt");
    let rmse = |t: &SideBySide, k: &str| t.rows[k].1;
    let time = |t: &SideBySide, k: &str| t.rows[k].0;
    let (sobol, mj) = ("raystep-fast_sobol", "mitsuba-llvm_ad_rgb-multijitter");

    assert!(cornell.throughput > 1.2, "{}", cornell.throughput);
    assert!((1.05..1.5).contains(&cornell.efficiency));
    assert!(cornell.efficiency < cornell.throughput);
    assert!(rmse(&cornell, mj) < rmse(&cornell, sobol));

    let gap = |t: &SideBySide| (rmse(t, sobol) - rmse(t, mj)).abs();
    assert!(gap(&rr5) < gap(&cornell));
    assert!(1.0 < rr5.throughput && rr5.throughput < cornell.throughput);

    // With SSE2: more paths per second than Mitsuba, less efficient; the
    // fastest row at more than four fifths of AVX2's rate; Sobol numbers
    // losing more than independent ones.
    assert!(portable.throughput > 1.1, "{}", portable.throughput);
    assert!(portable.efficiency < 1.0);
    let avx2 = side_by_side("sbs-cornell-avx2.txt");
    let fastest = |t: &SideBySide| {
        t.rows
            .iter()
            .filter(|(k, _)| k.starts_with("raystep-fast"))
            .map(|(_, v)| v.0)
            .fold(f64::INFINITY, f64::min)
    };
    let share = fastest(&avx2) / fastest(&portable);
    assert!(share > 0.8, "{share}");
    let indep = "raystep-fast_independent";
    let lost = |k: &str| time(&portable, k) / time(&avx2, k);
    assert!(lost(sobol) > lost(indep), "{} {}", lost(sobol), lost(indep));

    assert!(glass.throughput > 1.0 && glass.efficiency > 1.0);
    let share = time(&glass, sobol) / time(&glass, "raystep-readable_sobol");
    assert!(share < 0.5, "{share}");
    let r =
        rmse(&glass, "raystep-fast_independent") / rmse(&glass, "mitsuba-llvm_ad_rgb-independent");
    assert!((0.97..1.03).contains(&r), "independent / independent: {r}");
    assert!(rmse(&glass, sobol) < rmse(&glass, mj));
    // Mitsuba's orthogonal sampler draws more samples than asked for, and
    // the page says how many; by RMSE²·s it is never Mitsuba's best.
    let text = figure("sbs-samplers.txt");
    let drawn: BTreeMap<&str, u32> = text
        .lines()
        .skip(1)
        .map(|l| {
            let cells: Vec<&str> = l.split_whitespace().collect();
            (cells[0], cells[1].parse().unwrap())
        })
        .collect();
    assert_eq!(
        (drawn["independent"], drawn["multijitter"]),
        (64, 64),
        "{text}"
    );
    let orthogonal = drawn["orthogonal"];
    assert!(orthogonal > 64, "{text}");
    says(
        page,
        &format!("64 it draws {orthogonal}, as Mitsuba itself reports"),
    );
    let cost = |t: &SideBySide, k: &str| rmse(t, k).powi(2) * time(t, k);
    for t in [&cornell, &rr5, &portable, &glass] {
        let o = cost(t, "mitsuba-llvm_ad_rgb-orthogonal");
        assert!(o > cost(t, mj), "{o}");
    }
    // What the page says of those tables.
    for phrase in [
        "The fast engine runs the most paths per second of all, and its best",
        "RMSE²·s is lower than Mitsuba's best, by less than its lead in speed",
        "samples Mitsuba's multijitter sampler leaves less error than raystep's",
        "Sobol points, and the faster engine more than buys that back",
        "closer to multijitter's, and its lead in speed shrinks",
        "With SSE2, raystep still runs more paths per second than Mitsuba's",
        "compiled code but is less efficient. Its fastest row runs at more than",
        "four fifths of the rate of AVX2's",
        "Sobol numbers lose more than independent ones there",
        "raystep is ahead on both ratios here, and its fast engine takes",
        "less than half the readable engine's time",
        "both sides the RMSE columns agree",
        "Sobol points leave less error than multijitter here",
    ] {
        says(page, phrase);
    }
}
