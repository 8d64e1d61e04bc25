//! Chapter 3: ray-triangle intersection and a BVH.
//! `cargo run --release --bin ch3 -- --help`
//!
//! Traces the first hit of every primary ray and writes four views (depth,
//! normal, barycentrics, triangle id); `--report` adds the anti-aliasing and
//! naive-vs-BVH studies, the leak counts and the stiff cases. `ch3 --bench`
//! instead prints the throughput benchmark (BVH build, Mrays/s on 1 and 2
//! threads, raystep's stage against obvhs alone); `ch3 --bench bunny` only
//! the bunny's rows.

fn main() -> std::process::ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if let Some(i) = args.iter().position(|a| a == "--bench") {
        // `ch3 --bench [MESH]`: an optional filter on the mesh names.
        let only = args.get(i + 1).map(String::as_str);
        print!(
            "{}",
            raystep::ch3_ray_triangle::bench::benchmark(only).to_text()
        );
        return std::process::ExitCode::SUCCESS;
    }
    raystep::core::run::chapter_main(&raystep::ch3_ray_triangle::stage::RayTriangle)
}
