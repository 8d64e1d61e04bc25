//! The terminal UI: layout snapshots, keys, and an end-to-end run in tmux.

#![cfg(feature = "tui")]

mod converge;
mod curves;
mod difference;
mod effects;
mod end_to_end;
mod flip;
mod graphics;
mod inspect;
mod layout_and_keys;
mod nonfinite;
mod painter;
mod pin;
mod region;
mod signals;
mod sixel;
mod sizes_and_keys;
mod split;
mod warp;
mod zoom;
mod zview;
