//! Every way to ask for samples is held to the sample limit: the main
//! program's `--spp` (headless, it used to start rendering 4e9 samples per
//! pixel) and chapter 6's `--spp-figure`, like every chapter's `--spp`.

use std::process::Command;

use raystep::core::run::MAX_SPP;

#[test]
fn every_sample_count_flag_is_bounded() {
    let over = (u64::from(MAX_SPP) + 1).to_string();
    for (bin, args) in [
        (
            env!("CARGO_BIN_EXE_raystep"),
            vec!["--headless", "--spp", "4000000000"],
        ),
        (
            env!("CARGO_BIN_EXE_raystep"),
            vec!["--headless", "--spp", &over],
        ),
        (env!("CARGO_BIN_EXE_ch6"), vec!["--spp-figure", &over]),
        (env!("CARGO_BIN_EXE_ch6"), vec!["--spp", &over]),
    ] {
        let run = Command::new(bin).args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{args:?}: {err}");
        let flag = args[args.len() - 2];
        assert!(
            err.contains(flag) && err.contains(&MAX_SPP.to_string()),
            "{err}"
        );
    }
}
