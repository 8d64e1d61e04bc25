//! The checks' hand-worked cases are data (`src/grading/cases.toml`): the
//! file names only exercises that exist, each case reads as its check's
//! kind (raystep's reference solutions pass every check that reads them),
//! and a mistake in the file is named by its line.

use raystep::grading::{self, cases};

fn ids() -> Vec<String> {
    grading::all().iter().map(|e| e.id()).collect()
}

fn table() -> toml::Table {
    toml::from_str(cases::TEXT).expect("the case file parses")
}

#[test]
fn the_case_file_names_only_exercises_with_lists_of_cases() {
    assert_eq!(cases::problems(&ids()), Vec::<String>::new());
    assert!(table().len() >= 12, "the hand-worked cases of 12 checks");
}

#[test]
fn every_check_that_reads_cases_reads_them_and_passes_the_reference() {
    for id in table().keys() {
        let ex = grading::all().into_iter().find(|e| &e.id() == id).unwrap();
        let check = (ex.reference)();
        assert!(
            check.passed(),
            "{id}: {} (error {} over {})",
            check.detail,
            check.error,
            check.tolerance
        );
        assert!(!check.detail.contains("case file is broken"), "{id}");
    }
}

#[test]
fn a_case_that_does_not_read_is_named_by_file_line_and_exercise() {
    let first = "[[\"ch5/spot\"]]\nwhy = \"soft\"\ninner = 0.1\n";
    let text = format!("{first}\n[[\"ch5/spot\"]]\nwhy = \"wide\"\ninner = \"wide\"\n");
    // Read as maps of numbers, the second table fails: "wide" is no number.
    type Numbers = std::collections::BTreeMap<String, f64>;
    let err = cases::of_text::<Numbers>(&text, "ch5/spot").unwrap_err();
    assert!(
        err.starts_with("src/grading/cases.toml: line 5: case 2 of ch5/spot:")
            && err.contains("expected f64"),
        "{err}"
    );
    // The first alone reads, its `why` apart from its inputs.
    let read = cases::of_text::<Numbers>(first, "ch5/spot").unwrap();
    assert_eq!(read.len(), 1);
    assert_eq!(read[0].why, "soft");
    assert_eq!(read[0].case.get("inner"), Some(&0.1));
    // A case that does not say what it is about.
    let err = cases::of_text::<Numbers>("[[\"ch5/spot\"]]\ninner = 0.1\n", "ch5/spot").unwrap_err();
    assert!(err.contains("line 1: case 1 of ch5/spot: no `why"), "{err}");
    let err = cases::of_text::<Numbers>("x = ", "ch5/spot").unwrap_err();
    assert!(err.starts_with("src/grading/cases.toml: line 1:"), "{err}");
    let err = cases::of_text::<Numbers>(&text, "ch5/lambert_brdf").unwrap_err();
    assert!(err.contains("no [[\"ch5/lambert_brdf\"]] cases"), "{err}");
}

#[test]
fn a_table_for_no_exercise_or_not_a_list_is_refused() {
    let bad: toml::Table =
        toml::from_str("[[\"ch9/warp_drive\"]]\nx = 1\n\n[\"ch5/spot\"]\ninner = 1\n").unwrap();
    let problems = cases::problems_in(&bad, &ids());
    assert_eq!(problems.len(), 2, "{problems:?}");
    assert!(
        problems[0].contains("\"ch5/spot\" must be a list"),
        "{problems:?}"
    );
    assert!(
        problems[1].contains("\"ch9/warp_drive\" does not exist"),
        "{problems:?}"
    );
}

#[test]
fn a_broken_case_fails_the_check_as_the_course_s_fault() {
    let check = cases::unreadable("src/grading/cases.toml: line 3: oops".into());
    assert!(!check.passed());
    assert!(check.detail.contains("not your code"), "{}", check.detail);
}
