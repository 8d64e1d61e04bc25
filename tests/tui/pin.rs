//! tev's reference pinning on the real chapter 6: `p` pins the render
//! shown, and the compare views then set the next render (another
//! estimator's) against it; the z view's verdict says whether the two
//! estimators agree within their noise.

use raystep::tui::app::{App, Compare, Msg};
use raystep::tui::update::update;

use super::curves::render_current;
use super::inspect::rendered;

#[test]
fn a_pinned_render_is_what_the_next_estimator_is_compared_with() {
    let first = render_current(rendered());
    let image = first.snapshot.as_ref().unwrap().views[0].clone();
    let app = update(first, Msg::TogglePin);
    let pinned = app.pinned_here().expect("pinned");
    assert!(pinned.label.contains("spp"), "{}", pinned.label);
    assert!(app.message.starts_with("pinned "), "{}", app.message);
    // Another estimator (MIS with independent numbers): its difference is
    // against the pinned image.
    let app = render_current(update(app, Msg::PrevVariant));
    assert!(app.pinned_here().is_some(), "a new estimator keeps the pin");
    let (render, reference) = app.compared_pair().unwrap();
    assert_eq!(reference, &image);
    assert_ne!(*render, image);
    let app: App = update(update(app, Msg::CycleCompare), Msg::CycleCompare);
    assert_eq!(app.compare, Compare::Difference);
    let title = raystep::tui::labels::preview_title_parts(&app).join(" · ");
    assert!(
        title.contains("render - pinned") && title.contains("pinned "),
        "{title}"
    );
    // Both know their noise: the z view compares the two estimators, and
    // two unbiased ones agree.
    let app = update(update(app, Msg::CycleCompare), Msg::CycleCompare);
    assert_eq!(app.compare, Compare::Z);
    let v = app.verdict().expect("a verdict between the two renders");
    assert!(v.within_noise(), "two unbiased estimators disagree: {v:?}");
    // p again unpins: the stored reference is back.
    let app = update(app, Msg::TogglePin);
    assert!(app.pinned_here().is_none());
    let stored = app.snapshot.as_ref().unwrap().reference.clone().unwrap();
    assert_eq!(app.compared_pair().unwrap().1, &stored);
}

/// The lecture's uniform walk at 8 samples has found the small lamp in
/// few pixels: where all its samples agree (variance 0), the verdict says
/// too few samples, not a bias.
#[test]
fn an_estimator_that_has_not_found_the_light_yet_is_not_called_biased() {
    let app = update(render_current(rendered()), Msg::TogglePin);
    let app = render_current(update(app, Msg::NextVariant));
    let info = app.current_chapter().unwrap().info();
    assert!(info.variants[app.variant].name.starts_with("uniform"));
    let app = (0..4).fold(app, |a, _| update(a, Msg::CycleCompare));
    assert_eq!(app.compare, Compare::Z);
    let v = app.verdict().unwrap();
    let [first, _] = v.lines();
    assert!(
        first != "verdict: biased" && !first.starts_with("verdict: biased,"),
        "{v:?}"
    );
}
