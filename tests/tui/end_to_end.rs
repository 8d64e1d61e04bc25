//! End to end: the real `raystep` binary in a pseudo-terminal (tmux):
//! start, change chapter, step bounces (or views, for chapters without
//! bounces), save, quit; then check the saved image and that the terminal
//! came back (the shell prints the exit status; no alternate screen; the
//! cursor is visible).
//!
//! Without tmux each test is skipped and says so on the terminal
//! ("skipped: tmux not found"), except under `CI`, where a missing tmux
//! is a failure (`.ci/run` installs it): one gate, [`shell`].

use crate::common;
use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

/// A private tmux server (its own socket), killed on drop.
pub(super) struct Tmux {
    socket: String,
}

impl Tmux {
    pub(super) fn run(&self, args: &[&str]) -> Output {
        Command::new("tmux")
            .args(["-L", &self.socket, "-f", "/dev/null"])
            .args(args)
            .output()
            .expect("running tmux")
    }

    pub(super) fn capture(&self) -> String {
        String::from_utf8_lossy(&self.run(&["capture-pane", "-p", "-t", "t"]).stdout).into_owned()
    }

    pub(super) fn flag(&self, name: &str) -> String {
        let f = format!("#{{{name}}}");
        String::from_utf8_lossy(&self.run(&["display-message", "-p", "-t", "t", &f]).stdout)
            .trim()
            .to_string()
    }

    pub(super) fn keys(&self, keys: &str) {
        self.run(&["send-keys", "-t", "t", "-l", keys]);
    }

    pub(super) fn key(&self, key: &str) {
        self.run(&["send-keys", "-t", "t", key]);
    }

    /// Polls every 30 ms until `ok` holds for the screen, or fails showing
    /// the screen. `secs` is what the step takes on a loaded machine; the
    /// limit is four times that, because it is there to end a hang, not to
    /// time the UI: it costs nothing when the screen arrives in time, and a
    /// CI machine running the whole suite on two cores can be that slow.
    pub(super) fn wait(&self, what: &str, secs: u64, ok: impl Fn(&Tmux, &str) -> bool) -> String {
        const SLACK: u64 = 4;
        let start = Instant::now();
        loop {
            let screen = self.capture();
            if ok(self, &screen) {
                return screen;
            }
            if start.elapsed() > Duration::from_secs(secs * SLACK) {
                panic!("timed out waiting for {what}; the screen:\n{screen}");
            }
            std::thread::sleep(Duration::from_millis(30));
        }
    }
}

impl Drop for Tmux {
    fn drop(&mut self) {
        let _ = self.run(&["kill-server"]);
    }
}

fn tmux_available() -> bool {
    Command::new("tmux")
        .arg("-V")
        .output()
        .is_ok_and(|o| o.status.success())
}

fn pngs(dir: &Path) -> Vec<std::path::PathBuf> {
    std::fs::read_dir(dir)
        .map(|d| {
            d.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|e| e == "png"))
                .collect()
        })
        .unwrap_or_default()
}

/// What a tmux test does, from whether tmux runs here and whether the
/// `CI` variable is set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum TmuxPlan {
    /// tmux is there: the test runs.
    Run,
    /// No tmux, not under CI: the test is skipped, and says so.
    Skip,
    /// No tmux under CI: the test fails (a CI that cannot run it must not
    /// count it as passed).
    Fail,
}

fn tmux_plan(available: bool, under_ci: bool) -> TmuxPlan {
    match (available, under_ci) {
        (true, _) => TmuxPlan::Run,
        (false, false) => TmuxPlan::Skip,
        (false, true) => TmuxPlan::Fail,
    }
}

/// Says on the terminal that a test was skipped and why. Written to the
/// process's stderr directly, not through `eprintln!`, which the test
/// harness captures and shows only for failing tests: a skip printed that
/// way would never be seen.
fn say_skipped(reason: &str) {
    use std::io::Write;
    let thread = std::thread::current();
    let test = thread.name().unwrap_or("a tmux test");
    let _ = writeln!(std::io::stderr().lock(), "{test}: skipped: {reason}");
}

/// A private tmux session running a shell, in a fresh temporary folder
/// named after `name`, once its prompt is up. The one gate of every tmux
/// test ([`tmux_plan`]): `None` without tmux (the test is skipped, and says
/// so on the terminal), and a failure without tmux under `CI`.
pub(super) fn shell(name: &str) -> Option<(Tmux, crate::common::TempDir)> {
    match tmux_plan(tmux_available(), std::env::var_os("CI").is_some()) {
        TmuxPlan::Run => {}
        TmuxPlan::Skip => {
            say_skipped("tmux not found (install tmux to run it; under CI this fails)");
            return None;
        }
        TmuxPlan::Fail => panic!("tmux not found under CI (.ci/run installs it)"),
    }
    let dir = common::temp_dir(name);
    // What the UI remembers between runs goes to this test's own folder,
    // never the real home (and no test opens where another one left off).
    let shell = format!(
        "env PS1='READY$ ' {}={} sh",
        raystep::tui::last::CONFIG_DIR_ENV,
        dir.join("config").display()
    );
    let tmux = Tmux {
        socket: format!("raystep-{name}-{}", std::process::id()),
    };
    let started = tmux.run(&[
        "new-session",
        "-d",
        "-s",
        "t",
        "-x",
        "110",
        "-y",
        "34",
        "-c",
        dir.to_str().unwrap(),
        &shell,
    ]);
    assert!(started.status.success(), "{started:?}");
    tmux.wait("the shell", 10, |_, s| s.contains("READY$"));
    Some((tmux, dir))
}

/// Runs `raystep` in the shell with the test hook `hook` set (it fails
/// while the UI owns the terminal), waits until the shell prints exit
/// status `code` on the main screen, checks that the cursor is visible and
/// returns the screen.
fn run_failing(tmux: &Tmux, dir: &Path, hook: &str, code: u8) -> String {
    tmux.keys(&format!(
        "{hook}=1 {} --scenes {}; echo \"EXIT=$?\"",
        env!("CARGO_BIN_EXE_raystep"),
        dir.display()
    ));
    tmux.key("Enter");
    let exit = format!("EXIT={code}");
    let screen = tmux.wait(&format!("the shell after {exit}"), 30, |t, s| {
        s.contains(&exit) && t.flag("alternate_on") == "0"
    });
    assert_eq!(tmux.flag("cursor_flag"), "1");
    screen
}

#[test]
fn a_missing_tmux_skips_here_and_fails_under_ci() {
    assert_eq!(tmux_plan(true, false), TmuxPlan::Run);
    assert_eq!(tmux_plan(true, true), TmuxPlan::Run);
    assert_eq!(tmux_plan(false, false), TmuxPlan::Skip);
    assert_eq!(tmux_plan(false, true), TmuxPlan::Fail);
}

#[test]
fn the_real_binary_in_a_terminal() {
    let Some((tmux, dir)) = shell("tui-e2e") else {
        return;
    };
    let out = dir.join("out");

    let command = format!(
        "{} --scenes {} --out {}; echo \"EXIT=$?\"",
        env!("CARGO_BIN_EXE_raystep"),
        common::root().join("scenes").display(),
        out.display()
    );
    tmux.keys(&command);
    tmux.key("Enter");
    // Start: the UI is up and the first pass of chapter 1 is shown.
    tmux.wait("the first preview", 30, |t, s| {
        t.flag("alternate_on") == "1" && s.contains("chapters") && s.contains("│ pass ")
    });

    // Change chapter (to the second one, where there is one).
    let chapters = raystep::chapters::all();
    let chapter = *chapters.get(1).unwrap_or(&chapters[0]);
    tmux.key("Down");
    let tag = format!("ch{} {} │", chapter.info().number, chapter.info().slug);
    tmux.wait(&tag, 60, |_, s| {
        s.lines()
            .any(|l| l.starts_with(&tag) && l.contains("│ pass "))
    });

    // Step bounces where the chapter has them, else step views.
    if chapter.info().bounces {
        tmux.wait("the bounce control", 60, |_, s| s.contains("bounces all"));
        tmux.keys("]");
        tmux.wait("bounce 0", 10, |_, s| s.contains("up to 0 bounces"));
        tmux.keys("m");
        tmux.wait("exactly 0", 10, |_, s| s.contains("exactly 0 bounces"));
    } else if chapter.info().views.len() > 1 {
        let name = chapter.info().views[1].name;
        tmux.keys("v");
        tmux.wait("the second view", 10, |_, s| {
            s.contains(&format!("view 2/{}: {name}", chapter.info().views.len()))
        });
    }

    // Save.
    tmux.keys("s");
    tmux.wait("the save message", 20, |_, s| s.contains("saved "));
    let saved = pngs(&out);
    assert_eq!(saved.len(), 1, "{saved:?}");
    let name = saved[0].file_name().unwrap().to_string_lossy().into_owned();
    assert!(
        name.starts_with(&format!("tui-ch{}-cornell-box-", chapter.info().number)),
        "{name}"
    );
    let film = raystep::core::film::Film::read_png(&saved[0]).unwrap();
    assert!(film.width > 0 && film.height > 0);
    assert!(saved[0].with_extension("exr").exists());

    // Quit: the shell is back, on the main screen, with a visible cursor.
    tmux.keys("q");
    let screen = tmux.wait("the shell after quitting", 20, |t, s| {
        s.contains("EXIT=0") && t.flag("alternate_on") == "0"
    });
    assert!(!screen.contains("chapters"), "{screen}");
    assert_eq!(tmux.flag("cursor_flag"), "1");
    tmux.wait("the prompt", 10, |_, s| {
        s.lines().filter(|l| l.starts_with("READY$")).count() >= 2
    });
}

#[test]
fn a_panic_restores_the_terminal_before_printing() {
    let Some((tmux, dir)) = shell("tui-e2e-panic") else {
        return;
    };
    let screen = run_failing(&tmux, &dir, raystep::tui::TEST_PANIC, 101);
    assert!(screen.contains("a deliberate panic"), "{screen}");
}

#[test]
fn an_error_restores_the_terminal_before_printing() {
    let Some((tmux, dir)) = shell("tui-e2e-error") else {
        return;
    };
    // The event loop returns an error after its first frame, while the UI
    // owns the terminal (raw mode, alternate screen, hidden cursor).
    let screen = run_failing(&tmux, &dir, raystep::tui::TEST_ERROR, 2);
    // The message was printed after restoring, so it is on the main
    // screen, above the exit status, and the UI is gone.
    let message = screen
        .lines()
        .position(|l| l.contains("error: terminal UI:") && l.contains("a deliberate error"));
    let exit = screen.lines().position(|l| l.contains("EXIT=2"));
    assert!(message.is_some() && message < exit, "{screen}");
    assert!(!screen.contains("chapters"), "{screen}");
    // Raw mode is off: the shell echoes typed text and runs it on Enter.
    tmux.keys("echo typed-$((6*7))");
    tmux.key("Enter");
    tmux.wait("the shell to run a command", 10, |_, s| {
        s.contains("typed-42")
    });
}

/// The numbers after `spp ` and `rmse ` in the status line, if shown.
fn spp_and_rmse(screen: &str) -> Option<(u32, f64)> {
    let line = screen.lines().find(|l| l.starts_with("ch6 "))?;
    let field = |key: &str| {
        line.split(" │ ")
            .find_map(|f| f.strip_prefix(key))
            .map(str::to_string)
    };
    let spp = field("spp ")?.split('/').next()?.parse().ok()?;
    let rmse = field("rmse ")?.parse().ok()?;
    Some((spp, rmse))
}

#[test]
fn chapter_6_converges_in_a_real_terminal() {
    let Some((tmux, dir)) = shell("tui-e2e-converge") else {
        return;
    };
    // Wide enough for the whole status line.
    tmux.run(&["resize-window", "-t", "t", "-x", "170", "-y", "40"]);
    let command = format!(
        "{} --chapter 6 --spp 64 --scenes {} --out {}; echo \"EXIT=$?\"",
        env!("CARGO_BIN_EXE_raystep"),
        dir.display(),
        dir.join("out").display()
    );
    tmux.keys(&command);
    tmux.key("Enter");
    // It opens on chapter 6 with the best estimator, and the first
    // preview comes with its sample count and error.
    let first = tmux.wait("chapter 6's first preview", 60, |_, s| {
        spp_and_rmse(s).is_some()
    });
    assert!(first.contains("mis-sobol"), "{first}");
    let (spp0, rmse0) = spp_and_rmse(&first).unwrap();
    // It keeps going: more samples, and the error falls below what one
    // or two samples per pixel give (about 0.2 and 0.12).
    let later = tmux.wait("spp to grow and the RMSE to fall", 180, |_, s| {
        spp_and_rmse(s).is_some_and(|(spp, rmse)| spp > spp0 && rmse < 0.06)
    });
    let (spp1, rmse1) = spp_and_rmse(&later).unwrap();
    assert!(
        spp1 > spp0 && rmse1 < rmse0,
        "{spp0} {rmse0} → {spp1} {rmse1}"
    );
    // Space pauses; the status says so.
    tmux.keys(" ");
    tmux.wait("paused or finished", 20, |_, s| {
        s.contains("· paused") || s.contains("finished: > raises the target")
    });
    tmux.keys("q");
    tmux.wait("the shell after quitting", 20, |t, s| {
        s.contains("EXIT=0") && t.flag("alternate_on") == "0"
    });
}

/// A terminal that claims kitty graphics but runs inside tmux (the test's
/// own), and one forced with `--halfblocks`: both show the half-block
/// preview, start as fast as ever, and put the terminal back on quit.
#[test]
fn the_half_block_fallback_in_tmux_and_with_the_flag() {
    let Some((tmux, dir)) = shell("tui-e2e-halfblocks") else {
        return;
    };
    for flag in ["", "--halfblocks"] {
        let command = format!(
            "TERM=xterm-kitty KITTY_WINDOW_ID=1 {} {flag} --scenes {}; echo \"EXIT=$?\"",
            env!("CARGO_BIN_EXE_raystep"),
            dir.display()
        );
        tmux.keys(&command);
        tmux.key("Enter");
        let screen = tmux.wait("the first preview", 30, |t, s| {
            t.flag("alternate_on") == "1" && s.contains("│ pass ")
        });
        // Half blocks in the preview, no graphics escape shown as text,
        // and the title does not claim a graphics protocol.
        assert!(screen.contains('▀'), "{screen}");
        assert!(!screen.contains("kitty graphics"), "{screen}");
        assert!(!screen.contains("_G"), "{screen}");
        tmux.keys("q");
        tmux.wait("the shell after quitting", 20, |t, s| {
            s.contains("EXIT=0") && t.flag("alternate_on") == "0"
        });
        tmux.keys("clear");
        tmux.key("Enter");
        tmux.wait("a clear screen", 10, |_, s| !s.contains("EXIT=0"));
    }
}

/// At 80x24, the default terminal: Esc closes the help, the path table and
/// inspect mode one at a time and, with nothing open, does not quit; the
/// pixel panel shows the pixel's values and the path table its vertices;
/// `q` quits.
#[test]
fn esc_never_quits_and_the_inspector_has_room_at_80x24() {
    let Some((tmux, dir)) = shell("tui-e2e-esc") else {
        return;
    };
    tmux.run(&["resize-window", "-t", "t", "-x", "80", "-y", "24"]);
    let command = format!(
        "{} --chapter 6 --spp 16 --scenes {} --out {}; echo \"EXIT=$?\"",
        env!("CARGO_BIN_EXE_raystep"),
        dir.display(),
        dir.join("out").display()
    );
    tmux.keys(&command);
    tmux.key("Enter");
    let up = |t: &Tmux| t.flag("alternate_on") == "1";
    tmux.wait("chapter 6's first preview", 60, |t, s| {
        up(t) && s.contains("│ spp ")
    });
    // Nothing open: Esc only says how to quit.
    for _ in 0..3 {
        tmux.key("Escape");
    }
    tmux.wait("the hint after Esc", 10, |t, s| {
        up(t) && s.contains("nothing to close: q quits")
    });
    // The help, then Esc.
    tmux.keys("?");
    tmux.wait("the help", 10, |_, s| s.contains("keys (Esc"));
    tmux.key("Escape");
    tmux.wait("the help closed", 10, |t, s| {
        up(t) && !s.contains("keys (Esc")
    });
    // The pixel panel, with the pixel's values in view.
    tmux.keys("i");
    let panel = tmux.wait("the pixel panel", 20, |_, s| {
        s.contains("pixel (") && s.contains("image: ") && s.contains("Esc: close")
    });
    println!("inspector at 80x24:\n{panel}");
    // A path, over the picture at this width; Esc closes it and keeps the
    // panel; Esc again closes the panel; once more changes nothing.
    tmux.keys("t");
    let path = tmux.wait("the path table", 30, |_, s| {
        s.contains("path: sample 0 of pixel") && s.contains("camera ray")
    });
    println!("path table at 80x24:\n{path}");
    tmux.key("Escape");
    tmux.wait("the table closed", 10, |_, s| {
        !s.contains("camera ray") && s.contains("image: ")
    });
    tmux.key("Escape");
    tmux.wait("the panel closed", 10, |t, s| {
        up(t) && !s.contains("image: ")
    });
    tmux.key("Escape");
    std::thread::sleep(std::time::Duration::from_millis(300));
    let screen = tmux.capture();
    assert!(up(&tmux) && screen.contains("chapters"), "{screen}");
    tmux.keys("q");
    tmux.wait("the shell after quitting", 20, |t, s| {
        s.contains("EXIT=0") && t.flag("alternate_on") == "0"
    });
}
