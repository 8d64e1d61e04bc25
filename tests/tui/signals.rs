//! The terminal is never left broken: the real `raystep` in tmux, ended by
//! TERM, HUP and INT, stopped by TSTP and by Ctrl-Z and continued, handed a
//! paste, and run under `TERM=dumb`. After each: the main screen, the
//! cursor shown, no mouse reports, and the terminal's modes (`stty -g`) as
//! they were before the UI started.

use std::path::Path;
use std::process::Command;

use super::end_to_end::{shell, Tmux};
use crate::common;

/// Starts the UI from the shell (its terminal modes saved to `before`
/// first) and waits until it is up.
fn start(tmux: &Tmux, dir: &Path) {
    tmux.keys(&format!(
        "stty -g > {}/before; {} --scenes {}; echo \"EXIT=$?\"",
        dir.display(),
        env!("CARGO_BIN_EXE_raystep"),
        common::root().join("scenes").display()
    ));
    tmux.key("Enter");
    up(tmux);
}

/// Waits until the UI shows its chapter list on the alternate screen.
fn up(tmux: &Tmux) {
    tmux.wait("the UI", 30, |t, s| {
        t.flag("alternate_on") == "1" && s.contains("chapters") && s.contains("│ pass ")
    });
}

/// The UI's process: the child of the pane's shell.
fn ui_pid(tmux: &Tmux) -> String {
    let shell = tmux.flag("pane_pid");
    let out = Command::new("pgrep")
        .args(["-P", &shell])
        .output()
        .expect("pgrep");
    let pids = String::from_utf8_lossy(&out.stdout).trim().to_string();
    assert!(
        !pids.is_empty() && !pids.contains('\n'),
        "children of {shell}: {pids:?}"
    );
    pids
}

fn kill(pid: &str, signal: &str) {
    let status = Command::new("kill")
        .args([&format!("-{signal}"), pid])
        .status()
        .expect("kill");
    assert!(status.success());
}

/// The terminal as the shell needs it: main screen, cursor shown, no mouse
/// reports, and (asked of the shell) the modes saved before the UI started.
fn restored(tmux: &Tmux, dir: &Path, what: &str) {
    assert_eq!(tmux.flag("alternate_on"), "0", "{what}");
    assert_eq!(tmux.flag("cursor_flag"), "1", "{what}: cursor hidden");
    for mouse in ["mouse_any_flag", "mouse_button_flag", "mouse_standard_flag"] {
        assert_eq!(tmux.flag(mouse), "0", "{what}: {mouse}");
    }
    let _ = std::fs::remove_file(dir.join("after"));
    tmux.keys(&format!("stty -g > {}/after; echo STTY-$?", dir.display()));
    tmux.key("Enter");
    tmux.wait("stty", 10, |_, s| s.contains("STTY-0"));
    let read = |f: &str| std::fs::read_to_string(dir.join(f)).unwrap_or_default();
    let (before, after) = (read("before"), read("after"));
    assert!(!before.trim().is_empty(), "{what}: no saved modes");
    assert_eq!(after, before, "{what}: the terminal's modes changed");
    tmux.keys("clear");
    tmux.key("Enter");
}

#[test]
fn term_hup_and_int_restore_the_terminal_and_exit_with_the_usual_status() {
    let Some((tmux, dir)) = shell("tui-signals") else {
        return;
    };
    for (signal, code) in [("TERM", 143), ("HUP", 129), ("INT", 130)] {
        start(&tmux, &dir);
        kill(&ui_pid(&tmux), signal);
        let exit = format!("EXIT={code}");
        tmux.wait(&exit, 20, |t, s| {
            s.contains(&exit) && t.flag("alternate_on") == "0"
        });
        restored(&tmux, &dir, signal);
    }
}

#[test]
fn tstp_and_ctrl_z_suspend_and_fg_takes_the_terminal_back() {
    let Some((tmux, dir)) = shell("tui-suspend") else {
        return;
    };
    for how in ["TSTP", "C-z"] {
        start(&tmux, &dir);
        let pid = ui_pid(&tmux);
        match how {
            "TSTP" => kill(&pid, "TSTP"),
            key => tmux.key(key),
        }
        tmux.wait("the shell after a stop", 20, |t, s| {
            t.flag("alternate_on") == "0" && s.contains("Stopped")
        });
        restored(&tmux, &dir, how);
        // Back in the foreground: the UI redraws, and reads keys without
        // Enter (raw mode again).
        tmux.keys("fg");
        tmux.key("Enter");
        up(&tmux);
        tmux.keys("q");
        // (The shell dropped the rest of the stopped command line: its
        // `echo` is asked again here.)
        tmux.wait("the main screen after fg", 20, |t, _| {
            t.flag("alternate_on") == "0"
        });
        tmux.keys("echo \"FG=$?\"");
        tmux.key("Enter");
        tmux.wait("the exit status after fg", 10, |_, s| s.contains("FG=0"));
        restored(&tmux, &dir, &format!("{how}, fg, q"));
    }
}

#[test]
fn a_paste_is_never_read_as_keys() {
    let Some((tmux, dir)) = shell("tui-paste") else {
        return;
    };
    start(&tmux, &dir);
    // `q` quits, `s` saves: pasted, neither happens.
    tmux.run(&["set-buffer", "-b", "p", "sssq\nqq"]);
    tmux.run(&["paste-buffer", "-p", "-b", "p", "-t", "t"]);
    tmux.wait("the paste message", 10, |_, s| s.contains("paste ignored"));
    assert_eq!(tmux.flag("alternate_on"), "1", "a pasted q quit the UI");
    assert!(!tmux.capture().contains("saved "));
    tmux.keys("q");
    tmux.wait("the exit", 20, |t, s| {
        s.contains("EXIT=0") && t.flag("alternate_on") == "0"
    });
    restored(&tmux, &dir, "paste");
}

#[test]
fn term_dumb_gets_the_headless_summary() {
    let Some((tmux, dir)) = shell("tui-dumb") else {
        return;
    };
    tmux.keys(&format!(
        "stty -g > {}/before; TERM=dumb {} --out {} > {}/summary.txt; echo \"EXIT=$?\"",
        dir.display(),
        env!("CARGO_BIN_EXE_raystep"),
        dir.join("out").display(),
        dir.display()
    ));
    tmux.key("Enter");
    tmux.wait("the summary's end", 240, |t, s| {
        s.contains("EXIT=0") && t.flag("alternate_on") == "0"
    });
    restored(&tmux, &dir, "TERM=dumb");
    let summary = std::fs::read_to_string(dir.join("summary.txt")).unwrap();
    assert!(!summary.contains('\x1b'), "escape sequences: {summary:?}");
    assert!(summary.contains("ch6"), "{summary}");
}
