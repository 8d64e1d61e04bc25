//! Every figure regenerates: each image the book shows is in
//! `book/src/figures` and is made by a line of `book/figures.sh`, and the
//! script runs every chapter.

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The images (`figures/....png`) the book's pages show, other than the
/// wrong pictures and their partners.
fn images_shown() -> Vec<String> {
    // Wrong pictures and their partners come from `diagrams` (checked
    // below), not from a chapter run.
    shown_ending(".png")
        .into_iter()
        .filter(|n| !n.ends_with("-wrong.png") && !n.ends_with("-right.png"))
        .collect()
}

/// One run of a chapter binary in the script: chapter, scene name, the
/// folder under `book/src/figures` it writes to, and whether it runs the
/// studies.
#[derive(Debug)]
struct Run {
    chapter: u32,
    scenes: Vec<String>,
    subdir: String,
    report: bool,
}

fn runs(script: &str) -> Vec<Run> {
    let mut runs = Vec::new();
    let mut loop_scenes: Vec<String> = Vec::new();
    for line in script.lines().map(str::trim) {
        if let Some(list) = line
            .strip_prefix("for scene in ")
            .and_then(|l| l.strip_suffix("; do"))
        {
            loop_scenes = list.split_whitespace().map(String::from).collect();
            continue;
        }
        let Some(at) = line.find("/ch") else {
            continue;
        };
        if !line.starts_with("\"$bin/ch") {
            continue;
        }
        let chapter = line[at + 3..at + 4].parse().unwrap();
        let words: Vec<&str> = line.split_whitespace().collect();
        let arg = |flag: &str| {
            words
                .iter()
                .position(|w| *w == flag)
                .map(|i| words[i + 1].trim_matches('"').to_string())
        };
        let scenes = match arg("--scene") {
            Some(s) if s.contains("$scene") => loop_scenes.clone(),
            Some(s) => vec![Path::new(&s)
                .file_stem()
                .unwrap()
                .to_string_lossy()
                .into_owned()],
            None => vec!["cornell-box".into()],
        };
        let out = arg("--out").unwrap_or_default();
        let subdir = out
            .strip_prefix("$out")
            .unwrap_or("")
            .trim_matches('/')
            .to_string();
        runs.push(Run {
            chapter,
            scenes,
            subdir,
            report: words.contains(&"--report"),
        });
    }
    runs
}

/// Whether `run` writes `image` (a path under the figures folder).
fn makes(run: &Run, image: &str) -> bool {
    let (dir, file) = match image.rsplit_once('/') {
        Some((d, f)) => (d, f),
        None => ("", image),
    };
    let Some(name) = file
        .strip_prefix(&format!("ch{}-", run.chapter))
        .and_then(|f| f.strip_suffix(".png"))
    else {
        return false;
    };
    if dir != run.subdir {
        return false;
    }
    // Chapter 5's study plots and chapter 2's checkered floor come from any
    // run with --report, whatever its scene.
    let study_plot = (run.chapter == 5 && name.starts_with("error-time-"))
        || (run.chapter == 2 && name.starts_with("checker-floor"));
    (study_plot && run.report)
        || run
            .scenes
            .iter()
            .any(|s| name == s || name.starts_with(&format!("{s}-")))
}

#[test]
fn every_image_the_book_shows_exists_and_the_script_makes_it() {
    let script = std::fs::read_to_string(root().join("book/figures.sh")).unwrap();
    let runs = runs(&script);
    for n in 1..=6 {
        assert!(
            runs.iter().any(|r| r.chapter == n),
            "book/figures.sh never runs ch{n}: {runs:?}"
        );
    }
    let images = images_shown();
    assert!(images.len() > 20, "{images:?}");
    for image in &images {
        assert!(
            root().join("book/src/figures").join(image).is_file(),
            "the book shows figures/{image}, which does not exist"
        );
        assert!(
            runs.iter().any(|r| makes(r, image)),
            "no line of book/figures.sh makes figures/{image}"
        );
    }
}

#[test]
fn the_script_parser_sees_loops_subfolders_and_reports() {
    let script = "for scene in a b; do\n  \"$bin/ch1\" --scene \"scenes/$scene.toml\" --out \"$out\"\ndone\n\
                  \"$bin/ch4\" --scene scenes/x.toml --out \"$out/fixed\" > /dev/null\n\
                  \"$bin/ch5\" --scene scenes/s.toml --report --out \"$out\"\n\
                  \"$bin/ch2\" --scene scenes/t.toml --out \"$out\"\n\
                  \"$bin/ch2\" --scene scenes/t.toml --report --out \"$out\"\n";
    let runs = runs(script);
    assert_eq!(runs.len(), 5);
    assert!(makes(&runs[0], "ch1-b-depth.png"));
    assert!(!makes(&runs[0], "ch1-c.png"));
    assert!(makes(&runs[1], "fixed/ch4-x.png"));
    assert!(!makes(&runs[1], "ch4-x.png"));
    assert!(makes(&runs[2], "ch5-error-time-area.png"));
    assert!(!makes(&runs[0], "ch2-a.png"));
    assert!(!makes(&runs[3], "ch2-checker-floor.png"));
    assert!(makes(&runs[4], "ch2-checker-floor-affine.png"));
}

/// The `figures/…` files of one kind (`.svg`, `-wrong.png`) the book shows.
fn shown_ending(ending: &str) -> Vec<String> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(root().join("book/src")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "md") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        for (i, _) in text.match_indices("](figures/") {
            let rest = &text[i + "](figures/".len()..];
            let end = rest.find(')').unwrap();
            if rest[..end].ends_with(ending) {
                out.push(rest[..end].to_string());
            }
        }
    }
    out.sort();
    out.dedup();
    out
}

/// The `diagrams` binary run with `args`: its standard output, after
/// checking that it succeeded.
fn diagrams(args: &[&std::ffi::OsStr]) -> String {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_diagrams"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// What `diagrams --list` names: the file of each diagram and wrong or
/// right picture.
fn diagram_list() -> Vec<String> {
    diagrams(&["--list".as_ref()])
        .lines()
        .map(|l| l.split(':').next().unwrap().to_string())
        .collect()
}

#[test]
fn the_diagrams_are_what_the_code_draws_now() {
    let script = std::fs::read_to_string(root().join("book/figures.sh")).unwrap();
    assert!(
        script.contains("\"$bin/diagrams\" --out \"$out\""),
        "book/figures.sh does not draw the diagrams"
    );
    let dir = std::env::temp_dir().join(format!("raystep-diagrams-{}", std::process::id()));
    diagrams(&["--out".as_ref(), dir.as_os_str()]);
    let shown = shown_ending(".svg");
    assert!(
        shown.len() >= 15,
        "the book shows {} diagrams, fewer than 15: {shown:?}",
        shown.len()
    );
    for name in &shown {
        assert!(
            name.ends_with("-diagram.svg"),
            "{name}: a diagram's name ends in -diagram.svg"
        );
        let drawn = std::fs::read(dir.join(name)).unwrap_or_else(|_| {
            panic!("the book shows figures/{name}, which diagrams does not draw")
        });
        let committed = std::fs::read(root().join("book/src/figures").join(name))
            .unwrap_or_else(|_| panic!("figures/{name} is not in book/src/figures"));
        assert!(
            drawn == committed,
            "figures/{name} differs from what diagrams draws now: run bash book/figures.sh"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn every_chapter_shows_a_wrong_picture_beside_the_right_one() {
    let script = std::fs::read_to_string(root().join("book/figures.sh")).unwrap();
    assert!(
        script.contains("\"$bin/diagrams\" --wrong --out \"$out\""),
        "book/figures.sh does not render the wrong pictures"
    );
    let listed = diagram_list();
    let wrong = shown_ending("-wrong.png");
    for n in 1..=6 {
        assert!(
            wrong.iter().any(|w| w.starts_with(&format!("ch{n}-"))),
            "chapter {n} shows no wrong picture: {wrong:?}"
        );
    }
    let pages: Vec<String> = std::fs::read_dir(root().join("book/src"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    for name in &wrong {
        let right = name.replace("-wrong.png", "-right.png");
        for file in [name, &right] {
            assert!(
                listed.contains(file),
                "diagrams --wrong does not render {file}"
            );
            assert!(
                root().join("book/src/figures").join(file).is_file(),
                "figures/{file} does not exist"
            );
        }
        assert!(
            pages
                .iter()
                .any(|p| p.contains(&format!("(figures/{name})"))
                    && p.contains(&format!("(figures/{right})"))),
            "figures/{name} is not shown on the same page as figures/{right}"
        );
    }
}
