//! Which vector instructions the fast engine's ray queries use, chosen
//! at run time.

thread_local! {
    /// Levels [`Level::pretend_lacking`] hides on this thread (a bit each).
    static LACKING: std::cell::Cell<u8> = const { std::cell::Cell::new(0) };
}

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

    /// This level if the CPU has it (and [`Level::pretend_lacking`] does
    /// not hide it on this thread), else the portable one: what a tree is
    /// built for.
    pub fn or_portable(self) -> Level {
        let hidden = LACKING.with(|l| l.get()) >> self as u8 & 1 == 1;
        match self.available() && !hidden {
            true => self,
            false => Level::Portable,
        }
    }

    /// Runs `f` as if this CPU lacked `levels`, for what [`Level::or_portable`]
    /// decides on this thread: how a test sees that a tree asked for
    /// instructions the CPU lacks is built for the portable ones. It can
    /// only take levels away, never claim one the CPU lacks.
    pub fn pretend_lacking<R>(levels: &[Level], f: impl FnOnce() -> R) -> R {
        let mask = levels.iter().fold(0u8, |m, l| m | 1 << *l as u8);
        let before = LACKING.with(|l| l.replace(l.get() | mask));
        struct Restore(u8);
        impl Drop for Restore {
            fn drop(&mut self) {
                LACKING.with(|l| l.set(self.0));
            }
        }
        let _restore = Restore(before);
        f()
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
