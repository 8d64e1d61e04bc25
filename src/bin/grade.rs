//! `cargo run --release --bin grade -- [ch1 ...] [--reference]`: grades the
//! exercise files against raystep's reference. See `raystep::grading`.

fn main() -> std::process::ExitCode {
    raystep::grading::grade_main()
}
