//! A FIFO where a scene or a mesh is expected is refused at once (opening
//! one for reading used to wait for a writer for ever: every binary hung on
//! a FIFO mesh, and the terminal UI on a FIFO `*.toml` in its scenes
//! folder, before drawing anything).

use std::path::Path;
use std::process::Command;
use std::sync::mpsc;
use std::time::Duration;

use raystep::scene::Scene;

use crate::common;

fn mkfifo(path: &Path) {
    assert!(Command::new("mkfifo").arg(path).status().unwrap().success());
}

/// Loads `path` on a thread of its own: the error, or a hang after 5 s.
fn load_within_5_s(path: &Path) -> String {
    let (tx, rx) = mpsc::channel();
    let p = path.to_path_buf();
    std::thread::spawn(move || {
        let _ = tx.send(Scene::load(&p).map(|_| ()).map_err(|e| e.to_string()));
    });
    match rx.recv_timeout(Duration::from_secs(5)) {
        Ok(Err(message)) => message,
        Ok(Ok(())) => panic!("{} loaded", path.display()),
        Err(_) => {
            // Unblock the stuck open so the thread can end.
            let _ = std::fs::write(path, "");
            panic!("loading {} hung", path.display())
        }
    }
}

#[test]
fn a_fifo_scene_or_mesh_is_refused_at_once() {
    let dir = common::temp_dir("fifo");
    let scene = dir.join("pipe.toml");
    mkfifo(&scene);
    let m = load_within_5_s(&scene);
    assert!(
        m.contains("pipe.toml") && m.contains("not a regular file"),
        "{m}"
    );

    let mesh = dir.join("pipe.obj");
    mkfifo(&mesh);
    let with_mesh = dir.join("mesh.toml");
    std::fs::write(
        &with_mesh,
        "[[materials]]\nname = \"m\"\nreflectance = [0.5, 0.5, 0.5]\n\n[[objects]]\nmesh = \"pipe.obj\"\nmaterial = \"m\"\n",
    )
    .unwrap();
    let m = load_within_5_s(&with_mesh);
    assert!(
        m.contains("pipe.obj") && m.contains("not a regular file"),
        "{m}"
    );
}
