//! Which vector instructions the fast engine's ray queries use, chosen
//! at run time.

/// A set of vector instructions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    /// The build's baseline (SSE2 on x86-64).
    Portable,
    /// AVX2 and FMA (x86-64).
    Avx2,
    /// AVX-512 F, VL, BW and DQ (x86-64).
    Avx512,
}

impl Level {
    /// Every level, narrowest first.
    pub const ALL: [Level; 3] = [Level::Portable, Level::Avx2, Level::Avx512];

    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            Level::Portable => "portable",
            Level::Avx2 => "avx2",
            Level::Avx512 => "avx512",
        }
    }

    /// Whether this CPU has the level's instructions (asked once: the
    /// vector kernels ask before every call).
    pub fn available(self) -> bool {
        static HAS: std::sync::OnceLock<[bool; 3]> = std::sync::OnceLock::new();
        HAS.get_or_init(|| Level::ALL.map(Level::ask_cpu))[self as usize]
    }

    /// Whether this CPU has the level's instructions, asked of the CPU.
    fn ask_cpu(self) -> bool {
        #[cfg(target_arch = "x86_64")]
        {
            match self {
                Level::Portable => true,
                // Everything the AVX2 functions enable (every AVX2 CPU
                // has the bit-manipulation ones; checked all the same).
                Level::Avx2 => {
                    std::arch::is_x86_feature_detected!("avx2")
                        && std::arch::is_x86_feature_detected!("fma")
                        && std::arch::is_x86_feature_detected!("bmi1")
                        && std::arch::is_x86_feature_detected!("bmi2")
                        && std::arch::is_x86_feature_detected!("lzcnt")
                        && std::arch::is_x86_feature_detected!("popcnt")
                }
                Level::Avx512 => {
                    Level::Avx2.ask_cpu()
                        && std::arch::is_x86_feature_detected!("avx512f")
                        && std::arch::is_x86_feature_detected!("avx512vl")
                        && std::arch::is_x86_feature_detected!("avx512bw")
                        && std::arch::is_x86_feature_detected!("avx512dq")
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            self == Level::Portable
        }
    }

    /// The widest level this CPU has, or the one `RAYSTEP_SIMD` names
    /// if the CPU has it (a name it does not know, or a level the CPU
    /// lacks, is ignored with a warning on stderr).
    pub fn detect() -> Level {
        let best = Level::ALL
            .into_iter()
            .rev()
            .find(|l| l.available())
            .unwrap_or(Level::Portable);
        let Ok(asked) = std::env::var("RAYSTEP_SIMD") else {
            return best;
        };
        match Level::ALL.into_iter().find(|l| l.name() == asked) {
            Some(l) if l.available() => l,
            Some(l) => {
                eprintln!(
                    "RAYSTEP_SIMD={asked}: this CPU has no {}; using {}",
                    l.name(),
                    best.name()
                );
                best
            }
            None => {
                eprintln!(
                    "RAYSTEP_SIMD={asked}: expected portable, avx2 or avx512; using {}",
                    best.name()
                );
                best
            }
        }
    }
}
