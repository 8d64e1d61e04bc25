//! `grade-student <chN/name> <out dir>`: runs one exercise's check on the
//! student's code and prints the verdict. Started by `grade`, one process
//! per exercise, under a time limit.

fn main() -> std::process::ExitCode {
    raystep::grading::runner::runner_main(raystep_exercises::registry(), raystep_exercises::warps())
}
