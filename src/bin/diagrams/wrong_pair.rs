//! What the wrong pictures' modules share: a pair of pictures, the
//! shipped scenes, and magnifying a picture.

use std::path::PathBuf;

use raystep::core::error::Result;
use raystep::core::film::Film;
use raystep::scene::Scene;

/// One pair: the file stem (`chN-what`) and the two pictures.
pub struct Pair {
    /// `chN-what`: the files are `chN-what-right.png` and `chN-what-wrong.png`.
    pub stem: &'static str,
    /// The lesson's picture.
    pub right: Film,
    /// The bug's picture.
    pub wrong: Film,
}

/// A shipped scene of `scenes/`.
pub fn scene(name: &str) -> Result<Scene> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name);
    Scene::load(&path)
}

/// `film` magnified `k` times, each pixel a k x k block (a leak is one
/// pixel wide).
pub fn magnify(film: &Film, k: u32) -> Film {
    let mut big = Film::new(film.width * k, film.height * k);
    for y in 0..big.height {
        for x in 0..big.width {
            *big.get_mut(x, y) = film.get(x / k, y / k);
        }
    }
    big
}
