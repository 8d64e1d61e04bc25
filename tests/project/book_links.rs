//! The book's links lead somewhere: every link to a heading (`page.md#id`
//! or `#id`) finds a heading with that id, as mdBook makes them, and the
//! coverage page quotes real slides and leaves no lecture topic out.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn book_src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("book/src")
}

/// The id mdBook gives a heading: lower case, spaces to `-`, only
/// letters, digits, `-` and `_` kept.
fn heading_id(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .map(|c| if c.is_whitespace() { '-' } else { c })
        .filter(|c| c.is_alphanumeric() || *c == '-' || *c == '_')
        .collect()
}

/// The ids of a page's headings (outside code blocks), with mdBook's
/// `-1`, `-2` suffixes for repeats.
fn heading_ids(text: &str) -> BTreeSet<String> {
    let mut ids = BTreeSet::new();
    let mut in_code = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            in_code = !in_code;
            continue;
        }
        if in_code || !line.starts_with('#') {
            continue;
        }
        let id = heading_id(line.trim_start_matches('#'));
        let mut unique = id.clone();
        let mut n = 1;
        while ids.contains(&unique) {
            unique = format!("{id}-{n}");
            n += 1;
        }
        ids.insert(unique);
    }
    ids
}

fn pages() -> Vec<(String, String)> {
    let mut pages: Vec<(String, String)> = std::fs::read_dir(book_src())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .collect();
    pages.sort();
    pages
}

/// Every `](target#id)` link of `text` outside code blocks.
fn anchored_links(text: &str) -> Vec<(String, String)> {
    let mut links = Vec::new();
    let mut in_code = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            in_code = !in_code;
            continue;
        }
        if in_code {
            continue;
        }
        for part in line.split("](").skip(1) {
            let target = part.split(')').next().unwrap_or("");
            if target.contains("://") {
                continue;
            }
            if let Some((page, id)) = target.split_once('#') {
                links.push((page.to_string(), id.to_string()));
            }
        }
    }
    links
}

#[test]
fn every_link_to_a_heading_finds_it() {
    let pages = pages();
    let mut broken = Vec::new();
    let mut checked = 0;
    for (name, text) in &pages {
        for (page, id) in anchored_links(text) {
            let target = if page.is_empty() {
                name.as_str()
            } else {
                page.as_str()
            };
            let Some((_, target_text)) = pages.iter().find(|(n, _)| n == target) else {
                continue; // a missing page is book.rs's to report
            };
            checked += 1;
            if !heading_ids(target_text).contains(&id) {
                broken.push(format!("{name}: ({page}#{id}) has no heading with that id"));
            }
        }
    }
    assert!(checked > 30, "only {checked} links to headings were found");
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

#[test]
fn heading_ids_are_mdbooks() {
    assert_eq!(
        heading_id(" Route 2: one 3x3 system (Möller–Trumbore)"),
        "route-2-one-3x3-system-möllertrumbore"
    );
    assert_eq!(
        heading_id(" Which side of an edge? The edge function"),
        "which-side-of-an-edge-the-edge-function"
    );
    let ids = heading_ids("# A\n## Summary\n```\n# not a heading\n```\n## Summary\n");
    assert!(ids.contains("summary") && ids.contains("summary-1") && !ids.contains("not-a-heading"));
    let links = anchored_links("see [x](ch1.md#a) and [y](#b)\n```\n[z](#c)\n```\n");
    assert_eq!(
        links,
        vec![("ch1.md".into(), "a".into()), ("".into(), "b".into())]
    );
}

#[test]
fn the_coverage_page_quotes_real_slides_and_leaves_no_topic_out() {
    let lecture = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/lecture-11-rendering.txt"),
    );
    let coverage = std::fs::read_to_string(book_src().join("coverage.md")).unwrap();
    let rows: Vec<&str> = coverage.lines().filter(|l| l.starts_with("| \"")).collect();
    assert!(
        rows.len() >= 50,
        "the coverage table has only {} rows",
        rows.len()
    );
    // The lecture's text sits beside the checkout; where it is absent (a
    // clone on its own) the quotes cannot be checked, the rest can.
    if let Ok(lecture) = lecture {
        for row in &rows {
            let quote = row[3..].split('"').next().unwrap();
            assert!(
                lecture.contains(quote),
                "coverage.md quotes \"{quote}\", which is not in the lecture"
            );
        }
    }
    for row in &rows {
        assert!(
            row.contains("](") && row.contains(".md"),
            "{row}: no link to a section"
        );
    }
    // The topics the lecture treats, each of which must have a row.
    for topic in [
        "Pinhole camera model",
        "Parallel lines",
        "Rasterization—Illumination",
        "Why triangles",
        "Explicit",
        "Implicit",
        "Eikonal",
        "Signed distance",
        "Barycentric",
        "Linear interpolation",
        "Rasterization Pipeline",
        "Manifold",
        "boundary",
        "Ray equation",
        "Ray-plane",
        "Ray-triangle",
        "performance",
        "Electromagnetic",
        "Radiant flux",
        "Irradiance",
        "Lambert",
        "directional",
        "point source",
        "Spotlight",
        "Area light",
        "Solid angle",
        "Radiance",
        "reflectance distribution",
        "basic reflection functions",
        "semi-gloss",
        "Multiple light sources",
        "Environment",
        "Rendering equation",
        "Transmission",
        "Kajiya",
        "Recursive",
        "How to solve",
        "transparency",
        "Integration",
        "path tracing",
        "Noise decreases",
        "bounce",
        "deep learning",
        "sensor",
    ] {
        assert!(
            rows.iter()
                .any(|r| r.split('|').nth(1).unwrap().contains(topic)),
            "coverage.md has no row for the lecture's \"{topic}\""
        );
    }
}

#[test]
fn the_appendix_is_a_lesson_of_at_most_2500_words() {
    let text = std::fs::read_to_string(book_src().join("making-it-fast.md")).unwrap();
    let words = text.split_whitespace().count();
    assert!(
        words <= 2500,
        "making-it-fast.md has {words} words, more than 2,500"
    );
    assert!(words >= 1000, "making-it-fast.md has only {words} words");
}

#[test]
fn every_chapter_ends_with_key_ideas_what_to_try_and_further_reading() {
    for (name, text) in pages() {
        if !name.starts_with("ch") || !name.as_bytes()[2].is_ascii_digit() {
            continue;
        }
        let summary = text
            .split("\n## Summary\n")
            .nth(1)
            .unwrap_or_else(|| panic!("{name} has no closing ## Summary section"));
        assert!(
            !summary.contains("\n## "),
            "{name}: the summary is not the last section"
        );
        for part in ["**Key ideas.**", "**What to try.**", "**Further reading.**"] {
            assert!(summary.contains(part), "{name}: the summary lacks {part}");
        }
        let commands = summary.split("**What to try.**").nth(1).unwrap();
        assert!(
            commands.contains("```sh\ncargo run --release --bin ch"),
            "{name}: what to try gives no command"
        );
    }
}
